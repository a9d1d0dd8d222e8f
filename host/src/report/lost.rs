//! `report.md`'s table of lost runs: per observer and set, how many runs it lost
//! ([`crate::observers::lost`]), which a pooled RMSE or a p95 over runs can hide.

use std::fmt::Write;

use super::schema::Report;
use crate::observers::lost::{Lost, LAST_PART, LOST_FRACTION};

/// The table, every observer in the report's order.
pub fn table(report: &Report<'_>) -> String {
    let mut s = format!(
        "\nLost runs: a run is lost when an estimate is not finite, or when over its last {:.0} % some target's RMSE exceeds {} times the target's spread, the RMSE of the best constant estimate (lost / runs; — where the set is not run):\n\n\
         | observer | validation | tuning | scenario draws | mismatch | long |\n|---|---|---|---|---|---|\n",
        100.0 * LAST_PART,
        LOST_FRACTION,
    );
    let show = |lost: Option<Lost>| lost.map_or("—".to_owned(), |l| format!("{} / {}", l.lost, l.runs));
    for o in &report.observers {
        let l = &o.lost;
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} |",
            o.kind,
            show(Some(l.validation)),
            show(l.tuning),
            show(l.scenario_draws),
            show(l.mismatch),
            show(l.long)
        );
    }
    s
}
