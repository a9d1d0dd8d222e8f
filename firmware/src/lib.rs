//! Run-time maths of the off-line moving-horizon observer (M. Alamir, *A new identification framework
//! for off-line computation of moving-horizon observers*).
//!
//! For every quantity `r` to estimate, the host fits off-line a map
//!
//! ```text
//! r = F(Z) = Γ⁻¹(Lᵀ Z),     Z(k) = (y(k), …, y(k-N+1), u(k), …, u(k-N+1))   (newest first)
//! ```
//!
//! where `Γ` is strictly increasing. This crate evaluates such maps; it is `#![no_std]`, allocates
//! nothing, and is generic over the scalar ([`Scalar`]: `f32` on the target, `f64` on the host, which
//! evaluates its own fitted maps through this very code: one implementation, two precisions).
//!
//! # Conventions
//!
//! * `η(r) = (r - r_min) / (r_max - r_min)` normalises the target to `[0, 1]` over the learning data.
//! * Every non-constant basis function of the paper is a member of one family (module `basis`):
//!   `B(η; c) = c η / ((1 - η) + c η)`, odds ratio `c > 0`, with `B(0) = 0`, `B(1) = 1`, `B' > 0`.
//!   The paper's `B1_i` is `c = e^{β(1-i)}` (convex) and its `B2_i` is `c = e^{β(i-1)}` (concave);
//!   `B1_1 = B2_1 = η` is `c = 1`.
//! * `Γ(η) = offset + Σ_j μ_j B(η; c_j) = offset + η Σ_j w_j / ((1 - η) + c_j η)` with `w_j = μ_j c_j`
//!   (`Gamma`); the offset holds the constant basis coefficient minus any intercept of `Lᵀ Z`.
//!
//! # What the chip computes
//!
//! The exact inverse of `Γ` (bisection, `Gamma::inverse`) is the host's reference. The chip runs a
//! certified table instead ([`InverseTable`]): with `K` segments uniform in `v = Lᵀ Z`,
//!
//! ```text
//! t = offset' + Σ_i g_i z_i        (g = L K / (Γ(1) - Γ(0)),  offset' = -Γ(0) K / (Γ(1) - Γ(0)))
//! r = a_k + b_k t,  k = ⌊t⌋        (saturated, visibly, to r_min / r_max outside [0, K])
//! ```
//!
//! a dot product, a float-to-int conversion and a multiply-add: no division and no loop. Where `Γ` is so
//! flat somewhere that uniform knots would be needed by the thousand, the host places the knots by the
//! curvature of `Γ⁻¹` instead ([`Knots::Searched`]) and the segment is found by a binary search of
//! fixed length (`⌈log₂ K⌉` selects, the same steps whatever `t` is). Generated designs ([`Design`])
//! write the dot products (and the search steps) out as straight-line code; the [`Observer`] keeps the
//! last `N` samples in a window that is always contiguous ([`window`]).
//!
//! # The peer
//!
//! [`Ekf`] is an extended Kalman filter over any [`Plant`] (one sampling period of the model and its
//! output, with Jacobians), in plain arrays with sequential scalar updates in Joseph form: the observer
//! every design is compared with. [`Started`] runs a model-based [`Follower`] from the map's first
//! estimate (the model-corrected map, the map-started EKF); [`Restarted`] runs a filter from the
//! first sample and checks the map once, restarting from it when the two disagree.
//!
//! # Features
//!
//! * `reference` (off by default): the host's reference maths, which the chip never runs: `Γ` and
//!   its exact inverse by bisection (`gamma`: `Gamma`, `Inverse`, `gamma::weight`,
//!   `gamma::value_from_coefficients`), the basis functions and their integrals (`basis`), and
//!   `Scalar::BISECTION_STEPS` and `Scalar::constant`. The host enables it; firmware leaves it off,
//!   so that its API is exactly what runs on the chip, where a bisection of 24 steps, each a sum of
//!   divisions, could not be afforded every sample.
#![cfg_attr(not(test), no_std)]
// No unsafe code but one instruction: the FPU's square root (`maths::sqrt_f32`), allowed there alone.
#![deny(unsafe_code)]
#![warn(missing_docs)]

// The crate doc names the `reference` items without links: a link to an absent item fails `cargo doc`.
#[cfg(any(test, feature = "reference"))]
pub mod basis;
pub mod bounds;
pub mod ekf;
pub mod estimate;
pub mod family;
pub mod fixed;
#[cfg(any(test, feature = "reference"))]
pub mod gamma;
pub mod inverse;
pub mod map;
pub mod maths;
pub mod matrix;
pub mod mhe;
pub mod model;
pub mod observer;
pub mod restarted;
pub mod scalar;
pub mod started;
pub mod window;

pub use ekf::{Ekf, Plant};
pub use family::{FamilyObserver, Member};
pub use fixed::{FixedDesign, FixedMap, FixedTable};
#[cfg(any(test, feature = "reference"))]
pub use gamma::{Gamma, Inverse};
pub use inverse::{search_halves, search_step, InverseTable, Knots};
pub use map::{Estimate, Saturation, TargetMap};
pub use maths::Maths;
pub use model::{Model, Rk4};
pub use observer::{estimate_by_loops, Design, Observer, RejectedSample};
pub use restarted::{Restart, Restarted};
pub use scalar::Scalar;
pub use started::{Follower, Started};
pub use window::{Sample, Stored, Window};
