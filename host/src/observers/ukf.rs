//! The unscented Kalman filter on the host: the written-out sample of [`crate::plant::unscented`]
//! run in f64 (the operations the emitted code runs), with the EKF's constants (`Q`, `P(0)`
//! diagonal, `R` the outputs' noise variances, the chip's RK4 substeps), tuned on the tuning runs
//! by the EKF's search and score ([`super::ekf::tuning`]: the same grid, starts and Nelder–Mead
//! iterations), started from the centre of the state box.
//!
//! A sample is taken as the chip's EKF takes it (`firmware::Ekf::push`): a non-finite input changes
//! nothing; a non-finite output is refused and only predicted (no estimate); a sample whose
//! result is not finite is not taken (no estimate, the state kept).

use crate::data::{DataSet, Rows, Run};
use crate::plant::kalman::{diagonal_upper, EkfConstants, FilterCode};
use crate::plant::unscented::unscented_code;
use crate::plant::ModelCode;
use crate::spec::Design;

use super::ekf::{self, Tuned};

/// The targets estimated at every sample of `run` by the written-out UKF `filter` started at `x0`
/// with `P(0) = diag(p0)`: NaN where a sample gave no estimate.
pub fn estimate_run(code: &ModelCode, filter: &FilterCode, x0: &[f64], p0: &[f64], run: &Run) -> Rows {
    let nx = code.dimensions.states;
    let (mut x, mut p) = (x0.to_vec(), diagonal_upper(p0));
    let mut scratch = Vec::new();
    let mut estimates = Rows::new(code.dimensions.targets);
    for (y, u) in run.measurements.iter().zip(run.inputs.iter()) {
        let mut estimate = None;
        if u.iter().all(|v| v.is_finite()) {
            let measured = y.iter().all(|v| v.is_finite()).then_some(y);
            let (updated, next, covariance) = filter.run(&x, &p, measured, u, &mut scratch);
            if next.iter().chain(&covariance).all(|v| v.is_finite()) {
                (x, p, estimate) = (next, covariance, updated);
            }
        }
        let state = estimate.unwrap_or_else(|| vec![f64::NAN; nx]);
        estimates.push(&code.targets(&state, u, &mut scratch));
    }
    estimates
}

/// The UKF's estimates of every run of `data` with `constants`, started at `x0` (an
/// [`ekf::Estimator`]); `None` for a model beyond the sizes the host filters ([`ekf::supported`]).
pub fn estimates(code: &ModelCode, constants: &EkfConstants, x0: &[f64], data: &DataSet) -> Option<Vec<Rows>> {
    if !ekf::supported(code) {
        return None;
    }
    let filter = unscented_code(code, constants);
    Some(
        data.runs
            .iter()
            .map(|run| estimate_run(code, &filter, x0, &constants.p0, run))
            .collect(),
    )
}

/// Chooses the UKF's `Q` and `P(0)` on `tuning` as the EKF's are chosen ([`ekf::tune`]).
pub fn tune(
    design: &Design,
    code: &ModelCode,
    tuning: &DataSet,
    learning: &DataSet,
    target_spreads: &[f64],
) -> Option<Tuned> {
    ekf::tune_with(estimates, design, code, tuning, learning, target_spreads)
}

#[cfg(test)]
mod tests;
