//! The trade-off of the design search: which candidates no other beats on every count, and which one
//! is chosen.

use super::Candidate;
use crate::observers::CHEAPER_WITHIN;

/// The counts a candidate is judged on, each the lower the better: score, instructions, delay to the
/// first estimate. `None` for a candidate that failed.
fn counts(c: &Candidate) -> Option<[f64; 3]> {
    Some([c.score?, c.cost?.instructions, c.cost?.first_estimate])
}

/// Whether `a` dominates `b`: no worse on every count and better on one.
fn dominates(a: &[f64; 3], b: &[f64; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| x <= y) && a.iter().zip(b).any(|(x, y)| x < y)
}

/// Sets `on_front` on every fitted candidate that no other fitted candidate dominates.
pub fn mark_front(candidates: &mut [Candidate]) {
    let all: Vec<Option<[f64; 3]>> = candidates.iter().map(counts).collect();
    for (c, mine) in candidates.iter_mut().zip(&all) {
        c.on_front = mine.is_some_and(|m| !all.iter().flatten().any(|other| dominates(other, &m)));
    }
}

/// The chosen candidate: among those within budget, the fewest instructions (then the earliest first
/// estimate) whose score is within [`CHEAPER_WITHIN`] of the best. `None` when none is within budget.
pub fn choose(candidates: &[Candidate]) -> Option<usize> {
    let eligible = || candidates.iter().enumerate().filter(|(_, c)| c.within_budget);
    let best = eligible().filter_map(|(_, c)| c.score).fold(f64::INFINITY, f64::min);
    eligible()
        .filter_map(|(i, c)| Some((i, counts(c)?)))
        .filter(|(_, [score, ..])| *score <= best * (1.0 + CHEAPER_WITHIN))
        .min_by(|(_, a), (_, b)| a[1].total_cmp(&b[1]).then(a[2].total_cmp(&b[2])).then(a[0].total_cmp(&b[0])))
        .map(|(i, _)| i)
}
