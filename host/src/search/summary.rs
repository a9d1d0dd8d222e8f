//! The search told in a few lines for the console (`gen`, `search`): what was searched, the front and
//! the choice; the full tables are the report's.

use super::Outcome;
use crate::spec::Design;

/// The search in a few lines, as `gen` and `search` print it: what was searched, the front, the choice.
pub fn summary(design: &Design, outcome: &Outcome) -> String {
    use std::fmt::Write;
    let fitted = outcome.candidates.iter().filter(|c| c.score.is_some()).count();
    let sparse = outcome.candidates.iter().any(|c| c.taps < c.regressor_len);
    let mut text = format!(
        "  search: {} candidates (N, n_m, β{}), {fitted} fitted, scored on {} tuning windows in {:.1} s; front (score = mean RMSE / spread on the tuning runs):\n",
        outcome.candidates.len(),
        if sparse { ", taps" } else { "" },
        outcome.windows,
        outcome.seconds
    );
    let unit = &design.time_unit;
    let front = outcome.front();
    let at = front
        .iter()
        .position(|c| std::ptr::eq(*c, outcome.chosen()))
        .unwrap_or(0);
    // A few lines: the cheapest, two either side of the choice, the best score.
    let best = (0..front.len())
        .min_by(|&a, &b| {
            front[a]
                .score
                .unwrap_or(f64::INFINITY)
                .total_cmp(&front[b].score.unwrap_or(f64::INFINITY))
        })
        .unwrap_or(0);
    let mut shown: Vec<usize> = vec![0, best];
    shown.extend(at.saturating_sub(2)..(at + 3).min(front.len()));
    shown.sort_unstable();
    shown.dedup();
    let mut last = None;
    for i in shown {
        if last.is_some_and(|l: usize| i > l + 1) {
            text.push_str("    …\n");
        }
        last = Some(i);
        let c = front[i];
        let cost = c.cost.expect("a front candidate has a cost");
        let mark = match (i == at, c.within_budget) {
            (true, _) => "  ← chosen",
            (false, false) => "  (over budget)",
            _ => "",
        };
        let taps = if sparse {
            format!("  {:>3}/{:<3} taps", c.taps, c.regressor_len)
        } else {
            String::new()
        };
        let _ = writeln!(
            text,
            "    N = {:>3}, n_m = {}, β = {:<4}{taps}  score {:.4}  ~{:.0} instructions  first estimate after {} {unit}  ~{:.0} B flash{mark}",
            c.horizon,
            c.nm,
            c.beta,
            c.score.expect("a front candidate is scored"),
            cost.instructions,
            short(cost.first_estimate),
            cost.flash,
        );
    }
    let _ = writeln!(
        text,
        "    ({} on the front; all of it in report.md, every candidate in report.json)",
        front.len()
    );
    text
}

/// A delay as tables show it: four decimals at most, trailing zeros dropped (`2.3`, not `2.3000000000000003`).
pub fn short(value: f64) -> String {
    let text = format!("{value:.4}");
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}
