//! The report of a design: `report.json` (everything, machine-readable), `report.md` (one table a
//! person reads) and the one-screen summary `gen` prints.

mod draw;
pub mod gates;
pub mod html;
pub mod on_target;
pub mod plots;
pub mod recorded;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::fit::evaluate::Evaluation;
use crate::fit::identify::Diagnostics;
use crate::fit::maps::FittedMap;
use crate::fit::DesignResult;
use crate::observers::Comparison;
use crate::output::write_atomically;
use crate::spec::{Design, MapSettings};

/// `report.json`.
#[derive(Serialize)]
pub struct Report<'a> {
    /// Design name.
    pub design: &'a str,
    /// What it is.
    pub description: &'a str,
    /// The spec file.
    pub spec: String,
    /// Version of the tool that wrote it.
    pub tool_version: &'static str,
    /// Sample period.
    pub tau: f64,
    /// Its unit.
    pub time_unit: &'a str,
    /// Samples per validation run (a drift window).
    pub validation_samples: usize,
    /// Map settings.
    pub map: &'a MapSettings,
    /// `n_z`.
    pub regressor_len: usize,
    /// Learning set.
    pub learning: SetSummary,
    /// Validation set.
    pub validation: SetSummary,
    /// One entry per target.
    pub targets: Vec<TargetReport<'a>>,
    /// Tuning runs (what the EKF's constants were chosen on; never reported as accuracy).
    pub tuning: SetSummary,
    /// Every observer on the same data: the map, then the EKF.
    pub observers: Vec<ObserverReport>,
    /// How the EKF was tuned, when the host could run one.
    pub ekf_tuning: Option<EkfTuning>,
    /// The EKF from the box centre started instead at the scenario's `observer_x0` (the paper's
    /// `x̂(0)`): that start, and its scenario RMSE per target in spec order.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ekf_from_observer_x0: Option<(Vec<f64>, Vec<f64>)>,
    /// How the model-corrected map was tuned, or why the design has none.
    pub corrected_tuning: CorrectedTuning,
    /// What the design's `observer()` is (`map`, `corrected` or `ekf`, the map-started EKF), and why.
    pub observer: (crate::spec::ObserverKind, String),
    /// The model on the chip against the learning simulation's.
    pub chip_model: ChipModel,
    /// The quality gates the design fails ([`gates`]), one sentence each; empty when it passes them all.
    pub quality_gates: Vec<String>,
    /// The plants of the `rmse_mismatch` figures, when parameters are uncertain.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mismatch: Option<MismatchReport>,
    /// The design search, when the spec asks for one (every candidate, the front, the choice).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub search: Option<&'a crate::search::Outcome>,
    /// Validation accuracy against the taps of `L` kept, when the spec prunes it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub taps: Option<&'a [crate::search::sparsity::Row]>,
}

/// One observer's figures.
#[derive(Serialize)]
pub struct ObserverReport {
    /// [`crate::spec::ObserverKind::name`]: `"map"`, `"corrected"`, `"ekf_box"`, `"ekf_map"`,
    /// `"ekf_restart"`.
    pub kind: &'static str,
    /// Per target name.
    pub targets: std::collections::BTreeMap<String, FiguresReport>,
    /// Measured on the emulated Cortex-M4F by `cargo run -p integration-tests --bin on-target-report`
    /// ([`on_target`]); `null` until the generated source written is measured.
    pub on_target: Option<on_target::OnTarget>,
}

/// [`crate::observers::Figures`] as serialised (NaN, where a filter diverged, as `null`).
#[derive(Serialize)]
pub struct FiguresReport {
    /// RMSE over the validation windows.
    pub rmse_validation: Option<f64>,
    /// Largest |error| there.
    pub max_error_validation: Option<f64>,
    /// The 95th percentile over validation runs of each run's RMSE (the tail the pooled RMSE hides).
    pub p95_validation: Option<f64>,
    /// RMSE over the scenario's windows (every observer from where it starts on the chip).
    pub rmse_scenario: Option<f64>,
    /// RMSE over the scenario's first 2 time units after the map's first estimate.
    pub rmse_transient: Option<f64>,
    /// RMSE over the scenario's noise draws (`data::scenario_draws`), when there is a scenario
    /// (`null` where a filter diverged).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rmse_scenario_draws: Option<Option<f64>>,
    /// The 95th percentile over those draws of each draw's RMSE.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub p95_scenario_draws: Option<Option<f64>>,
    /// RMSE over the tuning runs.
    pub rmse_tuning: Option<f64>,
    /// The 95th percentile over tuning runs of each run's RMSE.
    pub p95_tuning: Option<f64>,
    /// RMSE over the mismatch runs (every corner of the uncertain parameters' box; [`MismatchReport`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rmse_mismatch: Option<f64>,
    /// The same per corner, in the order of [`MismatchReport::corners`].
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub rmse_corners: Vec<Option<f64>>,
    /// RMSE over the mismatch runs replayed on the nominal plant (with uncertain parameters, whose
    /// `rmse_validation` is over plants drawn in the box).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rmse_nominal: Option<f64>,
    /// Drift over long runs on the nominal plant ([`crate::observers::Drift`]).
    pub drift: DriftReport,
    /// The same on the plant at the last corner of the uncertain parameters' box.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drift_mismatch: Option<DriftReport>,
}

/// [`crate::observers::Drift`] as serialised.
#[derive(Serialize)]
pub struct DriftReport {
    /// RMSE over the first window after the start-up.
    pub rmse_first: Option<f64>,
    /// RMSE over the last window of the long runs.
    pub rmse_last: Option<f64>,
}

/// What the mismatch figures are measured on.
#[derive(Serialize)]
pub struct MismatchReport {
    /// How the plants were chosen.
    pub plants: &'static str,
    /// The uncertain parameters.
    pub parameters: Vec<String>,
    /// Every corner, the parameters in that order.
    pub corners: Vec<Vec<f64>>,
    /// Runs per corner.
    pub runs_per_corner: usize,
    /// The nominal values (the model's), in the same order.
    pub nominal: Vec<f64>,
}

/// See [`MismatchReport::plants`].
pub const MISMATCH_PLANTS: &str = "the corners of the box of the uncertain parameters (not drawn): at each, the \
     validation set's number of runs from its own seed, the same initial states, inputs and noise at every corner";

/// The EKF's tuning ([`crate::observers::ekf`]).
#[derive(Serialize)]
pub struct EkfTuning {
    /// `log10(Q_ii / s_i²)` per state (`s_i`: the state's spread over the learning runs).
    pub log_q: Vec<f64>,
    /// `log10(P(0)_ii / s_i²)` per state.
    pub log_p0: Vec<f64>,
    /// The score on the tuning runs at the choice ([`crate::observers::score`]).
    pub cost: f64,
    /// The score at the best point of the isotropic grid the search started from.
    pub grid_cost: f64,
    /// Score evaluations (grid and Nelder–Mead).
    pub evaluations: u64,
    /// The tuning runs it was chosen on (those from random starts).
    pub runs: usize,
    /// The map-started EKF's start covariance over the map's mean squared error per state.
    pub started_factor: Option<f64>,
    /// `diag(Q)`.
    pub q_diagonal: Vec<f64>,
    /// `diag(P(0))`.
    pub p0_diagonal: Vec<f64>,
    /// `x̂(0)` (centre of the state box).
    pub x0: Vec<f64>,
}

/// The model-corrected map's tuning ([`crate::observers::corrected`]).
#[derive(Serialize)]
#[serde(untagged)]
pub enum CorrectedTuning {
    /// Tuned.
    Tuned {
        /// `G` per state, after the start-up.
        g: Vec<f64>,
        /// `K`, states × outputs, row by row.
        k: Vec<f64>,
        /// `K₀`: the start-up gain, falling to `K` on the blend's schedule.
        k_start: Vec<f64>,
        /// `T`: the start-up blend's time constant, in estimates.
        schedule: f64,
        /// `J`: estimates that take the start-up blend.
        start_up: usize,
        /// Each state's clamp (its map's range), lower ends.
        lower: Vec<f64>,
        /// Upper ends.
        upper: Vec<f64>,
        /// Mean normalised RMSE on the tuning runs at the choice.
        cost: f64,
        /// The same at the best of the search's starts.
        start_cost: f64,
        /// Criterion evaluations (Nelder–Mead, every start).
        evaluations: u64,
        /// The best criterion with `G` free, and with `G = 0` (no map after the start-up).
        cost_with_and_without_map: (f64, f64),
    },
    /// Not available.
    Unavailable {
        /// Why.
        unavailable: String,
    },
}

/// The chip's model against the simulation's.
#[derive(Serialize)]
pub struct ChipModel {
    /// RK4 steps per sample on the chip.
    pub chip_substeps: usize,
    /// RK4 steps per sample of the learning simulation.
    pub simulation_substeps: usize,
    /// Per state: largest one-sample difference of the two over the validation states, relative to
    /// the state's spread.
    pub max_step_difference_relative: Vec<f64>,
}

/// Size of a data set.
#[derive(Serialize)]
pub struct SetSummary {
    /// Simulated runs.
    pub runs: usize,
    /// Windows (`n_E` for the learning set).
    pub windows: usize,
    /// Seed.
    pub seed: u64,
}

/// One target's figures.
#[derive(Serialize)]
pub struct TargetReport<'a> {
    /// Name.
    pub name: &'a str,
    /// `g(x)`.
    pub expr: &'a str,
    /// RMSE of the map on the learning windows.
    pub rmse_learning: f64,
    /// RMSE of the map on the validation windows.
    pub rmse_validation: f64,
    /// Largest error on the validation windows (empirical `ε_x`).
    pub max_error_validation: f64,
    /// Fraction of validation windows where `Γ⁻¹` saturated.
    pub saturated_fraction_validation: f64,
    /// The linear floor on the same windows.
    pub linear: LinearReport,
    /// `rmse_validation / linear.rmse_validation` (below 1: the map beats the floor).
    pub ratio_to_linear_validation: f64,
    /// How the QP went.
    pub qp: &'a Diagnostics,
    /// The fitted map.
    pub fitted: &'a FittedMap,
}

/// The linear floor's figures.
#[derive(Serialize)]
pub struct LinearReport {
    /// RMSE on the learning windows.
    pub rmse_learning: f64,
    /// RMSE on the validation windows.
    pub rmse_validation: f64,
    /// Largest error on the validation windows.
    pub max_error_validation: f64,
}

/// Assembles the report of a run.
pub fn report<'a>(design: &'a Design, result: &'a DesignResult, comparison: &'a Comparison) -> Report<'a> {
    let finite = |v: f64| v.is_finite().then_some(v);
    let drift = |d: crate::observers::Drift| DriftReport {
        rmse_first: finite(d.first),
        rmse_last: finite(d.last),
    };
    let summary = |set: &crate::data::DataSet, seed| SetSummary {
        runs: set.runs.len(),
        windows: set.window_count(),
        seed,
    };
    Report {
        design: &design.name,
        description: &design.description,
        spec: design.file.display().to_string(),
        tool_version: env!("CARGO_PKG_VERSION"),
        tau: design.tau,
        time_unit: &design.time_unit,
        validation_samples: design.validation.samples,
        map: &design.map,
        regressor_len: result.learning.regressor_len(),
        learning: summary(&result.learning, design.learning.seed),
        validation: summary(&result.validation, design.validation.seed),
        targets: result
            .targets
            .iter()
            .map(|t| {
                let (learning, validation): (&Evaluation, &Evaluation) = (&t.learning, &t.validation);
                TargetReport {
                    name: &design.targets[t.index].name,
                    expr: design.targets[t.index].expr.text(),
                    rmse_learning: learning.map.rmse,
                    rmse_validation: validation.map.rmse,
                    max_error_validation: validation.map.max_error,
                    saturated_fraction_validation: validation.saturated_fraction,
                    linear: LinearReport {
                        rmse_learning: learning.linear.rmse,
                        rmse_validation: validation.linear.rmse,
                        max_error_validation: validation.linear.max_error,
                    },
                    ratio_to_linear_validation: validation.map.rmse / validation.linear.rmse,
                    qp: &t.fit.diagnostics,
                    fitted: &t.fit.map,
                }
            })
            .collect(),
        tuning: summary(&comparison.tuning, design.tuning.seed),
        observers: comparison
            .observers
            .iter()
            .map(|o| ObserverReport {
                kind: o.kind,
                targets: design
                    .targets
                    .iter()
                    .zip(&o.targets)
                    .map(|(t, f)| {
                        (
                            t.name.clone(),
                            FiguresReport {
                                rmse_validation: finite(f.rmse_validation),
                                max_error_validation: finite(f.max_error_validation),
                                p95_validation: finite(f.p95_validation),
                                rmse_scenario: finite(f.rmse_scenario),
                                rmse_transient: finite(f.rmse_transient),
                                rmse_scenario_draws: f.scenario_draws.map(|d| finite(d.0)),
                                p95_scenario_draws: f.scenario_draws.map(|d| finite(d.1)),
                                rmse_tuning: finite(f.rmse_tuning),
                                p95_tuning: finite(f.p95_tuning),
                                rmse_mismatch: f.rmse_mismatch.and_then(finite),
                                rmse_corners: f.rmse_corners.iter().map(|&v| finite(v)).collect(),
                                rmse_nominal: f.rmse_nominal.and_then(finite),
                                drift: drift(f.drift),
                                drift_mismatch: f.drift_mismatch.map(drift),
                            },
                        )
                    })
                    .collect(),
                on_target: None,
            })
            .collect(),
        ekf_tuning: comparison.ekf.as_ref().map(|t| EkfTuning {
            log_q: t.log_q.clone(),
            log_p0: t.log_p0.clone(),
            cost: t.cost,
            grid_cost: t.grid_cost,
            evaluations: t.evaluations,
            runs: t.runs,
            started_factor: comparison.started.as_ref().map(|s| s.factor),
            q_diagonal: t.constants.q.clone(),
            p0_diagonal: t.constants.p0.clone(),
            x0: t.constants.x0.clone(),
        }),
        ekf_from_observer_x0: comparison.ekf_from_observer_x0.clone(),
        observer: comparison.chosen.clone(),
        corrected_tuning: match &comparison.corrected {
            Ok(t) => CorrectedTuning::Tuned {
                g: t.constants.g.clone(),
                k: t.constants.k.clone(),
                k_start: t.constants.k_start.clone(),
                schedule: t.constants.schedule,
                start_up: t.constants.start_up,
                lower: t.constants.lower.clone(),
                upper: t.constants.upper.clone(),
                cost: t.cost,
                start_cost: t.start_cost,
                evaluations: t.evaluations,
                cost_with_and_without_map: (t.cost_with_map, t.cost_without_map),
            },
            Err(why) => CorrectedTuning::Unavailable {
                unavailable: why.clone(),
            },
        },
        chip_model: ChipModel {
            chip_substeps: design.chip_substeps,
            simulation_substeps: design.substeps,
            max_step_difference_relative: comparison.chip_model_error.clone(),
        },
        quality_gates: gates::check(design, result, comparison)
            .iter()
            .map(ToString::to_string)
            .collect(),
        mismatch: comparison.mismatch.as_ref().map(|m| MismatchReport {
            plants: MISMATCH_PLANTS,
            parameters: m.names.clone(),
            corners: m.corners.clone(),
            runs_per_corner: m.runs_per_corner,
            nominal: m.nominal.clone(),
        }),
        search: None,
        taps: None,
    }
}

/// An observer's figures per target, in the spec's order of targets (`report.json` keys them by name).
fn in_spec_order<'r>(
    report: &'r Report<'_>,
    o: &'r ObserverReport,
) -> impl Iterator<Item = (&'r String, &'r FiguresReport)> {
    report.targets.iter().filter_map(|t| o.targets.get_key_value(t.name))
}

/// A figure in the report's tables: four decimals (scientific from 10⁴ on, where a filter ran away),
/// or "diverged" where it is not finite.
fn show(v: Option<f64>) -> String {
    match v {
        None => "diverged".to_owned(),
        Some(v) if v.abs() >= 1e4 => format!("{v:.3e}"),
        Some(v) => format!("{v:.4}"),
    }
}

/// The observers side by side (Markdown), and per figure a sentence naming the better one.
pub fn observers_table(report: &Report<'_>) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "| observer | target | RMSE validation | p95 validation | max error validation | RMSE scenario | RMSE transient | RMSE tuning | p95 tuning |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|");
    for o in &report.observers {
        for (name, f) in in_spec_order(report, o) {
            let _ = writeln!(
                s,
                "| {} | {name} | {} | {} | {} | {} | {} | {} | {} |",
                o.kind,
                show(f.rmse_validation),
                show(f.p95_validation),
                show(f.max_error_validation),
                show(f.rmse_scenario),
                show(f.rmse_transient),
                show(f.rmse_tuning),
                show(f.p95_tuning)
            );
        }
    }
    let draws = report
        .observers
        .iter()
        .any(|o| o.targets.values().any(|f| f.rmse_scenario_draws.is_some()));
    if draws {
        let _ = writeln!(
            s,
            "\nFrom the scenario's initial state, over {} noise draws of it (every observer from where it starts on the chip):\n",
            crate::data::SCENARIO_DRAWS
        );
        let _ = writeln!(s, "| observer | target | RMSE | p95 |");
        let _ = writeln!(s, "|---|---|---|---|");
        for o in &report.observers {
            for (name, f) in in_spec_order(report, o) {
                let _ = writeln!(
                    s,
                    "| {} | {name} | {} | {} |",
                    o.kind,
                    show(f.rmse_scenario_draws.flatten()),
                    show(f.p95_scenario_draws.flatten())
                );
            }
        }
    }
    if let Some(m) = &report.mismatch {
        s.push_str(&mismatch_table(report, m));
    }
    s.push_str(&drift_table(report));
    let _ = writeln!(s, "\n`observer()` is {:?}: {}.", report.observer.0, report.observer.1);
    if let CorrectedTuning::Unavailable { unavailable } = &report.corrected_tuning {
        let _ = writeln!(s, "\nNo model-corrected map: {unavailable}.");
    }
    if report.observers.len() < 2 {
        let _ = writeln!(s, "\nNo EKF: the model is beyond the sizes the host runs one for.");
        return s;
    }
    type Pick = fn(&FiguresReport) -> Option<f64>;
    let figures: [(&str, Pick); 7] = [
        ("validation RMSE", |f| f.rmse_validation),
        ("validation p95 (per-run RMSE)", |f| f.p95_validation),
        ("scenario draws RMSE", |f| f.rmse_scenario_draws.flatten()),
        ("scenario draws p95", |f| f.p95_scenario_draws.flatten()),
        ("validation max error", |f| f.max_error_validation),
        ("scenario RMSE", |f| f.rmse_scenario),
        ("transient RMSE", |f| f.rmse_transient),
    ];
    let _ = writeln!(s);
    for (label, pick) in figures {
        if label.starts_with("scenario draws") && !draws {
            continue;
        }
        let mut verdicts = Vec::new();
        for name in report.targets.iter().map(|t| t.name) {
            let best = report
                .observers
                .iter()
                .filter_map(|o| pick(&o.targets[name]).map(|v| (o.kind, v)))
                .min_by(|a, b| a.1.total_cmp(&b.1));
            verdicts.push(match best {
                Some((kind, _)) => format!("{kind} for {name}"),
                None => format!("neither for {name} (both diverged)"),
            });
        }
        let _ = writeln!(s, "Better on {label}: {}.", verdicts.join(", "));
    }
    s
}

/// Every observer's drift over long runs (Markdown).
fn drift_table(report: &Report<'_>) -> String {
    let long = crate::observers::Drift::WINDOWS * report.validation_samples;
    let time = |samples: usize| crate::recording::time_text(samples, report.tau);
    let mut s = format!(
        "\nDrift: RMSE over the first and the last {} {} of {} {} after the start-up (3N estimates after the first), on {} long runs from their own seed{}:\n\n\
         | observer | target | first | last | last / first |{}\n|---|---|---|---|---|{}\n",
        time(report.validation_samples),
        report.time_unit,
        time(long),
        report.time_unit,
        report.validation.runs,
        if report.mismatch.is_some() { "; then on the plant at the last corner" } else { "" },
        if report.mismatch.is_some() { " first (last corner) | last (last corner) | last / first |" } else { "" },
        if report.mismatch.is_some() { "---|---|---|" } else { "" },
    );
    let ratio = |d: &DriftReport| match (d.rmse_first, d.rmse_last) {
        (Some(a), Some(b)) => format!("{:.2}", b / a),
        _ => "—".to_owned(),
    };
    for o in &report.observers {
        for (name, f) in in_spec_order(report, o) {
            let _ = write!(
                s,
                "| {} | {name} | {} | {} | {} |",
                o.kind,
                show(f.drift.rmse_first),
                show(f.drift.rmse_last),
                ratio(&f.drift)
            );
            if let Some(d) = &f.drift_mismatch {
                let _ = write!(s, " {} | {} | {} |", show(d.rmse_first), show(d.rmse_last), ratio(d));
            }
            s.push('\n');
        }
    }
    s
}

/// Every observer on the plants of the uncertain parameters' corners (Markdown).
fn mismatch_table(report: &Report<'_>, m: &MismatchReport) -> String {
    let corner = |c: &[f64]| {
        m.parameters
            .iter()
            .zip(c)
            .map(|(name, v)| format!("{name} = {v}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut s = format!(
        "\nWith the model's parameters wrong (the plant at {}, {} runs each; the observers keep the nominal model):\n\n\
         | observer | target | RMSE validation (drawn plants) | nominal plant ({}) | RMSE mismatch (all corners) | {} |\n|---|---|---|---|---|{}\n",
        MISMATCH_PLANTS.split(':').next().unwrap_or(MISMATCH_PLANTS),
        m.runs_per_corner,
        corner(&m.nominal),
        m.corners.iter().map(|c| corner(c)).collect::<Vec<_>>().join(" | "),
        "---|".repeat(m.corners.len()),
    );
    for o in &report.observers {
        for (name, f) in in_spec_order(report, o) {
            let corners: Vec<String> = f.rmse_corners.iter().map(|&v| show(v)).collect();
            let _ = writeln!(
                s,
                "| {} | {name} | {} | {} | {} | {} |",
                o.kind,
                show(f.rmse_validation),
                show(f.rmse_nominal),
                show(f.rmse_mismatch),
                corners.join(" | ")
            );
        }
    }
    s
}

/// The table shared by `report.md` and the terminal summary.
pub fn table(report: &Report<'_>) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "| target | RMSE learning | RMSE validation | max error validation | linear RMSE validation | ratio | saturated | QP status | iterations | active / constraints | collapsed | Γ⁻¹ segments | proven table error |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for t in &report.targets {
        let _ = writeln!(
            s,
            "| {} | {:.4} | {:.4} | {:.4} | {:.4} | {:.3} | {:.1} % | {:?} | {} | {} / {} | {} | {} | {} |",
            t.name,
            t.rmse_learning,
            t.rmse_validation,
            t.max_error_validation,
            t.linear.rmse_validation,
            t.ratio_to_linear_validation,
            100.0 * t.saturated_fraction_validation,
            t.qp.status,
            t.qp.iterations,
            t.qp.active_constraints,
            t.qp.constraints,
            if t.qp.collapsed { "yes" } else { "no" },
            t.fitted
                .table
                .as_ref()
                .map_or("none (not emittable)".to_owned(), |t| format!(
                    "{} {}",
                    t.segments.len(),
                    t.knots_kind()
                )),
            t.fitted
                .table
                .as_ref()
                .map_or("—".to_owned(), |t| format!("{:.1e}", t.proven_bound))
        );
    }
    s
}

/// The design search's Pareto front as a Markdown table, with what was searched and how it was judged.
pub fn search_table(outcome: &crate::search::Outcome, time_unit: &str) -> String {
    let fitted = outcome.candidates.iter().filter(|c| c.score.is_some()).count();
    let budget = &outcome.budget;
    let limits: Vec<String> = [
        budget.instructions.map(|b| format!("{b} instructions")),
        budget
            .first_estimate
            .map(|b| format!("first estimate within {b} {time_unit}")),
        budget.flash.map(|b| format!("{b} B of flash")),
    ]
    .into_iter()
    .flatten()
    .collect();
    let sparse = outcome.candidates.iter().any(|c| c.taps < c.regressor_len);
    let mut s = format!(
        "{} candidates (N, n_m, β{}), {fitted} fitted in {:.1} s, each scored on the same {} tuning windows (mean RMSE / spread of the map; \
         never on validation); budget: {}. The front: no other candidate is better on score, predicted instructions and delay to the \
         first estimate at once; the chosen one is the best score within budget, the fewest instructions preferred within 2 %. \
         Costs are predicted (`search::cost`, checked against the emulated chip on the shipped designs). Figure: `search`.\n\n",
        outcome.candidates.len(),
        if sparse { ", taps" } else { "" },
        outcome.seconds,
        outcome.windows,
        if limits.is_empty() { "none".to_owned() } else { limits.join(", ") }
    );
    let (taps_head, taps_rule) = if sparse {
        (" taps per target |", "---|")
    } else {
        ("", "")
    };
    s.push_str(&format!(
        "| N | n_m | β |{taps_head} tuning score | instructions | first estimate [{time_unit}] | flash [B] | within budget | |\n|---|---|---|{taps_rule}---|---|---|---|---|---|\n"
    ));
    for c in outcome.front() {
        let cost = c.cost.expect("a front candidate has a cost");
        let taps = if sparse {
            format!(" {}/{} |", c.taps, c.regressor_len)
        } else {
            String::new()
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} |{taps} {:.4} | {:.0} | {} | {:.0} | {} | {} |",
            c.horizon,
            c.nm,
            c.beta,
            c.score.expect("a front candidate is scored"),
            cost.instructions,
            crate::search::short(cost.first_estimate),
            cost.flash,
            if c.within_budget { "yes" } else { "no" },
            if std::ptr::eq(c, outcome.chosen()) {
                "**chosen**"
            } else {
                ""
            }
        );
    }
    s
}

/// Validation accuracy against the taps of `L` kept, as a Markdown table.
pub fn taps_table(rows: &[crate::search::sparsity::Row], targets: &[&str]) -> String {
    let mut s = format!(
        "N = {}·(outputs + inputs) gives {} taps per target; `L` pruned by backward elimination (`fit::identify::prune`), refitted at \
         every count and judged on the validation runs (tables sketched, not certified: within 10⁻³ of the emitted figures). \
         Instructions are predicted (`search::cost`).\n\n| taps per target | instructions |",
        rows.first().map_or(0, |r| r.regressor_len),
        rows.first().map_or(0, |r| r.regressor_len),
    );
    for t in targets {
        let _ = write!(s, " RMSE {t} |");
    }
    s.push_str(" |\n|---|---|");
    for _ in targets {
        s.push_str("---|");
    }
    s.push_str("---|\n");
    for row in rows {
        let _ = write!(s, "| {}/{} | {:.0} |", row.taps, row.regressor_len, row.instructions);
        for rmse in &row.rmse {
            let _ = write!(s, " {rmse:.4} |");
        }
        let _ = writeln!(s, " {} |", if row.chosen { "**chosen**" } else { "" });
    }
    s
}

/// `report.md`.
pub fn markdown(report: &Report<'_>) -> String {
    // The description as text: nothing in it is Markdown or HTML of the report's (or its HTML page's).
    let mut s = format!(
        "# {}\n\n{}\n\n",
        report.design,
        crate::emit::doc_prose(report.description)
    );
    let m = report.map;
    let _ = writeln!(
        s,
        "Spec `{}`. τ = {}, N = {}, n_m = {}, β = {}, ε = {}, normalisation `{:?}`, n_z = {}. \
         Learning: {} runs, n_E = {} windows. Validation: {} fresh runs, {} windows.\n",
        report.spec,
        report.tau,
        m.horizon,
        m.nm,
        m.beta,
        m.epsilon,
        m.normalisation,
        report.regressor_len,
        report.learning.runs,
        report.learning.windows,
        report.validation.runs,
        report.validation.windows
    );
    s.push_str(&table(report));
    if report.quality_gates.is_empty() {
        s.push_str("\nQuality gates (linear floor, learning range, observability, EKF): all passed.\n");
    } else {
        s.push_str("\n**Quality gates failed** (`gen` warns, `gen --strict` refuses):\n\n");
        for gate in &report.quality_gates {
            let _ = writeln!(s, "- {gate}");
        }
    }
    if let Some(search) = report.search {
        s.push_str("\n## Design search\n\n");
        s.push_str(&search_table(search, report.time_unit));
    }
    if let Some(rows) = report.taps {
        s.push_str("\n## Sparse L: accuracy against taps\n\n");
        let names: Vec<&str> = report.targets.iter().map(|t| t.name).collect();
        s.push_str(&taps_table(rows, &names));
    }
    s.push_str("\n## Observers on the same data\n\n");
    s.push_str(&observers_table(report));
    if let Some(t) = &report.ekf_tuning {
        let _ = writeln!(
            s,
            "\nEKF: the firmware's filter over the model emitted as Rust ({} RK4 step(s) per sample on the chip, {} in the learning simulation; \
             largest one-sample difference between the two over the validation states, relative to each state's spread: {}), \
             starting at the centre of the state box; Q = diag({}), P(0) = diag({}), each value per state chosen on the {} tuning runs from random starts, which no figure above but \
             *RMSE tuning* and *p95 tuning* uses (score {:.4} at an isotropic grid's best point, {:.4} after Nelder–Mead; {} evaluations){}.",
            report.chip_model.chip_substeps,
            report.chip_model.simulation_substeps,
            report.chip_model.max_step_difference_relative.iter().map(|v| format!("{v:.1e}")).collect::<Vec<_>>().join(", "),
            t.q_diagonal.iter().map(|v| format!("{v:.3e}")).collect::<Vec<_>>().join(", "),
            t.p0_diagonal.iter().map(|v| format!("{v:.3e}")).collect::<Vec<_>>().join(", "),
            t.runs,
            t.grid_cost,
            t.cost,
            t.evaluations,
            t.started_factor.map_or(String::new(), |c| format!(
                "; the EKF started by the map shares Q and starts with P = {c:.3} × the map's mean squared error per state (tuned factor)"
            )),
        );
    }
    if let Some((x0, rmse)) = &report.ekf_from_observer_x0 {
        let _ = writeln!(
            s,
            "\nThe same EKF started at the scenario's `observer_x0` = ({}) instead of the box centre (the paper's x̂(0)): RMSE scenario {}.",
            x0.iter().map(|v| format!("{v}")).collect::<Vec<_>>().join(", "),
            report.targets.iter().zip(rmse).map(|(t, v)| format!("{} {v:.4}", t.name)).collect::<Vec<_>>().join(", ")
        );
    }
    // Every kind or none: `on-target-report` measures them all at once.
    let measured: std::collections::BTreeMap<String, on_target::OnTarget> = report
        .observers
        .iter()
        .filter_map(|o| Some((o.kind.to_owned(), o.on_target.clone()?)))
        .collect();
    s.push_str("\n## On the emulated Cortex-M4F\n\n");
    s.push_str(&on_target::section(&measured));
    s.push_str(
        "\n*ratio*: validation RMSE of the map over that of the plain linear least-squares map `Lᵀ Z + c` on the same data \
         (below 1: the nonlinear map beats the floor). *max error validation* is the paper's empirical ε_x. \
         *saturated*: windows where Γ⁻¹ clamped the estimate to the learning range. *collapsed*: Γ is a straight \
         line (≥ 90 % of the monotonicity constraints active). *Γ⁻¹ segments*: the table the chip evaluates instead of \
         inverting Γ; *proven table error*: its proven largest distance to the exact Γ⁻¹ (target units, at most 1e-4 of \
         the learning range); every estimate in this report uses that table, as the chip does. Full figures and the fitted coefficients: `report.json`.\n",
    );
    s.push_str(&figures(report));
    s
}

/// The report's figures, embedded (each beside this file as PNG and SVG), with what each shows.
fn figures(report: &Report<'_>) -> String {
    let mut s = String::from(
        "\n## Figures\n\nEach as PNG and SVG beside this file; saturated estimates (clamped by Γ⁻¹ to the learning range) are ringed.\n",
    );
    for (stem, shows) in plots::figure_stems(report.mismatch.is_some(), report.search.is_some()) {
        let _ = write!(s, "\n### {stem}\n\n{shows}.\n\n![{stem}]({stem}.png)\n");
    }
    s
}

/// `markdown` with its figures' links (`![stem](stem.png)`, relative to the report's folder) made
/// relative to the folder that holds the report's folder as `folder` (for a page that embeds the
/// report from there).
pub fn relocate_figures(markdown: &str, folder: &str) -> String {
    markdown
        .lines()
        .map(
            |line| match line.strip_prefix("![").and_then(|rest| rest.split_once("](")) {
                Some((alt, target)) if !target.contains('/') => format!("![{alt}]({folder}/{target}"),
                _ => line.to_owned(),
            },
        )
        .map(|line| line + "\n")
        .collect()
}

/// The report as its two files' texts: `report.json` and `report.md`.
pub fn texts(report: &Report<'_>) -> (String, String) {
    let json = serde_json::to_string_pretty(report).expect("the report serialises: plain numbers and strings") + "\n";
    (json, markdown(report))
}

/// Writes `report.json`, `report.md` (from [`texts`]) and `report.html` (the Markdown for a browser,
/// [`html::page`]) into `folder`; returns their paths in that order.
pub fn write_texts((json, markdown): &(String, String), folder: &Path) -> std::io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(folder)?;
    let json_path = folder.join("report.json");
    write_atomically(&json_path, json.as_bytes())?;
    let mut paths = vec![json_path];
    paths.extend(write_markdown(folder, markdown)?);
    Ok(paths)
}

/// Writes `report.md` and `report.html` (the Markdown for a browser, [`html::page`], titled by its
/// first heading) into `folder`; returns their paths in that order.
pub fn write_markdown(folder: &Path, markdown: &str) -> std::io::Result<Vec<PathBuf>> {
    let paths = vec![folder.join("report.md"), folder.join("report.html")];
    let title = markdown
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("# "))
        .unwrap_or("report");
    write_atomically(&paths[0], markdown.as_bytes())?;
    write_atomically(&paths[1], html::page(title, markdown).as_bytes())?;
    Ok(paths)
}
