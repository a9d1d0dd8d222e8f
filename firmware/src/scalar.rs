//! The scalar types the runtime is generic over.

use nalgebra::RealField;

use crate::window::Stored;

/// A floating-point scalar the observer can run in: `f32` on the microcontroller, `f64` on the host.
pub trait Scalar: RealField + Copy + Stored {
    /// Bisection steps of the exact reference inverse [`crate::Gamma::inverse`]: enough to resolve
    /// `η ∈ [0, 1]` to the type's precision (`2^-24` for `f32`, `2^-52` for `f64`). Only with the
    /// `reference` feature. It has a default, `f64`'s 52, which suits any type no finer than `f64`
    /// (steps past the type's resolution leave the bracket as it is), so that enabling the feature
    /// cannot break an implementation written without it.
    #[cfg(any(test, feature = "reference"))]
    const BISECTION_STEPS: u32 = 52;

    /// Converts an `f64` constant (rounding to nearest). Only with the `reference` feature: the chip's
    /// constants arrive already rounded, in the generated tables.
    #[cfg(any(test, feature = "reference"))]
    #[must_use]
    fn constant(value: f64) -> Self {
        nalgebra::convert(value)
    }

    /// The constant written `single` in `f32` and `double` in `f64`: how emitted code spells a number
    /// once for both precisions, each rounded by the host at generation time, so that the chip never
    /// converts from `f64`.
    #[must_use]
    fn literal(single: f32, double: f64) -> Self;

    /// `⌊t⌋` as an index for `t ≥ 0`: Rust's `as usize`, which saturates (negative and NaN give 0,
    /// too large gives `usize::MAX`), so it never panics. One `VCVT` on the Cortex-M4F.
    #[must_use]
    fn index(self) -> usize;
}

impl Scalar for f32 {
    #[cfg(any(test, feature = "reference"))]
    const BISECTION_STEPS: u32 = 24;
    #[inline(always)]
    fn literal(single: f32, _: f64) -> Self {
        single
    }
    #[inline(always)]
    fn index(self) -> usize {
        self as usize
    }
}

impl Scalar for f64 {
    #[cfg(any(test, feature = "reference"))]
    const BISECTION_STEPS: u32 = 52;
    #[inline(always)]
    fn literal(_: f32, double: f64) -> Self {
        double
    }
    #[inline(always)]
    fn index(self) -> usize {
        self as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_round_to_nearest() {
        // 1 + 1.5·2⁻²⁴ lies between the f32 neighbours 1 and 1 + 2⁻²³, nearer the upper: truncation
        // would give 1.
        let value = 1.0 + 1.5 * f64::powi(2.0, -24);
        assert_eq!(f32::constant(value), 1.0 + f32::EPSILON);
        assert_eq!(f64::constant(value), value);
    }

    #[test]
    fn bisection_steps_resolve_the_unit_interval_to_each_precision() {
        // After `steps` halvings of [0, 1] the bracket is 2^-steps wide: no coarser than half an ulp
        // of 1 (f32) or one ulp (f64), the spacing of the η the bisection can return near 1.
        assert_eq!(f32::powi(2.0, -(f32::BISECTION_STEPS as i32)), f32::EPSILON / 2.0);
        assert_eq!(f64::powi(2.0, -(f64::BISECTION_STEPS as i32)), f64::EPSILON);
    }
}
