//! Design-time side of the off-line moving-horizon observer (M. Alamir, *A new identification
//! framework for off-line computation of moving-horizon observers*).
//!
//! # The problem
//!
//! For a plant `x⁺ = f(x, u)`, `y = h(x, u) + w` and every quantity `r(x)` to estimate, find a map of
//! the last `N` measurements
//!
//! ```text
//! r̂ = F(Z) = Γ⁻¹(Lᵀ Z),   Z(k) = (y(k), …, y(k-N+1), u(k), …, u(k-N+1)),
//! Γ(η) = μ₀ + Σ_j μ_j B(η; c_j),  η = (r - r_min)/(r_max - r_min),  Γ' ≥ ε > 0 on [0, 1],
//! ```
//!
//! by least squares of `Γ(η(r)) - Lᵀ Z` over simulated windows: a convex QP in `(μ, L)`. On the chip
//! `Γ⁻¹` becomes a table whose distance to the exact inverse is proven, so an estimate is a dot
//! product and a table lookup.
//!
//! # The pipeline, one folder per stage
//!
//! 1. [`spec`]: a TOML design (model as expressions, sample time, state box, noise, map settings)
//!    parsed and validated into a [`spec::Design`]; every problem names the file, field and fix.
//! 2. [`data`]: every run of a design simulated once by RK4 ([`data::simulate`]) into one value,
//!    [`data::Runs`] (learning runs from a grid of initial states; tuning, validation, scenario,
//!    long and mismatch runs from their own seeds), cut into windows `(Z, r)`.
//! 3. [`fit`]: per target, the constrained least squares ([`fit::identify`]: streamed QR, elimination
//!    of `L`, whitening, Clarabel through [`fit::qp`], monotonicity checked on a fine grid), the
//!    certified table of `Γ⁻¹` ([`fit::inverse_table`]), the fitted map ([`fit::maps`], evaluated by
//!    the `firmware` crate's own code in `f64`), and its validation beside the linear floor
//!    `Lᵀ Z + c` ([`fit::evaluate`]).
//! 4. [`emit`]: the `generated` crate's Rust source (f32 tables, straight-line code), written only
//!    after the f32 evaluation is checked against the f64 one on every validation window
//!    ([`emit::precision`]).
//! 5. [`observers`]: every observer kind of the registry ([`observers::kind`]) tuned on the tuning
//!    runs and judged on the others, and the kind `observer()` is.
//! 6. [`report`]: JSON and Markdown reports and the paper's figures, each figure's set of runs named.
//!
//! [`generate`] runs the whole job (`mho gen`) into the project's `generated/` crate, [`standalone`]
//! writes a user's design as a crate of its own (`mho gen --spec`), [`search`] chooses `N`, `n_m`, `β`
//! and the taps of `L` within a budget; [`commands`] the `simulate` and `estimate` jobs, with
//! [`recording`] reading and writing CSV recordings; [`output`] writes files atomically.
#![warn(missing_docs)]

pub mod cli;
pub mod commands;
pub mod data;
pub mod emit;
pub mod fit;
pub mod fixed_point;
pub mod generate;
pub mod observers;
pub mod output;
pub mod plant;
pub mod recording;
pub mod report;
pub mod search;
pub mod spec;
pub mod standalone;
pub mod tables;
