//! `report.md`'s section on the filters whose constants the spec fixes (`[observer.<filter>]`,
//! [`super::FixedFilterReport`]): which constants are the spec's and which
//! `gen` tuned, and the spec's filter beside the same filter with every constant tuned by the same
//! search on the same tuning runs, on the same validation runs and scenario. A published filter is
//! reproduced; whether tuning would do better is measured.

use std::fmt::Write;

use super::schema::Report;
use crate::plant::Covariance;

/// `report.md`'s section; empty when the spec fixes no filter's constants.
pub fn section(report: &Report<'_>) -> String {
    let mut s = String::new();
    for entry in &report.fixed_filters {
        let Some(spec) = report.observers.iter().find(|o| o.kind == entry.kind) else {
            continue;
        };
        let tuned: Vec<&str> = ["q", "p0"]
            .into_iter()
            .filter(|name| !entry.fixed.contains(name))
            .collect();
        let _ = writeln!(
            s,
            "\n### `{}`: the constants the spec fixes\n\n`[{}]` fixes {}; `gen` tuned {}; the filter starts at {}. \
             Beside it, the same filter with every constant tuned by the same search on the same tuning runs (from the box centre), on the same data:\n",
            entry.kind,
            entry.section,
            words(&entry.fixed),
            if tuned.is_empty() { "nothing".to_owned() } else { words(&tuned) },
            if entry.fixed.contains(&"x0") { "the spec's `x0`" } else { "the centre of the state box" },
        );
        let names: Vec<&String> = spec.targets.keys().collect();
        let _ = write!(s, "| filter | x̂(0) | Q | P(0) | score, random tuning runs |");
        for name in &names {
            let _ = write!(
                s,
                " {name} RMSE validation | {name} p95 validation | {name} RMSE scenario |"
            );
        }
        let _ = write!(s, "\n|---|---|---|---|---|");
        s.push_str(&"---|---|---|".repeat(names.len()));
        s.push('\n');
        for (label, constants, figures) in [
            ("the spec's", &entry.spec, spec),
            ("every constant tuned", &entry.all_tuned, &entry.all_tuned_figures),
        ] {
            let _ = write!(
                s,
                "| {label} | ({}) | {} | {} | {:.4} |",
                constants
                    .x0
                    .iter()
                    .map(|v| format!("{v}"))
                    .collect::<Vec<_>>()
                    .join(", "),
                matrix(&constants.q),
                matrix(&constants.p0),
                constants.score,
            );
            for name in &names {
                let f = &figures.targets[*name];
                let _ = write!(
                    s,
                    " {} | {} | {} |",
                    value(f.rmse_validation),
                    value(f.p95_validation),
                    value(f.rmse_scenario)
                );
            }
            s.push('\n');
        }
    }
    s
}

/// `["x0", "q"]` as `x0 and q`.
fn words(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
    match quoted.split_last() {
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
        None => String::new(),
    }
}

/// A covariance as the report writes it: `diag(…)`, or its rows.
fn matrix(c: &Covariance) -> String {
    let list = |values: &[f64]| values.iter().map(|v| format!("{v:.3e}")).collect::<Vec<_>>().join(", ");
    match c {
        Covariance::Diagonal(d) => format!("diag({})", list(d)),
        Covariance::Full(rows) => format!(
            "[{}]",
            rows.iter()
                .map(|r| format!("[{}]", list(r)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// A figure, `diverged` where a filter gave none.
fn value(v: Option<f64>) -> String {
    v.map_or("diverged".to_owned(), |v| format!("{v:.4}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_are_listed_as_a_sentence_and_matrices_as_written() {
        assert_eq!(words(&["x0"]), "`x0`");
        assert_eq!(words(&["x0", "q", "p0"]), "`x0`, `q` and `p0`");
        assert_eq!(
            matrix(&Covariance::Diagonal(vec![1.0, 0.25])),
            "diag(1.000e0, 2.500e-1)"
        );
        assert_eq!(
            matrix(&Covariance::Full(vec![vec![1.0, 0.5], vec![0.5, 2.0]])),
            "[[1.000e0, 5.000e-1], [5.000e-1, 2.000e0]]"
        );
    }
}
