//! The bench's part for the filters that start from a point (`ekf_box`, `ukf_box`): their tuning
//! runs and search with the spec's fixed constants, and their figures on each scenario, from their
//! own start or from the observer start the scenario names.

use super::Bench;
use crate::data::{DataSet, Rows, Run};
use crate::observers::ekf;
use crate::observers::figures::{Beside, FromObserverStart, ObserverFigures, TRANSIENT_TIME};
use crate::observers::score::errors;
use crate::spec::FixedFilter;

impl Bench<'_> {
    /// The tuning runs from random starts: what the box filters (`ekf_box`, `ukf_box`) are tuned on.
    pub fn random_tuning(&self) -> DataSet {
        let tuning = &self.result.runs.tuning;
        DataSet {
            runs: tuning.runs[..self.design.tuning.trajectories].to_vec(),
            horizon: tuning.horizon,
        }
    }

    /// A box filter (its estimates by `estimator`) tuned on [`Bench::random_tuning`] but for the
    /// constants the spec fixes (`fixed`), and its figures by `judge`. Where the spec fixes any, the
    /// same filter with every constant tuned is judged too, into [`Bench::beside`].
    pub fn box_filter(
        &mut self,
        estimator: ekf::Estimator,
        fixed: &FixedFilter,
        judge: &dyn Fn(&Self, &ekf::Tuned) -> ObserverFigures,
    ) -> Option<(ekf::Tuned, ObserverFigures)> {
        let random = self.random_tuning();
        let learning = &self.result.runs.learning;
        let tune = |fixed: &FixedFilter| {
            ekf::tune_with(
                estimator,
                fixed,
                self.design,
                self.code,
                &random,
                learning,
                &self.spreads,
            )
        };
        let tuned = tune(fixed)?;
        let figures = judge(self, &tuned);
        if fixed.any() {
            if let Some(all) = tune(&FixedFilter::default()) {
                let figures = judge(self, &all);
                self.beside.push(Beside { tuned: all, figures });
            }
        }
        Some((tuned, figures))
    }

    /// [`Bench::scenario_errors`] along scenario `i`'s run (in the spec's order).
    pub fn on_scenario(&self, i: usize, rows: &Rows) -> Vec<(f64, f64)> {
        self.scenario_errors(&self.result.runs.scenarios[i], rows)
    }

    /// Per target, the RMSE of `rows` (estimates along `run`) over the run's windows and over its
    /// transient (its first [`TRANSIENT_TIME`] time units from the map's first estimate).
    pub fn scenario_errors(&self, run: &Run, rows: &Rows) -> Vec<(f64, f64)> {
        let run = std::slice::from_ref(run);
        let rows = std::slice::from_ref(rows);
        let horizon = self.design.map.horizon;
        let transient = (TRANSIENT_TIME / self.design.tau).round() as usize;
        (0..self.design.targets.len())
            .map(|t| {
                let whole = errors(run, rows, t, self.windows()).0;
                let start = errors(run, rows, t, |run| {
                    horizon - 1..horizon.saturating_add(transient).min(run.targets.len())
                });
                (whole, start.0)
            })
            .collect()
    }

    /// A box filter (kind `kind`) on every scenario that names an observer start, started there by
    /// `estimate(x0, run)`: into [`Bench::from_observer_start`].
    pub fn from_observer_starts(&mut self, kind: &'static str, estimate: &dyn Fn(&[f64], &Run) -> Rows) {
        for (i, scenario) in self.design.scenarios.iter().enumerate() {
            let Some(x0) = &scenario.observer_x0 else { continue };
            let rows = estimate(x0, &self.result.runs.scenarios[i]);
            let targets = self.on_scenario(i, &rows);
            self.from_observer_start.push(FromObserverStart {
                kind,
                scenario: i,
                targets,
            });
        }
    }
}
