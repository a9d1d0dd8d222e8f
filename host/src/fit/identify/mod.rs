//! Identification of `r ≈ Γ⁻¹(Lᵀ Z)` by constrained least squares (paper eq. `defdeLSopt`):
//!
//! ```text
//! minimise (1/n_E) Σ_E (B(η(r)) μ - Lᵀ Z)²   over (μ, L)
//! subject to B'(η_q) μ ≥ ε on a grid η_q of [0, 1]            (Γ strictly increasing)
//!            and, with the `paper` normalisation, [∫₀¹ B] μ = (r_min + r_max)/2.
//! ```
//!
//! Two normalisations fix the scale the paper leaves free:
//! * `paper`: basis `{1, B(·; c_j)}`, no constant in `Z`, the equality above.
//! * `intercept`: a constant 1 appended to `Z`. It and the constant basis function are then the same
//!   degree of freedom, so the constant function is dropped, and the equality (which only pinned `μ₀`)
//!   with it. The problem is homogeneous: the scale of `(μ, L)` is set by `ε`, the fitted `F` does not
//!   depend on `ε`, and since `η` does not change when `r` is shifted, neither does `F - r`.
//!
//! # Solving it robustly
//!
//! The Hessian in `(μ, L)` has condition numbers up to 1e19: nearly collinear basis columns, outputs
//! of different scales. Handing it to a solver as it is invites "insufficient progress" far from the
//! optimum. Instead:
//! 1. One pass over the windows accumulates the triangular factor `R` of the column-scaled data
//!    `[Z̃ | 1 | B | r]` ([`StreamingQr`](crate::fit::streaming_qr::StreamingQr)): memory independent of `n_E`, condition not squared.
//! 2. For fixed `μ` the best `L` is least squares, so `L` is eliminated: with `R` partitioned by the
//!    `L`-columns and the `μ`-columns, the objective is `‖R_μμ μ‖² / n_E` and `L = R_LL⁻¹ R_Lμ μ`.
//! 3. `μ` is whitened through the SVD `R_μμ / √n_E = U S Vᵀ`: `μ = V Σ⁻¹ x` with `σ_i = max(s_i,
//!    10⁻³ s_max)`, so Clarabel sees a diagonal Hessian with entries in `[0, 2]` (2 where the data
//!    determine `μ`) and unit-norm constraint rows.
//! 4. Monotonicity is imposed on a grid clustered at both ends (Chebyshev–Lobatto), checked after the
//!    solve on a much finer grid; points where `Γ' < ε` are added and the QP solved again (a few
//!    rounds); a map that is still not strictly increasing is refused.
//!
//! The linear floor `r ≈ Lᵀ Z + c` comes from the same `R` (its leading block and the `r` column).
//!
//! Here: what a fit returns and the entry points. `learning` gathers one target's data and fits it on
//! a support of `L` (steps 1 and 2), `reduce` holds the linear algebra, `solve` the whitened QP with its
//! refinement rounds (steps 3 and 4), and [`prune`] the sparse `L`.

// `!(x > y)` is deliberate throughout: a NaN must fail every check.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod learning;
pub mod prune;
mod reduce;
mod solve;

pub(crate) use learning::Learning;

use clarabel::solver::SolverStatus;
use firmware::basis;
use std::sync::Arc;

use serde::Serialize;

use crate::data::{Column, DataSet};
use crate::fit::maps::{FittedMap, LinearMap, Tabulation};
use crate::fit::monotonicity::NotMonotone;
use crate::fit::qp::QpError;
use crate::spec::MapSettings;

/// Relative floor of the whitening scales `σ_i` (step 3 above). Directions of `μ` the data barely
/// see (`s_i` below the floor) keep a Hessian entry `(s_i/σ_i)² < 1` instead of blowing their
/// constraint columns up by `1/s_i`: with a floor of 1e-7 Clarabel met the normalised constraint rows
/// to its tolerance while `Γ'(0)` was off by 10⁶ ε at β = 5 (odds ratios from e^-15 to e^20); 1e-3 solves
/// β up to 7 on Example 1 in at most two refinement rounds, with the same intercept-map estimates.
pub(crate) const WHITENING_FLOOR: f64 = 1e-3;

/// Why a map could not be fitted.
#[derive(Debug, thiserror::Error)]
pub enum FitError {
    /// The target takes a single value on the learning data, so `η` is undefined.
    #[error("the target is constant ({value}) on the learning windows")]
    ConstantTarget {
        /// Its value.
        value: f64,
    },
    /// A regressor column is (numerically) a combination of the others.
    #[error("regressor column {column} is a linear combination of the others")]
    DependentRegressor {
        /// The column index in `Z` (`n_z` is the intercept).
        column: usize,
    },
    /// The learning data contain a non-finite value.
    #[error("the learning data contain a non-finite value")]
    NonFinite,
    /// Clarabel found no solution.
    #[error(transparent)]
    Qp(#[from] QpError),
    /// The table of `Γ⁻¹` could not be certified.
    #[error("the inverse table: {0}")]
    Table(#[from] crate::fit::inverse_table::TableError),
    /// After refinement `Γ` is still not strictly increasing somewhere.
    #[error(transparent)]
    NotMonotone(#[from] NotMonotone),
}

/// How the QP went, for the report.
#[derive(Clone, Debug, Serialize)]
pub struct Diagnostics {
    /// Clarabel's status of the last solve (`Solved` or `AlmostSolved`).
    #[serde(serialize_with = "as_debug_text")]
    pub status: SolverStatus,
    /// Interior-point iterations, summed over refinement rounds.
    pub iterations: u32,
    /// Clarabel's solve time, summed over rounds, in seconds.
    pub solve_time_s: f64,
    /// Monotonicity constraints in the last solve (grid plus refinement points).
    pub constraints: usize,
    /// Of those, how many are active (`Γ'(η_q) = ε`).
    pub active_constraints: usize,
    /// Whether `Γ` collapsed to a straight line (at least 90 % of the constraints active).
    pub collapsed: bool,
    /// `max |Γ(η) - chord(η)| / (Γ(1) - Γ(0))` on the fine grid: 0 for a straight line.
    pub nonlinearity: f64,
    /// Re-solves with points added to the grid.
    pub refinement_rounds: usize,
    /// `min Γ' / ε` on the fine check grid (`≥ 1` means the grid constraint held everywhere).
    pub min_slope_over_epsilon: f64,
    /// `s_max / s_min` of `R_μμ`: the square root of the reduced Hessian's condition number.
    pub reduced_condition: f64,
    /// Objective `(1/n_E) Σ (Γ(r) - Lᵀ Z)²` at the solution, in units of `ε²`.
    pub objective_over_epsilon_squared: f64,
}

/// What the KKT check of a fit needs, at the internal scale the QP was solved in.
#[derive(Clone, Debug)]
pub struct Certificate {
    /// `ε` the QP was solved with: the spec's `ε` over the internal scale (1 for `intercept`).
    pub epsilon: f64,
    /// Right-hand side of the `paper` equality at the internal scale.
    pub mean: f64,
    /// `μ` at that scale, the constant coefficient first with the `paper` normalisation.
    pub mu: Vec<f64>,
    /// Whether `mu[0]` is the constant basis coefficient.
    pub with_constant: bool,
    /// The `η` of every monotonicity constraint.
    pub grid: Vec<f64>,
    /// Their multipliers (in `μ` space): `∇f(μ) = Σ λ_q B'(η_q) + ν ∫B`.
    pub lambda: Vec<f64>,
    /// Multiplier of the `paper` equality.
    pub nu: Option<f64>,
}

/// Clarabel's status as its name (`"Solved"`), for the JSON report.
fn as_debug_text<S: serde::Serializer>(status: &SolverStatus, serializer: S) -> Result<S::Ok, S::Error> {
    serializer.serialize_str(&format!("{status:?}"))
}

/// A fitted target: the map, the linear floor on the same data, and how the solve went.
#[derive(Clone, Debug)]
pub struct Fit {
    /// The map `Γ⁻¹(Lᵀ Z)`.
    pub map: FittedMap,
    /// The linear least-squares floor.
    pub linear: LinearMap,
    /// QP diagnostics.
    pub diagnostics: Diagnostics,
    /// Optimality data for checking.
    pub certificate: Certificate,
}

/// The odds ratios `c_j` of the paper's basis for `settings` (`n_m`, `β`): computed once per design
/// and shared by every target's map.
pub fn basis_of(settings: &MapSettings) -> Arc<[f64]> {
    basis::paper_odds_ratios(settings.nm, settings.beta).collect()
}

/// Fits target `target` of `data` with `settings` on the basis `odds_ratios` ([`basis_of`]), with a
/// certified table of `Γ⁻¹`.
pub fn fit(
    data: &DataSet,
    target: impl Into<Column>,
    target_name: &str,
    settings: &MapSettings,
    odds_ratios: &Arc<[f64]>,
) -> Result<Fit, FitError> {
    fit_tabulated(data, target, target_name, settings, odds_ratios, Tabulation::Certified)
}

/// [`fit`], with `Γ⁻¹` tabulated as `tabulation` says (sketched for the design search). With
/// `settings.taps` below the regressor's length, `L` is pruned to that many taps ([`prune`]).
pub fn fit_tabulated(
    data: &DataSet,
    target: impl Into<Column>,
    target_name: &str,
    settings: &MapSettings,
    odds_ratios: &Arc<[f64]>,
    tabulation: Tabulation,
) -> Result<Fit, FitError> {
    let learning = Learning::gather(data, target.into(), settings, odds_ratios)?;
    match settings.taps.filter(|&taps| taps < learning.regressor_len()) {
        None => learning.fit(&learning.dense(), target_name, tabulation),
        Some(taps) => {
            let mut fits = prune::fit_path(&learning, &[taps], target_name, tabulation)?;
            Ok(fits.pop().expect("one fit per count"))
        }
    }
}

/// One fit per entry of `counts` (taps kept per target, [`prune`]), from one elimination path;
/// `settings.taps` is ignored.
pub fn fit_counts(
    data: &DataSet,
    target: impl Into<Column>,
    target_name: &str,
    settings: &MapSettings,
    odds_ratios: &Arc<[f64]>,
    counts: &[usize],
    tabulation: Tabulation,
) -> Result<Vec<Fit>, FitError> {
    let learning = Learning::gather(data, target.into(), settings, odds_ratios)?;
    prune::fit_path(&learning, counts, target_name, tabulation)
}

#[cfg(test)]
mod tests;
