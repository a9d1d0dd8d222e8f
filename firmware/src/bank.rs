//! A bank of filters: `M` copies of one filter, each started in its own slice of the state box and
//! weighed by how well it predicts the measurements; the estimate is their weighted mean.
//!
//! One filter from the centre of the box settles on the wrong branch where the outputs cannot tell
//! two states apart early on (on E. coli a run that starts with little substrate: the first light
//! readings fit a high substrate and a low product as well). A bank keeps every branch alive until
//! the data decide. With member `m` started at `x̂ₘ(0)`, `Pₘ(0)` and prior mass `πₘ` (its slice's
//! share of the box), and its innovation `νₘ` with covariance `Sₘ` at every measured sample, the
//! members' posterior weights are those of a Gaussian sum filter (D. Alspach and H. Sorenson,
//! "Nonlinear Bayesian estimation using Gaussian sum approximations", 1972):
//!
//! ```text
//! ln wₘ ← ln wₘ − eₘ,   eₘ = εₘ / 2 + ln √det Sₘ,   εₘ = νₘᵀ Sₘ⁻¹ νₘ        (ln wₘ(0) = ln πₘ)
//! x̂ = Σ wₘ x̂ₘ / Σ wₘ
//! ```
//!
//! `−eₘ` is the log-likelihood of the member's innovation, `ln N(νₘ; 0, Sₘ)`, but for a constant
//! common to all members. The log-weights are kept relative to the best member's (which is 0 after
//! every sample) and no lower than [`FLOOR`], so that their exponentials neither overflow nor
//! underflow, a member far behind can still come back, and the sum of the weights is at least 1: its
//! one division is safe. A NaN weight goes to the floor. A member whose step restarts it (the rules of
//! [`crate::rules`], its own χ² watch) starts again in its slice at the floor's weight and is left out
//! of that sample's mean; when every member restarts, the bank starts again with its prior weights.
//!
//! Per measured sample: `M` filter samples, `M` logarithms, `M` exponentials and one division, on
//! the same path every sample.

use crate::bounds::at_least;
use crate::maths::Maths;
use crate::Scalar;

/// The lowest relative log-weight a member keeps: `e⁻⁶⁴ ≈ 1.6 · 10⁻²⁸`, a normal `f32`.
pub const FLOOR: f64 = -64.0;

/// [`FLOOR`] in `T`.
#[inline(always)]
#[must_use]
pub fn floor<T: Scalar>() -> T {
    T::literal(-64.0, FLOOR)
}

/// A member's `eₘ = ε / 2 + ln root` from its normalised innovation squared `nis` and `root = √det S`
/// (the product of the diagonal of `S`'s Cholesky factor), in this order (the emitted Rust and C
/// compute the same operations).
#[inline(always)]
#[must_use]
pub fn evidence<T: Scalar + Maths>(nis: T, root: T) -> T {
    nis * T::literal(0.5, 0.5) + Maths::ln(root)
}

/// The log-weights `log` after a measured sample: each member that took it (`taken`) less its
/// `evidence`, one that restarted on it at the floor; then relative to the best of them (which is
/// 0), each no lower than the floor (a NaN to the floor).
#[inline(always)]
pub fn weigh<T: Scalar>(log: &mut [T], evidence: &[T], taken: &[bool]) {
    let floor = floor::<T>();
    let mut top = floor;
    for ((weight, &e), &took) in log.iter_mut().zip(evidence).zip(taken) {
        *weight -= e;
        top = core::hint::select_unpredictable(took && *weight > top, *weight, top);
    }
    for (weight, &took) in log.iter_mut().zip(taken) {
        *weight = core::hint::select_unpredictable(took, at_least(*weight - top, floor), floor);
    }
}

/// The weighted mean `out = Σ wₘ xₘ / Σ wₘ` of the members' `states`, `wₘ = e^{log[m]}` for the members
/// that took the sample (`taken`) and 0 for the others (whose `states` must be finite: the callers pass
/// zeros, `0 · NaN` being NaN); at least one took it, and its weight is at least `e^FLOOR`, so the sum
/// is positive.
#[inline(always)]
pub fn mix<T: Scalar + Maths, S: AsRef<[T]>>(log: &[T], taken: &[bool], states: &[S], out: &mut [T]) {
    for o in out.iter_mut() {
        *o = T::ZERO;
    }
    let mut total = T::ZERO;
    for ((&weight, &took), state) in log.iter().zip(taken).zip(states) {
        let w = core::hint::select_unpredictable(took, Maths::exp(weight), T::ZERO);
        total += w;
        for (o, &x) in out.iter_mut().zip(state.as_ref()) {
            *o += w * x;
        }
    }
    let inverse = T::one() / total;
    for o in out.iter_mut() {
        *o *= inverse;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_are_the_members_likelihoods_relative_to_the_best() {
        // Two members, prior ln 0.25 and ln 0.75; evidence 1 and 3: ln w = ln 0.25 − 1 and ln 0.75 − 3,
        // by hand, relative to the first (the larger).
        let mut log = [0.25f64.ln(), 0.75f64.ln()];
        weigh(&mut log, &[1.0, 3.0], &[true, true]);
        let second = (0.75f64.ln() - 3.0) - (0.25f64.ln() - 1.0);
        assert_eq!(log[0], 0.0);
        assert!((log[1] - second).abs() < 1e-15, "{log:?}");
        // The mean of states 1 and 3 with those weights: (1 + 3 e^second) / (1 + e^second).
        let mut out = [0.0];
        mix(&log, &[true, true], &[[1.0], [3.0]], &mut out);
        let w = second.exp();
        assert!((out[0] - (1.0 + 3.0 * w) / (1.0 + w)).abs() < 1e-15);
    }

    #[test]
    fn a_nan_or_a_restart_goes_to_the_floor_and_out_of_the_mean() {
        let mut log = [0.0f32, -1.0, -2.0];
        weigh(&mut log, &[f32::NAN, 0.5, 1e30], &[true, true, false]);
        // The second is the best (−1.5 → 0); the NaN and the restarted member sit on the floor.
        assert_eq!(log, [-64.0, 0.0, -64.0]);
        // The restarted member's state is left out: its weight is 0, not e⁻⁶⁴.
        let mut out = [0.0f32; 2];
        mix(
            &log,
            &[true, true, false],
            &[[0.0, 1.0], [2.0, 3.0], [5.0, 7.0]],
            &mut out,
        );
        let w = (-64.0f32).exp();
        assert_eq!(
            out,
            [(w * 0.0 + 2.0) * (1.0 / (w + 1.0)), (w * 1.0 + 3.0) * (1.0 / (w + 1.0))]
        );
        // Every weight far below the best stays on the floor, never below: e⁻⁶⁴ is a normal f32.
        let mut log = [0.0f32, 0.0];
        weigh(&mut log, &[0.0, 1e6], &[true, true]);
        assert_eq!(log, [0.0, -64.0]);
        assert!(log[1].exp().is_normal());
    }

    #[test]
    fn evidence_is_half_the_nis_plus_the_log_root() {
        assert_eq!(evidence(3.0f64, 1.0), 1.5);
        assert!((evidence(0.0f64, 2.0) - 2.0f64.ln()).abs() < 1e-15);
    }
}
