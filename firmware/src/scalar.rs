//! The scalar types the runtime is generic over.

use nalgebra::RealField;

/// A floating-point scalar the observer can run in: `f32` on the microcontroller, `f64` on the host.
pub trait Scalar: RealField + Copy {
    /// Bisection steps of the exact reference inverse [`crate::Gamma::inverse`]: enough to resolve
    /// `η ∈ [0, 1]` to the type's precision (`2^-24` for `f32`, `2^-52` for `f64`).
    const BISECTION_STEPS: u32;

    /// `0`, usable in `const` contexts (an empty window is filled with it).
    const ZERO: Self;

    /// Converts an `f64` constant (rounding to nearest).
    fn constant(value: f64) -> Self;

    /// `⌊t⌋` as an index for `t ≥ 0`: Rust's `as usize`, which saturates (negative and NaN give 0,
    /// too large gives `usize::MAX`), so it never panics. One `VCVT` on the Cortex-M4F.
    fn index(self) -> usize;
}

impl Scalar for f32 {
    const BISECTION_STEPS: u32 = 24;
    const ZERO: Self = 0.0;
    fn constant(value: f64) -> Self {
        value as f32
    }
    #[inline(always)]
    fn index(self) -> usize {
        self as usize
    }
}

impl Scalar for f64 {
    const BISECTION_STEPS: u32 = 52;
    const ZERO: Self = 0.0;
    fn constant(value: f64) -> Self {
        value
    }
    #[inline(always)]
    fn index(self) -> usize {
        self as usize
    }
}
