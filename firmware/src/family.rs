//! A family of designs that differ by the value of one measured output at the start of a batch (the
//! paper's Example 2 has one design per initial biomass): the observer picks, at the first accepted
//! sample of each batch, the member whose value is nearest that sample's output, and keeps it until
//! [`FamilyObserver::reset`].

use crate::{Estimate, Observer, RejectedSample, Scalar, TargetMap};

/// One member: the maps of a design and its value of the selecting output.
#[derive(Clone, Copy, Debug)]
pub struct Member<'a, T, const NT: usize> {
    /// The member's value of the selecting output (e.g. its initial biomass).
    pub value: T,
    /// Its maps.
    pub maps: &'a [TargetMap<'a, T>; NT],
}

/// An observer over a family of `K` designs sharing `N`, `NY`, `NU` and `NT`.
pub struct FamilyObserver<'a, T, const N: usize, const NY: usize, const NU: usize, const NT: usize, const K: usize> {
    members: &'a [Member<'a, T, NT>; K],
    output: usize,
    chosen: Option<(usize, Observer<'a, T, N, NY, NU, NT>)>,
}

impl<'a, T: Scalar, const N: usize, const NY: usize, const NU: usize, const NT: usize, const K: usize>
    FamilyObserver<'a, T, N, NY, NU, NT, K>
{
    /// A family observer choosing by output `output` (an index into `y`).
    pub const fn new(members: &'a [Member<'a, T, NT>; K], output: usize) -> Self {
        FamilyObserver {
            members,
            output,
            chosen: None,
        }
    }

    /// Appends a sample; the first accepted sample of a batch chooses the member. A sample with a NaN
    /// or infinite value is refused and nothing changes.
    pub fn push(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), RejectedSample> {
        if !y.iter().chain(u.iter()).all(|v| v.is_finite()) {
            return Err(RejectedSample);
        }
        if self.chosen.is_none() {
            let selector = y.get(self.output).copied().unwrap_or_else(T::zero);
            let mut best: Option<(usize, T)> = None;
            for (index, member) in self.members.iter().enumerate() {
                let distance = (member.value - selector).abs();
                if best.is_none_or(|(_, d)| distance < d) {
                    best = Some((index, distance));
                }
            }
            if let Some((index, _)) = best {
                if let Some(member) = self.members.get(index) {
                    self.chosen = Some((index, Observer::new(member.maps)));
                }
            }
        }
        match &mut self.chosen {
            Some((_, observer)) => observer.push(y, u),
            None => Err(RejectedSample), // an empty family has nothing to estimate with
        }
    }

    /// Starts a new batch: forgets the samples and the chosen member.
    pub fn reset(&mut self) {
        self.chosen = None;
    }

    /// Index of the member in use, once the batch's first sample has arrived.
    pub fn chosen(&self) -> Option<usize> {
        self.chosen.as_ref().map(|(index, _)| *index)
    }

    /// The chosen member's estimates, or `None` before `N` samples of the batch have arrived.
    pub fn estimate(&self) -> Option<[Estimate<T>; NT]> {
        self.chosen.as_ref()?.1.estimate()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Gamma;

    static W: [f64; 1] = [1.0];
    static B: [f64; 1] = [1.0];
    static LOW: [TargetMap<'static, f64>; 1] = [TargetMap {
        gains: &[1.0, 0.0],
        gamma: Gamma {
            offset: 0.0,
            weights: &W,
            odds_ratios: &B,
        },
        r_min: 0.0,
        r_span: 1.0,
    }];
    static HIGH: [TargetMap<'static, f64>; 1] = [TargetMap {
        gains: &[1.0, 0.0],
        gamma: Gamma {
            offset: 0.0,
            weights: &W,
            odds_ratios: &B,
        },
        r_min: 10.0,
        r_span: 1.0,
    }];
    static MEMBERS: [Member<'static, f64, 1>; 2] = [
        Member { value: 0.5, maps: &LOW },
        Member {
            value: 2.0,
            maps: &HIGH,
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
        assert_eq!(e.value, 1.0); // LOW clamps v = 1.9 to r_max = 1; HIGH would give 11
        observer.reset();
        assert!(observer.estimate().is_none());
        observer.push([1.6], []).unwrap();
        assert_eq!(observer.chosen(), Some(1));
    }
}
