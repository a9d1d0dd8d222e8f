//! The scalar types the runtime is generic over.

use nalgebra::RealField;

/// A floating-point scalar the observer can run in: `f32` on the microcontroller, `f64` on the host.
pub trait Scalar: RealField + Copy {
    /// Bisection steps for `Γ⁻¹`: enough to resolve `η ∈ [0, 1]` to the type's precision
    /// (`2^-24` for `f32`, `2^-52` for `f64`), fixed so that every sample costs the same.
    const BISECTION_STEPS: u32;

    /// Converts an `f64` constant (rounding to nearest).
    fn constant(value: f64) -> Self;
}

impl Scalar for f32 {
    const BISECTION_STEPS: u32 = 24;
    fn constant(value: f64) -> Self {
        value as f32
    }
}

impl Scalar for f64 {
    const BISECTION_STEPS: u32 = 52;
    fn constant(value: f64) -> Self {
        value
    }
}
