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
//!    `[Z̃ | 1 | B | r]` ([`StreamingQr`]): memory independent of `n_E`, condition not squared.
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

use firmware::basis;
use firmware::gamma::weight as basis_weight;
use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use crate::data::DataSet;
use crate::fit::maps::{FittedMap, LinearMap};
use crate::fit::monotonicity::{check_grid, check_strictly_increasing, monotonicity_grid, NotMonotone};
use crate::fit::qp::{self, Problem, QpError};
use crate::fit::streaming_qr::StreamingQr;
use crate::spec::{MapSettings, Normalisation};

/// Relative floor of the whitening scales `σ_i` (step 3 above). Directions of `μ` the data barely
/// see (`s_i` below the floor) keep a Hessian entry `(s_i/σ_i)² < 1` instead of blowing their
/// constraint columns up by `1/s_i`: with a floor of 1e-7 Clarabel met the normalised constraint rows
/// to its tolerance while `Γ'(0)` was off by 10⁶ ε at β = 5 (odds ratios from e^-15 to e^20); 1e-3 solves
/// β up to 7 on Example 1 in at most two refinement rounds, with the same intercept-map estimates.
const WHITENING_FLOOR: f64 = 1e-3;
/// At most this many re-solves with points added to the monotonicity grid.
const REFINEMENT_ROUNDS: usize = 6;
/// A constraint whose slack is below this fraction of `ε` counts as active.
const ACTIVE_TOLERANCE: f64 = 1e-4;
/// `Γ` has collapsed to a straight line when at least this fraction of the constraints is active.
const COLLAPSE_FRACTION: f64 = 0.9;

/// Why a map could not be fitted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
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
    /// Clarabel's status of the last solve.
    pub status: String,
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

/// Fits target `target` of `data` with `settings`.
pub fn fit(data: &DataSet, target: usize, target_name: &str, settings: &MapSettings) -> Result<Fit, FitError> {
    let odds_ratios: Vec<f64> = basis::paper_odds_ratios(settings.nm, settings.beta).collect();
    let range = TargetRange::gather(data, target)?;
    let r_factor = accumulate(data, target, &range, &odds_ratios);
    let linear = linear_floor(&r_factor, &range)?;
    let with_constant = settings.normalisation == Normalisation::Paper;
    let reduced = Reduced::new(&r_factor, range.scales.len(), with_constant, range.windows);
    let columns = Columns {
        odds_ratios: &odds_ratios,
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
    let n_z = range.scales.len();
    let l_scaled = solve_upper(&reduced.r_ll, &(&reduced.r_lmu * mu))?;
    let gains = (0..n_z).map(|c| scale * l_scaled[c] / range.scales[c]).collect();
    let intercept = if with_constant { 0.0 } else { scale * l_scaled[n_z] };
    let mu_constant = if with_constant { scale * mu[0] } else { 0.0 };
    let mu_basis: Vec<f64> = mu.iter().skip(usize::from(with_constant)).map(|m| scale * m).collect();
    let weights: Vec<f64> = mu_basis
        .iter()
        .zip(&odds_ratios)
        .map(|(&m, &c)| basis_weight(m, c))
        .collect();
    let min_slope = check_strictly_increasing(&firmware::Gamma {
        offset: mu_constant - intercept,
        weights: &weights,
        odds_ratios: &odds_ratios,
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
        status: solved.status.clone(),
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

/// Range of the target and RMS of each regressor column over the learning windows (pass 1).
struct TargetRange {
    min: f64,
    max: f64,
    /// RMS of each column of `Z` (1 for an all-zero column): `Z̃ = Z / scale`.
    scales: Vec<f64>,
    /// `n_E`.
    windows: usize,
}

impl TargetRange {
    fn gather(data: &DataSet, target: usize) -> Result<Self, FitError> {
        let n_z = data.regressor_len();
        let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut sum_squares = vec![0.0; n_z];
        let mut z = Vec::with_capacity(n_z);
        let mut windows = 0usize;
        for window in data.windows() {
            let r = data.target(window, target);
            data.regressor(window, &mut z);
            if !r.is_finite() || z.iter().any(|v| !v.is_finite()) {
                return Err(FitError::NonFinite);
            }
            min = min.min(r);
            max = max.max(r);
            for (s, v) in sum_squares.iter_mut().zip(&z) {
                *s += v * v;
            }
            windows += 1;
        }
        if !(max - min > 1e-12 * max.abs().max(min.abs()).max(1e-300)) {
            return Err(FitError::ConstantTarget { value: min });
        }
        let scales = sum_squares
            .iter()
            .map(|s| if *s > 0.0 { (s / windows as f64).sqrt() } else { 1.0 })
            .collect();
        Ok(TargetRange {
            min,
            max,
            scales,
            windows,
        })
    }
}

/// `R` of `[Z̃ | 1 | B(η; c_j) | r]` over every learning window (pass 2).
fn accumulate(data: &DataSet, target: usize, range: &TargetRange, odds_ratios: &[f64]) -> DMatrix<f64> {
    let n_z = range.scales.len();
    let columns = n_z + 1 + odds_ratios.len() + 1;
    let mut qr = StreamingQr::new(columns);
    let mut row = vec![0.0; columns];
    let mut z = Vec::with_capacity(n_z);
    for window in data.windows() {
        let r = data.target(window, target);
        data.regressor(window, &mut z);
        let eta = (r - range.min) / (range.max - range.min);
        for (c, (v, s)) in z.iter().zip(&range.scales).enumerate() {
            row[c] = v / s;
        }
        row[n_z] = 1.0;
        for (j, &b) in odds_ratios.iter().enumerate() {
            row[n_z + 1 + j] = basis::value(b, eta);
        }
        row[columns - 1] = r;
        qr.push(&row);
    }
    qr.finish()
}

/// Least squares of `r` on `[Z̃ | 1]`: the leading block of `R` and its last column.
fn linear_floor(r_factor: &DMatrix<f64>, range: &TargetRange) -> Result<LinearMap, FitError> {
    let n_z = range.scales.len();
    let last = r_factor.ncols() - 1;
    let coefficients = solve_upper(
        &r_factor.view((0, 0), (n_z + 1, n_z + 1)).into_owned(),
        &r_factor.view((0, last), (n_z + 1, 1)).column(0).into_owned(),
    )?;
    Ok(LinearMap {
        gains: (0..n_z).map(|c| coefficients[c] / range.scales[c]).collect(),
        intercept: coefficients[n_z],
    })
}

/// The `μ`-columns of a normalisation: the basis functions, after the constant with `paper`.
struct Columns<'a> {
    odds_ratios: &'a [f64],
    with_constant: bool,
}

impl Columns<'_> {
    /// `B'(η)` of each column (the constant's is 0).
    fn slopes(&self, eta: f64) -> DVector<f64> {
        let constant = self.with_constant.then_some(0.0);
        DVector::from_iterator(
            self.odds_ratios.len() + usize::from(self.with_constant),
            constant
                .into_iter()
                .chain(self.odds_ratios.iter().map(|&b| basis::slope(b, eta))),
        )
    }

    /// `∫₀¹ B` of each column (the constant's is 1).
    fn integrals(&self) -> DVector<f64> {
        let constant = self.with_constant.then_some(1.0);
        DVector::from_iterator(
            self.odds_ratios.len() + usize::from(self.with_constant),
            constant
                .into_iter()
                .chain(self.odds_ratios.iter().map(|&b| basis::integral(b))),
        )
    }

    /// `Γ'(η) = B'(η) μ`.
    fn slope(&self, eta: f64, mu: &DVector<f64>) -> f64 {
        self.slopes(eta).dot(mu)
    }
}

/// The problem in `μ` alone once `L` is eliminated, and its whitening `μ = T x`.
struct Reduced {
    r_ll: DMatrix<f64>,
    r_lmu: DMatrix<f64>,
    /// `R_μμ / √n_E`: the objective is `‖R_μμ μ‖² / n_E`.
    r_mumu: DMatrix<f64>,
    /// `T = V Σ⁻¹`.
    transform: DMatrix<f64>,
    /// Clarabel's `P` in `x`: `diag(2 (s_i/σ_i)²)`, so that `½ xᵀ P x = ‖R_μμ μ‖² / n_E`.
    hessian: DMatrix<f64>,
    /// `s_max / s_min`.
    condition: f64,
}

impl Reduced {
    fn new(r_factor: &DMatrix<f64>, n_z: usize, with_constant: bool, windows: usize) -> Self {
        let l_count = if with_constant { n_z } else { n_z + 1 };
        let mu_count = r_factor.ncols() - 1 - l_count;
        let r_ll = r_factor.view((0, 0), (l_count, l_count)).into_owned();
        let r_lmu = r_factor.view((0, l_count), (l_count, mu_count)).into_owned();
        let r_mumu = r_factor.view((l_count, l_count), (mu_count, mu_count)).into_owned() / (windows as f64).sqrt();
        let svd = r_mumu.clone().svd(false, true);
        let v = svd.v_t.as_ref().expect("V was requested").transpose();
        let s = &svd.singular_values;
        let floor = if s.max() > 0.0 { WHITENING_FLOOR * s.max() } else { 1.0 };
        let sigma = s.map(|s| s.max(floor));
        Reduced {
            transform: v * DMatrix::from_diagonal(&sigma.map(|g| 1.0 / g)),
            hessian: DMatrix::from_diagonal(&s.zip_map(&sigma, |s, g| 2.0 * (s / g).powi(2))),
            condition: s.max() / s.min(),
            r_ll,
            r_lmu,
            r_mumu,
        }
    }
}

/// A solution of the reduced QP with its multipliers in `μ` space.
struct Solved {
    mu: DVector<f64>,
    grid: Vec<f64>,
    lambda: Vec<f64>,
    nu: Option<f64>,
    status: String,
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

/// Solves `R x = b` for upper-triangular `R`, refusing a (numerically) singular one.
fn solve_upper(r: &DMatrix<f64>, b: &DVector<f64>) -> Result<DVector<f64>, FitError> {
    let largest = r.diagonal().amax();
    if let Some(column) = r.diagonal().iter().position(|d| !(d.abs() > 1e-12 * largest)) {
        return Err(FitError::DependentRegressor { column });
    }
    r.solve_upper_triangular(b)
        .ok_or(FitError::DependentRegressor { column: 0 })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::{Run, Window};
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;
    use rand_distr::StandardNormal;

    /// A data set with horizon 1 whose "measurements" are the given regressors.
    fn pairs(samples: &[(Vec<f64>, f64)]) -> DataSet {
        let run = Run {
            states: vec![vec![]; samples.len()],
            inputs: vec![vec![]; samples.len()],
            measurements: samples.iter().map(|s| s.0.clone()).collect(),
            targets: samples.iter().map(|s| vec![s.1]).collect(),
        };
        DataSet {
            runs: vec![run],
            horizon: 1,
        }
    }

    fn settings(normalisation: Normalisation, nm: usize, beta: f64, epsilon: f64) -> MapSettings {
        MapSettings {
            horizon: 1,
            nm,
            beta,
            epsilon,
            normalisation,
            monotonicity_grid: 201,
        }
    }

    /// Regressors and targets of a known map r = 3 + 2 Γ⁻¹(Lᵀ Z), Γ from the same basis family.
    fn synthetic(seed: u64, count: usize) -> Vec<(Vec<f64>, f64)> {
        let odds_ratios: Vec<f64> = basis::paper_odds_ratios(3, 1.0).collect();
        let mu = [0.2, 1.5, 0.1, 0.8];
        let weights: Vec<f64> = mu
            .iter()
            .zip(&odds_ratios)
            .map(|(&m, &b)| firmware::gamma::weight(m, b))
            .collect();
        let gamma = firmware::Gamma {
            offset: 0.0,
            weights: &weights,
            odds_ratios: &odds_ratios,
        };
        let gains = [0.7, -0.4, 0.25];
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut samples = Vec::new();
        // Two samples at η = 0 and η = 1 exactly, so that r_min and r_max are 3 and 5.
        for v in [gamma.value(0.0), gamma.upper()] {
            let mut z: Vec<f64> = (0..3).map(|_| rng.sample::<f64, _>(StandardNormal)).collect();
            z[0] = (v - gains[1] * z[1] - gains[2] * z[2]) / gains[0];
            samples.push((z, 3.0 + 2.0 * gamma.inverse(v).eta));
        }
        while samples.len() < count {
            let z: Vec<f64> = (0..3).map(|_| 2.0 * rng.sample::<f64, _>(StandardNormal)).collect();
            let v: f64 = gains.iter().zip(&z).map(|(g, z)| g * z).sum();
            let inverse = gamma.inverse(v);
            if !inverse.saturation.is_saturated() {
                samples.push((z, 3.0 + 2.0 * inverse.eta));
            }
        }
        samples
    }

    #[test]
    fn recovers_a_map_of_its_own_class() {
        let learning = synthetic(1, 600);
        let fit = fit(
            &pairs(&learning),
            0,
            "r",
            &settings(Normalisation::Intercept, 3, 1.0, 0.01),
        )
        .unwrap();
        let fresh = synthetic(2, 300);
        let table = fit.map.table.as_ref().expect("a certified table");
        for (z, r) in fresh.iter().skip(2) {
            let exact = fit.map.exact_estimate(z);
            assert!((exact.value - r).abs() < 1e-5, "estimate {} vs truth {r}", exact.value);
            // The library estimate is the table: within its proven bound of the exact inverse.
            let tabulated = fit.map.estimate(z);
            assert!((tabulated.value - exact.value).abs() <= table.proven_bound + 1e-12);
        }
        // The linear floor cannot: Γ is far from a line.
        let worst_linear = fresh
            .iter()
            .map(|(z, r)| (fit.linear.estimate(z) - r).abs())
            .fold(0.0, f64::max);
        assert!(worst_linear > 1e-2, "{worst_linear}");
    }

    #[test]
    fn linear_floor_matches_an_independent_least_squares_solve() {
        let samples = synthetic(3, 400);
        let fit = fit(
            &pairs(&samples),
            0,
            "r",
            &settings(Normalisation::Intercept, 3, 1.0, 0.01),
        )
        .unwrap();
        let a = DMatrix::from_fn(samples.len(), 4, |i, j| if j < 3 { samples[i].0[j] } else { 1.0 });
        let b = DVector::from_iterator(samples.len(), samples.iter().map(|s| s.1));
        let x = a.clone().svd(true, true).solve(&b, 1e-14).unwrap();
        for j in 0..3 {
            assert!(
                (fit.linear.gains[j] - x[j]).abs() < 1e-10 * x.amax(),
                "{} vs {}",
                fit.linear.gains[j],
                x[j]
            );
        }
        assert!((fit.linear.intercept - x[3]).abs() < 1e-10 * x.amax());
    }

    /// Checks the KKT conditions of a fit against matrices built directly from the data: the reduced
    /// gradient `2/n_E (P⊥B)ᵀ (P⊥B) μ`, with `P⊥` the projector off `Z`'s columns by an SVD solve.
    fn assert_kkt(data: &DataSet, settings: &MapSettings) {
        let fit = fit(data, 0, "r", settings).unwrap();
        let c = &fit.certificate;
        let windows: Vec<Window> = data.windows().collect();
        let n_e = windows.len();
        let n_z = data.regressor_len();
        let (r_min, r_max) = (fit.map.r_min, fit.map.r_max);
        let odds_ratios = &fit.map.odds_ratios;
        let m = c.mu.len();
        let l_count = if c.with_constant { n_z } else { n_z + 1 };
        let mut z_matrix = DMatrix::zeros(n_e, l_count);
        let mut b_matrix = DMatrix::zeros(n_e, m);
        let mut z = Vec::new();
        for (i, &w) in windows.iter().enumerate() {
            data.regressor(w, &mut z);
            for j in 0..n_z {
                z_matrix[(i, j)] = z[j];
            }
            if !c.with_constant {
                z_matrix[(i, n_z)] = 1.0;
            }
            let eta = (data.target(w, 0) - r_min) / (r_max - r_min);
            let values: Vec<f64> = c
                .with_constant
                .then_some(1.0)
                .into_iter()
                .chain(odds_ratios.iter().map(|&b| basis::value(b, eta)))
                .collect();
            for j in 0..m {
                b_matrix[(i, j)] = values[j];
            }
        }
        let projected = &b_matrix - &z_matrix * z_matrix.clone().svd(true, true).solve(&b_matrix, 1e-13).unwrap();
        let mu = DVector::from_column_slice(&c.mu);
        let gradient = 2.0 / n_e as f64 * projected.transpose() * (&projected * &mu);
        let slope_row = |eta: f64| -> DVector<f64> {
            DVector::from_iterator(
                m,
                c.with_constant
                    .then_some(0.0)
                    .into_iter()
                    .chain(odds_ratios.iter().map(|&b| basis::slope(b, eta))),
            )
        };
        let mut multiplier_term = DVector::zeros(m);
        let mut complementarity: f64 = 0.0;
        for (&eta, &lambda) in c.grid.iter().zip(&c.lambda) {
            let row = slope_row(eta);
            let slack = row.dot(&mu) - c.epsilon;
            assert!(
                slack >= -1e-6 * c.epsilon,
                "constraint at η = {eta} violated: slack {slack}"
            );
            assert!(lambda >= -1e-9, "negative multiplier {lambda}");
            complementarity = complementarity.max((lambda * slack).abs());
            multiplier_term += lambda * row;
        }
        if c.with_constant {
            let integral = DVector::from_iterator(
                m,
                std::iter::once(1.0).chain(odds_ratios.iter().map(|&b| basis::integral(b))),
            );
            assert!(
                (integral.dot(&mu) - c.mean).abs() < 1e-8 * (1.0 + c.mean.abs()),
                "equality violated"
            );
            multiplier_term += c.nu.unwrap() * integral;
        }
        let residual = (&gradient - &multiplier_term).norm();
        let scale = gradient.norm().max(multiplier_term.norm());
        assert!(
            residual <= 1e-5 * scale,
            "stationarity residual {residual} vs gradient {scale}"
        );
        assert!(complementarity <= 1e-6 * scale, "complementarity {complementarity}");
    }

    /// A window set with a real nonlinearity and noise: r = x, y = x³ + noise over a grid.
    fn cubic(seed: u64) -> DataSet {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let samples: Vec<(Vec<f64>, f64)> = (0..800)
            .map(|_| {
                let x: f64 = rng.random_range(-1.5..1.5);
                let noise: f64 = rng.sample(StandardNormal);
                (vec![x * x * x + 0.05 * noise, x + 0.2 * noise], x)
            })
            .collect();
        pairs(&samples)
    }

    #[test]
    fn kkt_conditions_hold_with_either_normalisation() {
        for normalisation in [Normalisation::Intercept, Normalisation::Paper] {
            for beta in [0.5, 2.0, 4.0] {
                assert_kkt(&cubic(5), &settings(normalisation, 5, beta, 0.05));
            }
        }
    }

    #[test]
    fn intercept_fit_is_invariant_to_epsilon_and_to_a_shift_of_the_target() {
        let data = cubic(6);
        let mut shifted = data.clone();
        for t in shifted.runs[0].targets.iter_mut() {
            t[0] += 10.0;
        }
        let base = fit(&data, 0, "r", &settings(Normalisation::Intercept, 5, 1.0, 0.01)).unwrap();
        let other_epsilon = fit(&data, 0, "r", &settings(Normalisation::Intercept, 5, 1.0, 3.0)).unwrap();
        let moved = fit(&shifted, 0, "r", &settings(Normalisation::Intercept, 5, 1.0, 0.01)).unwrap();
        let mut z = Vec::new();
        for w in data.windows() {
            data.regressor(w, &mut z);
            let e = base.map.estimate(&z).value;
            assert!((other_epsilon.map.estimate(&z).value - e).abs() < 1e-9);
            assert!((moved.map.estimate(&z).value - 10.0 - e).abs() < 1e-9);
        }
        // The paper's normalisation is not shift-invariant: its estimates move.
        let paper = fit(&data, 0, "r", &settings(Normalisation::Paper, 5, 1.0, 0.01)).unwrap();
        let paper_moved = fit(&shifted, 0, "r", &settings(Normalisation::Paper, 5, 1.0, 0.01)).unwrap();
        let largest_change = data
            .windows()
            .map(|w| {
                data.regressor(w, &mut z);
                (paper_moved.map.estimate(&z).value - 10.0 - paper.map.estimate(&z).value).abs()
            })
            .fold(0.0, f64::max);
        assert!(largest_change > 1e-3, "{largest_change}");
    }

    #[test]
    fn constant_target_is_an_error() {
        let samples: Vec<(Vec<f64>, f64)> = (0..50).map(|i| (vec![i as f64, 1.0 / (1.0 + i as f64)], 2.0)).collect();
        assert_eq!(
            fit(
                &pairs(&samples),
                0,
                "r",
                &settings(Normalisation::Intercept, 3, 1.0, 0.01)
            )
            .unwrap_err(),
            FitError::ConstantTarget { value: 2.0 }
        );
    }
}
