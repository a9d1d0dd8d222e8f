//! Every observer of a design judged on the same data: the fitted map and its peer, an extended Kalman
//! filter over the model ([`ekf`]), each target's error on the validation runs, the scenario (whole,
//! and its transient) and the tuning runs. The EKF's constants are chosen on the tuning runs only; the
//! map's were fitted on the learning runs only, so the validation and scenario figures are on data
//! neither saw.

pub mod choice;
pub mod corrected;
pub mod ekf;
pub mod figures;
pub mod recorded;
pub mod restart;
pub mod score;
pub mod started;

pub use choice::{check_before_fit, choose, row_name, KINDS};
pub use figures::{Comparison, Drift, Figures, Mismatch, ObserverFigures, Started, TRANSIENT_TIME};
pub use score::CHEAPER_WITHIN;

use crate::data::{self, DataSet, Rows, Run};
use crate::fit::DesignResult;
use crate::plant::ModelCode;
use crate::search::cost;
use crate::spec::{Design, SpecError};

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
pub fn map_estimates(result: &DesignResult, horizon: usize, run: &Run) -> Rows {
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

/// The mismatch plants of `design` and their runs (every corner, the nominal plant, and long runs at the
/// last corner), `None` when every parameter is known.
fn mismatch(design: &Design, long_samples: usize) -> Result<Option<(Mismatch, [DataSet; 3])>, SpecError> {
    let Some(set) = data::uncertain::mismatch_set(design)? else {
        return Ok(None);
    };
    let corners = data::uncertain::corners(&design.model);
    let last = corners.last().expect("a mismatch set has corners");
    let plant = design.model.with_parameters(&design.model.values_with_uncertain(last));
    let scenario = match data::scenario_run(design, &plant, "mismatch scenario")? {
        Some(run) => run,
        None => set.runs[set.runs.len() - design.validation.trajectories].clone(),
    };
    let nominal = data::uncertain::nominal(&design.model);
    let sets = [
        set,
        data::uncertain::corner_set(design, &nominal)?,
        data::uncertain::long_set(design, Some(last), long_samples)?,
    ];
    Ok(Some((
        Mismatch {
            names: design.model.uncertain.iter().map(|u| u.name.clone()).collect(),
            runs_per_corner: design.validation.trajectories,
            nominal,
            corners,
            scenario,
        },
        sets,
    )))
}

/// Simulates the tuning runs, tunes the EKF and the model-corrected map on them, and judges every
/// observer on the validation runs, the scenario and (with uncertain parameters) the mismatch runs.
pub fn compare(design: &Design, result: &DesignResult, code: &ModelCode) -> Result<Comparison, SpecError> {
    let tuning = data::tuning_set(design)?;
    let draws = data::scenario_draws(design)?;
    let horizon = design.map.horizon;
    let start_up = horizon - 1 + corrected::START_UP_HORIZONS * horizon;
    let window = design.validation.samples;
    let long_samples = start_up + Drift::WINDOWS * window;
    let mismatch = mismatch(design, long_samples)?;
    let long = data::uncertain::long_set(design, None, long_samples)?;
    let drift = |runs: &[Run], estimates: &[Rows], t: usize| Drift {
        first: errors(runs, estimates, t, |_| start_up..start_up + window).0,
        last: errors(runs, estimates, t, |_| long_samples - window..long_samples).0,
    };
    let targets = design.targets.len();
    // Each target's spread over the tuning runs normalises the tuning criteria: the tuning runs are the
    // only data any constant below is chosen on.
    let spreads: Vec<f64> = result
        .targets
        .iter()
        .map(|t| crate::fit::evaluate::evaluate(&tuning, t.index, &t.fit).target_spread)
        .collect();
    // The EKF from the box centre is tuned, as an expert tunes a filter for starts anywhere in the
    // box, on the random runs alone: the scenario's start is one the chip's `ekf()` does not know.
    // `auto` then judges it, as every kind, on all the tuning runs (its tail from the scenario's start).
    let random = DataSet {
        runs: tuning.runs[..design.tuning.trajectories].to_vec(),
        horizon: tuning.horizon,
    };
    let tuned = ekf::tune(design, code, &random, &result.learning, &spreads);
    let transient = (TRANSIENT_TIME / design.tau).round() as usize;
    let windows = |run: &Run| horizon - 1..run.targets.len();
    // One observer judged everywhere: `estimate(run, is_scenario)` is its estimate of every target
    // at every sample of `run` (a scenario's EKF starts from `scenario.observer_x0`).
    let judge = |kind: &'static str, instructions: f64, estimate: &dyn Fn(&Run, bool) -> Rows| -> ObserverFigures {
        let validation: Vec<Rows> = result.validation.runs.iter().map(|r| estimate(r, false)).collect();
        let scenario = estimate(&result.scenario, true);
        let on_tuning: Vec<Rows> = tuning.runs.iter().map(|r| estimate(r, false)).collect();
        let on_draws: Option<Vec<Rows>> = draws
            .as_ref()
            .map(|d| d.runs.iter().map(|r| estimate(r, true)).collect());
        let on = |set: &DataSet| -> Vec<Rows> { set.runs.iter().map(|r| estimate(r, false)).collect() };
        let on_mismatch: Option<[Vec<Rows>; 3]> = mismatch.as_ref().map(|(_, sets)| sets.each_ref().map(on));
        let on_long = on(&long);
        let one_scenario = std::slice::from_ref(&result.scenario);
        let on_scenario = std::slice::from_ref(&scenario);
        let targets = (0..targets)
            .map(|t| {
                let (rmse_validation, max_error_validation) = errors(&result.validation.runs, &validation, t, windows);
                let (rmse_mismatch, rmse_corners, rmse_nominal, drift_mismatch) = match (&mismatch, &on_mismatch) {
                    (Some((m, [set, nominal, long])), Some([estimates, on_nominal, on_long])) => (
                        Some(errors(&set.runs, estimates, t, windows).0),
                        set.runs
                            .chunks(m.runs_per_corner)
                            .zip(estimates.chunks(m.runs_per_corner))
                            .map(|(runs, estimates)| errors(runs, estimates, t, windows).0)
                            .collect(),
                        Some(errors(&nominal.runs, on_nominal, t, windows).0),
                        Some(drift(&long.runs, on_long, t)),
                    ),
                    _ => (None, Vec::new(), None, None),
                };
                let p95 = |runs: &[Run], estimates: &[Rows]| {
                    score::percentile_95(&score::per_run_rmse(runs, estimates, t, windows))
                };
                Figures {
                    rmse_validation,
                    max_error_validation,
                    p95_validation: p95(&result.validation.runs, &validation),
                    p95_tuning: p95(&tuning.runs, &on_tuning),
                    rmse_scenario: errors(one_scenario, on_scenario, t, windows).0,
                    rmse_transient: errors(one_scenario, on_scenario, t, |run| {
                        horizon - 1..horizon.saturating_add(transient).min(run.targets.len())
                    })
                    .0,
                    rmse_tuning: errors(&tuning.runs, &on_tuning, t, windows).0,
                    scenario_draws: draws
                        .as_ref()
                        .zip(on_draws.as_ref())
                        .map(|(d, on)| (errors(&d.runs, on, t, windows).0, p95(&d.runs, on))),
                    rmse_mismatch,
                    rmse_corners,
                    rmse_nominal,
                    drift: drift(&long.runs, &on_long, t),
                    drift_mismatch,
                }
            })
            .collect();
        ObserverFigures {
            kind,
            instructions,
            targets,
            mismatch_scenario: mismatch.as_ref().map(|(m, _)| estimate(&m.scenario, true)),
            scenario,
        }
    };
    let maps: Vec<&crate::fit::maps::FittedMap> = result.targets.iter().map(|t| &t.fit.map).collect();
    let map_cost = cost::of_maps(&maps, horizon, design.tau);
    let mut observers = vec![judge("map", map_cost.instructions, &|run, _| {
        map_estimates(result, horizon, run)
    })];
    let mut ekf_from_observer_x0 = None;
    if let Some(tuned) = &tuned {
        // From the box centre everywhere, the scenario included: where `ekf()` starts on the chip.
        let centre = ekf::box_centre(design);
        let filter = crate::plant::kalman::filter_code(code, &tuned.constants);
        observers.push(judge("ekf_box", cost::of_ekf(&filter), &|run, _| {
            ekf::estimate_run(code, &tuned.constants, &centre, run).expect("size checked by tune")
        }));
        // The paper's comparison: the same filter from the scenario's `observer_x0`.
        if let Some(x0) = design.scenario.as_ref().and_then(|s| s.observer_x0.clone()) {
            let rows = ekf::estimate_run(code, &tuned.constants, &x0, &result.scenario).expect("size checked by tune");
            let one = std::slice::from_ref(&result.scenario);
            let rmse = (0..targets)
                .map(|t| errors(one, std::slice::from_ref(&rows), t, windows).0)
                .collect();
            ekf_from_observer_x0 = Some((x0, rmse));
        }
    }
    let corrected = corrected::state_targets(design).map(|state_targets| {
        let setting = corrected::Setting::for_design(design, result, code, &state_targets);
        let maps: Vec<Rows> = tuning.runs.iter().map(|r| map_estimates(result, horizon, r)).collect();
        let tuned = corrected::tune(&setting, &tuning, &maps, &spreads);
        let programs = crate::plant::correction::correction_code(code, &tuned.constants);
        observers.push(judge(
            "corrected",
            cost::of_corrected(&programs, &map_cost),
            &|run, _| {
                corrected::estimate_rows(
                    &setting,
                    &programs,
                    &tuned.constants,
                    &map_estimates(result, horizon, run),
                    run,
                )
            },
        ));
        tuned
    });
    let started = match (&tuned, corrected::state_targets(design)) {
        (Some(tuned), Ok(state_targets)) => {
            let map = &observers[0].targets;
            let squared: Vec<f64> = state_targets.iter().map(|&t| map[t].rmse_tuning.powi(2)).collect();
            let filter = crate::plant::kalman::filter_code(code, &tuned.constants);
            let run_started = |p0: &[f64], run: &Run| -> Rows {
                let map: Vec<Vec<f64>> = map_estimates(result, horizon, run)
                    .iter()
                    .map(<[f64]>::to_vec)
                    .collect();
                Rows::from(ekf::estimate_started(
                    &filter,
                    p0,
                    &state_targets,
                    horizon - 1,
                    &map,
                    run,
                    code,
                ))
            };
            let scaled = |c: f64| -> Vec<f64> { squared.iter().map(|e| c * e).collect() };
            let (factor, _) = ekf::tune_started(|c| {
                let p0 = scaled(c);
                let estimates: Vec<Rows> = tuning.runs.iter().map(|run| run_started(&p0, run)).collect();
                score::of_estimates(&tuning.runs, &estimates, &spreads, windows)
            });
            let p0 = scaled(factor);
            observers.push(judge("ekf_map", cost::of_started(&filter), &|run, _| {
                run_started(&p0, run)
            }));
            Some((
                Started {
                    p0,
                    factor,
                    state_targets,
                },
                squared,
            ))
        }
        _ => None,
    };
    // The box-started EKF checked once against the map, restarted from it as `ekf_map` starts.
    let restart = match (&tuned, &started) {
        (Some(tuned), Some((started, squared))) => {
            let filter = crate::plant::kalman::filter_code(code, &tuned.constants);
            let run_restarted = |constants: &restart::RestartConstants, run: &Run| -> Rows {
                let map: Vec<Vec<f64>> = map_estimates(result, horizon, run)
                    .iter()
                    .map(<[f64]>::to_vec)
                    .collect();
                Rows::from(restart::estimate(
                    &filter,
                    &tuned.constants,
                    &started.p0,
                    constants,
                    &started.state_targets,
                    &map,
                    run,
                    code,
                ))
            };
            let with = |threshold: f64| restart::RestartConstants {
                threshold,
                variances: squared.clone(),
            };
            let (threshold, _) = restart::tune(|t| {
                let constants = with(t);
                let estimates: Vec<Rows> = tuning.runs.iter().map(|run| run_restarted(&constants, run)).collect();
                score::of_estimates(&tuning.runs, &estimates, &spreads, windows)
            });
            let constants = with(threshold);
            observers.push(judge("ekf_restart", cost::of_restarted(&filter), &|run, _| {
                run_restarted(&constants, run)
            }));
            Some(constants)
        }
        _ => None,
    };
    let started = started.map(|(started, _)| started);
    let chosen = choose(design, &observers, &spreads)?;
    Ok(Comparison {
        observers,
        started,
        restart,
        chosen,
        ekf: tuned,
        corrected,
        chip_model_error: chip_model_error(design, result),
        ekf_from_observer_x0,
        tuning,
        mismatch: mismatch.map(|(m, _)| m),
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
