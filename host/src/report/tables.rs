//! The report's tables in Markdown: the map's figures per target, the observers side by side (with
//! the scenario draws, the mismatch corners and the drift), the design search's front and the taps
//! of a pruned `L`; shared by `report.md` and `gen`'s console.

use std::fmt::Write as _;

use super::schema::{
    CorrectedTuning, DriftReport, FiguresReport, MismatchReport, ObserverReport, Report, MISMATCH_PLANTS,
};

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
        "| observer | target | RMSE validation | p95 validation | lost validation | max error validation | RMSE scenario | RMSE transient | RMSE tuning | p95 tuning |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|");
    // Lost runs are the kind's, over every target (`lost`): repeated on each of its rows.
    let lost =
        |l: Option<crate::observers::lost::Lost>| l.map_or("—".to_owned(), |l| format!("{} / {}", l.lost, l.runs));
    for o in &report.observers {
        for (name, f) in in_spec_order(report, o) {
            let _ = writeln!(
                s,
                "| {} | {name} | {} | {} | {} | {} | {} | {} | {} | {} |",
                o.kind,
                show(f.rmse_validation),
                show(f.p95_validation),
                lost(Some(o.lost.validation)),
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
        let _ = writeln!(s, "| observer | target | RMSE | p95 | lost |");
        let _ = writeln!(s, "|---|---|---|---|---|");
        for o in &report.observers {
            for (name, f) in in_spec_order(report, o) {
                let _ = writeln!(
                    s,
                    "| {} | {name} | {} | {} | {} |",
                    o.kind,
                    show(f.rmse_scenario_draws.flatten()),
                    show(f.p95_scenario_draws.flatten()),
                    lost(o.lost.scenario_draws)
                );
            }
        }
    }
    if let Some(m) = &report.mismatch {
        s.push_str(&mismatch_table(report, m));
    }
    s.push_str(&drift_table(report));
    s.push_str(&super::lost::table(report));
    s.push_str(&super::tuning_score::table(
        &report.tuning_score,
        report.tau,
        report.time_unit,
    ));
    let _ = writeln!(s, "\n`observer()` is {:?}: {}.", report.observer.0, report.observer.1);
    if !report.helpers.is_empty() {
        let each: Vec<String> = (report.helpers.iter())
            .map(|(state, rmse)| format!("`{state}` (validation RMSE {rmse:.4})"))
            .collect();
        let _ = writeln!(
            s,
            "\nHelper maps, fitted for the model-corrected map and the map-started and restarted EKFs, which start from the map's estimate of every state (no observer returns them): {}.",
            each.join(", ")
        );
    }
    if let CorrectedTuning::Unavailable { unavailable } = &report.corrected_tuning {
        let _ = writeln!(
            s,
            "\nNo model-corrected map, map-started or restarted EKF: {unavailable}."
        );
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
    s.push_str(&super::sensitivity::sentence(report, m));
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

/// The figures of every observer on every scenario, one table per scenario (the box filters from the
/// observer start it names, too), when the spec names more than one; else empty (the observers'
/// table has the one scenario's figures).
pub fn scenarios_section(report: &Report<'_>) -> String {
    if report.scenarios.len() < 2 {
        return String::new();
    }
    let mut s = String::from(
        "\n## Scenarios\n\nEvery observer on every scenario the spec names, as the chip starts it (the box filters also from the \
         scenario's observer start, where it names one): RMSE over the scenario's windows, then over its transient (the first \
         2 time units from the map's first estimate). `auto`'s score counts each scenario through its own tuning runs \
         from the scenario's start, pooled with the random ones.\n",
    );
    let list = |v: &[f64]| v.iter().map(|x| format!("{x}")).collect::<Vec<_>>().join(", ");
    for (i, scenario) in report.scenarios.iter().enumerate() {
        let _ = write!(
            s,
            "\n### `{}`: x(0) = ({}){}, {} samples, seed {}\n\n| observer |",
            scenario.name,
            list(&scenario.x0),
            scenario
                .observer_x0
                .as_ref()
                .map_or(String::new(), |x| format!(", observer start ({})", list(x))),
            scenario.samples,
            scenario.seed,
        );
        for t in &report.targets {
            let _ = write!(s, " {} RMSE | {} transient |", t.name, t.name);
        }
        let _ = write!(s, "\n|---|{}\n", "---|---|".repeat(report.targets.len()));
        for o in &report.observers {
            let _ = write!(s, "| {} |", o.kind);
            for (_, f) in in_spec_order(report, o) {
                let (rmse, transient) = f.scenarios.get(i).copied().unwrap_or((None, None));
                let _ = write!(s, " {} | {} |", show(rmse), show(transient));
            }
            s.push('\n');
        }
        for (kind, targets) in &scenario.from_observer_start {
            let _ = write!(s, "| {kind} from the observer start |");
            for (rmse, transient) in targets {
                let _ = write!(s, " {} | {} |", show(*rmse), show(*transient));
            }
            s.push('\n');
        }
    }
    s
}
