//! `report.md`'s tables of lost and restarted runs: per observer and set, how many runs it lost
//! ([`crate::observers::lost`]), which a pooled RMSE or a p95 over runs can hide, and how many it
//! restarted on, with the most restarts on one run.

use std::fmt::Write;

use super::schema::Report;
use crate::observers::lost::{Lost, LAST_PART, LOST_FRACTION};

/// The table, every observer in the report's order.
pub fn table(report: &Report<'_>) -> String {
    let mut s = format!(
        "\nLost runs: a run is lost when an estimate is not finite, or when over its last {:.0} % some target's RMSE exceeds {} times the target's spread, the RMSE of the best constant estimate (lost / runs; — where the set is not run; *k by the floor too*: k of those runs the particle floor lost at every particle count it tried, whose data do not determine a target: no gate counts them):\n\n\
         | observer | validation | tuning | scenario draws | mismatch | long |\n|---|---|---|---|---|---|\n",
        100.0 * LAST_PART,
        LOST_FRACTION,
    );
    let show = |lost: Option<Lost>| {
        lost.map_or("—".to_owned(), |l| match l.floor_lost {
            0 => format!("{} / {}", l.lost, l.runs),
            k => format!("{} / {} ({k} by the floor too)", l.lost, l.runs),
        })
    };
    let rows = (report.observers.iter().map(|o| (o.kind, &o.lost))).chain(
        report
            .references
            .iter()
            .filter(|r| r.name == "floor")
            .map(|r| (r.name, &r.lost)),
    );
    for (name, l) in rows {
        let _ = writeln!(
            s,
            "| {name} | {} | {} | {} | {} | {} |",
            show(Some(l.validation)),
            show(l.tuning),
            show(l.scenario_draws),
            show(l.mismatch),
            show(l.long)
        );
    }
    s.push_str(&restarts(report));
    s
}

/// The restarts: a row per observer that restarted on some run, or a sentence saying none did.
fn restarts(report: &Report<'_>) -> String {
    let sets = |o: &super::schema::ObserverReport| {
        let l = &o.lost;
        [Some(l.validation), l.tuning, l.scenario_draws, l.mismatch, l.long]
    };
    let restarting: Vec<_> = (report.observers.iter())
        .filter(|o| sets(o).iter().flatten().any(|l| l.restarted > 0))
        .collect();
    if restarting.is_empty() {
        return "\nRestarts: no observer restarted on any run (a filter restarts when its state or step goes non-finite, a box filter also when its χ² watch finds its innovations implausible; `ekf_restart`'s restarts from the map on its check are its usual work, not counted).\n".to_owned();
    }
    let mut s = "\nRestarts: a filter restarts when its state or step goes non-finite, a box filter also when its χ² watch finds its innovations implausible (runs with a restart / runs, the most restarts on one run; observers that never restarted are left out; `ekf_restart`'s restarts from the map on its check are its usual work, not counted):\n\n\
         | observer | validation | tuning | scenario draws | mismatch | long |\n|---|---|---|---|---|---|\n"
        .to_owned();
    let show = |lost: Option<Lost>| {
        lost.map_or("—".to_owned(), |l| match l.restarted {
            0 => format!("0 / {}", l.runs),
            _ => format!("{} / {}, ≤ {}", l.restarted, l.runs, l.most_restarts),
        })
    };
    for o in restarting {
        let cells: Vec<String> = sets(o).into_iter().map(show).collect();
        let _ = writeln!(s, "| {} | {} |", o.kind, cells.join(" | "));
    }
    s
}
