//! The run-time observer: the last `N` samples in a ring buffer, one estimate per target.

use heapless::Deque;

use crate::{Estimate, Scalar, TargetMap};

/// One sampling instant: the measured outputs and the applied inputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample<T, const NY: usize, const NU: usize> {
    /// `y(k)`.
    pub y: [T; NY],
    /// `u(k)`.
    pub u: [T; NU],
}

/// A sample was refused because one of its values is NaN or infinite; the observer is unchanged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RejectedSample;

/// Observer of `NT` targets from the last `N` samples of `NY` outputs and `NU` inputs.
///
/// Memory is fixed at compile time (the ring buffer holds `N` samples); [`Observer::estimate`] runs
/// the same instructions for every sample once the buffer is full. Generated designs provide the
/// tables and a constructor; by hand it looks like this:
///
/// ```
/// use firmware::{Gamma, Observer, TargetMap};
///
/// // r = Γ⁻¹(0.5 y(k) + 0.5 y(k-1)) with Γ(η) = η on [0, 1], r ∈ [0, 10].
/// static MAPS: [TargetMap<'static, f32>; 1] = [TargetMap {
///     gains: &[0.5, 0.5],
///     gamma: Gamma { offset: 0.0, weights: &[1.0], odds_ratios: &[1.0] },
///     r_min: 0.0,
///     r_span: 10.0,
/// }];
/// let mut observer: Observer<'_, f32, 2, 1, 0, 1> = Observer::new(&MAPS);
/// observer.push([0.2], []).unwrap();
/// assert!(observer.estimate().is_none()); // fewer than N = 2 samples
/// observer.push([0.4], []).unwrap();
/// assert!(observer.push([f32::NAN], []).is_err()); // refused, the window is unchanged
/// let [r] = observer.estimate().unwrap();
/// assert!((r.value - 3.0).abs() < 1e-5 && !r.saturation.is_saturated());
/// ```
pub struct Observer<'a, T, const N: usize, const NY: usize, const NU: usize, const NT: usize> {
    maps: &'a [TargetMap<'a, T>; NT],
    /// The last `N` accepted samples, oldest first. (A `Deque` rather than a `HistoryBuf`: its
    /// accesses are unchecked inside heapless, so no bounds-check panic path reaches the firmware.)
    window: Deque<Sample<T, NY, NU>, N>,
}

impl<'a, T: Scalar, const N: usize, const NY: usize, const NU: usize, const NT: usize> Observer<'a, T, N, NY, NU, NT> {
    /// An observer with an empty window. Each map's gains are laid out as the regressor
    /// `Z = (y(k), …, y(k-N+1), u(k), …, u(k-N+1))`: `N·NY` output gains, then `N·NU` input gains.
    pub const fn new(maps: &'a [TargetMap<'a, T>; NT]) -> Self {
        Observer {
            maps,
            window: Deque::new(),
        }
    }

    /// Appends the sample of the current instant. A sample with a NaN or infinite value is refused
    /// and nothing stored changes.
    pub fn push(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), RejectedSample> {
        if y.iter().chain(u.iter()).all(|v| v.is_finite()) {
            if self.window.is_full() {
                self.window.pop_front();
            }
            // Cannot fail: there is room now (and N = 0 is refused by heapless at compile time).
            let _ = self.window.push_back(Sample { y, u });
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
    pub fn is_ready(&self) -> bool {
        self.window.is_full()
    }

    /// One estimate per target from the last `N` samples, or `None` before `N` samples have arrived.
    pub fn estimate(&self) -> Option<[Estimate<T>; NT]> {
        if !self.window.is_full() {
            return None;
        }
        Some(self.maps.map(|map| map.estimate_from_projection(self.project(&map))))
    }

    /// `Lᵀ Z` over the window, summed in regressor order (all outputs newest first, then all inputs),
    /// so that it rounds exactly as [`TargetMap::project`] on the same regressor.
    fn project(&self, map: &TargetMap<'_, T>) -> T {
        let (output_gains, input_gains) = map.gains.split_at_checked(N * NY).unwrap_or((map.gains, &[]));
        let mut sum = T::zero();
        for (gains, sample) in output_gains.chunks_exact(NY.max(1)).zip(self.window.iter().rev()) {
            for (&g, &y) in gains.iter().zip(&sample.y) {
                sum += g * y;
            }
        }
        for (gains, sample) in input_gains.chunks_exact(NU.max(1)).zip(self.window.iter().rev()) {
            for (&g, &u) in gains.iter().zip(&sample.u) {
                sum += g * u;
            }
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Gamma, Saturation};

    // Γ(η) = 1 + 2η + 3 B(η; c = 5), two outputs and one input over a horizon of 3.
    const WEIGHTS: [f64; 2] = [2.0, 15.0];
    const ODDS_RATIOS: [f64; 2] = [1.0, 5.0];
    const GAINS: [f64; 9] = [0.5, -0.25, 0.125, 1.0, -1.0, 0.75, 0.3, -0.2, 0.1];
    static MAPS: [TargetMap<'static, f64>; 1] = [TargetMap {
        gains: &GAINS,
        gamma: Gamma {
            offset: 1.0,
            weights: &WEIGHTS,
            odds_ratios: &ODDS_RATIOS,
        },
        r_min: -2.0,
        r_span: 4.0,
    }];

    fn sample(k: usize) -> ([f64; 2], [f64; 1]) {
        let t = k as f64;
        ([(0.3 * t).sin() + 1.0, 0.1 * t], [(0.7 * t).cos()])
    }

    #[test]
    fn estimates_equal_the_regressor_path_bit_for_bit() {
        let mut observer: Observer<'_, f64, 3, 2, 1, 1> = Observer::new(&MAPS);
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
            let expected = MAPS[0].estimate(&z);
            assert_eq!(observer.estimate().unwrap()[0], expected, "k = {k}");
        }
    }

    #[test]
    fn non_finite_samples_are_refused_and_change_nothing() {
        let mut observer: Observer<'_, f64, 3, 2, 1, 1> = Observer::new(&MAPS);
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
        let mut observer: Observer<'_, f64, 3, 2, 1, 1> = Observer::new(&MAPS);
        for _ in 0..3 {
            observer.push([-1e6, 0.0], [0.0]).unwrap(); // Lᵀ Z = (0.5 + 0.125 - 1) · -1e6 > Γ(1)
        }
        let estimate = observer.estimate().unwrap()[0];
        assert_eq!(
            estimate,
            Estimate {
                value: 2.0,
                saturation: Saturation::High
            }
        );
    }

    #[test]
    fn works_in_f32_without_inputs() {
        static GAINS32: [f32; 2] = [1.0, 1.0];
        static W: [f32; 1] = [1.0];
        static B: [f32; 1] = [1.0];
        static MAPS32: [TargetMap<'static, f32>; 1] = [TargetMap {
            gains: &GAINS32,
            gamma: Gamma {
                offset: 0.0,
                weights: &W,
                odds_ratios: &B,
            },
            r_min: 0.0,
            r_span: 1.0,
        }];
        let mut observer: Observer<'_, f32, 2, 1, 0, 1> = Observer::new(&MAPS32);
        observer.push([0.25], []).unwrap();
        observer.push([0.5], []).unwrap();
        let estimate = observer.estimate().unwrap()[0];
        assert!((estimate.value - 0.75).abs() < 1e-6 && estimate.saturation == Saturation::Inside);
    }
}
