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
        .min_by(|(_, a), (_, b)| {
            a[1].total_cmp(&b[1])
                .then(a[2].total_cmp(&b[2]))
                .then(a[0].total_cmp(&b[0]))
        })
        .map(|(i, _)| i)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::Cost;

    /// A fitted candidate with the given score, instructions and delay, within budget unless `over`.
    fn candidate(score: f64, instructions: f64, first_estimate: f64, over: bool) -> Candidate {
        Candidate {
            horizon: 1,
            nm: 1,
            beta: 1.0,
            taps: 1,
            regressor_len: 1,
            score: Some(score),
            rmse: Vec::new(),
            failure: None,
            cost: Some(Cost {
                instructions,
                flash: 0.0,
                first_estimate,
            }),
            within_budget: !over,
            on_front: false,
        }
    }

    #[test]
    fn the_front_is_what_nothing_beats_on_every_count() {
        let mut all = vec![
            candidate(0.30, 100.0, 0.4, false), // 0: cheapest, earliest: front
            candidate(0.10, 150.0, 1.0, false), // 1: front
            candidate(0.12, 160.0, 1.2, false), // 2: worse than 1 on all three: off
            candidate(0.10, 150.0, 1.1, false), // 3: as 1 but later: off
            candidate(0.05, 300.0, 3.0, false), // 4: best score: front
            candidate(0.20, 90.0, 2.0, false),  // 5: fewest instructions: front
        ];
        all.push(Candidate {
            score: None,
            cost: None,
            failure: Some("failed".into()),
            ..candidate(0.0, 0.0, 0.0, false)
        }); // 6: failed: never on the front, never chosen
        mark_front(&mut all);
        let front: Vec<bool> = all.iter().map(|c| c.on_front).collect();
        assert_eq!(front, [true, true, false, false, true, true, false]);
    }

    #[test]
    fn the_choice_is_the_best_within_budget_or_a_cheaper_one_within_two_percent() {
        // Best within budget is 2 (0.100); 1 is within 2 % of it and cheaper: chosen. 3 is better but
        // over budget; 0 is cheaper but 5 % worse.
        let all = [
            candidate(0.105, 100.0, 0.5, false),
            candidate(0.1015, 120.0, 0.9, false),
            candidate(0.100, 140.0, 0.9, false),
            candidate(0.050, 130.0, 0.9, true),
        ];
        assert_eq!(choose(&all), Some(1));
        // Tighten the rule's margin by making 1 3 % worse: the best, 2, is chosen.
        let mut worse = all.clone();
        worse[1].score = Some(0.103);
        assert_eq!(choose(&worse), Some(2));
        // Nothing within budget: no choice.
        let over: Vec<Candidate> = all
            .iter()
            .map(|c| Candidate {
                within_budget: false,
                ..c.clone()
            })
            .collect();
        assert_eq!(choose(&over), None);
    }
}
