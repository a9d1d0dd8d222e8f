//! Steps 1–3 of the identification (see [`super`]): the target's range and column scales, the streamed
//! factor `R` of `[Z̃ | 1 | B | r]`, the elimination of `L`, the whitening of `μ`, and the linear floor
//! from the same `R`.

use nalgebra::{DMatrix, DVector};

use super::{FitError, WHITENING_FLOOR};
use crate::data::{Column, DataSet};
use crate::fit::maps::LinearMap;
use crate::fit::streaming_qr::StreamingQr;
use firmware::basis;

/// Range of the target and RMS of each regressor column over the learning windows (pass 1).
pub(super) struct TargetRange {
    pub(super) min: f64,
    pub(super) max: f64,
    /// RMS of each column of `Z` (1 for an all-zero column): `Z̃ = Z / scale`.
    pub(super) scales: Vec<f64>,
    /// `n_E`.
    pub(super) windows: usize,
}

impl TargetRange {
    pub(super) fn gather(data: &DataSet, target: Column) -> Result<Self, FitError> {
        let n_z = data.regressor_len();
        let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut sum_squares = vec![0.0; n_z];
        let mut z = Vec::with_capacity(n_z);
        let mut windows = 0usize;
        for window in data.windows() {
            let r = data.value(window, target);
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
pub(super) fn accumulate(data: &DataSet, target: Column, range: &TargetRange, odds_ratios: &[f64]) -> DMatrix<f64> {
    let n_z = range.scales.len();
    let columns = n_z + 1 + odds_ratios.len() + 1;
    let mut qr = StreamingQr::new(columns);
    let mut row = vec![0.0; columns];
    let mut z = Vec::with_capacity(n_z);
    for window in data.windows() {
        let r = data.value(window, target);
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

/// Least squares of `r` on `[Z̃ | 1]`: the leading block of `R` and its last column. `scales` are the
/// RMS of the `Z̃` columns `R` was built from (a support's, for a pruned `L`).
pub(super) fn linear_floor(r_factor: &DMatrix<f64>, scales: &[f64]) -> Result<LinearMap, FitError> {
    let n_z = scales.len();
    let last = r_factor.ncols() - 1;
    let coefficients = solve_upper(
        &r_factor.view((0, 0), (n_z + 1, n_z + 1)).into_owned(),
        &r_factor.view((0, last), (n_z + 1, 1)).column(0).into_owned(),
    )?;
    Ok(LinearMap {
        gains: (0..n_z).map(|c| coefficients[c] / scales[c]).collect(),
        intercept: coefficients[n_z],
    })
}

/// The `μ`-columns of a normalisation: the basis functions, after the constant with `paper`.
pub(super) struct Columns<'a> {
    pub(super) odds_ratios: &'a [f64],
    pub(super) with_constant: bool,
}

impl Columns<'_> {
    /// `B'(η)` of each column (the constant's is 0).
    pub(super) fn slopes(&self, eta: f64) -> DVector<f64> {
        let constant = self.with_constant.then_some(0.0);
        DVector::from_iterator(
            self.odds_ratios.len() + usize::from(self.with_constant),
            constant
                .into_iter()
                .chain(self.odds_ratios.iter().map(|&b| basis::slope(b, eta))),
        )
    }

    /// `∫₀¹ B` of each column (the constant's is 1).
    pub(super) fn integrals(&self) -> DVector<f64> {
        let constant = self.with_constant.then_some(1.0);
        DVector::from_iterator(
            self.odds_ratios.len() + usize::from(self.with_constant),
            constant
                .into_iter()
                .chain(self.odds_ratios.iter().map(|&b| basis::integral(b))),
        )
    }

    /// `Γ'(η) = B'(η) μ`.
    pub(super) fn slope(&self, eta: f64, mu: &DVector<f64>) -> f64 {
        self.slopes(eta).dot(mu)
    }
}

/// The problem in `μ` alone once `L` is eliminated, and its whitening `μ = T x`.
pub(super) struct Reduced {
    pub(super) r_ll: DMatrix<f64>,
    pub(super) r_lmu: DMatrix<f64>,
    /// `R_μμ / √n_E`: the objective is `‖R_μμ μ‖² / n_E`.
    pub(super) r_mumu: DMatrix<f64>,
    /// `T = V Σ⁻¹`.
    pub(super) transform: DMatrix<f64>,
    /// Clarabel's `P` in `x`: `diag(2 (s_i/σ_i)²)`, so that `½ xᵀ P x = ‖R_μμ μ‖² / n_E`.
    pub(super) hessian: DMatrix<f64>,
    /// `s_max / s_min`.
    pub(super) condition: f64,
}

impl Reduced {
    pub(super) fn new(r_factor: &DMatrix<f64>, n_z: usize, with_constant: bool, windows: usize) -> Self {
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

/// Solves `R x = b` for upper-triangular `R`, refusing a (numerically) singular one.
pub(super) fn solve_upper(r: &DMatrix<f64>, b: &DVector<f64>) -> Result<DVector<f64>, FitError> {
    let largest = r.diagonal().amax();
    if let Some(column) = r.diagonal().iter().position(|d| !(d.abs() > 1e-12 * largest)) {
        return Err(FitError::DependentRegressor { column });
    }
    r.solve_upper_triangular(b)
        .ok_or(FitError::DependentRegressor { column: 0 })
}
