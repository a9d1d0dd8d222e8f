//! The bench's part for the filters that start from a point (the box filters): their tuning
//! runs and search with the spec's fixed constants, and their figures on each scenario, from their
//! own start or from the observer start the scenario names.

use super::Bench;
use crate::data::{DataSet, Rows, Run};
use crate::observers::ekf;
use crate::observers::figures::{Beside, FromObserverStart, ObserverFigures, TRANSIENT_TIME};
use crate::observers::kind::FixedSection;
use crate::observers::score::{self, errors};
use crate::spec::FixedFilter;

impl Bench<'_> {
    /// Once the box filters are judged, and unless the spec sets `tuning.start_up`: the score's
    /// start-up lasts as long as the slowest of them takes to settle on the tuning runs' random
    /// starts ([`mod@score::settle`]), at least one horizon `N` and at most a run's estimates, and every
    /// kind judged so far has its terms taken again with it. The kinds after them are tuned on it.
    pub fn settle_start_up(&mut self) {
        if self.design.start_up.is_some() {
            return;
        }
        let runs = &self.result.runs.tuning.runs;
        let scoring = &self.scoring;
        let first = scoring.regimes.first;
        let Some(random) = scoring.regimes.random_starts() else {
            return;
        };
        let box_filters = crate::observers::kind::REGISTRY
            .iter()
            .filter(|k| k.filter_code.is_some())
            .map(|k| k.kind.name());
        let slowest = (self.observers.iter())
            .filter(|o| box_filters.clone().any(|name| name == o.kind) && !o.tuning_estimates.is_empty())
            .filter_map(|o| {
                let picked = random.iter().map(|&i| (&runs[i], &o.tuning_estimates[i]));
                score::settle(picked, first, &scoring.spreads, &scoring.weights).map(|s| (s, o.kind))
            })
            .max_by_key(|&(samples, _)| samples);
        let Some((samples, kind)) = slowest else {
            return;
        };
        let estimates = runs
            .iter()
            .map(|r| r.targets.len())
            .min()
            .unwrap_or(0)
            .saturating_sub(first);
        self.scoring
            .regimes
            .set_start_up(samples.max(self.design.map.horizon).min(estimates));
        self.scoring.start_up_by = score::StartUpBy::Settled(kind, samples);
        let scoring = &self.scoring;
        let judged = (self.observers.iter_mut()).chain(self.beside.iter_mut().map(|b| &mut b.figures));
        for o in judged.filter(|o| !o.tuning_estimates.is_empty()) {
            o.tuning_terms = scoring.terms(runs, &o.tuning_estimates);
        }
    }

    /// The tuning runs from random starts and from the box's edges (not the scenarios'): what the box
    /// filters' `Q` and `P(0)` are tuned on, by the score of that one regime (the random starts of
    /// [`crate::observers::score::regimes`]). Not the whole score: the box EKF's `Q` is also the
    /// map-started and the restarted EKF's, which the map starts near the truth; tuned on every regime,
    /// it traded their steady state for the box EKF's convergence from far starts (Example 1: the
    /// map-started EKF's validation RMSE 0.0877 / 0.1195 → 0.1146 / 0.1564, and over the scenario's
    /// draws 0.0512 / 0.0986 → 0.0921 / 0.1413). `auto` judges every box filter on every regime.
    pub fn random_tuning(&self) -> DataSet {
        let tuning = &self.result.runs.tuning;
        let random = self.design.tuning.trajectories;
        let scenarios = self.design.scenarios.len() * crate::data::SCENARIO_TUNING_RUNS;
        DataSet {
            runs: tuning.runs[..random]
                .iter()
                .chain(&tuning.runs[random + scenarios..])
                .cloned()
                .collect(),
            horizon: tuning.horizon,
        }
    }

    /// A box filter (its estimates by `estimator`, its state in `coordinates`) tuned on
    /// [`Bench::random_tuning`] but for the
    /// constants the spec fixes in its `section`, and its figures by `judge`. Where the spec fixes any, the
    /// same filter with every constant tuned is judged too, into [`Bench::beside`].
    ///
    /// A filter that cannot run with the constants the spec fixes (every candidate of the search
    /// diverges) is not left out in silence: [`Bench::refused`] says which constants and what happened.
    pub fn box_filter(
        &mut self,
        estimator: ekf::Estimator,
        coordinates: &crate::plant::Coordinates,
        section: FixedSection,
        judge: &dyn Fn(&Self, &ekf::Tuned) -> ObserverFigures,
    ) -> Option<(ekf::Tuned, ObserverFigures)> {
        let fixed = section.of(self.design);
        let random = self.random_tuning();
        let random_scoring = score::Scoring {
            regimes: score::Regimes::whole(self.design.map.horizon - 1, random.runs.len()),
            ..self.scoring.clone()
        };
        let learning = &self.result.runs.learning;
        let tune = |fixed: &FixedFilter| {
            ekf::tune_with(
                estimator,
                fixed,
                self.design,
                self.code,
                coordinates,
                &random,
                learning,
                &random_scoring,
            )
        };
        // A fixed start outside the model's domain is refused as such: a filter that restarts there at
        // every sample would hold its one estimate and score as merely lost.
        let outside = fixed
            .x0
            .as_ref()
            .is_some_and(|x0| !self.one_sample(x0, &random).iter().all(|v| v.is_finite()));
        let tuned = if outside { None } else { tune(fixed) };
        let Some(tuned) = tuned else {
            if fixed.any() && ekf::supported(self.code) && self.refused.is_none() {
                self.refused = Some(self.cannot_run(section.section, fixed, &random));
            }
            return None;
        };
        let figures = judge(self, &tuned);
        if fixed.any() {
            if let Some(all) = tune(&FixedFilter::default()) {
                let figures = judge(self, &all);
                self.beside.push(Beside { tuned: all, figures });
            }
        }
        Some((tuned, figures))
    }

    /// Why the filter of `[section]` cannot run with the constants the spec fixes there (`fixed`):
    /// which constants, and what the model does one sample after the filter's start on the first
    /// tuning run (not finite: the start is outside the model's domain), or else that every candidate
    /// of the search diverged on the tuning runs.
    fn cannot_run(&self, section: &str, fixed: &FixedFilter, random: &DataSet) -> crate::spec::SpecError {
        let design = self.design;
        let given: Vec<String> = [
            ("x0", fixed.x0.is_some()),
            ("q", fixed.q.is_some()),
            ("p0", fixed.p0.is_some()),
        ]
        .iter()
        .filter(|(_, given)| *given)
        .map(|(name, _)| format!("`{section}.{name}`"))
        .collect();
        let field = match (&fixed.x0, &fixed.q) {
            (Some(_), _) => format!("{section}.x0"),
            (None, Some(_)) => format!("{section}.q"),
            (None, None) => format!("{section}.p0"),
        };
        let start = ekf::start(design, fixed);
        let x = self.one_sample(&start, random);
        let state = |values: &[f64]| {
            let pairs: Vec<String> = design
                .model
                .states
                .iter()
                .zip(values)
                .map(|(name, v)| format!("{name} = {v:e}"))
                .collect();
            pairs.join(", ")
        };
        let what = if x.iter().all(|v| v.is_finite()) {
            format!(
                "from its start ({}) its estimates diverge (or every sample is refused) on every tuning run, whatever the constants left to tune",
                state(&start)
            )
        } else {
            format!(
                "one sample after its start ({}) the model is not finite ({}): the start is outside the model's domain",
                state(&start),
                state(&x)
            )
        };
        design.error(
            field,
            format!(
                "the filter cannot run with the constants the spec fixes ({}): {what}; its kinds would be left out of the comparison and the crate",
                given.join(", ")
            ),
            "start it where the model is defined (inside the learning box), give a larger p0 or q, or leave the constants out to have them tuned",
        )
    }

    /// The plant's state one sample after `start`, with the first tuning run's first input.
    fn one_sample(&self, start: &[f64], random: &DataSet) -> Vec<f64> {
        let design = self.design;
        let mut x = start.to_vec();
        let inputs = random.runs.first().and_then(|run| run.inputs.iter().next());
        crate::data::simulate::Integrator::new(&design.model, design.tau, design.substeps)
            .advance(&mut x, inputs.unwrap_or(&[]));
        x
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
