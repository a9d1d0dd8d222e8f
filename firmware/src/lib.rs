//! Run-time maths of the off-line moving-horizon observer (M. Alamir, *A new identification framework
//! for off-line computation of moving-horizon observers*).
//!
//! For every quantity `r` to estimate, the host fits off-line a map
//!
//! ```text
//! r = F(Z) = Γ⁻¹(Lᵀ Z),     Z(k) = (y(k), …, y(k-N+1), u(k), …, u(k-N+1))   (newest first)
//! ```
//!
//! where `Γ` is strictly increasing. This crate evaluates such a map; it is `#![no_std]`, allocates
//! nothing, and is generic over the scalar ([`Scalar`]: `f32` on the target, `f64` on the host, which
//! evaluates its own fitted maps through this very code: one implementation, two precisions).
//!
//! # Conventions
//!
//! * `η(r) = (r - r_min) / (r_max - r_min)` normalises the target to `[0, 1]` over the learning data.
//! * Every non-constant basis function of the paper is a member of one family ([`basis`]):
//!   `B(η; c) = c η / ((1 - η) + c η)`, odds ratio `c > 0`, with `B(0) = 0`, `B(1) = 1`, `B' > 0`.
//!   The paper's `B1_i` is `c = e^{β(1-i)}` (convex) and its `B2_i` is `c = e^{β(i-1)}` (concave);
//!   `B1_1 = B2_1 = η` is `c = 1`.
//! * `Γ(η) = offset + Σ_j μ_j B(η; c_j) = offset + η Σ_j w_j / ((1 - η) + c_j η)` with `w_j = μ_j c_j`
//!   ([`Gamma`]); the offset holds the constant basis coefficient minus any intercept of `Lᵀ Z`.
//! * The estimate solves `Γ(η) = Lᵀ Z` for `η ∈ [0, 1]` by bisection with a fixed number of steps
//!   ([`Scalar::BISECTION_STEPS`]), and saturates, visibly, at `r_min` or `r_max` when `Lᵀ Z` lies
//!   outside `[Γ(0), Γ(1)]` ([`Saturation`]).
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod basis;
pub mod family;
pub mod gamma;
pub mod map;
pub mod observer;
pub mod scalar;

pub use family::{FamilyObserver, Member};
pub use gamma::{Gamma, Inverse, Saturation};
pub use map::{Estimate, TargetMap};
pub use observer::{Observer, RejectedSample, Sample};
pub use scalar::Scalar;
