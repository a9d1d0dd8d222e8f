//! `report.md`: the design's settings, its tables, the observers' tuning, the on-target figures and
//! the figures embedded, for a person to read; and its figures' links relocated for a page that
//! embeds it.

use std::fmt::Write as _;

use super::schema::Report;
use super::tables::{observers_table, search_table, table, taps_table};
use super::{on_target, plots};

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
    s.push_str("\n## Runs: which figure comes from which set\n\n");
    s.push_str(
        "Each set is simulated once, from its own seed; no figure is computed on runs a constant was chosen on, but those named *tuning* and *learning*.\n\n",
    );
    s.push_str(&super::runs::table(&report.runs));
    s.push_str("\n## Observers on the same data\n\n");
    s.push_str(&observers_table(report));
    s.push_str(&super::filters::against_ekf(report));
    s.push_str(&super::references::section(report));
    if let Some(t) = &report.ekf_tuning {
        let _ = writeln!(
            s,
            "\nEKF: the firmware's filter over the model emitted as Rust ({} RK4 step(s) per sample on the chip, {} in the learning simulation; \
             largest one-sample difference between the two over the validation states, relative to each state's spread: {}), \
             starting at {}; Q = diag({}), P(0) = diag({}), {} on the {} tuning runs from random starts, which no figure above but \
             *RMSE tuning* and *p95 tuning* uses (score {:.4} at an isotropic grid's best point, {:.4} after Nelder–Mead and the watch; {} evaluations); {}{}.",
            report.chip_model.chip_substeps,
            report.chip_model.simulation_substeps,
            report.chip_model.max_step_difference_relative.iter().map(|v| format!("{v:.1e}")).collect::<Vec<_>>().join(", "),
            if t.fixed.contains(&"x0") { "the spec's x̂(0)" } else { "the centre of the state box" },
            t.q_diagonal.iter().map(|v| format!("{v:.3e}")).collect::<Vec<_>>().join(", "),
            t.p0_diagonal.iter().map(|v| format!("{v:.3e}")).collect::<Vec<_>>().join(", "),
            match t.fixed.iter().filter(|c| **c != "x0").count() {
                0 => "each value per state chosen".to_owned(),
                2 => "both fixed by the spec (`[observer.ekf]`; their diagonals shown) and scored".to_owned(),
                _ => format!("`{}` fixed by the spec (`[observer.ekf]`; its diagonal shown), the other chosen per state", if t.fixed.contains(&"q") { "q" } else { "p0" }),
            },
            t.runs,
            t.grid_cost,
            t.cost,
            t.evaluations,
            match t.watch.threshold.is_finite() {
                true => format!(
                    "watched: it restarts when the mean of its normalised innovations squared over about {} samples exceeds {} times the outputs' number (τ chosen on the tuning runs, the largest of equal scores)",
                    t.watch.window, t.watch.threshold
                ),
                false => "not watched (every χ² watch on its innovations scored worse on the tuning runs)".to_owned(),
            },
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
    s.push_str(&super::fixed_filters::section(report));
    s.push_str(&super::tables::scenarios_section(report));
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
    if let Some(fixed) = &report.fixed_point {
        s.push_str(&super::fixed_point::section(fixed));
    }
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
