//! The unscented Kalman filter on the host: the written-out sample of [`crate::observers::kind::ukf_box::program`]
//! run in f32, the chip's arithmetic and its bits (the operations the emitted code runs; tuned and
//! judged so, since on E. coli, where the sigma points reach the substrate's bound and the chip's
//! one RK4 step per sample is stiff, the f32 and f64 runs part by up to 0.8 g/L), with the EKF's
//! constants (`Q`, `P(0)` diagonal, `R` the outputs' noise variances, the chip's RK4 substeps),
//! tuned on the tuning runs
//! by the EKF's search and score ([`super::ekf::tuning`]: the same grid, starts and Nelder–Mead
//! iterations), started from the centre of the state box.
//!
//! A sample is taken as the chip's EKF takes it (`firmware::Ekf::push`): a non-finite input changes
//! nothing; a non-finite output is refused and only predicted (no estimate); a sample whose
//! result is not finite is not taken (no estimate, the state kept).

use crate::data::{DataSet, Rows, Run};
use crate::observers::kind::ukf_box::program::unscented_code;
use crate::observers::lost::{Track, Tracker};
use crate::plant::kalman::{EkfConstants, FilterCode};
use crate::plant::ModelCode;
use crate::spec::Design;

use super::ekf::{self, Tuned};

/// The targets estimated at every sample of `run` by the written-out UKF `filter` started at `x0`
/// with `P(0)` and the watch of `constants`, in `f32` as the chip runs it (step for step the generated `Ukf::push`,
/// [`ekf::BoxStep`]): NaN where a sample gave no estimate.
pub fn estimate_run(code: &ModelCode, filter: &FilterCode, x0: &[f64], constants: &EkfConstants, run: &Run) -> Rows {
    track_run(code, filter, x0, constants, run).rows
}

/// [`estimate_run`], with the restarts on the run.
pub fn track_run(code: &ModelCode, filter: &FilterCode, x0: &[f64], constants: &EkfConstants, run: &Run) -> Track {
    let mut filter = ekf::BoxStep::<f32>::new(filter, x0, constants, code);
    let mut track = Tracker::new(code.dimensions.targets);
    for (y, u) in run.measurements.iter().zip(run.inputs.iter()) {
        let before = filter.restarts();
        match filter.step(y, u) {
            Some(targets) => track.estimate(targets.into_iter().map(f64::from)),
            None if filter.restarts() > before => track.restarted(),
            None => track.refused(),
        }
    }
    track.finish()
}

/// The UKF's estimates of every run of `data` with `constants`, started at `x0` (both in the model's
/// log coordinates, [`ModelCode::logarithmic`]; an
/// [`ekf::Estimator`]); `None` for a model beyond the sizes the host filters ([`ekf::supported`]).
pub fn estimates(code: &ModelCode, constants: &EkfConstants, x0: &[f64], data: &DataSet) -> Option<Vec<Rows>> {
    if !ekf::supported(code) {
        return None;
    }
    let filter = unscented_code(code, constants);
    Some(
        data.runs
            .iter()
            .map(|run| estimate_run(code, &filter, x0, constants, run))
            .collect(),
    )
}

/// Chooses the UKF's `Q` and `P(0)` on `tuning` as the EKF's are chosen ([`ekf::tune`]), those the
/// spec does not fix (`[observer.ukf]`), in the model's log coordinates (its start too).
pub fn tune(
    design: &Design,
    code: &ModelCode,
    tuning: &DataSet,
    learning: &DataSet,
    target_spreads: &[f64],
) -> Option<Tuned> {
    ekf::tune_with(
        estimates,
        super::FIXED.of(design),
        design,
        code,
        &code.log_coordinates,
        tuning,
        learning,
        &crate::observers::score::Scoring::of_tuning(design, target_spreads, tuning.runs.len()),
    )
}

#[cfg(test)]
mod tests;
