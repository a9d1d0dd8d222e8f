//! The report assembled from a design's results: the fit, the observers compared on the same data,
//! and the quality gates, gathered into [`Report`] as `report.json` holds them.

use super::gates;
use super::schema::{
    ChipModel, CorrectedTuning, DriftReport, EkfTuning, FiguresReport, FilterConstants, FixedFilterReport,
    LinearReport, MismatchReport, ObserverReport, Report, SetSummary, TargetReport, MISMATCH_PLANTS,
};
use crate::fit::evaluate::Evaluation;
use crate::fit::DesignResult;
use crate::observers::Comparison;
use crate::spec::{Design, ObserverKind};

/// Assembles the report of a run.
pub fn report<'a>(design: &'a Design, result: &'a DesignResult, comparison: &'a Comparison) -> Report<'a> {
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
        regressor_len: result.runs.learning.regressor_len(),
        learning: summary(&result.runs.learning, design.learning.seed),
        validation: summary(&result.runs.validation, design.validation.seed),
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
        tuning: summary(&result.runs.tuning, design.tuning.seed),
        runs: super::runs::sets(design, &result.runs),
        observers: comparison.observers.iter().map(|o| observer(design, o)).collect(),
        fixed_filters: fixed_filters(design, comparison),
        references: super::references::assemble(design, comparison),
        mhe_tuning: comparison.tuned.mhe().map(super::references::mhe_tuning),
        ekf_tuning: comparison.tuned.ekf_box().map(|t| EkfTuning {
            log_q: t.log_q.clone(),
            log_p0: t.log_p0.clone(),
            cost: t.cost,
            grid_cost: t.grid_cost,
            evaluations: t.evaluations,
            runs: t.runs,
            started_factor: comparison.tuned.ekf_map().map(|s| s.factor),
            q_diagonal: t.constants.q.diagonal(),
            p0_diagonal: t.constants.p0.diagonal(),
            x0: t.constants.x0.clone(),
            fixed: t.fixed.clone(),
            watch: t.constants.watch,
        }),
        ekf_from_observer_x0: design.scenario().and_then(|s| s.observer_x0.clone()).and_then(|x0| {
            let from = comparison
                .from_observer_start
                .iter()
                .find(|f| f.kind == "ekf_box" && f.scenario == 0)?;
            Some((x0, from.targets.iter().map(|(rmse, _)| *rmse).collect()))
        }),
        observer: comparison.chosen.clone(),
        tuning_score: super::tuning_score::assemble(comparison),
        helpers: (result.helpers.iter().flatten())
            .map(|h| (design.model.states[h.index].clone(), h.validation.map.rmse))
            .collect(),
        corrected_tuning: match comparison.tuned.corrected() {
            Some(t) => CorrectedTuning::Tuned {
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
            None => CorrectedTuning::Unavailable {
                unavailable: comparison
                    .unavailable
                    .get(&ObserverKind::Corrected)
                    .cloned()
                    .unwrap_or_else(|| "not tuned".to_owned()),
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
        mismatch: result.runs.mismatch.as_ref().map(|m| MismatchReport {
            plants: MISMATCH_PLANTS,
            parameters: design.model.uncertain.iter().map(|u| u.name.clone()).collect(),
            corners: m.corners.clone(),
            runs_per_corner: design.validation.trajectories,
            nominal: m.nominal.clone(),
        }),
        scenarios: super::scenarios::assemble(design, comparison),
        search: None,
        taps: None,
        fixed_point: None,
    }
}

/// One observer's figures as `report.json` holds them (NaN, where a filter diverged, as `null`).
pub fn observer(design: &Design, o: &crate::observers::ObserverFigures) -> ObserverReport {
    let finite = |v: f64| v.is_finite().then_some(v);
    let drift = |d: crate::observers::Drift| DriftReport {
        rmse_first: finite(d.first),
        rmse_last: finite(d.last),
    };
    ObserverReport {
        kind: o.kind,
        predicted_instructions: o.instructions,
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
                        scenarios: f.scenarios.iter().map(|&(r, t)| (finite(r), finite(t))).collect(),
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
        lost: o.lost,
        on_target: None,
    }
}

/// The report's entries, one per filter the spec fixes constants of.
fn fixed_filters(design: &Design, comparison: &Comparison) -> Vec<FixedFilterReport> {
    comparison
        .beside
        .iter()
        .filter_map(|beside| {
            let entry = crate::observers::kind::named(beside.figures.kind)?;
            let section = entry.fixed.filter(|fixed| fixed.own)?.section;
            let spec = comparison.tuned.filter(entry.kind)?;
            Some(FixedFilterReport {
                kind: beside.figures.kind,
                section,
                fixed: spec.fixed.clone(),
                spec: constants(spec),
                all_tuned: constants(&beside.tuned),
                all_tuned_figures: observer(design, &beside.figures),
            })
        })
        .collect()
}

/// A tuned filter's constants and score as the report holds them.
fn constants(t: &crate::observers::ekf::Tuned) -> FilterConstants {
    FilterConstants {
        x0: t.constants.x0.clone(),
        q: t.constants.q.clone(),
        p0: t.constants.p0.clone(),
        score: t.cost,
    }
}
