//! A family of designs that differ by the value of one measured output at the start of a batch (the
//! paper's Example 2 has one design per initial biomass): the observer picks, at the first accepted
//! sample of each batch, the member whose value is nearest that sample's output, and keeps it until
//! [`FamilyObserver::reset`].

use crate::observer::all_finite;
use crate::window::{Sample, Window};
use crate::{Estimate, RejectedSample, Scalar};

/// One member: its value of the selecting output and its estimate (a design's [`crate::Design::estimate`]).
#[derive(Clone, Copy, Debug)]
pub struct Member<T, const N: usize, const NY: usize, const NU: usize, const NT: usize> {
    /// The member's value of the selecting output (e.g. its initial biomass).
    pub value: T,
    /// Its estimate from a full window, oldest first.
    pub estimate: fn(&[Sample<T, NY, NU>; N]) -> [Estimate<T>; NT],
}

/// An observer over a family of `K` designs sharing `N`, `NY`, `NU` and `NT`.
///
/// A clone shares the members (they are borrowed) and copies the window and the choice.
#[derive(Clone, Debug)]
pub struct FamilyObserver<'a, T, const N: usize, const NY: usize, const NU: usize, const NT: usize, const K: usize> {
    members: &'a [Member<T, N, NY, NU, NT>; K],
    output: usize,
    window: Window<T, N, NY, NU>,
    chosen: Option<usize>,
}

impl<'a, T: Scalar, const N: usize, const NY: usize, const NU: usize, const NT: usize, const K: usize>
    FamilyObserver<'a, T, N, NY, NU, NT, K>
{
    /// A family observer choosing by output `output` (an index into `y`).
    #[must_use]
    pub const fn new(members: &'a [Member<T, N, NY, NU, NT>; K], output: usize) -> Self {
        FamilyObserver {
            members,
            output,
            window: Window::new(),
            chosen: None,
        }
    }

    /// Appends a sample; the first accepted sample of a batch chooses the member. A sample with a NaN
    /// or infinite value is refused and nothing changes; so is every sample of an empty family.
    pub fn push(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), RejectedSample> {
        if !all_finite(&y, &u) {
            return Err(RejectedSample);
        }
        if self.chosen.is_none() {
            let selector = y.get(self.output).copied().unwrap_or(T::ZERO);
            let mut best: Option<(usize, T)> = None;
            for (index, member) in self.members.iter().enumerate() {
                let distance = (member.value - selector).abs();
                if best.is_none_or(|(_, d)| distance < d) {
                    best = Some((index, distance));
                }
            }
            self.chosen = Some(best.ok_or(RejectedSample)?.0);
        }
        self.window.push(Sample { y, u });
        Ok(())
    }

    /// Starts a new batch: forgets the samples and the chosen member.
    pub fn reset(&mut self) {
        self.chosen = None;
        self.window.clear();
    }

    /// `true` once `N` samples of the batch have arrived (and a member is chosen).
    #[must_use]
    pub fn is_ready(&self) -> bool {
        self.chosen.is_some() && self.window.is_full()
    }

    /// Index of the member in use, once the batch's first sample has arrived.
    #[must_use]
    pub fn chosen(&self) -> Option<usize> {
        self.chosen
    }

    /// The chosen member's estimates, or `None` before `N` samples of the batch have arrived.
    #[must_use]
    pub fn estimate(&self) -> Option<[Estimate<T>; NT]> {
        let member = self.members.get(self.chosen?)?;
        self.window.samples().map(member.estimate)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Design, InverseTable, Knots, TargetMap};

    // Both members estimate y(k) itself (t = y(k), one segment), LOW on [0, 1], HIGH on [10, 11].
    struct Low;
    impl Design<f64, 2, 1, 0, 1> for Low {
        const MAPS: [TargetMap<'static, f64>; 1] = [TargetMap {
            gains: &[1.0, 0.0],
            offset: 0.0,
            inverse: InverseTable {
                knots: Knots::Uniform,
                segments: &[[0.0, 1.0]],
                t_max: 1.0,
                r_min: 0.0,
                r_max: 1.0,
            },
        }];
    }
    struct High;
    impl Design<f64, 2, 1, 0, 1> for High {
        const MAPS: [TargetMap<'static, f64>; 1] = [TargetMap {
            gains: &[1.0, 0.0],
            offset: 0.0,
            inverse: InverseTable {
                knots: Knots::Uniform,
                segments: &[[10.0, 1.0]],
                t_max: 1.0,
                r_min: 10.0,
                r_max: 11.0,
            },
        }];
    }
    static MEMBERS: [Member<f64, 2, 1, 0, 1>; 2] = [
        Member {
            value: 0.5,
            estimate: <Low as Design<f64, 2, 1, 0, 1>>::estimate,
        },
        Member {
            value: 2.0,
            estimate: <High as Design<f64, 2, 1, 0, 1>>::estimate,
        },
    ];

    #[test]
    fn picks_the_nearest_member_at_the_first_sample_of_each_batch() {
        let mut observer: FamilyObserver<'_, f64, 2, 1, 0, 1, 2> = FamilyObserver::new(&MEMBERS, 0);
        assert!(observer.push([f64::NAN], []).is_err() && observer.chosen().is_none());
        observer.push([1.1], []).unwrap(); // |1.1 - 0.5| < |1.1 - 2|
        observer.push([1.9], []).unwrap(); // later samples do not change the choice
        assert_eq!(observer.chosen(), Some(0));
        let [e] = observer.estimate().unwrap();
        assert_eq!(e.value, 1.0); // LOW clamps t = 1.9 to r_max = 1; HIGH would give 11
        observer.reset();
        assert!(observer.estimate().is_none());
        observer.push([1.6], []).unwrap();
        assert_eq!(observer.chosen(), Some(1));
    }

    #[test]
    fn a_clone_keeps_the_choice_and_continues_independently() {
        let mut observer: FamilyObserver<'_, f64, 2, 1, 0, 1, 2> = FamilyObserver::new(&MEMBERS, 0);
        observer.push([1.6], []).unwrap();
        let mut copy = observer.clone();
        copy.reset();
        copy.push([0.4], []).unwrap();
        assert_eq!((observer.chosen(), copy.chosen()), (Some(1), Some(0)));
        observer.push([0.5], []).unwrap(); // HIGH: r = 10 + y(k)
        assert_eq!(observer.estimate().unwrap()[0].value, 10.5);
        assert!(copy.estimate().is_none());
        let text = std::format!("{observer:?}");
        assert!(
            text.starts_with("FamilyObserver") && text.contains("chosen: Some(1)"),
            "{text}"
        );
    }

    #[test]
    fn an_empty_family_refuses_every_sample() {
        static NONE: [Member<f64, 2, 1, 0, 1>; 0] = [];
        let mut observer: FamilyObserver<'_, f64, 2, 1, 0, 1, 0> = FamilyObserver::new(&NONE, 0);
        assert_eq!(observer.push([1.0], []), Err(RejectedSample));
        assert!(observer.estimate().is_none());
    }
}
