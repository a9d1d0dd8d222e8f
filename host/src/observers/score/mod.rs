//! How an observer's errors on a set of runs become one number: the score every tuning criterion and
//! `auto` minimise.
//!
//! A pooled RMSE over runs from random starts is dominated by the many runs where every observer does
//! well; a filter that converges slowly from a few starts hides there. The score therefore counts the
//! tail beside the pool. For each target `t` with spread `s_t` (its range over the tuning runs), on
//! one regime of the tuning set ([`regimes`]: random starts, each scenario's start, the start-up):
//!
//! ```text
//! score = Σ_t w_t (RMSE_t + P95_t) / s_t  /  Σ_t w_t,
//! ```
//!
//! and a set's score is the mean of its regimes' ([`Scoring`]), so that no regime the user asks
//! about is drowned by the others.
//!
//! `RMSE_t` the RMSE over every window of every run, `P95_t` the 95th percentile over runs of each
//! run's own RMSE ([`percentile_95`]), `w_t` the target's `weight` (default 1: the plain mean over
//! targets; a target of weight 0 is left out, its errors and its lost runs alike). A run whose
//! estimate diverged (NaN) makes the score infinite: the worst, never a NaN that a search cannot
//! order.
//!
//! Neither figure sees one run lost among many good ones. A lost tuning run
//! ([`crate::observers::lost`]) therefore counts before everything else ([`Score`]): a candidate
//! that loses a run never beats one that loses none, whatever its pooled RMSE, and of two that lose
//! runs the one that loses fewer wins.

use crate::data::{Rows, Run};
use crate::spec::Design;

pub mod regimes;
pub mod settle;
pub use regimes::{Regimes, Scoring, StartUpBy, Term};
pub use settle::settle;

/// The spreads a run's loss is judged against: a target of weight 0 is never lost on its error (its
/// spread, as [`crate::observers::lost`] sees it, is ∞); a non-finite estimate of it still loses the run.
pub fn counted(spreads: &[f64], weights: &[f64]) -> Vec<f64> {
    (spreads.iter().zip(weights))
        .map(|(&s, &w)| if w > 0.0 { s } else { f64::INFINITY })
        .collect()
}

/// Each target's weight in the score (`[[targets]] weight`), in the spec's order.
pub fn weights(design: &Design) -> Vec<f64> {
    design.targets.iter().map(|t| t.weight).collect()
}

/// How much worse than the best a cheaper kind's score may be and still be chosen by `auto`.
pub const CHEAPER_WITHIN: f64 = 0.02;

/// What one lost tuning run adds to a score as a search sees it ([`Score::objective`]): far above any
/// score of runs that are not lost (each run's error at its end is below its targets' spreads, so
/// scores are a few units at most).
pub const LOST_RUN: f64 = 1e3;

/// A [`score`] with the runs lost on the same set: every tuning criterion and `auto` order candidates
/// by the lost runs first, then by the value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Score {
    /// Runs lost ([`crate::observers::lost`]).
    pub lost: usize,
    /// The [`score`] of the figures.
    pub value: f64,
}

impl Score {
    /// One number a search minimises, ordered as the scores are while a value stays below
    /// [`LOST_RUN`]: `LOST_RUN · lost + value`.
    pub fn objective(self) -> f64 {
        LOST_RUN * self.lost as f64 + self.value
    }
}

/// Each run's RMSE of target `target` over its samples `window(run)`.
pub fn per_run_rmse(
    runs: &[Run],
    estimates: &[Rows],
    target: usize,
    window: impl Fn(&Run) -> std::ops::Range<usize>,
) -> Vec<f64> {
    runs.iter()
        .zip(estimates)
        .map(|(run, estimate)| {
            let (sum, count) = squared_errors(run, estimate, target, window(run));
            (sum / count.max(1) as f64).sqrt()
        })
        .collect()
}

/// The sum of the squared errors of target `target` over samples `range` of `run`, and their count.
pub fn squared_errors(run: &Run, estimate: &Rows, target: usize, range: std::ops::Range<usize>) -> (f64, usize) {
    let count = range.len();
    let sum = range
        .map(|k| (estimate[k][target] - run.targets[k][target]).powi(2))
        .sum();
    (sum, count)
}

/// The 95th percentile of `values`, linearly interpolated between order statistics (position
/// `0.95 (n − 1)` in the sorted values, the usual "type 7" definition). NaN if any value is NaN or
/// there are none.
pub fn percentile_95(values: &[f64]) -> f64 {
    if values.is_empty() || values.iter().any(|v| v.is_nan()) {
        return f64::NAN;
    }
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let position = 0.95 * (sorted.len() - 1) as f64;
    let below = position.floor() as usize;
    let above = (below + 1).min(sorted.len() - 1);
    let fraction = position - below as f64;
    sorted[below] + fraction * (sorted[above] - sorted[below])
}

/// The score of per-target pooled RMSEs and 95th percentiles, each normalised by its target's spread
/// and weighted by `weights` (see the module docs); `f64::INFINITY` where it is not finite.
pub fn score(pooled: &[f64], p95: &[f64], spreads: &[f64], weights: &[f64]) -> f64 {
    let weighed = || (pooled.iter().zip(p95).zip(spreads).zip(weights)).filter(|(_, &w)| w > 0.0);
    let total: f64 = weighed().map(|(_, w)| w).sum();
    let mean = weighed()
        .map(|(((r, p), s), w)| w * ((r + p) / s.max(f64::MIN_POSITIVE)))
        .sum::<f64>()
        / total;
    if mean.is_finite() {
        mean
    } else {
        f64::INFINITY
    }
}

/// The candidate of lowest `score` (the first of equals, in `candidates`' order), scored in
/// parallel, and its score: the one-parameter grid searches of the tuning.
pub fn lowest(candidates: &[f64], score: impl Fn(f64) -> f64 + Sync) -> (f64, f64) {
    use rayon::prelude::*;
    candidates
        .par_iter()
        .map(|&c| (c, score(c)))
        .collect::<Vec<_>>()
        .into_iter()
        .fold(
            (candidates[0], f64::INFINITY),
            |best, c| if c.1 < best.1 { c } else { best },
        )
}

/// RMSE and largest |error| of `estimates` (one row per sample of each run) against the runs'
/// targets, over samples `from(run) .. to(run)`.
pub fn errors(
    runs: &[Run],
    estimates: &[Rows],
    target: usize,
    window: impl Fn(&Run) -> std::ops::Range<usize>,
) -> (f64, f64) {
    let (mut sum, mut count, mut max) = (0.0, 0usize, 0.0_f64);
    for (run, estimate) in runs.iter().zip(estimates) {
        for k in window(run) {
            let error = estimate[k][target] - run.targets[k][target];
            sum += error * error;
            count += 1;
            max = if error.is_nan() { f64::NAN } else { max.max(error.abs()) };
        }
    }
    ((sum / count.max(1) as f64).sqrt(), max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lowest_candidate_wins_and_the_first_of_equals() {
        let candidates = [1.0, 2.0, 3.0, 4.0];
        assert_eq!(lowest(&candidates, |c| (c - 3.0).abs()), (3.0, 0.0));
        assert_eq!(lowest(&candidates, |c| if c > 1.5 { 0.5 } else { 1.0 }), (2.0, 0.5));
        // Nothing finite: the first candidate, as the tuning's fallback.
        assert_eq!(lowest(&candidates, |_| f64::NAN).0, 1.0);
    }

    #[test]
    fn the_percentile_interpolates_between_order_statistics() {
        // 21 values 0, 1, …, 20 in any order: position 0.95 · 20 = 19 exactly.
        let values: Vec<f64> = (0..21).rev().map(f64::from).collect();
        assert_eq!(percentile_95(&values), 19.0);
        // 11 values 0…10: position 9.5, halfway between 9 and 10.
        let values: Vec<f64> = (0..11).map(f64::from).collect();
        assert_eq!(percentile_95(&values), 9.5);
        assert_eq!(percentile_95(&[3.0]), 3.0);
        assert!(percentile_95(&[1.0, f64::NAN]).is_nan());
        assert!(percentile_95(&[]).is_nan());
    }

    #[test]
    fn a_lost_run_ranks_before_any_value_in_the_objective() {
        let (lost, clean) = (Score { lost: 1, value: 0.01 }, Score { lost: 0, value: 5.0 });
        assert!(clean.objective() < lost.objective());
        assert_eq!(lost.objective(), 1000.01);
        assert!(Score { lost: 2, value: 0.3 }.objective() < Score { lost: 2, value: 0.4 }.objective());
    }

    #[test]
    fn the_score_counts_the_tail() {
        // Two observers with the same pooled RMSE: the one whose error sits in one run scores worse.
        let spreads = [2.0];
        let even = score(&[0.1], &[0.1], &spreads, &[1.0]);
        let tail = score(&[0.1], &[0.5], &spreads, &[1.0]);
        assert!((even - 0.1).abs() < 1e-15, "{even}");
        assert!((tail - 0.3).abs() < 1e-15, "{tail}");
        assert_eq!(score(&[f64::NAN], &[0.1], &spreads, &[1.0]), f64::INFINITY);
    }

    #[test]
    fn a_target_of_weight_0_is_left_out_of_the_value_and_of_the_lost_runs() {
        // Two targets of truth 0 over 8 samples, spreads (1, 1). The estimate is 0.5 on x1 and 3 on
        // x2 (lost: 3 > 1 · its spread over the last samples). Weights (1, 1): value (1 + 6) / 2 = 3.5
        // (each target's pooled RMSE equals its one run's, so RMSE + p95 = 2 · error), 1 run lost;
        // weights (1, 0): value 1, none lost; but a NaN on x2 loses the run whatever its weight.
        let rows = |values: [f64; 2]| {
            let mut rows = Rows::new(2);
            (0..8).for_each(|_| rows.push(&values));
            rows
        };
        let run = Run {
            states: rows([0.0; 2]),
            inputs: Rows::new(0),
            measurements: rows([0.0; 2]),
            targets: rows([0.0; 2]),
            parameters: Vec::new(),
        };
        let runs = [run];
        let scoring = |weights: [f64; 2]| Scoring {
            spreads: vec![1.0, 1.0],
            weights: weights.to_vec(),
            regimes: Regimes::whole(0, 1),
            start_up_by: StartUpBy::Horizons,
            constant: f64::INFINITY,
        };
        let both = scoring([1.0, 1.0]).score(&runs, &[rows([0.5, 3.0])]);
        assert_eq!((both.lost, both.value), (1, 3.5));
        let first = scoring([1.0, 0.0]).score(&runs, &[rows([0.5, 3.0])]);
        assert_eq!((first.lost, first.value), (0, 1.0));
        let nan = scoring([1.0, 0.0]).score(&runs, &[rows([0.5, f64::NAN])]);
        assert_eq!((nan.lost, nan.value), (1, 1.0));
    }

    #[test]
    fn per_run_rmse_is_each_runs_own() {
        let rows = |width: usize, value: f64| {
            let mut rows = Rows::new(width);
            for _ in 0..4 {
                rows.push(&vec![value; width]);
            }
            rows
        };
        let run = || Run {
            states: rows(1, 0.0),
            inputs: rows(0, 0.0),
            measurements: rows(1, 0.0),
            targets: rows(1, 0.0),
            parameters: Vec::new(),
        };
        let runs = [run(), run()];
        let mut a = Rows::new(1);
        let mut b = Rows::new(1);
        for k in 0..4 {
            a.push(&[if k >= 2 { 3.0 } else { 100.0 }]);
            b.push(&[if k >= 2 { 4.0 } else { 100.0 }]);
        }
        let rmse = per_run_rmse(&runs, &[a, b], 0, |_| 2..4);
        assert_eq!(rmse, vec![3.0, 4.0]);
    }
}
