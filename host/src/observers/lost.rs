//! When an observer has lost a run: a defined event, counted per kind and per set.
//!
//! Over the samples a kind is judged on (`window`: from the map's first estimate, `k ≥ N − 1`), a
//! run is **lost** when
//!
//! * an estimate of some target is not finite (the observer diverged), or
//! * over the run's last part (the last [`LAST_PART`] of those samples), some target's RMSE exceeds
//!   [`LOST_FRACTION`] times that target's spread (its standard deviation over the tuning windows:
//!   the RMSE of the best constant estimate): at the end of the run the observer does worse than
//!   one that knows nothing but the target's mean, whatever it did before.
//!
//! A filter that refuses every finite sample from some point on predicts alone from there, and its
//! error grows into the second case. A pooled RMSE or a p95 over runs can hide one such run among
//! many good ones; this count does not.
//!
//! Some runs no observer can track: their samples do not determine a target (on E. coli, a batch
//! whose substrate is nearly gone at the start shows no light, whatever its product). The posterior
//! mean is then the prior's, and a truth near the prior's edge is more than a spread away from it.
//! The particle floor ([`super::particles`]), the best estimate of the model and noise, loses such a
//! run too; so on the sets the floor is run on (validation, the scenario's draws, the mismatch runs),
//! each set also counts the runs lost that the floor lost as well ([`Lost::floor_lost`]): they are
//! shown, and the gates count only the others.
//!
//! Beside it, each set counts the runs on which the observer **restarted** (its state or step went
//! non-finite, or `ekf_restart`'s map check fired: `firmware::rules`) and the most restarts on one
//! run: a restarted run may end well, and the count says how often recovery was needed.

use std::ops::Range;

use serde::Serialize;

use crate::data::{Rows, Run};

/// The multiple of a target's spread above which an RMSE over a run's last part is lost track: 1,
/// worse than the best constant estimate.
pub const LOST_FRACTION: f64 = 1.0;

/// The part of a run's judged samples, at its end, that decides whether it was lost.
pub const LAST_PART: f64 = 0.25;

/// One observer's estimates of one run (`R`: [`Rows`], or the rows of some scalar type), and the
/// times it restarted on it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Track<R = Rows> {
    /// The estimate of every target at every sample.
    pub rows: R,
    /// Restarts on the run, as the chip counts them.
    pub restarts: u32,
}

impl From<Rows> for Track {
    /// The estimates of an observer that never restarts (the map, a reference).
    fn from(rows: Rows) -> Self {
        Track { rows, restarts: 0 }
    }
}

impl From<Track<Vec<Vec<f64>>>> for Track {
    /// Rows as [`Rows`].
    fn from(track: Track<Vec<Vec<f64>>>) -> Self {
        Track {
            rows: Rows::from(track.rows),
            restarts: track.restarts,
        }
    }
}

/// A [`Track`] built sample by sample as the chip's `estimate()` reads a filter after each `push`:
/// an estimate is the sample's, a restart keeps the latest estimate (and is counted), a refused
/// sample gives none (NaN).
pub struct Tracker {
    track: Track,
    latest: Vec<f64>,
}

impl Tracker {
    /// Before the first sample of a run, for `targets` targets.
    pub fn new(targets: usize) -> Self {
        Tracker {
            track: Track {
                rows: Rows::new(targets),
                restarts: 0,
            },
            latest: vec![f64::NAN; targets],
        }
    }

    /// The sample gave `estimate`.
    pub fn estimate(&mut self, estimate: impl IntoIterator<Item = f64>) {
        self.latest.clear();
        self.latest.extend(estimate);
        self.track.rows.push(&self.latest);
    }

    /// The filter restarted at the sample: the latest estimate stays.
    pub fn restarted(&mut self) {
        self.track.restarts += 1;
        self.track.rows.push(&self.latest);
    }

    /// The sample was refused: no estimate.
    pub fn refused(&mut self) {
        self.latest.fill(f64::NAN);
        self.track.rows.push(&self.latest);
    }

    /// The run's track.
    pub fn finish(self) -> Track {
        self.track
    }
}

/// Whether the observer whose estimates of `run` are `estimates` lost it (see the module docs),
/// judged over samples `window` against each target's spread `spreads`.
pub fn is_lost(run: &Run, estimates: &Rows, window: Range<usize>, spreads: &[f64]) -> bool {
    let targets = spreads.len();
    if window.is_empty() {
        return false;
    }
    if window.clone().any(|k| estimates[k].iter().any(|v| !v.is_finite())) {
        return true;
    }
    let last = ((window.len() as f64 * LAST_PART).ceil() as usize).clamp(1, window.len());
    let part = window.end - last..window.end;
    (0..targets).any(|t| {
        let squared: f64 = part
            .clone()
            .map(|k| (estimates[k][t] - run.targets[k][t]).powi(2))
            .sum();
        (squared / last as f64).sqrt() > LOST_FRACTION * spreads[t]
    })
}

/// The lost and the restarted runs of one set.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Lost {
    /// Runs lost.
    pub lost: usize,
    /// Runs in the set.
    pub runs: usize,
    /// Runs on which the observer restarted at least once.
    pub restarted: usize,
    /// The most restarts on one run.
    pub most_restarts: u32,
    /// Of the runs lost, those the particle floor lost too (see the module docs); 0 where the floor is
    /// not run on the set.
    pub floor_lost: usize,
}

impl Lost {
    /// The runs lost that the floor did not lose: the observer's own failures.
    #[must_use]
    pub fn beyond_floor(&self) -> usize {
        self.lost - self.floor_lost
    }
}

/// The runs of a set for which [`is_lost`] holds (their indices, in order), each over its samples
/// `window(run)`.
pub fn which(runs: &[Run], estimates: &[Rows], window: impl Fn(&Run) -> Range<usize>, spreads: &[f64]) -> Vec<usize> {
    (runs.iter().zip(estimates).enumerate())
        .filter(|(_, (run, rows))| is_lost(run, rows, window(run), spreads))
        .map(|(i, _)| i)
        .collect()
}

/// [`is_lost`] over every run of a set, each over its samples `window(run)`, with the restarts on
/// each run (`restarts[i]` on `runs[i]`).
pub fn count(
    runs: &[Run],
    estimates: &[Rows],
    restarts: &[u32],
    window: impl Fn(&Run) -> Range<usize>,
    spreads: &[f64],
) -> Lost {
    Lost {
        lost: which(runs, estimates, window, spreads).len(),
        runs: runs.len(),
        restarted: restarts.iter().filter(|&&r| r > 0).count(),
        most_restarts: restarts.iter().copied().max().unwrap_or(0),
        floor_lost: 0,
    }
}

/// An observer's lost runs on each set it is judged on; `None` where the design has no such set or
/// the observer is not run on it (a reference on the tuning and long runs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct LostRuns {
    /// The validation runs.
    pub validation: Lost,
    /// The tuning runs.
    pub tuning: Option<Lost>,
    /// The scenario's noise draws.
    pub scenario_draws: Option<Lost>,
    /// The mismatch runs (plants at the corners of the uncertain parameters' box).
    pub mismatch: Option<Lost>,
    /// The long runs.
    pub long: Option<Lost>,
}

/// Which runs an observer lost on the sets the floor is run on ([`which`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LostWhich {
    /// On the validation runs.
    pub validation: Vec<usize>,
    /// On the scenario's noise draws.
    pub scenario_draws: Vec<usize>,
    /// On the mismatch runs.
    pub mismatch: Vec<usize>,
}

impl LostRuns {
    /// Sets [`Lost::floor_lost`] on the sets the floor is run on: how many of the runs `mine` (this
    /// observer's lost runs) are among `floor`'s.
    pub fn with_floor(&mut self, mine: &LostWhich, floor: &LostWhich) {
        let shared = |a: &[usize], b: &[usize]| a.iter().filter(|i| b.contains(i)).count();
        self.validation.floor_lost = shared(&mine.validation, &floor.validation);
        if let Some(l) = self.scenario_draws.as_mut() {
            l.floor_lost = shared(&mine.scenario_draws, &floor.scenario_draws);
        }
        if let Some(l) = self.mismatch.as_mut() {
            l.floor_lost = shared(&mine.mismatch, &floor.mismatch);
        }
    }

    /// The sets with a run lost beyond the floor ([`Lost::beyond_floor`]), by the names the report
    /// gives them, with their counts: validation, then the scenario's draws, the mismatch runs and the
    /// long runs (the tuning runs are where constants were chosen, not where a kind is judged).
    pub fn judged(&self) -> Vec<(&'static str, Lost)> {
        self.judged_sets()
            .into_iter()
            .filter_map(|(set, lost)| lost.filter(|l| l.beyond_floor() > 0).map(|l| (set, l)))
            .collect()
    }

    /// The sets a kind is judged on, by the names the report gives them, in [`Self::judged`]'s order:
    /// `None` where the observer is not run on the set.
    pub fn judged_sets(&self) -> [(&'static str, Option<Lost>); 4] {
        [
            ("validation", Some(self.validation)),
            ("scenario draws", self.scenario_draws),
            ("mismatch", self.mismatch),
            ("long", self.long),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A one-target run whose truth is 0 at every sample, and estimates `values`.
    fn run(values: &[f64]) -> (Run, Rows) {
        let mut targets = Rows::new(1);
        let mut estimates = Rows::new(1);
        for &v in values {
            targets.push(&[0.0]);
            estimates.push(&[v]);
        }
        let empty = Rows::new(0);
        let run = Run {
            states: empty.clone(),
            inputs: empty.clone(),
            measurements: empty,
            targets,
            parameters: Vec::new(),
        };
        (run, estimates)
    }

    #[test]
    fn a_run_is_lost_when_its_last_quarter_is_off_by_more_than_half_the_spread() {
        // 12 judged samples: the last quarter is the last 3. Spread 1: lost above an RMSE of 1.
        let mut values = vec![0.0; 12];
        let (r, e) = run(&values);
        assert!(!is_lost(&r, &e, 0..12, &[1.0]));
        // Off by 5 early on, then back: not lost (the pooled RMSE would have counted it).
        values[..9].fill(5.0);
        let (r, e) = run(&values);
        assert!(!is_lost(&r, &e, 0..12, &[1.0]));
        // RMSE over the last 3 of sqrt((1.1² · 3) / 3) = 1.1 > 1: lost; 0.9 is not.
        values[9..].fill(1.1);
        let (r, e) = run(&values);
        assert!(is_lost(&r, &e, 0..12, &[1.0]));
        values[9..].fill(0.9);
        let (r, e) = run(&values);
        assert!(!is_lost(&r, &e, 0..12, &[1.0]));
        // Two samples of 1.5 and one of 0: RMSE sqrt(4.5 / 3) = 1.22 > 1, though one sample is exact.
        values[9..].copy_from_slice(&[1.5, 0.0, 1.5]);
        let (r, e) = run(&values);
        assert!(is_lost(&r, &e, 0..12, &[1.0]));
    }

    #[test]
    fn a_tracker_keeps_the_latest_estimate_over_a_restart_and_none_over_a_refusal() {
        let mut tracker = Tracker::new(2);
        tracker.restarted(); // before any estimate: nothing to keep
        tracker.estimate([1.0, 2.0]);
        tracker.restarted();
        tracker.refused();
        tracker.restarted(); // after a refusal: still nothing
        tracker.estimate([3.0, 4.0]);
        let track = tracker.finish();
        assert_eq!(track.restarts, 3);
        let rows: Vec<Vec<f64>> = (0..track.rows.len()).map(|k| track.rows[k].to_vec()).collect();
        let nan = |r: &Vec<f64>| r.iter().all(|v| v.is_nan());
        assert!(nan(&rows[0]) && nan(&rows[3]) && nan(&rows[4]), "{rows:?}");
        assert_eq!(
            (&rows[1], &rows[2], &rows[5]),
            (&vec![1.0, 2.0], &vec![1.0, 2.0], &vec![3.0, 4.0])
        );
    }

    #[test]
    fn a_non_finite_estimate_loses_the_run_but_only_inside_the_window() {
        let mut values = vec![0.0; 10];
        values[0] = f64::NAN;
        let (r, e) = run(&values);
        // Before the first judged sample (the map's window filling): not counted.
        assert!(!is_lost(&r, &e, 1..10, &[1.0]));
        assert!(is_lost(&r, &e, 0..10, &[1.0]));
        values[0] = 0.0;
        values[4] = f64::INFINITY;
        let (r, e) = run(&values);
        assert!(is_lost(&r, &e, 1..10, &[1.0]));
    }

    #[test]
    fn a_set_counts_its_lost_and_its_restarted_runs() {
        let (good, good_rows) = run(&[0.0; 8]);
        let (off, off_rows) = run(&[3.0; 8]);
        // The first run restarted twice and ended well; the second was lost without a restart.
        let lost = count(
            &[good.clone(), off, good],
            &[good_rows.clone(), off_rows, good_rows],
            &[2, 0, 1],
            |r| 0..r.targets.len(),
            &[1.0],
        );
        let expected = Lost {
            lost: 1,
            runs: 3,
            restarted: 2,
            most_restarts: 2,
            floor_lost: 0,
        };
        assert_eq!(lost, expected);
        let counted = |lost, runs| Lost {
            lost,
            runs,
            ..Lost::default()
        };
        let runs = LostRuns {
            validation: lost,
            long: Some(counted(0, 4)),
            mismatch: Some(counted(2, 8)),
            ..LostRuns::default()
        };
        assert_eq!(runs.judged(), [("validation", lost), ("mismatch", counted(2, 8))]);
    }

    #[test]
    fn runs_the_floor_lost_too_are_shown_but_not_judged() {
        // Runs 1 and 3 off by 3 (lost), run 2 by 0.5 (kept); the floor lost runs 3 and 4.
        let (good, good_rows) = run(&[0.0; 8]);
        let (off, off_rows) = run(&[3.0; 8]);
        let (_, near_rows) = run(&[0.5; 8]);
        let runs = [good.clone(), off.clone(), good.clone(), off.clone(), off];
        let window = |r: &Run| 0..r.targets.len();
        let mine = which(
            &runs,
            &[
                good_rows.clone(),
                off_rows.clone(),
                near_rows,
                off_rows.clone(),
                good_rows.clone(),
            ],
            window,
            &[1.0],
        );
        assert_eq!(mine, [1, 3]);
        let floor = which(
            &runs,
            &[
                good_rows.clone(),
                good_rows.clone(),
                good_rows.clone(),
                off_rows.clone(),
                off_rows,
            ],
            window,
            &[1.0],
        );
        assert_eq!(floor, [3, 4]);
        let counted = |lost| Lost {
            lost,
            runs: 5,
            ..Lost::default()
        };
        let mut lost = LostRuns {
            validation: counted(2),
            scenario_draws: Some(counted(1)),
            long: Some(counted(1)),
            ..LostRuns::default()
        };
        lost.with_floor(
            &LostWhich {
                validation: mine.clone(),
                scenario_draws: vec![3],
                ..LostWhich::default()
            },
            &LostWhich {
                validation: floor,
                scenario_draws: vec![3],
                ..LostWhich::default()
            },
        );
        // Validation: 1 of its 2 lost runs shared with the floor, judged as 1; the draws' one run is the
        // floor's too, not judged; the long runs have no floor.
        assert_eq!((lost.validation.floor_lost, lost.validation.beyond_floor()), (1, 1));
        assert_eq!(lost.scenario_draws.map(|l| l.beyond_floor()), Some(0));
        let judged: Vec<_> = lost
            .judged()
            .into_iter()
            .map(|(set, l)| (set, l.beyond_floor()))
            .collect();
        assert_eq!(judged, [("validation", 1), ("long", 1)]);
    }
}
