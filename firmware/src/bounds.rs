//! Physical bounds on a state (a concentration, a level, a pressure cannot be negative): every
//! observer that carries the model projects its state onto them after each update and each
//! prediction, the usual practice for an EKF whose linearisation overshoots (clipping; Haseltine and
//! Rawlings, *Critical evaluation of extended Kalman filtering and moving-horizon estimation*, 2005).
//!
//! A projection is a comparison and a select per bounded side: no division, no branch, the same
//! instructions whatever the value. A NaN goes to the bound (never a NaN carried on); the filters
//! refuse a step whose covariance is not finite in any case.

/// `x`, or `low` where `x` is below it (or NaN): `max(x, low)` by a select.
#[inline(always)]
#[must_use]
#[allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x >= low)`: a NaN goes to the bound.
pub fn at_least<T: PartialOrd + Copy>(x: T, low: T) -> T {
    core::hint::select_unpredictable(!(x >= low), low, x)
}

/// `x`, or `high` where `x` is above it: `min(x, high)` by a select (a NaN stays NaN).
#[inline(always)]
#[must_use]
pub fn at_most<T: PartialOrd + Copy>(x: T, high: T) -> T {
    core::hint::select_unpredictable(x > high, high, x)
}

/// `x` projected onto the box `[lower, upper]` entry by entry: [`at_least`], then [`at_most`]. An
/// unbounded side is `±∞`, which leaves every finite value as it is.
#[inline(always)]
#[must_use]
pub fn project<T: PartialOrd + Copy, const M: usize>(x: &[T; M], lower: &[T; M], upper: &[T; M]) -> [T; M] {
    let mut out = *x;
    for i in 0..M {
        out[i] = at_most(at_least(x[i], lower[i]), upper[i]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn projection_is_the_nearest_point_of_the_box() {
        let (lower, upper) = ([0.0, f64::NEG_INFINITY], [1.0, 2.0]);
        assert_eq!(project(&[-0.5, -1e300], &lower, &upper), [0.0, -1e300]);
        assert_eq!(project(&[0.25, 3.0], &lower, &upper), [0.25, 2.0]);
        assert_eq!(project(&[7.0, 2.0], &lower, &upper), [1.0, 2.0]);
        // -0 is not below 0: left as it is (a select, not arithmetic).
        assert_eq!(at_least(-0.0_f64, 0.0).to_bits(), (-0.0_f64).to_bits());
        assert_eq!(at_least(f64::NAN, 0.0), 0.0);
        assert!(at_most(f64::NAN, 1.0).is_nan());
    }
}
