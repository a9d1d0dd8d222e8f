//! Every observer of a design judged on the same data: the fitted map and its peer, an extended Kalman
//! filter over the model ([`ekf`]), each target's error on the validation runs, the scenario (whole,
//! and its transient) and the tuning runs. The EKF's constants are chosen on the tuning runs only; the
//! map's were fitted on the learning runs only, so the validation and scenario figures are on data
//! neither saw.

pub mod corrected;
pub mod ekf;

use crate::data::{self, DataSet, Rows, Run};
use crate::fit::DesignResult;
use crate::plant::ModelCode;
use crate::spec::{Design, SpecError};

/// Errors of one observer on one target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Figures {
    /// RMSE over the validation windows.
    pub rmse_validation: f64,
    /// Largest |error| over the validation windows.
    pub max_error_validation: f64,
    /// RMSE over the scenario's windows.
    pub rmse_scenario: f64,
    /// RMSE over the scenario's first [`TRANSIENT_TIME`] time units after the map's first estimate.
    pub rmse_transient: f64,
    /// RMSE over the tuning runs' windows.
    pub rmse_tuning: f64,
}

/// Length of the transient judged, in the spec's time unit, from the first window.
pub const TRANSIENT_TIME: f64 = 2.0;

/// One observer's figures, per target in spec order.
#[derive(Clone, Debug)]
pub struct ObserverFigures {
    /// `"map"`, `"ekf"` or `"corrected"`.
    pub kind: &'static str,
    /// Per target.
    pub targets: Vec<Figures>,
}

/// The comparison of a design's observers.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// The map first, then the EKF when the host could run one.
    pub observers: Vec<ObserverFigures>,
    /// The tuned EKF (`None` when the model is beyond the host's sizes, [`ekf::supported`]).
    pub ekf: Option<ekf::Tuned>,
    /// The tuned model-corrected map, or why the design cannot have one.
    pub corrected: Result<corrected::Tuned, String>,
    /// The tuning runs.
    pub tuning: DataSet,
    /// Largest one-sample difference between the chip's model (`chip_substeps`) and the learning
    /// simulation's (`substeps`) over the validation states, per state, relative to its spread.
    pub chip_model_error: Vec<f64>,
}

/// RMSE and largest |error| of `estimates` (one row per sample of each run) against the runs'
/// targets, over samples `from(run) .. to(run)`.
fn errors(
    runs: &[Run],
    estimates: &[Rows],
    target: usize,
    window: impl Fn(&Run) -> std::ops::Range<usize>,
) -> (f64, f64) {
    let (mut sum, mut count, mut max) = (0.0, 0usize, 0.0_f64);
    for (run, estimate) in runs.iter().zip(estimates) {
        for k in window(run) {
            let error = estimate[k][target] - run.targets[k][target];
            sum += error * error;
            count += 1;
            max = if error.is_nan() { f64::NAN } else { max.max(error.abs()) };
        }
    }
    ((sum / count.max(1) as f64).sqrt(), max)
}

/// The map's estimate of every target at every sample of `run` (NaN before the window is full).
fn map_estimates(result: &DesignResult, horizon: usize, run: &Run) -> Rows {
    let data = DataSet {
        runs: vec![run.clone()],
        horizon,
    };
    let mut rows = Rows::new(result.targets.len());
    let mut z = Vec::new();
    for _ in 0..horizon.saturating_sub(1).min(run.targets.len()) {
        rows.push(&vec![f64::NAN; result.targets.len()]);
    }
    for window in data.windows() {
        data.regressor(window, &mut z);
        let values: Vec<f64> = result.targets.iter().map(|t| t.fit.map.estimate(&z).value).collect();
        rows.push(&values);
    }
    rows
}

/// Simulates the tuning runs, tunes the EKF on them, and judges both observers.
pub fn compare(design: &Design, result: &DesignResult, code: &ModelCode) -> Result<Comparison, SpecError> {
    let tuning = data::tuning_set(design)?;
    let horizon = design.map.horizon;
    let targets = design.targets.len();
    let spreads: Vec<f64> = result.targets.iter().map(|t| t.validation.target_spread).collect();
    let tuned = ekf::tune(design, code, &tuning, &result.learning, &spreads);
    let transient = (TRANSIENT_TIME / design.tau).round() as usize;
    let scenario = std::slice::from_ref(&result.scenario);
    let windows = |run: &Run| horizon - 1..run.targets.len();
    let figures = |estimate: &dyn Fn(&Run, bool) -> Rows| -> Vec<Figures> {
        let validation: Vec<Rows> = result.validation.runs.iter().map(|r| estimate(r, false)).collect();
        let on_scenario = vec![estimate(&result.scenario, true)];
        let on_tuning: Vec<Rows> = tuning.runs.iter().map(|r| estimate(r, false)).collect();
        (0..targets)
            .map(|t| {
                let (rmse_validation, max_error_validation) = errors(&result.validation.runs, &validation, t, windows);
                Figures {
                    rmse_validation,
                    max_error_validation,
                    rmse_scenario: errors(scenario, &on_scenario, t, windows).0,
                    rmse_transient: errors(scenario, &on_scenario, t, |run| {
                        horizon - 1..horizon.saturating_add(transient).min(run.targets.len())
                    })
                    .0,
                    rmse_tuning: errors(&tuning.runs, &on_tuning, t, windows).0,
                }
            })
            .collect()
    };
    let mut observers = vec![ObserverFigures {
        kind: "map",
        targets: figures(&|run, _| map_estimates(result, horizon, run)),
    }];
    if let Some(tuned) = &tuned {
        let centre = ekf::box_centre(design);
        let scenario_start = design
            .scenario
            .as_ref()
            .and_then(|s| s.observer_x0.clone())
            .unwrap_or_else(|| centre.clone());
        observers.push(ObserverFigures {
            kind: "ekf",
            targets: figures(&|run, is_scenario| {
                let x0 = if is_scenario { &scenario_start } else { &centre };
                ekf::estimate_run(code, &tuned.constants, x0, run).expect("size checked by tune")
            }),
        });
    }
    let corrected = corrected::state_targets(design).map(|state_targets| {
        let setting = corrected::Setting::new(
            code,
            design.tau / design.chip_substeps as f64,
            design.chip_substeps,
            &state_targets,
            horizon - 1,
        );
        let maps: Vec<Rows> = tuning.runs.iter().map(|r| map_estimates(result, horizon, r)).collect();
        let tuned = corrected::tune(&setting, &tuning, &maps, &spreads);
        observers.push(ObserverFigures {
            kind: "corrected",
            targets: figures(&|run, _| setting.estimate_run(&tuned.gains, &map_estimates(result, horizon, run), run)),
        });
        tuned
    });
    Ok(Comparison {
        observers,
        ekf: tuned,
        corrected,
        chip_model_error: chip_model_error(design, result),
        tuning,
    })
}

/// See [`Comparison::chip_model_error`].
fn chip_model_error(design: &Design, result: &DesignResult) -> Vec<f64> {
    use crate::data::simulate::Integrator;
    let states = design.model.states.len();
    let spreads = ekf::state_spreads(&result.learning, states);
    let mut fine = Integrator::new(&design.model, design.tau, design.substeps);
    let mut coarse = Integrator::new(&design.model, design.tau, design.chip_substeps);
    let mut worst = vec![0.0_f64; states];
    for run in &result.validation.runs {
        for (x, u) in run.states.iter().zip(run.inputs.iter()) {
            let (mut a, mut b) = (x.to_vec(), x.to_vec());
            fine.advance(&mut a, u);
            coarse.advance(&mut b, u);
            for i in 0..states {
                worst[i] = worst[i].max((a[i] - b[i]).abs() / spreads[i]);
            }
        }
    }
    worst
}
