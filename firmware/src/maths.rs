//! The elementary functions of the spec's expression language, as the emitted model calls them.
//!
//! Every function is `libm`'s (pure Rust, the same code on the host and on the chip), never the host
//! platform's C library: an `f32` model evaluated on the host then gives the chip's bits exactly,
//! which is what the generated-vs-target tests compare. The one exception is `f32`'s square root on
//! a chip with a single-precision FPU (`eabihf`, the Cortex-M4F): the FPU's `VSQRT.F32`, one
//! instruction where `libm`'s is about 70, and the same bits, since IEEE 754 requires both to be
//! correctly rounded ([`sqrt_f32`]). Emitted code calls them by path
//! (`Maths::sin(t3)`), so they cannot be confused with `nalgebra`'s methods of the same names.

/// The functions, one per name of the expression language (`ln` and `log` are both the natural
/// logarithm), plus the binary operators that are not arithmetic.
#[allow(missing_docs)] // each is the function its name says, as in `f64`'s documentation
pub trait Maths: Sized {
    fn abs(self) -> Self;
    /// `1` for `+0` and positive values, `-1` for `-0` and negative ones, NaN for NaN (as `f64::signum`).
    fn signum(self) -> Self;
    fn sin(self) -> Self;
    fn cos(self) -> Self;
    fn tan(self) -> Self;
    fn asin(self) -> Self;
    fn acos(self) -> Self;
    fn atan(self) -> Self;
    fn sinh(self) -> Self;
    fn cosh(self) -> Self;
    fn tanh(self) -> Self;
    fn asinh(self) -> Self;
    fn acosh(self) -> Self;
    fn atanh(self) -> Self;
    fn floor(self) -> Self;
    /// Half-way cases away from zero (as `f64::round`).
    fn round(self) -> Self;
    fn ceil(self) -> Self;
    fn trunc(self) -> Self;
    /// `self - trunc(self)` (as `f64::fract`).
    fn fract(self) -> Self;
    fn exp(self) -> Self;
    fn sqrt(self) -> Self;
    fn cbrt(self) -> Self;
    fn ln(self) -> Self;
    fn log2(self) -> Self;
    fn log10(self) -> Self;
    fn powf(self, exponent: Self) -> Self;
    /// `atan2(self, x)`: the angle of the point `(x, self)`.
    fn atan2(self, x: Self) -> Self;
    /// The smaller, ignoring a NaN operand (as `f64::min`).
    fn min(self, other: Self) -> Self;
    /// The larger, ignoring a NaN operand (as `f64::max`).
    fn max(self, other: Self) -> Self;
}

/// Implements [`Maths`] for a float type from `libm`'s functions of that type.
macro_rules! maths {
    ($t:ty, sqrt: $sqrt:path, copysign: $copysign:ident; unary: $($name:ident => $libm:ident),*; binary: $($name2:ident => $libm2:ident),*) => {
        impl Maths for $t {
            $(
                #[inline]
                fn $name(self) -> Self {
                    libm::$libm(self)
                }
            )*
            $(
                #[inline]
                fn $name2(self, other: Self) -> Self {
                    libm::$libm2(self, other)
                }
            )*
            #[inline]
            fn sqrt(self) -> Self {
                $sqrt(self)
            }
            #[inline]
            fn signum(self) -> Self {
                if self.is_nan() {
                    self
                } else {
                    libm::$copysign(1.0, self)
                }
            }
            #[inline]
            fn fract(self) -> Self {
                self - Maths::trunc(self)
            }
        }
    };
}

maths!(f32, sqrt: sqrt_f32, copysign: copysignf; unary: abs => fabsf, sin => sinf, cos => cosf, tan => tanf, asin => asinf, acos => acosf, atan => atanf, sinh => sinhf, cosh => coshf, tanh => tanhf, asinh => asinhf, acosh => acoshf, atanh => atanhf, floor => floorf, round => roundf, ceil => ceilf, trunc => truncf, exp => expf, cbrt => cbrtf, ln => logf, log2 => log2f, log10 => log10f; binary: powf => powf, atan2 => atan2f, min => fminf, max => fmaxf);
maths!(f64, sqrt: libm::sqrt, copysign: copysign; unary: abs => fabs, sin => sin, cos => cos, tan => tan, asin => asin, acos => acos, atan => atan, sinh => sinh, cosh => cosh, tanh => tanh, asinh => asinh, acosh => acosh, atanh => atanh, floor => floor, round => round, ceil => ceil, trunc => trunc, exp => exp, cbrt => cbrt, ln => log, log2 => log2, log10 => log10; binary: powf => pow, atan2 => atan2, min => fmin, max => fmax);

/// `√x` in `f32`, correctly rounded: `VSQRT.F32` on a chip with a single-precision FPU (the
/// hard-float ARM targets, `thumbv7em-none-eabihf`), `libm::sqrtf` elsewhere. Rust declares no
/// FPU register class for these targets' default features, so the value passes through a core
/// register and `s0`, saved and restored around the instruction: seven instructions in all.
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[inline]
#[allow(unsafe_code)]
pub fn sqrt_f32(x: f32) -> f32 {
    let bits: u32;
    // SAFETY: `s0` is pushed before it is written and popped after it is read; nothing else is
    // touched but the stack, below the stack pointer, as `vpush` does.
    unsafe {
        core::arch::asm!(
            "vpush {{s0}}",
            "vmov s0, {x}",
            "vsqrt.f32 s0, s0",
            "vmov {r}, s0",
            "vpop {{s0}}",
            x = in(reg) x.to_bits(),
            r = lateout(reg) bits,
            options(pure, nomem, preserves_flags),
        )
    };
    f32::from_bits(bits)
}

/// `√x` in `f32`, correctly rounded: `libm::sqrtf` (on a hard-float ARM chip, its FPU's `VSQRT.F32`).
#[cfg(not(all(target_arch = "arm", target_abi = "eabihf")))]
#[inline]
pub fn sqrt_f32(x: f32) -> f32 {
    libm::sqrtf(x)
}
