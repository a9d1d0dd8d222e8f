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
//! last `N` samples in a window that is always contiguous.
//!
//! # The peer
//!
//! [`Ekf`] is an extended Kalman filter over any [`Plant`] (one sampling period of the model and its
//! output, with Jacobians), in plain arrays with sequential scalar updates in Joseph form: the observer
//! every design is compared with. [`Started`] runs a model-based follower from the map's first
//! estimate (the model-corrected map, the map-started EKF); [`Restarted`] runs a filter from the
//! first sample and checks it against the map at every sample from the map's first estimate on,
//! restarting from the map when the two disagree.
//!
//! # The interface a firmware holds
//!
//! Every observer kind a design carries implements one trait, [`Estimator`]: `push` the sample of
//! the current instant, read `estimate`, `reset` for a new run, `is_ready` once it estimates; its
//! associated types say what a value is (`f32`, or `i32` for the map in integers), what a sample's
//! outputs and inputs and an estimate are, and why a sample is refused. Firmware written against it
//! switches kinds by a type. The runtimes the kinds share:
//!
//! | what runs | type |
//! |---|---|
//! | the map | [`Observer`] |
//! | a follower the map starts (a model-based kind started at the map's estimate) | [`Started`] over the design's follower |
//! | a filter the map checks once and restarts | [`Restarted`] |
//! | a Kalman filter from the centre of the state box | [`FilterObserver`] over the design's filter |
//! | the moving-horizon estimate | [`mhe::Observer`] |
//! | the map in integers | [`fixed::Observer`] |
//! | a family of maps | [`FamilyObserver`] |
//!
//! A generated design names each kind it has by a type (`MapObserver`, …, `Observer` for the kind
//! `gen` chose), and lists them all with their types in its `<design>_observers!` macro. What only the generated code calls or implements (the traits a design
//! implements, the straight-line code's helpers, the solver steps) is in `emitted`, hidden from
//! this documentation: it follows the generator, not a firmware's needs.
//!
//! # Const generic parameters
//!
//! Every type, trait and function takes the sizes it needs in one order, each named the same
//! everywhere: `N` (the horizon: samples in the window), `NX` (states), `NY` (outputs), `NU`
//! (inputs), `NT` (targets), then `K` (members of a family) or `SUBSTEPS` (RK4 steps per sample);
//! type parameters (the scalar `T` first, then the design's types) come before them. A helper over
//! any vector or square matrix takes its size as `M`.
//!
//! # Features
//!
//! * `reference` (off by default): the host's reference maths, which the chip never runs: `Γ` and
//!   its exact inverse by bisection (`gamma`: `Gamma`, `Inverse`, `gamma::weight`,
//!   `gamma::value_from_coefficients`), the basis functions and their integrals (`basis`), and
//!   `Scalar::BISECTION_STEPS` and `Scalar::constant`. The host enables it; firmware leaves it off,
//!   so that its API is exactly what runs on the chip, where a bisection of 24 steps, each a sum of
//!   divisions, could not be afforded every sample.
//! * `defmt` (off by default): [`Estimate`], [`Saturation`], [`RejectedSample`] and
//!   [`fixed::OutOfRange`] implement `defmt::Format`, for a firmware that logs with `defmt`.
#![cfg_attr(not(test), no_std)]
// No unsafe code but one instruction: the FPU's square root (`maths::sqrt_f32`), allowed there alone.
#![deny(unsafe_code)]
#![warn(missing_docs)]

pub mod bank;
// The crate doc names the `reference` items without links: a link to an absent item fails `cargo doc`.
#[cfg(any(test, feature = "reference"))]
pub mod basis;
mod bounds;
mod ekf;
mod estimate;
mod estimator;
mod family;
mod filter;
pub mod fixed;
#[cfg(any(test, feature = "reference"))]
pub mod gamma;
mod inverse;
mod map;
mod maths;
mod matrix;
pub mod mhe;
mod model;
mod observer;
mod restarted;
pub mod rules;
mod scalar;
mod started;
pub mod watch;
mod window;

pub use ekf::{Ekf, Plant};
pub use estimate::{Estimate, Saturation};
pub use estimator::Estimator;
pub use family::FamilyObserver;
pub use filter::FilterObserver;
#[cfg(any(test, feature = "reference"))]
pub use gamma::{Gamma, Inverse};
pub use inverse::{InverseTable, Knots};
pub use map::TargetMap;
pub use model::{Model, Rk4};
pub use observer::{Design, Observer, RejectedSample};
pub use restarted::Restarted;
pub use scalar::Scalar;
pub use started::Started;
pub use window::Sample;

// The C emitter (`host::emit::c`) still names the search's halves at the root: hidden there too.
#[doc(hidden)]
pub use inverse::search_halves;

// The generator's items by the names the modules use for one another.
use emitted::Follower;

/// What only generated code (and the host that writes it) calls or implements: the traits a design
/// implements for its observers, the helpers of its straight-line code, the steps of the
/// moving-horizon solve. Not the interface a firmware uses (see the [crate's](crate) documentation):
/// it follows the generator and may change with it.
#[doc(hidden)]
pub mod emitted {
    pub use crate::bounds::{at_least, at_most, project};
    pub use crate::family::Member;
    pub use crate::filter::Filter;
    pub use crate::inverse::{search_halves, search_step};
    pub use crate::maths::{sqrt_f32, Maths};
    pub use crate::matrix::product;
    pub use crate::observer::estimate_by_loops;
    pub use crate::restarted::Restart;
    pub use crate::started::{clamp, Follower};
    pub use crate::window::{Stored, Window};

    /// The generator's part of [`crate::fixed`]: the integer design, its tables and helpers.
    pub mod fixed {
        pub use crate::fixed::design::{estimate_by_loops, in_range, reach, FixedDesign, FixedMap};
        pub use crate::fixed::table::{flag, FixedTable};
    }

    /// The generator's part of [`crate::mhe`]: the design's constants and the solve's steps.
    pub mod mhe {
        pub use crate::mhe::observer::Horizon;
        pub use crate::mhe::solver::{
            normal_equations, propagate, solve_cholesky, solve_window, Normal, Settings, Solved,
        };
        pub use crate::watch::Watch;
    }
}
