//! One target's learning data reduced to the triangular factor `R` of `[Z̃ | 1 | B | r]` in one pass
//! (steps 1 and 2 of the method above), and the fit of the map on a support of `L` from it: what the
//! dense fit and every support the pruning tries share.

use nalgebra::DMatrix;
use std::sync::Arc;

use super::reduce::{accumulate, linear_floor, solve_upper, Columns, Reduced, TargetRange};
use super::solve::solve_refined;
use super::{Certificate, Diagnostics, Fit, FitError};
use crate::data::{Column, DataSet};
use crate::fit::maps::{FittedMap, LinearMap, Tabulation};
use crate::fit::monotonicity::{check_grid, check_strictly_increasing};
use crate::spec::{MapSettings, Normalisation};

/// A constraint whose slack is below this fraction of `ε` counts as active.
const ACTIVE_TOLERANCE: f64 = 1e-4;
/// `Γ` has collapsed to a straight line when at least this fraction of the constraints is active.
const COLLAPSE_FRACTION: f64 = 0.9;

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
        target: Column,
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

    pub(super) fn with_constant(&self) -> bool {
        self.settings.normalisation == Normalisation::Paper
    }

    /// `R` of `[Z̃_S | 1 | B | r]` for the support `S` (increasing entries of `Z`): the full factor when
    /// `S` is every entry, else the QR of its columns (`R_Sᵀ R_S = Z_Sᵀ Z_S`, same data, no new pass).
    pub(super) fn factor_of(&self, support: &[usize]) -> std::borrow::Cow<'_, DMatrix<f64>> {
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
    pub(super) fn fit(&self, support: &[usize], target_name: &str, tabulation: Tabulation) -> Result<Fit, FitError> {
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
