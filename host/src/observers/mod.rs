//! Every observer of a design judged on the same data: the fitted map and its peer, an extended Kalman
//! filter over the model ([`ekf`]), each target's error on the validation runs, the scenario (whole,
//! and its transient) and the tuning runs. The EKF's constants are chosen on the tuning runs only; the
//! map's were fitted on the learning runs only, so the validation and scenario figures are on data
//! neither saw.

pub mod corrected;
pub mod ekf;
pub mod recorded;
pub mod restart;
pub mod score;
pub mod started;

use crate::data::{self, DataSet, Rows, Run};
use crate::fit::DesignResult;
use crate::plant::ModelCode;
use crate::search::cost;
use crate::spec::{Design, ObserverKind, SpecError};

/// Errors of one observer on one target.
#[derive(Clone, Debug, PartialEq)]
pub struct Figures {
    /// RMSE over the validation windows.
    pub rmse_validation: f64,
    /// Largest |error| over the validation windows.
    pub max_error_validation: f64,
    /// The 95th percentile over validation runs of each run's RMSE ([`score::percentile_95`]).
    pub p95_validation: f64,
    /// RMSE over the scenario's windows.
    pub rmse_scenario: f64,
    /// RMSE over the scenario's first [`TRANSIENT_TIME`] time units after the map's first estimate.
    pub rmse_transient: f64,
    /// RMSE over the windows of the scenario's noise draws (`data::scenario_draws`), and the 95th
    /// percentile over draws of each draw's RMSE; `None` without a scenario.
    pub scenario_draws: Option<(f64, f64)>,
    /// RMSE over the tuning runs' windows.
    pub rmse_tuning: f64,
    /// The 95th percentile over tuning runs of each run's RMSE.
    pub p95_tuning: f64,
    /// RMSE over the mismatch runs' windows: the validation runs replayed on plants at every corner of
    /// the box of the uncertain parameters (`data::uncertain::mismatch_set`); `None` when every
    /// parameter is known.
    pub rmse_mismatch: Option<f64>,
    /// The same per corner, in the order of [`Mismatch::corners`].
    pub rmse_corners: Vec<f64>,
    /// RMSE over the mismatch runs replayed on the nominal plant (the model's values), when
    /// parameters are uncertain (`rmse_validation` is then over plants drawn in the box).
    pub rmse_nominal: Option<f64>,
    /// Drift over long runs on the nominal plant ([`Drift`]).
    pub drift: Drift,
    /// The same on the plant at the last corner ([`Mismatch::scenario`]'s plant).
    pub drift_mismatch: Option<Drift>,
}

/// Whether an observer drifts: its RMSE over the first and the last window of
/// [`Drift::WINDOWS`] after the start-up (`START_UP_HORIZONS · N` estimates after the first, for every
/// kind), on long runs from their own seed (`data::uncertain::long_set`). A window is as long as a
/// validation run (`validation.samples`): 10 s and 60 s on Example 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drift {
    /// RMSE over the first window after the start-up.
    pub first: f64,
    /// RMSE over the last window.
    pub last: f64,
}

impl Drift {
    /// Windows after the start-up in a long run.
    pub const WINDOWS: usize = 6;
}

/// Length of the transient judged, in the spec's time unit, from the first window.
pub const TRANSIENT_TIME: f64 = 2.0;

/// One observer's figures, per target in spec order, and its estimates along the scenarios.
#[derive(Clone, Debug)]
pub struct ObserverFigures {
    /// [`ObserverKind::name`]: `"map"`, `"ekf_box"` (from the box centre), `"corrected"`,
    /// `"ekf_map"` (started by the map) or `"ekf_restart"` (from the box centre, restarted by the map).
    pub kind: &'static str,
    /// Predicted instructions per sample on the chip in steady state ([`crate::search::cost`]).
    pub instructions: f64,
    /// Per target.
    pub targets: Vec<Figures>,
    /// Its estimate of every target at every sample of the scenario (NaN before its first).
    pub scenario: Rows,
    /// The same along [`Mismatch::scenario`], when parameters are uncertain.
    pub mismatch_scenario: Option<Rows>,
}

/// The plants an observer with uncertain parameters is judged on besides the nominal one.
#[derive(Clone, Debug)]
pub struct Mismatch {
    /// Every corner of the box of the uncertain parameters (`data::uncertain::corners`), the
    /// parameters in the order of `Model::uncertain`.
    pub corners: Vec<Vec<f64>>,
    /// The names of the uncertain parameters, in that order.
    pub names: Vec<String>,
    /// Runs per corner (the validation set's count).
    pub runs_per_corner: usize,
    /// The nominal values of the uncertain parameters.
    pub nominal: Vec<f64>,
    /// The scenario (its initial state, inputs and noise) on the plant at the last corner, every
    /// uncertain parameter at its `max`.
    pub scenario: Run,
}

/// The EKF started by the map at `k = N − 1`, sharing the EKF's `Q` and `R`.
#[derive(Clone, Debug)]
pub struct Started {
    /// `P(N−1)` diagonal: `factor` times the map's mean squared error per state on the tuning runs.
    pub p0: Vec<f64>,
    /// The factor, chosen on the tuning runs ([`ekf::tune_started`]).
    pub factor: f64,
    /// Each state's target.
    pub state_targets: Vec<usize>,
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
    /// The EKF started by the map; `None` without an EKF or the full state.
    pub started: Option<Started>,
    /// The box-started EKF's check against the map ([`restart`]); `None` without `started`.
    pub restart: Option<restart::RestartConstants>,
    /// What `observer()` is, and why.
    pub chosen: (ObserverKind, String),
    /// The EKF from the box centre started instead at the scenario's `observer_x0` (the paper's
    /// `x̂(0)`): that start, and its RMSE per target over the scenario's windows.
    pub ekf_from_observer_x0: Option<(Vec<f64>, Vec<f64>)>,
    /// The tuning runs.
    pub tuning: DataSet,
    /// The mismatch plants, when parameters are uncertain.
    pub mismatch: Option<Mismatch>,
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

/// A kind's [score](score::score) on the tuning runs.
fn tuning_score(figures: &ObserverFigures, spreads: &[f64]) -> f64 {
    let pooled: Vec<f64> = figures.targets.iter().map(|f| f.rmse_tuning).collect();
    let p95: Vec<f64> = figures.targets.iter().map(|f| f.p95_tuning).collect();
    score::score(&pooled, &p95, spreads)
}

/// The kinds `observer()` may be; each names its row in [`Comparison::observers`]
/// ([`ObserverKind::name`]).
pub const KINDS: [ObserverKind; 5] = [
    ObserverKind::Map,
    ObserverKind::Corrected,
    ObserverKind::EkfBox,
    ObserverKind::EkfMap,
    ObserverKind::EkfRestart,
];

/// The name of `kind`'s row in [`Comparison::observers`] (`Auto` is not a kind a design has: `map`).
pub fn row_name(kind: ObserverKind) -> &'static str {
    match kind {
        ObserverKind::Auto => "map",
        other => other.name(),
    }
}

/// How much worse than the best a cheaper kind's score may be and still be chosen by `auto`.
pub const CHEAPER_WITHIN: f64 = 0.02;

/// What [`choose`] would refuse of the spec's `observer.kind` that is known before anything is fitted,
/// refused before the fit rather than minutes after it: a kind the map starts or checks while a state
/// is not a target, an EKF kind of a model beyond the sizes the host filters, and an EKF kind whose
/// predicted instructions exceed `budget.instructions`. The EKF's count depends on the model alone:
/// its tuned constants are all non-zero numbers written into the program, any such ones give it
/// (the map's and the corrected observer's counts need the fit, and are checked after it).
pub fn check_before_fit(design: &Design, code: &ModelCode) -> Result<(), SpecError> {
    let kind = design.observer;
    let ekf_kind = matches!(
        kind,
        ObserverKind::EkfBox | ObserverKind::EkfMap | ObserverKind::EkfRestart
    );
    let started = matches!(
        kind,
        ObserverKind::Corrected | ObserverKind::EkfMap | ObserverKind::EkfRestart
    );
    if (started && corrected::state_targets(design).is_err()) || (ekf_kind && !ekf::supported(code)) {
        return Err(cannot_have(design));
    }
    let Some(budget) = design.budget.instructions.filter(|_| ekf_kind) else {
        return Ok(());
    };
    let states = code.dimensions.states;
    let theta = vec![0.37f64.log10(); 2 * states];
    let constants = ekf::constants(design, &ekf::box_centre(design), &vec![1.0; states], &theta);
    let filter = crate::plant::kalman::filter_code(code, &constants);
    let instructions = match kind {
        ObserverKind::EkfBox => cost::of_ekf(&filter),
        ObserverKind::EkfMap => cost::of_started(&filter),
        _ => cost::of_restarted(&filter),
    };
    if instructions > budget as f64 {
        return Err(over_budget(design, kind.name(), instructions, budget as f64));
    }
    Ok(())
}

/// `observer.kind` names a kind the design cannot have.
fn cannot_have(design: &Design) -> SpecError {
    design.error(
        "observer.kind",
        format!(
            "the design cannot have a `{}` observer: it needs every state as a target and a model the host can filter",
            design.observer.name()
        ),
        "add a target per state (expr = the state's name), or set kind = \"map\" or \"auto\"",
    )
}

/// `observer.kind` names a kind over `budget.instructions`.
fn over_budget(design: &Design, name: &str, instructions: f64, budget: f64) -> SpecError {
    design.error(
        "observer.kind",
        format!(
            "the `{name}` observer needs ~{instructions:.0} instructions per sample, more than `budget.instructions` = {budget}"
        ),
        "raise `budget.instructions`, or set kind = \"auto\" to take the best kind within it",
    )
}

/// The kind `observer()` is: the spec's, or for `auto` the lowest [score](score::score) on the
/// tuning runs among the kinds within `[budget] instructions` (as [`cost`] predicts them), except
/// that the cheapest kind (fewest predicted instructions) within [`CHEAPER_WITHIN`] of the best is
/// preferred. Errors when the spec asks for a kind the design cannot have or the budget
/// does not allow.
pub fn choose(
    design: &Design,
    observers: &[ObserverFigures],
    spreads: &[f64],
) -> Result<(ObserverKind, String), SpecError> {
    let scored: Vec<(ObserverKind, &str, f64, f64)> = KINDS
        .iter()
        .map(|&kind| (kind, kind.name()))
        .filter_map(|(kind, name)| {
            observers
                .iter()
                .find(|o| o.kind == name)
                .map(|o| (kind, name, tuning_score(o, spreads), o.instructions))
        })
        .collect();
    let budget = design.budget.instructions.map(|b| b as f64);
    let within = |instructions: f64| budget.is_none_or(|b| instructions <= b);
    if design.observer != ObserverKind::Auto {
        return match scored.iter().find(|s| s.0 == design.observer) {
            Some(&(_, name, _, instructions)) if !within(instructions) => {
                Err(over_budget(design, name, instructions, budget.unwrap_or_default()))
            }
            Some(&(kind, name, score, instructions)) => Ok((
                kind,
                format!("`{name}` as the spec asks (tuning score {score:.4}, ~{instructions:.0} instructions)"),
            )),
            None => Err(cannot_have(design)),
        };
    }
    let allowed: Vec<&(ObserverKind, &str, f64, f64)> = scored.iter().filter(|s| within(s.3)).collect();
    let best = allowed.iter().map(|s| s.2).fold(f64::INFINITY, f64::min);
    let Some(&&(kind, name, _, _)) = allowed
        .iter()
        .filter(|s| s.2 <= best * (1.0 + CHEAPER_WITHIN))
        .min_by(|a, b| a.3.total_cmp(&b.3))
    else {
        return Err(design.error(
            "budget.instructions",
            format!(
                "no observer kind fits in {} instructions per sample (the map needs ~{:.0})",
                budget.unwrap_or_default(),
                scored.first().map_or(f64::NAN, |s| s.3)
            ),
            "raise `budget.instructions`, or shorten the map (`map.horizon`, `map.taps`)",
        ));
    };
    let all: Vec<String> = scored
        .iter()
        .map(|&(_, n, s, i)| {
            let over = if within(i) { "" } else { ", over budget" };
            format!("{n} {s:.4} at ~{i:.0} instructions{over}")
        })
        .collect();
    let limit = budget.map_or(String::new(), |b| format!(" within `budget.instructions` = {b}"));
    Ok((kind, format!("`{name}` by `auto`: the lowest tuning score (pooled RMSE + p95 over runs, per target over its spread; {}){limit}, a cheaper kind preferred within {:.0} %", all.join(", "), CHEAPER_WITHIN * 100.0)))
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
