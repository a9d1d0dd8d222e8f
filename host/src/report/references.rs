//! The report's references ([`crate::observers::references`]): the on-line moving-horizon estimate
//! the map replaces and the particle filter's floor, their figures and what they took
//! (`references` in `report.json`), and the sentences that place every observer between them.

use std::fmt::Write as _;

use super::schema::{ChipReport, ParticlesReport, ReferenceFigures, ReferenceReport, Report, SolverReport};
use crate::observers::kind::mhe::run::ChipTuned;
use crate::observers::references::{Cost, Reference};
use crate::observers::Comparison;
use crate::spec::Design;

mod floor;
use floor::{against_floor, no_floor_reason};
pub use floor::{floor_verdict, BEATEN_BEYOND};

/// The references of `comparison` as the report holds them.
pub fn assemble(design: &Design, comparison: &Comparison) -> Vec<ReferenceReport> {
    let finite = |v: f64| v.is_finite().then_some(v);
    let targets: Vec<String> = design.targets.iter().map(|t| t.name.clone()).collect();
    let observers: Vec<(&'static str, Vec<f64>)> = (comparison.observers.iter())
        .map(|o| (o.kind, o.targets.iter().map(|f| f.rmse_validation).collect()))
        .collect();
    comparison
        .references
        .iter()
        .map(|r: &Reference| ReferenceReport {
            name: r.figures.kind,
            what: r.what,
            targets: design
                .targets
                .iter()
                .zip(&r.figures.targets)
                .map(|(t, f)| {
                    (
                        t.name.clone(),
                        ReferenceFigures {
                            rmse_validation: finite(f.rmse_validation),
                            p95_validation: finite(f.p95_validation),
                            max_error_validation: finite(f.max_error_validation),
                            rmse_scenario: finite(f.rmse_scenario),
                            scenario_draws: f.scenario_draws.map(|(a, b)| (finite(a), finite(b))),
                            rmse_mismatch: f.rmse_mismatch.and_then(finite),
                        },
                    )
                })
                .collect(),
            lost: r.figures.lost,
            solver: match &r.cost {
                Cost::Solver {
                    prior,
                    windows,
                    mean_seconds,
                    max_seconds,
                    mean_iterations,
                    starts,
                } => Some(SolverReport {
                    prior: *prior,
                    windows: *windows,
                    mean_time_s: *mean_seconds,
                    max_time_s: *max_seconds,
                    mean_iterations: *mean_iterations,
                    starts: *starts,
                }),
                _ => None,
            },
            particles: match &r.cost {
                Cost::Particles {
                    count,
                    checked,
                    converged,
                } => Some(ParticlesReport {
                    count: *count,
                    checked: checked.clone(),
                    converged: *converged,
                }),
                _ => None,
            },
            floor: match &r.cost {
                Cost::Particles { converged, .. } => Some(floor_verdict(
                    *converged,
                    &targets,
                    &r.figures.targets.iter().map(|f| f.rmse_validation).collect::<Vec<_>>(),
                    &observers,
                )),
                _ => None,
            },
        })
        .collect()
}

/// How the `mhe` kind was tuned, as the report holds it.
pub fn mhe_tuning(tuned: &ChipTuned) -> ChipReport {
    ChipReport {
        constants: tuned.constants.clone(),
        prior_weight: tuned.prior.0,
        scores: tuned.scores.clone(),
        converged_score: tuned.prior.1,
    }
}

/// `value`, or "—" where it is not finite.
fn show(value: Option<f64>) -> String {
    value.map_or("—".to_owned(), |v| format!("{v:.4}"))
}

/// Each named observer's validation RMSE per target, in spec order.
fn validation(report: &Report<'_>, name: &str) -> Option<Vec<f64>> {
    let names = report.targets.iter().map(|t| t.name);
    if let Some(o) = report.observers.iter().find(|o| o.kind == name) {
        return names.map(|t| o.targets[t].rmse_validation).collect();
    }
    let r = report.references.iter().find(|r| r.name == name)?;
    names.map(|t| r.targets[t].rmse_validation).collect()
}

/// The mean over targets of `a[t] / b[t]`.
fn mean_ratio(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| a / b).sum::<f64>() / a.len() as f64
}

/// The report's section: the references' table, what they took, and where the observers stand
/// between them; empty without references.
pub fn section(report: &Report<'_>) -> String {
    if report.references.is_empty() {
        return String::new();
    }
    let mut s = String::from("\n## What the map replaces, and the floor\n\n");
    s.push_str(
        "Host-only references, on the same validation runs, scenario and mismatch runs as every observer (never tuned on them): \
         the on-line moving-horizon estimate (MHE) the paper's map approximates, solved to convergence at every window over the same N samples \
         with the model the observers carry, and a particle filter as the floor no observer of that model beats on average.\n\n",
    );
    let draws = report
        .references
        .iter()
        .any(|r| r.targets.values().any(|f| f.scenario_draws.is_some()));
    let mismatch = report.mismatch.is_some();
    let _ = writeln!(
        s,
        "| reference | target | RMSE validation | p95 validation | max error validation | RMSE scenario |{}{}",
        if draws {
            " RMSE scenario draws | p95 scenario draws |"
        } else {
            ""
        },
        if mismatch { " RMSE mismatch |" } else { "" }
    );
    let _ = writeln!(
        s,
        "|---|---|---|---|---|---|{}{}",
        if draws { "---|---|" } else { "" },
        if mismatch { "---|" } else { "" }
    );
    for r in &report.references {
        for t in report.targets.iter().map(|t| t.name) {
            let f = &r.targets[t];
            let _ = write!(
                s,
                "| {} | {t} | {} | {} | {} | {} |",
                r.name,
                show(f.rmse_validation),
                show(f.p95_validation),
                show(f.max_error_validation),
                show(f.rmse_scenario)
            );
            if draws {
                let (a, b) = f.scenario_draws.unwrap_or((None, None));
                let _ = write!(s, " {} | {} |", show(a), show(b));
            }
            if mismatch {
                let _ = write!(s, " {} |", show(f.rmse_mismatch));
            }
            s.push('\n');
        }
    }
    s.push('\n');
    for r in &report.references {
        if let Some(solver) = &r.solver {
            let _ = writeln!(
                s,
                "- `{}`: {}{}; {} windows, {:.1} Levenberg–Marquardt iterations per window (a run's first window: the sum over its {} starts); the solve time per window on this host (mean, largest) is in `report.json` (`mean_time_s`, `max_time_s`), since it differs from run to run.",
                r.name,
                r.what,
                solver.prior.map_or(String::new(), |(p, score)| format!(
                    ", prior weight p = {p} (tuned on the tuning runs: score {score:.4})"
                )),
                solver.windows,
                solver.mean_iterations,
                solver.starts,
            );
        }
        if let Some(particles) = &r.particles {
            let checked: Vec<String> = particles
                .checked
                .iter()
                .map(|(count, rmse)| {
                    format!(
                        "{count}: {}",
                        rmse.iter().map(|v| format!("{v:.4}")).collect::<Vec<_>>().join(" / ")
                    )
                })
                .collect();
            let within = 100.0 * crate::observers::references::CONVERGED_WITHIN;
            let _ = writeln!(
                s,
                "- `{}`: {} with {} particles, {} (validation RMSE per target at each count tried: {}).",
                r.name,
                r.what,
                particles.count,
                if particles.converged {
                    format!(
                        "the first count whose doubling moved no target's validation RMSE by more than {within:.0} %"
                    )
                } else {
                    format!(
                        "the most the host runs: doubling it still moved a target's validation RMSE by more than {within:.0} %"
                    )
                },
                checked.join("; ")
            );
        }
        if let Some(floor) = r.floor.as_ref().filter(|f| !f.is_floor) {
            let _ = writeln!(
                s,
                "- **No floor for this design**: {}; no observer is placed against the particle filter.",
                no_floor_reason(floor, true)
            );
        }
    }
    if let Some(chip) = &report.mhe_tuning {
        let _ = writeln!(
            s,
            "- `mhe` (the observer kind, `MheObserver`): {} Gauss–Newton step(s) per sample from the previous solution, `mhe_host_prior`'s weight, the fewest of those tried whose tuning score is within {:.0} % of the converged MHE's ({:.4}; tried: {}); its row is with the observers', the chip's arithmetic run on the host in f32.",
            chip.constants.iterations,
            100.0 * crate::observers::kind::mhe::run::CHIP_WITHIN,
            chip.converged_score,
            chip.scores.iter().map(|(k, v)| format!("{k}: {v:.4}")).collect::<Vec<_>>().join(", ")
        );
    }
    s.push_str(&verdict(report));
    s
}

/// Where the observers stand: the best embeddable one against the floor (or why there is none), and
/// the map against the MHE it replaces (validation RMSE, each target's ratio, averaged over targets).
pub fn verdict(report: &Report<'_>) -> String {
    let mut s = String::new();
    let Some(floor) = validation(report, "floor") else {
        return s;
    };
    let Some(verdict) = report.references.iter().find_map(|r| r.floor.as_ref()) else {
        return s;
    };
    let observers: Vec<(&str, Vec<f64>)> = (report.observers.iter())
        .filter_map(|o| Some((o.kind, validation(report, o.kind)?)))
        .collect();
    s.push_str(&against_floor(verdict, &floor, &observers));
    let map = validation(report, "map");
    for name in ["mhe_host", "mhe_host_prior"] {
        let (Some(map), Some(mhe)) = (&map, validation(report, name)) else {
            continue;
        };
        let to_mhe = mean_ratio(map, &mhe);
        let to_floor = mean_ratio(&mhe, &floor);
        let worse = "worse than the map: without a prior the MHE is the maximum-likelihood start of N samples alone, and where they hardly tell the states apart it fits their noise (its largest errors reach the box's edge), while the map, fitted over the box's runs, returns what those N samples say on average over the learning runs";
        let place = if !verdict.is_floor {
            if to_mhe < 1.0 {
                format!("; `{name}` is {worse}")
            } else {
                String::new()
            }
        } else if to_mhe >= 1.0 && to_floor >= 1.0 {
            format!("; `{name}` is {to_floor:.2}× the floor's, between the map and the floor")
        } else if to_mhe < 1.0 {
            format!("; `{name}` is {to_floor:.2}× the floor's, {worse}")
        } else {
            format!("; `{name}` is {to_floor:.2}× the floor's, better than the floor: the floor's particle count falls short there")
        };
        let _ = writeln!(
            s,
            "\nThe map against `{name}`, the on-line estimate it replaces: {to_mhe:.2}× its RMSE (mean over targets){place}."
        );
    }
    if let (Some(chip), Some(converged)) = (validation(report, "mhe"), validation(report, "mhe_host_prior")) {
        let _ = writeln!(
            s,
            "\nThe MHE as the chip runs it (`mhe`, `MheObserver`: fixed Gauss–Newton steps in f32): {:.2}× the converged `mhe_host_prior`'s RMSE (mean over targets).",
            mean_ratio(&chip, &converged)
        );
    }
    if let (Some(map), Some(mhe)) = (
        report.observers.iter().find(|o| o.kind == "map"),
        report.observers.iter().find(|o| o.kind == "mhe"),
    ) {
        let _ = writeln!(
            s,
            "\nWhat the map saves on the chip: ~{:.0} instructions per estimate against the chip MHE's ~{:.0} ({:.0}× fewer; predicted by the cost model, measured in docs/chip.md).",
            map.predicted_instructions,
            mhe.predicted_instructions,
            mhe.predicted_instructions / map.predicted_instructions
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::schema::BeatenReport;

    fn targets() -> Vec<String> {
        vec!["h1".to_owned(), "h2".to_owned()]
    }

    #[test]
    fn an_unconverged_filter_is_no_floor_and_gets_no_ratio() {
        let floor = [0.10, 0.20];
        let observers = [("ukf_box", vec![0.12, 0.25])];
        let verdict = floor_verdict(false, &targets(), &floor, &observers);
        assert!(!verdict.is_floor && verdict.beaten_by.is_empty(), "{verdict:?}");
        let sentence = against_floor(&verdict, &floor, &observers);
        assert!(
            sentence.contains("No floor for this design: the particle filter did not converge"),
            "{sentence}"
        );
        assert!(!sentence.contains('×'), "{sentence}");
    }

    #[test]
    fn a_filter_an_observer_beats_by_more_than_5_percent_is_no_floor() {
        let floor = [0.10, 0.20];
        // 0.094 < 0.95 × 0.10 on h1; 0.191 is within 5 % of 0.20 on h2.
        let observers = [("map", vec![0.30, 0.40]), ("ukf_box", vec![0.094, 0.191])];
        let verdict = floor_verdict(true, &targets(), &floor, &observers);
        assert_eq!(
            verdict.beaten_by,
            vec![BeatenReport {
                kind: "ukf_box",
                target: "h1".to_owned(),
                rmse_validation: 0.094,
                floor_rmse_validation: 0.10,
            }]
        );
        assert!(!verdict.is_floor);
        let sentence = against_floor(&verdict, &floor, &observers);
        assert!(
            sentence.contains("No floor for this design") && sentence.contains("`ukf_box` (h1)"),
            "{sentence}"
        );
        assert!(!sentence.contains('×'), "{sentence}");
        assert!(no_floor_reason(&verdict, true).contains("h1 0.0940 against 0.1000"));
    }

    #[test]
    fn a_converged_filter_no_observer_beats_by_5_percent_is_the_floor_with_the_best_ratio() {
        let floor = [0.10, 0.20];
        // 0.096 and 0.192: within 5 % below the filter (4 % each); the mean ratio 0.96.
        let observers = [("map", vec![0.30, 0.40]), ("ukf_box", vec![0.096, 0.192])];
        let verdict = floor_verdict(true, &targets(), &floor, &observers);
        assert!(verdict.is_floor && verdict.beaten_by.is_empty(), "{verdict:?}");
        let sentence = against_floor(&verdict, &floor, &observers);
        assert!(sentence.contains("`ukf_box`, 0.96× the floor's RMSE"), "{sentence}");
    }

    #[test]
    fn a_filter_both_unconverged_and_beaten_says_both() {
        let verdict = floor_verdict(false, &targets(), &[0.10, 0.20], &[("ekf_box", vec![0.01, 0.02])]);
        let reason = no_floor_reason(&verdict, false);
        assert!(
            reason.contains("did not converge") && reason.contains("`ekf_box` (h1, h2)"),
            "{reason}"
        );
    }
}
