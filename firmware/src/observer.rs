//! The run-time observer: the last `N` samples and one estimate per target.

use core::marker::PhantomData;

use crate::window::{Sample, Window};
use crate::{Estimate, Scalar, TargetMap};

/// A sample was refused because one of its values is NaN or infinite; the observer is unchanged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RejectedSample;

impl core::fmt::Display for RejectedSample {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("sample refused: a value is NaN or infinite (the observer is unchanged)")
    }
}

impl core::error::Error for RejectedSample {}

/// A design: `NT` maps of the last `N` samples of `NY` outputs and `NU` inputs.
///
/// Generated designs implement it for a unit type, override [`Design::estimate`] with the same sums
/// written out as straight-line code, and export `type Observer = firmware::Observer<…, Design, …>`.
pub trait Design<T: Scalar, const N: usize, const NY: usize, const NU: usize, const NT: usize> {
    /// Every target's map, in estimate order. Gains are laid out as the regressor
    /// `Z = (y(k), …, y(k-N+1), u(k), …, u(k-N+1))`: `N·NY` output gains, then `N·NU` input gains.
    const MAPS: [TargetMap<'static, T>; NT];

    /// One estimate per target from the last `N` samples, oldest first. The default loops over the
    /// gains ([`estimate_by_loops`]); an override must give the same bits.
    #[inline(always)]
    #[must_use]
    fn estimate(window: &[Sample<T, NY, NU>; N]) -> [Estimate<T>; NT] {
        estimate_by_loops(&Self::MAPS, window)
    }

    /// Whether a sample may enter the window: every value finite. The default loops; an override
    /// must give the same answer.
    #[inline(always)]
    #[must_use]
    fn accepts(y: &[T; NY], u: &[T; NU]) -> bool {
        all_finite(y, u)
    }
}

/// Every map's estimate from a window (oldest first), summing `offset + Σ g_i z_i` in regressor order
/// (all outputs newest first, then all inputs), so that it rounds exactly as [`TargetMap::project`]
/// on the same regressor. Pruned taps (gain exactly 0, sparse `L`) are skipped, as the generated
/// straight-line code leaves them out: the branch depends on the constants only, never on the data.
#[must_use]
pub fn estimate_by_loops<T: Scalar, const N: usize, const NY: usize, const NU: usize, const NT: usize>(
    maps: &[TargetMap<'_, T>; NT],
    window: &[Sample<T, NY, NU>; N],
) -> [Estimate<T>; NT] {
    maps.each_ref().map(|map| {
        let (output_gains, input_gains) = map.gains.split_at_checked(N * NY).unwrap_or((map.gains, &[]));
        let mut sum = map.offset;
        for (gains, sample) in output_gains.chunks_exact(NY.max(1)).zip(window.iter().rev()) {
            for (&g, &y) in gains.iter().zip(&sample.y) {
                if g != T::ZERO {
                    sum += g * y;
                }
            }
        }
        for (gains, sample) in input_gains.chunks_exact(NU.max(1)).zip(window.iter().rev()) {
            for (&g, &u) in gains.iter().zip(&sample.u) {
                if g != T::ZERO {
                    sum += g * u;
                }
            }
        }
        map.inverse.evaluate(sum)
    })
}

/// `true` when every value is finite. Without early exit, so that the compiler can flatten it.
#[inline(always)]
pub(crate) fn all_finite<T: Scalar, const NY: usize, const NU: usize>(y: &[T; NY], u: &[T; NU]) -> bool {
    let mut finite = true;
    for v in y {
        finite &= v.is_finite();
    }
    for v in u {
        finite &= v.is_finite();
    }
    finite
}

/// Observer of design `D`: `NT` targets from the last `N` samples of `NY` outputs and `NU` inputs.
///
/// Memory is fixed at compile time (the window of `N` samples, stored twice); once the window is
/// full, [`Observer::estimate`] runs the same instructions for every sample. Generated designs
/// provide `D` and a constructor; by hand it looks like this:
///
/// ```
/// use firmware::{Design, InverseTable, Knots, Observer, TargetMap};
///
/// // r = 10 (0.5 y(k) + 0.5 y(k-1)) on [0, 10]: Γ(η) = η, one segment (t = v, r = 10 t).
/// struct Mean;
/// impl Design<f32, 2, 1, 0, 1> for Mean {
///     const MAPS: [TargetMap<'static, f32>; 1] = [TargetMap {
///         gains: &[0.5, 0.5],
///         offset: 0.0,
///         inverse: InverseTable { knots: Knots::Uniform, segments: &[[0.0, 10.0]], t_max: 1.0, r_min: 0.0, r_max: 10.0 },
///     }];
/// }
/// let mut observer: Observer<f32, Mean, 2, 1, 0, 1> = Observer::new();
/// observer.push([0.2], []).unwrap();
/// assert!(observer.estimate().is_none()); // fewer than N = 2 samples
/// observer.push([0.4], []).unwrap();
/// assert!(observer.push([f32::NAN], []).is_err()); // refused, the window is unchanged
/// let [r] = observer.estimate().unwrap();
/// assert!((r.value - 3.0).abs() < 1e-5 && !r.saturation.is_saturated());
/// ```
pub struct Observer<T, D, const N: usize, const NY: usize, const NU: usize, const NT: usize> {
    window: Window<T, N, NY, NU>,
    design: PhantomData<fn() -> D>,
}

impl<T: Scalar, D: Design<T, N, NY, NU, NT>, const N: usize, const NY: usize, const NU: usize, const NT: usize>
    Observer<T, D, N, NY, NU, NT>
{
    /// An observer with an empty window.
    #[must_use]
    pub const fn new() -> Self {
        Observer {
            window: Window::new(),
            design: PhantomData,
        }
    }

    /// Appends the sample of the current instant. A sample with a NaN or infinite value is refused
    /// and nothing stored changes.
    #[inline]
    pub fn push(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), RejectedSample> {
        if D::accepts(&y, &u) {
            self.window.push(Sample { y, u });
            Ok(())
        } else {
            Err(RejectedSample)
        }
    }

    /// Forgets every sample (a new batch or run starts).
    pub fn reset(&mut self) {
        self.window.clear();
    }

    /// `true` once `N` samples have arrived.
    #[must_use]
    pub fn is_ready(&self) -> bool {
        self.window.is_full()
    }

    /// One estimate per target from the last `N` samples, or `None` before `N` samples have arrived.
    #[inline]
    #[must_use]
    pub fn estimate(&self) -> Option<[Estimate<T>; NT]> {
        self.window.samples().map(D::estimate)
    }
}

impl<T: Scalar, D: Design<T, N, NY, NU, NT>, const N: usize, const NY: usize, const NU: usize, const NT: usize> Default
    for Observer<T, D, N, NY, NU, NT>
{
    fn default() -> Self {
        Self::new()
    }
}

// `Clone` and `Debug` by hand: derives would demand them of the design `D`, a marker type that is
// never stored, so that `Observer<…, D, …>` would lack them for the unit types generated code emits.
impl<T: Clone, D, const N: usize, const NY: usize, const NU: usize, const NT: usize> Clone
    for Observer<T, D, N, NY, NU, NT>
{
    fn clone(&self) -> Self {
        Observer {
            window: self.window.clone(),
            design: PhantomData,
        }
    }
}

impl<T: core::fmt::Debug, D, const N: usize, const NY: usize, const NU: usize, const NT: usize> core::fmt::Debug
    for Observer<T, D, N, NY, NU, NT>
{
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Observer")
            .field("design", &core::any::type_name::<D>())
            .field("window", &self.window)
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{InverseTable, Knots, Saturation};

    // Two outputs and one input over a horizon of 3; t = offset + Lᵀ Z, r = 2 t² on [0, 2] in two
    // segments through t = 0, 1, 2 (chords of 2t²: r = 2t on [0, 1], r = -4 + 6t on [1, 2]).
    const GAINS: [f64; 9] = [0.05, -0.025, 0.0125, 0.1, -0.1, 0.075, 0.03, -0.02, 0.01];
    struct Test;
    impl Design<f64, 3, 2, 1, 1> for Test {
        const MAPS: [TargetMap<'static, f64>; 1] = [TargetMap {
            gains: &GAINS,
            offset: 1.0,
            inverse: InverseTable {
                knots: Knots::Uniform,
                segments: &[[0.0, 2.0], [-4.0, 6.0]],
                t_max: 2.0,
                r_min: 0.0,
                r_max: 8.0,
            },
        }];
    }
    type TestObserver = Observer<f64, Test, 3, 2, 1, 1>;

    fn sample(k: usize) -> ([f64; 2], [f64; 1]) {
        let t = k as f64;
        ([(0.3 * t).sin() + 1.0, 0.1 * t], [(0.7 * t).cos()])
    }

    #[test]
    fn estimates_equal_the_regressor_path_bit_for_bit() {
        let mut observer = TestObserver::new();
        for k in 0..20 {
            let (y, u) = sample(k);
            observer.push(y, u).unwrap();
            if k < 2 {
                assert!(observer.estimate().is_none() && !observer.is_ready());
                continue;
            }
            // Z = (y(k), y(k-1), y(k-2), u(k), u(k-1), u(k-2)), outputs of one instant together.
            let mut z = [0.0; 9];
            for lag in 0..3 {
                let (y, u) = sample(k - lag);
                z[2 * lag] = y[0];
                z[2 * lag + 1] = y[1];
                z[6 + lag] = u[0];
            }
            let expected = Test::MAPS[0].estimate(&z);
            assert_eq!(observer.estimate().unwrap()[0], expected, "k = {k}");
        }
    }

    #[test]
    fn non_finite_samples_are_refused_and_change_nothing() {
        let mut observer = TestObserver::new();
        for k in 0..3 {
            let (y, u) = sample(k);
            observer.push(y, u).unwrap();
        }
        let before = observer.estimate().unwrap();
        assert_eq!(observer.push([f64::NAN, 0.0], [0.0]), Err(RejectedSample));
        assert_eq!(observer.push([0.0, f64::INFINITY], [0.0]), Err(RejectedSample));
        assert_eq!(observer.push([0.0, 0.0], [f64::NEG_INFINITY]), Err(RejectedSample));
        assert_eq!(observer.estimate().unwrap(), before);
        observer.reset();
        assert!(observer.estimate().is_none());
    }

    #[test]
    fn saturation_is_reported() {
        let mut observer = TestObserver::new();
        for _ in 0..3 {
            // The y0 gains sum to 0.05 + 0.0125 - 0.1 = -0.0375: t = 1 - 37 500 < 0.
            observer.push([1e6, 0.0], [0.0]).unwrap();
        }
        assert_eq!(
            observer.estimate().unwrap()[0],
            Estimate {
                value: 0.0,
                saturation: Saturation::Low
            }
        );
        for _ in 0..3 {
            observer.push([-1e6, 0.0], [0.0]).unwrap();
        }
        assert_eq!(
            observer.estimate().unwrap()[0],
            Estimate {
                value: 8.0,
                saturation: Saturation::High
            }
        );
    }

    #[test]
    fn rejected_sample_says_what_happened() {
        let text = std::format!("{RejectedSample}");
        assert!(text.contains("NaN or infinite"), "{text}");
        // Usable wherever an error is expected (`?` into a boxed error, error reporters).
        let error: &dyn core::error::Error = &RejectedSample;
        assert_eq!(error.to_string(), text);
        assert!(error.source().is_none());
    }

    #[test]
    fn a_clone_continues_independently_and_debug_names_the_design() {
        // `Test` is neither `Clone` nor `Debug`: the observer must be both regardless.
        let mut observer = TestObserver::new();
        for k in 0..3 {
            let (y, u) = sample(k);
            observer.push(y, u).unwrap();
        }
        let mut copy = observer.clone();
        assert_eq!(copy.estimate(), observer.estimate());
        let (y, u) = sample(3);
        copy.push(y, u).unwrap();
        assert_ne!(copy.estimate(), observer.estimate());
        observer.push(y, u).unwrap();
        assert_eq!(copy.estimate(), observer.estimate());
        let text = std::format!("{observer:?}");
        assert!(text.starts_with("Observer") && text.contains("Test"), "{text}");
    }
}
