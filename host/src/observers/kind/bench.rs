//! The bench every kind is tuned and judged on: the design, its fit and runs, its model, the map's
//! estimates on every run (computed once: every kind after the map reads them), and the constants of
//! the kinds tuned so far. [`Bench::judge`] gives one kind's figures on every set of runs.

use crate::data::{DataSet, Rows, Run};
use crate::fit::DesignResult;
use crate::plant::ModelCode;
use crate::search::cost::{self, Cost};
use crate::spec::{Design, ObserverKind};

use super::tuned::TunedKinds;
use std::collections::BTreeMap;

use crate::observers::figures::{Beside, FromObserverStart, ObserverFigures};
use crate::observers::lost::Track;
use crate::observers::score;

mod figures;
mod filters;

/// See the module's documentation.
pub struct Bench<'a> {
    /// The design.
    pub design: &'a Design,
    /// Its fit, and every run ([`crate::data::Runs`]).
    pub result: &'a DesignResult,
    /// Its model as programs.
    pub code: &'a ModelCode,
    /// What every tuning criterion and `auto` score the tuning runs with: each target's spread over
    /// them (the tuning runs are the only data any constant is chosen on), its weight, and the
    /// tuning set's regimes.
    pub scoring: score::Scoring,
    /// The map's predicted cost.
    pub map_cost: Cost,
    /// The predicted cost of the map the map-started kinds read: the targets' and the helpers' rows
    /// ([`crate::fit::helpers`]); the map's own where every state is a target.
    pub start_map_cost: Cost,
    /// The figures of the kinds judged so far, in registry order (the map's first).
    pub observers: Vec<ObserverFigures>,
    /// What tuning gave each kind tuned so far (a kind reads the constants of those before it).
    pub tuned: TunedKinds,
    /// Why the design cannot have a kind, where its tuning says why (the report shows it).
    pub unavailable: BTreeMap<ObserverKind, String>,
    /// Each filter the spec fixes constants of, with every constant tuned instead.
    pub beside: Vec<Beside>,
    /// The box filters from each scenario's `observer_x0` ([`Bench::from_observer_start`]).
    pub from_observer_start: Vec<FromObserverStart>,
    /// Why a filter cannot run with the constants the spec fixes ([`Bench::box_filter`]): `gen`
    /// stops with it rather than leave the filter's kinds out.
    pub refused: Option<crate::spec::SpecError>,
    /// The map's estimates on every run: the targets', then the helpers' ([`DesignResult::start_maps`]).
    maps: MapRows,
}

/// One observer's estimates on every set of [`crate::data::Runs`].
struct Estimates {
    validation: Vec<Rows>,
    scenario: Rows,
    scenarios: Vec<Rows>,
    tuning: Vec<Rows>,
    draws: Option<Vec<Rows>>,
    /// On the corners, the nominal plant and the long runs at the last corner; the mismatch scenario.
    mismatch: Option<([Vec<Rows>; 3], Rows)>,
    long: Vec<Rows>,
    /// The restarts on each run of the sets whose lost runs are counted.
    restarts: Restarts,
}

/// The restarts on each run of a set, for the sets of [`LostRuns`] (empty where the observer never
/// restarts or the set is not run).
#[derive(Default)]
struct Restarts {
    validation: Vec<u32>,
    tuning: Vec<u32>,
    draws: Vec<u32>,
    corners: Vec<u32>,
    long: Vec<u32>,
}

/// Tracks as their rows and their restarts, run by run.
fn split(tracks: Vec<Track>) -> (Vec<Rows>, Vec<u32>) {
    tracks.into_iter().map(|t| (t.rows, t.restarts)).unzip()
}

/// The map's estimates on every run of [`crate::data::Runs`], set by set.
struct MapRows {
    validation: Vec<Rows>,
    tuning: Vec<Rows>,
    scenario: Rows,
    scenarios: Vec<Rows>,
    draws: Option<Vec<Rows>>,
    /// On the corners, the nominal plant and the long runs at the last corner; the mismatch scenario.
    mismatch: Option<([Vec<Rows>; 3], Rows)>,
    long: Vec<Rows>,
}

impl<'a> Bench<'a> {
    /// The bench of a fitted design, before any kind is tuned.
    pub fn new(design: &'a Design, result: &'a DesignResult, code: &'a ModelCode) -> Self {
        let runs = &result.runs;
        let horizon = design.map.horizon;
        let on = |set: &DataSet| -> Vec<Rows> { set.runs.iter().map(|r| map_estimates(result, horizon, r)).collect() };
        let maps = MapRows {
            validation: on(&runs.validation),
            tuning: on(&runs.tuning),
            scenario: map_estimates(result, horizon, &runs.scenario),
            scenarios: runs
                .scenarios
                .iter()
                .map(|r| map_estimates(result, horizon, r))
                .collect(),
            draws: runs.scenario_draws.as_ref().map(on),
            mismatch: runs.mismatch.as_ref().map(|m| {
                (
                    [on(&m.corners_set), on(&m.nominal_set), on(&m.long)],
                    map_estimates(result, horizon, &m.scenario),
                )
            }),
            long: on(&runs.long),
        };
        let spreads: Vec<f64> = result
            .targets
            .iter()
            .map(|t| crate::fit::evaluate::evaluate(&runs.tuning, t.index, &t.fit).target_spread)
            .collect();
        let fitted: Vec<&crate::fit::maps::FittedMap> = result.targets.iter().map(|t| &t.fit.map).collect();
        let start_maps: Vec<&crate::fit::maps::FittedMap> = result.start_maps().map(|t| &t.fit.map).collect();
        let mut scoring = score::Scoring::of_tuning(design, &spreads, runs.tuning.runs.len());
        scoring.constant = constant_score(&scoring, &runs.tuning.runs, horizon - 1);
        Bench {
            design,
            result,
            code,
            scoring,
            map_cost: cost::of_maps(&fitted, horizon, design.tau),
            start_map_cost: cost::of_maps(&start_maps, horizon, design.tau),
            observers: Vec::new(),
            tuned: TunedKinds::default(),
            unavailable: BTreeMap::new(),
            beside: Vec::new(),
            refused: None,
            from_observer_start: Vec::new(),
            maps,
        }
    }

    /// The windows every figure is over: from the map's first estimate to the run's end.
    pub fn windows(&self) -> impl Fn(&Run) -> std::ops::Range<usize> + Copy {
        let first = self.design.map.horizon - 1;
        move |run: &Run| first..run.targets.len()
    }

    /// The map row of every state ([`crate::fit::helpers::state_maps`]), or `None` where a helper map
    /// could not be fitted (the corrected kind records why).
    pub fn state_maps(&self) -> Option<Vec<usize>> {
        self.result
            .helpers
            .is_ok()
            .then(|| crate::fit::helpers::state_maps(self.design))
    }

    /// The mean squared error over the tuning runs' windows of map row `row` as an estimate of state
    /// `state` (a helper map's: a target's is among the map's figures).
    pub fn helper_mean_squared_error(&self, state: usize, row: usize) -> f64 {
        let (mut sum, mut count) = (0.0, 0usize);
        for (run, map) in self.result.runs.tuning.runs.iter().zip(&self.maps.tuning) {
            for k in self.windows()(run) {
                sum += (map[k][row] - run.states[k][state]).powi(2);
                count += 1;
            }
        }
        sum / count.max(1) as f64
    }

    /// The tuning runs' map estimates, run by run.
    pub fn tuning_maps(&self) -> &[Rows] {
        &self.maps.tuning
    }

    /// `estimate(run, map)` on every tuning run (`map`: the map's estimates on `run`).
    pub fn on_tuning(&self, estimate: impl Fn(&Run, &Rows) -> Rows) -> Vec<Rows> {
        let runs = &self.result.runs.tuning.runs;
        runs.iter()
            .zip(&self.maps.tuning)
            .map(|(r, m)| estimate(r, m))
            .collect()
    }

    /// The [score](score::Score::objective) of `estimates`, one per tuning run, its lost runs counted
    /// first.
    pub fn tuning_score(&self, estimates: &[Rows]) -> f64 {
        self.scoring.score(&self.result.runs.tuning.runs, estimates).objective()
    }

    /// One kind's figures on every set: `estimate(run, map)` is its estimate of every target at every
    /// sample of `run` (`map`: the map's estimates on `run`), every run from where the kind starts on
    /// the chip, with its restarts; the runs of a set in parallel.
    pub fn judge(
        &self,
        kind: &'static str,
        instructions: f64,
        estimate: &(dyn Fn(&Run, &Rows) -> Track + Sync),
    ) -> ObserverFigures {
        use rayon::prelude::*;
        let runs = &self.result.runs;
        let maps = &self.maps;
        let on = |set: &DataSet, maps: &[Rows]| -> (Vec<Rows>, Vec<u32>) {
            split(set.runs.par_iter().zip(maps).map(|(r, m)| estimate(r, m)).collect())
        };
        let rows = |run: &Run, map: &Rows| estimate(run, map).rows;
        let scenario = rows(&runs.scenario, &maps.scenario);
        let (validation, on_validation) = on(&runs.validation, &maps.validation);
        let (tuning, on_tuning) = on(&runs.tuning, &maps.tuning);
        let (draws, on_draws) = match runs.scenario_draws.as_ref().zip(maps.draws.as_ref()) {
            Some((d, m)) => {
                let (rows, restarts) = on(d, m);
                (Some(rows), restarts)
            }
            None => (None, Vec::new()),
        };
        let (long, on_long) = on(&runs.long, &maps.long);
        let mut on_corners = Vec::new();
        let mismatch = runs
            .mismatch
            .as_ref()
            .zip(maps.mismatch.as_ref())
            .map(|(m, (on_m, map))| {
                let corners;
                (corners, on_corners) = on(&m.corners_set, &on_m[0]);
                (
                    [corners, on(&m.nominal_set, &on_m[1]).0, on(&m.long, &on_m[2]).0],
                    rows(&m.scenario, map),
                )
            });
        let estimates = Estimates {
            validation,
            // The first scenario's run is the scenario's: its estimates are taken once.
            scenarios: (runs.scenarios.iter().zip(&maps.scenarios).enumerate())
                .map(|(i, (r, m))| if i == 0 { scenario.clone() } else { rows(r, m) })
                .collect(),
            scenario,
            tuning,
            draws,
            mismatch,
            long,
            restarts: Restarts {
                validation: on_validation,
                tuning: on_tuning,
                draws: on_draws,
                corners: on_corners,
                long: on_long,
            },
        };
        self.figures(kind, instructions, estimates, true)
    }

    /// A host-only reference's figures ([`super::super::references`]): `estimate(run, stream)` on the
    /// validation runs, the scenario, its draws and the mismatch runs but the long ones, in parallel
    /// (`stream`: a number of its own for every run, the same every time: validation run `i` is on
    /// stream `i`), but for the validation runs when their estimates are given. The tuning and long
    /// runs' figures are NaN: no reference is tuned on them or judged for drift.
    pub fn judge_reference(
        &self,
        name: &'static str,
        validation: Option<Vec<Rows>>,
        estimate: &(dyn Fn(&Run, u64) -> Rows + Sync),
    ) -> ObserverFigures {
        use rayon::prelude::*;
        let runs = &self.result.runs;
        let on = |set: &DataSet, first: u64| -> Vec<Rows> {
            set.runs
                .par_iter()
                .enumerate()
                .map(|(i, r)| estimate(r, first + i as u64))
                .collect()
        };
        let skipped = |set: &DataSet| -> Vec<Rows> {
            set.runs
                .iter()
                .map(|r| {
                    let mut rows = Rows::new(self.design.targets.len());
                    let nan = vec![f64::NAN; self.design.targets.len()];
                    (0..r.targets.len()).for_each(|_| rows.push(&nan));
                    rows
                })
                .collect()
        };
        // Each set's runs on streams of their own.
        const SET: u64 = 1 << 32;
        let scenario = estimate(&runs.scenario, SET);
        let estimates = Estimates {
            validation: validation.unwrap_or_else(|| on(&runs.validation, 0)),
            scenarios: (runs.scenarios.iter().enumerate())
                .map(|(i, r)| {
                    if i == 0 {
                        scenario.clone()
                    } else {
                        estimate(r, 6 * SET + i as u64)
                    }
                })
                .collect(),
            scenario,
            tuning: skipped(&runs.tuning),
            draws: runs.scenario_draws.as_ref().map(|d| on(d, 2 * SET)),
            mismatch: runs.mismatch.as_ref().map(|m| {
                (
                    [
                        on(&m.corners_set, 3 * SET),
                        on(&m.nominal_set, 4 * SET),
                        skipped(&m.long),
                    ],
                    estimate(&m.scenario, 5 * SET),
                )
            }),
            long: skipped(&runs.long),
            restarts: Restarts::default(),
        };
        self.figures(name, f64::NAN, estimates, false)
    }
}

/// The map's estimate of every target, then of every helper state ([`DesignResult::start_maps`]),
/// at every sample of `run` (NaN before the window is full).
pub fn map_estimates(result: &DesignResult, horizon: usize, run: &Run) -> Rows {
    let data = DataSet {
        runs: vec![run.clone()],
        horizon,
    };
    let width = result.start_maps().count();
    let mut rows = Rows::new(width);
    let mut z = Vec::new();
    for _ in 0..horizon.saturating_sub(1).min(run.targets.len()) {
        rows.push(&vec![f64::NAN; width]);
    }
    for window in data.windows() {
        data.regressor(window, &mut z);
        let values: Vec<f64> = result.start_maps().map(|t| t.fit.map.estimate(&z).value).collect();
        rows.push(&values);
    }
    rows
}

/// The tuning score of the constant estimate: each target's mean over the tuning runs' windows (from
/// sample `first`), at every sample: what a kind must beat to explain anything.
fn constant_score(scoring: &score::Scoring, runs: &[Run], first: usize) -> f64 {
    let width = scoring.spreads.len();
    let (mut sums, mut count) = (vec![0.0; width], 0usize);
    for run in runs {
        for k in first..run.targets.len() {
            sums.iter_mut().zip(&run.targets[k]).for_each(|(s, v)| *s += v);
            count += 1;
        }
    }
    let means: Vec<f64> = sums.iter().map(|s| s / count.max(1) as f64).collect();
    let estimates: Vec<Rows> = (runs.iter())
        .map(|run| {
            let mut rows = Rows::new(width);
            (0..run.targets.len()).for_each(|_| rows.push(&means));
            rows
        })
        .collect();
    scoring.score(runs, &estimates).value
}

/// The first `width` entries of every row of `rows` (the map's targets of its rows with helpers).
pub fn first_columns(rows: &Rows, width: usize) -> Rows {
    let mut out = Rows::new(width);
    rows.iter().for_each(|row| out.push(&row[..width]));
    out
}
