//! The moving-horizon estimate's building blocks: the Gauss–Newton normal equations of a window's
//! output error, and the Cholesky solve of the small system they give. The host's converged
//! reference (a projected Levenberg–Marquardt over these, `host::observers::mhe`) and a
//! fixed-iteration observer run the same arithmetic.
//!
//! # The problem
//!
//! Over a window of `N` samples `(y(j), u(j))`, oldest first, the paper's moving-horizon observer is
//! the state at the window's start minimising the noise-weighted output error (with an optional
//! prior `x̄` weighted by `p`, the paper's first remark):
//!
//! ```text
//! C(x) = Σ_j Σ_i w_i (y_i(j) − h_i(x(j), u(j)))²  +  Σ_i p_i (x_i − x̄_i)²,
//! x(0) = x,  x(j+1) = f(x(j), u(j))
//! ```
//!
//! With `Φ(j) = ∂x(j)/∂x` (`Φ(0) = I`, `Φ(j+1) = F(j) Φ(j)`) and `J(j) = H(j) Φ(j)`, one Gauss–Newton
//! step `δ` solves
//!
//! ```text
//! (Σ_j J(j)ᵀ W J(j) + diag(p)) δ = Σ_j J(j)ᵀ W r(j) − diag(p) (x − x̄),   r(j) = y(j) − h(x(j), u(j))
//! ```
//!
//! `normal_equations` returns the output part of both sides, the cost and `x(N−1)` (the estimate
//! at the window's end, where the map's estimate is); the prior is the caller's (a diagonal added).
//! A non-finite measurement contributes nothing (its weight is taken as zero), as a refused sample.
//!
//! # On the chip
//!
//! [`Observer`] is the estimator for a microcontroller: the last `N` samples in a window,
//! and at every sample a fixed number of Gauss–Newton steps from the previous solution moved one
//! sample on (`x̄ = f(x̂, u)`, also the prior's centre), each step the normal equations (`N` model
//! steps with their Jacobians), a Cholesky solve (`L D Lᵀ`: `n` divisions, no square root) and a
//! projection onto the box; then the solution carried to the window's end (`N − 1` more steps). No
//! allocation, no panic, the same instructions every sample, refused samples in the window included
//! (but for a step whose system is not positive definite, which ends the iterations early).

pub(crate) mod observer;
pub(crate) mod solver;

#[cfg(test)]
use observer::Horizon;
pub use observer::Observer;
#[cfg(test)]
use solver::{normal_equations, propagate, solve_cholesky, Settings};

#[cfg(test)]
mod tests;
