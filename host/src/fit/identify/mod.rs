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

// `!(x > y)` is deliberate throughout: a NaN must fail every check.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod prune;
mod reduce;

use reduce::{accumulate, linear_floor, solve_upper, Columns, Reduced, TargetRange};

use clarabel::solver::SolverStatus;
use firmware::basis;
use nalgebra::{DMatrix, DVector};
use std::sync::Arc;

use serde::Serialize;

use crate::data::DataSet;
use crate::fit::maps::{FittedMap, LinearMap, Tabulation};
use crate::fit::monotonicity::{check_grid, check_strictly_increasing, monotonicity_grid, NotMonotone};
use crate::fit::qp::{self, Problem, QpError};
use crate::spec::{MapSettings, Normalisation};

/// Relative floor of the whitening scales `σ_i` (step 3 above). Directions of `μ` the data barely
/// see (`s_i` below the floor) keep a Hessian entry `(s_i/σ_i)² < 1` instead of blowing their
/// constraint columns up by `1/s_i`: with a floor of 1e-7 Clarabel met the normalised constraint rows
/// to its tolerance while `Γ'(0)` was off by 10⁶ ε at β = 5 (odds ratios from e^-15 to e^20); 1e-3 solves
/// β up to 7 on Example 1 in at most two refinement rounds, with the same intercept-map estimates.
pub(crate) const WHITENING_FLOOR: f64 = 1e-3;
/// At most this many re-solves with points added to the monotonicity grid.
const REFINEMENT_ROUNDS: usize = 6;
/// A constraint whose slack is below this fraction of `ε` counts as active.
const ACTIVE_TOLERANCE: f64 = 1e-4;
/// `Γ` has collapsed to a straight line when at least this fraction of the constraints is active.
const COLLAPSE_FRACTION: f64 = 0.9;

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
    target: usize,
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
    target: usize,
    target_name: &str,
    settings: &MapSettings,
    odds_ratios: &Arc<[f64]>,
    tabulation: Tabulation,
) -> Result<Fit, FitError> {
    let learning = Learning::gather(data, target, settings, odds_ratios)?;
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
    target: usize,
    target_name: &str,
    settings: &MapSettings,
    odds_ratios: &Arc<[f64]>,
    counts: &[usize],
    tabulation: Tabulation,
) -> Result<Vec<Fit>, FitError> {
    let learning = Learning::gather(data, target, settings, odds_ratios)?;
    prune::fit_path(&learning, counts, target_name, tabulation)
}

/// The learning data of one target reduced to what a fit needs, gathered in one pass over the
/// windows: shared by every support of `L` the pruning tries.
pub(crate) struct Learning<'a> {
    range: TargetRange,
    /// `R` of `[Z̃ | 1 | B | r]`.
    r_factor: DMatrix<f64>,
    linear: LinearMap,
    settings: &'a MapSettings,
    odds_ratios: &'a Arc<[f64]>,
}

impl<'a> Learning<'a> {
    /// Pass 1 and 2 over the learning windows, and the linear floor.
    pub(crate) fn gather(
        data: &DataSet,
        target: usize,
        settings: &'a MapSettings,
        odds_ratios: &'a Arc<[f64]>,
    ) -> Result<Self, FitError> {
        let range = TargetRange::gather(data, target)?;
        let r_factor = accumulate(data, target, &range, odds_ratios);
        let linear = linear_floor(&r_factor, &range.scales)?;
        Ok(Learning {
            range,
            r_factor,
            linear,
            settings,
            odds_ratios,
        })
    }

    /// `n_z`: entries of the regressor.
    pub(crate) fn regressor_len(&self) -> usize {
        self.range.scales.len()
    }

    /// Every regressor entry.
    pub(crate) fn dense(&self) -> Vec<usize> {
        (0..self.regressor_len()).collect()
    }

    fn with_constant(&self) -> bool {
        self.settings.normalisation == Normalisation::Paper
    }

    /// `R` of `[Z̃_S | 1 | B | r]` for the support `S` (increasing entries of `Z`): the full factor when
    /// `S` is every entry, else the QR of its columns (`R_Sᵀ R_S = Z_Sᵀ Z_S`, same data, no new pass).
    fn factor_of(&self, support: &[usize]) -> std::borrow::Cow<'_, DMatrix<f64>> {
        let n_z = self.regressor_len();
        if support.len() == n_z {
            return std::borrow::Cow::Borrowed(&self.r_factor);
        }
        let columns: Vec<usize> = support.iter().copied().chain(n_z..self.r_factor.ncols()).collect();
        std::borrow::Cow::Owned(self.r_factor.select_columns(&columns).qr().r())
    }

    /// The linear floor on the support `S`: what a linear map reading the same taps achieves.
    fn linear_floor(&self, support: &[usize]) -> Result<LinearMap, FitError> {
        if support.len() == self.regressor_len() {
            return Ok(self.linear.clone());
        }
        let scales: Vec<f64> = support.iter().map(|&c| self.range.scales[c]).collect();
        let on_support = linear_floor(&self.factor_of(support), &scales)?;
        let mut gains = vec![0.0; self.regressor_len()];
        for (&c, &g) in support.iter().zip(&on_support.gains) {
            gains[c] = g;
        }
        Ok(LinearMap {
            gains,
            intercept: on_support.intercept,
        })
    }

    /// The reduced problem in `μ` on the support `S`.
    fn reduced(&self, support: &[usize]) -> Reduced {
        Reduced::new(
            &self.factor_of(support),
            support.len(),
            self.with_constant(),
            self.range.windows,
        )
    }

    /// Solves the QP with `L` restricted to `support` (the other gains are 0).
    fn fit(&self, support: &[usize], target_name: &str, tabulation: Tabulation) -> Result<Fit, FitError> {
        let (range, settings, odds_ratios) = (&self.range, self.settings, self.odds_ratios);
        let with_constant = self.with_constant();
        let reduced = self.reduced(support);
        let linear = self.linear_floor(support)?;
        let columns = Columns {
            odds_ratios,
            with_constant,
        };

        // The QP is solved at unit scale: Clarabel's tolerances are partly absolute, and with ε = 0.01 a
        // whole objective of 3e-7 would sit near them. `(μ, L)` scale with `scale`: exactly for `intercept`
        // (homogeneous), and for `paper` because ε and the equality's right-hand side are both divided by it.
        let mean = 0.5 * (range.min + range.max);
        let scale = if with_constant {
            settings.epsilon.max(mean.abs())
        } else {
            settings.epsilon
        };
        let epsilon = settings.epsilon / scale;
        let equality = with_constant.then_some(mean / scale);
        let solved = solve_refined(&reduced, &columns, epsilon, equality, settings.monotonicity_grid)?;
        let mu = &solved.mu;

        // Recover L, undo the internal scale and the column scaling of Z.
        let l_scaled = solve_upper(&reduced.r_ll, &(&reduced.r_lmu * mu)).map_err(|e| match e {
            FitError::DependentRegressor { column } => FitError::DependentRegressor {
                column: support.get(column).copied().unwrap_or(self.regressor_len()),
            },
            e => e,
        })?;
        let mut gains = vec![0.0; self.regressor_len()];
        for (c, &entry) in support.iter().enumerate() {
            gains[entry] = scale * l_scaled[c] / range.scales[entry];
        }
        let intercept = if with_constant {
            0.0
        } else {
            scale * l_scaled[support.len()]
        };
        let mu_constant = if with_constant { scale * mu[0] } else { 0.0 };
        let mu_basis: Vec<f64> = mu.iter().skip(usize::from(with_constant)).map(|m| scale * m).collect();
        let min_slope = check_strictly_increasing(&firmware::Gamma {
            offset: mu_constant - intercept,
            mu: &mu_basis,
            odds_ratios,
        })?;
        let map = FittedMap::new(
            target_name.to_owned(),
            settings.normalisation,
            gains,
            intercept,
            mu_constant,
            mu_basis,
            odds_ratios.clone(),
            (range.min, range.max),
            tabulation,
        )?;
        let gamma = map.gamma();
        let (g0, g1) = (gamma.value(0.0), gamma.value(1.0));
        let nonlinearity = check_grid()
            .iter()
            .map(|&eta| (gamma.value(eta) - g0 - eta * (g1 - g0)).abs())
            .fold(0.0, f64::max)
            / (g1 - g0);
        let active_constraints = solved
            .grid
            .iter()
            .filter(|&&eta| columns.slope(eta, mu) - epsilon <= ACTIVE_TOLERANCE * epsilon)
            .count();
        let diagnostics = Diagnostics {
            status: solved.status,
            iterations: solved.iterations,
            solve_time_s: solved.solve_time,
            constraints: solved.grid.len(),
            active_constraints,
            collapsed: active_constraints as f64 >= COLLAPSE_FRACTION * solved.grid.len() as f64,
            nonlinearity,
            refinement_rounds: solved.rounds,
            min_slope_over_epsilon: min_slope / settings.epsilon,
            reduced_condition: reduced.condition,
            objective_over_epsilon_squared: (&reduced.r_mumu * mu).norm_squared() / (epsilon * epsilon),
        };
        let certificate = Certificate {
            epsilon,
            mean: mean / scale,
            mu: mu.iter().copied().collect(),
            with_constant,
            grid: solved.grid,
            lambda: solved.lambda,
            nu: solved.nu,
        };
        Ok(Fit {
            map,
            linear,
            diagnostics,
            certificate,
        })
    }
}

/// A solution of the reduced QP with its multipliers in `μ` space.
struct Solved {
    mu: DVector<f64>,
    grid: Vec<f64>,
    lambda: Vec<f64>,
    nu: Option<f64>,
    status: SolverStatus,
    iterations: u32,
    solve_time: f64,
    rounds: usize,
}

/// Solves the whitened QP, re-solving with the worst points of [`check_grid`] added to the grid
/// while `Γ' < ε` somewhere (at most [`REFINEMENT_ROUNDS`] times).
fn solve_refined(
    reduced: &Reduced,
    columns: &Columns<'_>,
    epsilon: f64,
    equality: Option<f64>,
    grid_points: usize,
) -> Result<Solved, FitError> {
    let n = reduced.hessian.ncols();
    let check = check_grid();
    let mut grid = monotonicity_grid(grid_points);
    let (mut iterations, mut solve_time, mut rounds) = (0, 0.0, 0);
    loop {
        // Rows B'(η_q) T, each scaled to unit norm (the right-hand side with it).
        let rows: Vec<DVector<f64>> = grid
            .iter()
            .map(|&eta| reduced.transform.tr_mul(&columns.slopes(eta)))
            .collect();
        let norms: Vec<f64> = rows.iter().map(|r| r.norm()).collect();
        let integral_row = reduced.transform.tr_mul(&columns.integrals());
        let integral_norm = integral_row.norm();
        let problem = Problem {
            p: reduced.hessian.clone(),
            q: vec![0.0; n],
            e_matrix: match equality {
                Some(_) => DMatrix::from_row_slice(1, n, (&integral_row / integral_norm).as_slice()),
                None => DMatrix::zeros(0, n),
            },
            e: equality.map(|mean| mean / integral_norm).into_iter().collect(),
            g_matrix: DMatrix::from_fn(rows.len(), n, |i, j| rows[i][j] / norms[i]),
            g: norms.iter().map(|norm| epsilon / norm).collect(),
        };
        let solution = qp::solve(&problem)?;
        iterations += solution.iterations;
        solve_time += solution.solve_time;
        let mu = &reduced.transform * DVector::from_column_slice(&solution.x);
        let mut violations: Vec<(f64, f64)> = check
            .iter()
            .map(|&eta| (eta, columns.slope(eta, &mu)))
            .filter(|&(_, slope)| slope < epsilon * (1.0 - 1e-3))
            .collect();
        if violations.is_empty() || rounds == REFINEMENT_ROUNDS {
            // Row q was divided by its norm, so its multiplier in μ space is λ_q / norm_q.
            return Ok(Solved {
                mu,
                lambda: solution.lambda.iter().zip(&norms).map(|(l, norm)| l / norm).collect(),
                nu: equality.map(|_| solution.nu[0] / integral_norm),
                grid,
                status: solution.status,
                iterations,
                solve_time,
                rounds,
            });
        }
        violations.sort_by(|a, b| a.1.total_cmp(&b.1));
        grid.extend(violations.iter().take(50).map(|v| v.0));
        rounds += 1;
    }
}

#[cfg(test)]
mod tests;
