//! The χ² watch: a Kalman filter whose innovations stay implausible restarts.
//!
//! A filter can lose track with every number finite: its estimate settles on a wrong value and its
//! covariance shrinks, so that it trusts itself and ignores the measurements (a pendulum filter that
//! froze at a velocity of −13 rad/s while the pendulum hung still). What gives it away is the
//! innovation `ν = y − ŷ` against its predicted covariance `S`. The normalised innovation squared
//!
//! ```text
//! ε = νᵀ S⁻¹ ν           (R diagonal, sequential scalar updates: ε = Σᵢ νᵢ² / sᵢ)
//! ```
//!
//! is χ²-distributed with `m` degrees of freedom (`m` outputs) when the filter's model and noise are
//! right: its mean is `m`. One large `ε` is an outlier; a run of them is a lost filter. The watch keeps
//! their exponentially weighted mean over about `W` samples and restarts the filter when it leaves the
//! plausible range:
//!
//! ```text
//! c ← c + g (ε − c),   g = 1 / W,   c = m at the start;    restart when  not (c ≤ τ m)
//! ```
//!
//! `g` and the limit `τ m` are the design's constants (`τ` tuned on the tuning runs like every
//! constant, `+∞` where watching did not pay); a NaN `c` restarts too. One multiply-add and one
//! comparison per measured sample, no division, no buffer: a window of `W` samples in one number.

use crate::Scalar;

/// A watch's constants, where a kind keeps them as values (the moving-horizon estimate's settings):
/// the mean's start, its gain `g` and its limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Watch<T> {
    /// `c` at the start and after a restart: the watched quantity's mean when the model is right.
    pub start: T,
    /// `g = 1 / W`.
    pub gain: T,
    /// `τ` times the mean.
    pub limit: T,
}

impl<T: Scalar> Watch<T> {
    /// What a kind that keeps its watch as values (`watch`, `None`: not watched) does with a new
    /// `value` of the watched quantity: the mean after it (`chi`: the mean so far, `None` at the start
    /// or after a restart) and whether it is plausible. Unwatched: `(None, true)`.
    #[inline(always)]
    #[must_use]
    pub fn after(watch: Option<Self>, chi: Option<T>, value: T) -> (Option<T>, bool) {
        match watch {
            Some(w) => {
                let chi = watched(chi.unwrap_or(w.start), value, w.gain);
                (Some(chi), plausible(chi, w.limit))
            }
            None => (None, true),
        }
    }
}

/// `c` after a measured sample of normalised innovation squared `nis`: `c + g (ε − c)`, in this order
/// (the emitted Rust and C compute the same operations).
#[inline(always)]
#[must_use]
pub fn watched<T: Scalar>(chi: T, nis: T, gain: T) -> T {
    chi + gain * (nis - chi)
}

/// Whether the watched mean `chi` is plausible: `chi ≤ limit`, false for a NaN.
#[inline(always)]
#[must_use]
pub fn plausible<T: Scalar>(chi: T, limit: T) -> bool {
    chi <= limit
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_mean_follows_a_constant_innovation_as_a_geometric_series() {
        // From c = m = 1 with ε = 9 at every sample: c_k = 9 + (1 − 9)(1 − g)^k, closed form.
        let (gain, mut chi) = (0.1_f64, 1.0);
        for k in 1..=30 {
            chi = watched(chi, 9.0, gain);
            let closed = 9.0 - 8.0 * 0.9_f64.powi(k);
            assert!((chi - closed).abs() < 1e-12, "sample {k}: {chi} against {closed}");
        }
        // Above a limit of 4 m from the 5th sample on (9 − 8 · 0.9⁵ = 4.28 > 4, 9 − 8 · 0.9⁴ = 3.75 ≤ 4):
        // the watch needs a run of implausible samples, not one.
        let mut chi = 1.0;
        let first = (1..=30)
            .find(|_| {
                chi = watched(chi, 9.0, gain);
                !plausible(chi, 4.0)
            })
            .unwrap();
        assert_eq!(first, 5);
    }

    #[test]
    fn a_nan_is_implausible() {
        assert!(!plausible(f32::NAN, f32::INFINITY));
        assert!(plausible(1e30_f32, f32::INFINITY));
        assert!(!plausible(watched(1.0_f32, f32::INFINITY, 0.1), 1e30));
    }
}
