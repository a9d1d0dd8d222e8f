//! How long the start-up regime lasts by default: until the slowest box filter has settled on the
//! tuning runs from random starts.
//!
//! A box filter starts at the box centre, far from most runs' states; its error decays to a steady
//! level. With `e(j)` the [`OVER_RUNS`] quantile over runs (nearest rank) of each run's weighted
//! normalised error `√(Σ_t w_t ((r̂_t − r_t)/s_t)² / Σ_t w_t)` at `j` samples after the first
//! estimate, the steady level `E` is the median of `e(j)` over the runs' second half, and the filter
//! has settled at the first `j` from which `e` stays at or below [`SETTLED_WITHIN`] `· E` to the runs'
//! end. A high quantile, so that the runs a filter is slow from count (the median settled Example 1's
//! box EKF in fewer samples than its UKF, whose start-up term is half the EKF's); not the largest, so
//! that a lost run (counted as lost on its own) does not hold the start-up open to the runs' end.

use crate::data::{Rows, Run};

/// A filter has settled once its typical error stays within this factor of its steady level.
pub const SETTLED_WITHIN: f64 = 2.0;

/// The quantile over runs of the error that must settle: 9 runs in 10.
pub const OVER_RUNS: f64 = 0.9;

/// The samples after the first estimate (at sample `first`) that the estimates of `runs` (each run
/// with its estimates) take to settle (see the module docs), judged against each target's `spread`
/// and `weight`; `None` when there is no run or sample to judge.
pub fn settle<'a>(
    runs: impl Iterator<Item = (&'a Run, &'a Rows)> + Clone,
    first: usize,
    spreads: &[f64],
    weights: &[f64],
) -> Option<usize> {
    let len = runs.clone().map(|(r, _)| r.targets.len()).min()?;
    let samples = len.checked_sub(first).filter(|&s| s > 0)?;
    let total: f64 = weights.iter().sum();
    let error = |run: &Run, rows: &Rows, k: usize| -> f64 {
        let squares: f64 = (0..spreads.len())
            .map(|t| weights[t] * ((rows[k][t] - run.targets[k][t]) / spreads[t]).powi(2))
            .sum();
        let e = (squares / total).sqrt();
        if e.is_nan() {
            f64::INFINITY
        } else {
            e
        }
    };
    let typical: Vec<f64> = (0..samples)
        .map(|j| {
            let each = runs.clone().map(|(r, e)| error(r, e, first + j));
            quantile(each.collect(), OVER_RUNS)
        })
        .collect();
    let steady = quantile(typical[samples / 2..].to_vec(), 0.5);
    if !steady.is_finite() {
        return Some(samples); // most runs lost: never settled
    }
    let within = |e: &f64| *e <= SETTLED_WITHIN * steady;
    Some(typical.iter().rposition(|e| !within(e)).map_or(0, |last| last + 1))
}

/// The `q` quantile of `values` by nearest rank (the `⌈q n⌉`-th smallest); NaN when empty.
fn quantile(mut values: Vec<f64>, q: f64) -> f64 {
    values.sort_by(f64::total_cmp);
    let rank = ((q * values.len() as f64).ceil() as usize).max(1);
    values.get(rank - 1).copied().unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A run of `len` samples of one target at 0, and an estimate whose error is `error(k)`.
    fn run(len: usize, error: impl Fn(usize) -> f64) -> (Run, Rows) {
        let zeros: Rows = vec![vec![0.0]; len].into();
        let run = Run {
            states: zeros.clone(),
            inputs: Rows::new(0),
            measurements: zeros.clone(),
            targets: zeros,
            parameters: Vec::new(),
        };
        (run, (0..len).map(|k| vec![error(k)]).collect())
    }

    #[test]
    fn an_exponential_decay_settles_where_it_reaches_twice_its_floor() {
        // Error 1 + 63 e^{−j/5} (floor 1, spread 1): e(j) ≤ 2 once 63 e^{−j/5} ≤ 1, j ≥ 5 ln 63 =
        // 20.7, so from j = 21 on; counted from the first estimate at sample 4.
        let (runs, estimates): (Vec<Run>, Vec<Rows>) = (0..3)
            .map(|_| run(104, |k| 1.0 + 63.0 * (-((k as f64) - 4.0) / 5.0).exp()))
            .unzip();
        assert_eq!(settle(runs.iter().zip(&estimates), 4, &[1.0], &[1.0]), Some(21));
        // The spread scales the error and its floor alike.
        let scaled: Vec<Rows> = estimates
            .iter()
            .map(|e| e.iter().map(|r| vec![10.0 * r[0]]).collect())
            .collect();
        assert_eq!(settle(runs.iter().zip(&scaled), 4, &[10.0], &[1.0]), Some(21));
    }

    #[test]
    fn one_lost_run_of_ten_does_not_hold_the_start_up_open_and_a_slow_one_of_ten_does() {
        // Nine runs settled from the start (error 1), one lost (NaN from sample 10): the 9th smallest
        // of 10 is 1, settled from the first estimate.
        let runs_of = |tenth: fn(usize) -> f64, ninth: fn(usize) -> f64| -> (Vec<Run>, Vec<Rows>) {
            (0..10)
                .map(|i| match i {
                    9 => run(50, tenth),
                    8 => run(50, ninth),
                    _ => run(50, |_| 1.0),
                })
                .unzip()
        };
        let lost: fn(usize) -> f64 = |k| if k >= 10 { f64::NAN } else { 1.0 };
        let (runs, estimates) = runs_of(lost, |_| 1.0);
        assert_eq!(settle(runs.iter().zip(&estimates), 0, &[1.0], &[1.0]), Some(0));
        // Two of ten lost: the 9th is lost from sample 10 on, never settled before the end.
        let (runs, estimates) = runs_of(lost, lost);
        assert_eq!(settle(runs.iter().zip(&estimates), 0, &[1.0], &[1.0]), Some(50));
        // One lost and one slow (error 5 until sample 20): the slow one is the 9th, settled at 20,
        // where the median was settled from the first estimate.
        let (runs, estimates) = runs_of(lost, |k| if k < 20 { 5.0 } else { 1.0 });
        assert_eq!(settle(runs.iter().zip(&estimates), 0, &[1.0], &[1.0]), Some(20));
    }

    #[test]
    fn a_target_of_weight_0_does_not_count() {
        // Target 0 decays from 100 over 10 samples, target 1 is flat; with target 0 weighted 0 the
        // filter is settled from the first estimate.
        let len = 40;
        let zeros: Rows = vec![vec![0.0, 0.0]; len].into();
        let runs = [Run {
            states: zeros.clone(),
            inputs: Rows::new(0),
            measurements: zeros.clone(),
            targets: zeros,
            parameters: Vec::new(),
        }];
        let estimates = [(0..len)
            .map(|k| vec![if k < 10 { 100.0 } else { 1.0 }, 1.0])
            .collect::<Rows>()];
        assert_eq!(
            settle(runs.iter().zip(&estimates), 0, &[1.0, 1.0], &[1.0, 1.0]),
            Some(10)
        );
        assert_eq!(
            settle(runs.iter().zip(&estimates), 0, &[1.0, 1.0], &[0.0, 1.0]),
            Some(0)
        );
    }
}
