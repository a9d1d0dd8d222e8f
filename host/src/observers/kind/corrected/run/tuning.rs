//! The model-corrected map's tuning: the closed-loop search for its gains on the tuning runs, apart
//! from the observer it tunes ([`super`]), which every other caller runs with gains already chosen.
//!
//! # Tuning
//!
//! `(G, K, K₀, ln T)` minimises the [score](crate::observers::score) on the tuning runs (pooled RMSE and the
//! 95th percentile over runs, per target over its spread, over the tuning set's regimes; a lost run
//! first), the same criterion as the EKF's, by
//! Nelder–Mead (`argmin`) from a few fixed starts (closed loop: the
//! one-step least-squares criterion is not the closed-loop one), once with `G` free and once with
//! `G = 0` (no map after the start-up: the chip's steady sample is then the model and `K` alone);
//! `G = 0` is kept unless `G` free does better by more than
//! [`CHEAPER_WITHIN`](crate::observers::CHEAPER_WITHIN). Deterministic: fixed starts, fixed iterations, the best
//! of the starts by cost, the first of equals.

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::neldermead::NelderMead;

use crate::data::{DataSet, Rows};
use crate::observers::kind::corrected::program::{correction_code, CorrectionConstants};
use crate::observers::score::Scoring;

use super::{estimate_rows, Setting};

/// The tuned observer and how it was chosen.
#[derive(Clone, Debug)]
pub struct Tuned {
    /// The constants.
    pub constants: CorrectionConstants,
    /// The criterion there (the [score](crate::observers::score) on the tuning runs).
    pub cost: f64,
    /// The criterion at the best start before the search.
    pub start_cost: f64,
    /// Cost evaluations over every start.
    pub evaluations: u64,
    /// The best criterion with `G` free (the chip reads the map after the start-up where `G ≠ 0`).
    pub cost_with_map: f64,
    /// The best with `G = 0` (no map after the start-up): chosen when within
    /// [`CHEAPER_WITHIN`](crate::observers::CHEAPER_WITHIN) of [`Tuned::cost_with_map`].
    pub cost_without_map: f64,
}

/// The closed-loop criterion over a data set whose map estimates are given.
struct Criterion<'a> {
    /// Evaluations so far.
    count: &'a std::sync::atomic::AtomicU64,
    setting: &'a Setting<'a>,
    data: &'a DataSet,
    maps: &'a [Rows],
    /// What the tuning runs are scored with.
    scoring: &'a Scoring,
    /// Whether `G = 0` is fixed (and left out of `θ`): the chip reads no map after the start-up.
    without_map: bool,
}

impl Criterion<'_> {
    /// The [score](crate::observers::score) with `constants`.
    fn score(&self, constants: &CorrectionConstants) -> f64 {
        self.count.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let code = correction_code(self.setting.code, constants);
        let estimates: Vec<Rows> = self
            .data
            .runs
            .iter()
            .zip(self.maps)
            .map(|(run, map)| estimate_rows(self.setting, &code, constants, map, run).rows)
            .collect();
        let score = self.scoring.score(&self.data.runs, &estimates).objective();
        // A diverging candidate is the worst, not an infinity that Nelder–Mead cannot order.
        score.min(1e30)
    }
}

impl CostFunction for Criterion<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, theta: &Self::Param) -> Result<f64, argmin::core::Error> {
        Ok(self.score(&self.constants(theta)))
    }
}

impl Criterion<'_> {
    /// The constants `θ` stands for: `(G, K, K₀, ln T)`, or `(K, K₀, ln T)` with `G = 0`.
    fn constants(&self, theta: &[f64]) -> CorrectionConstants {
        if self.without_map {
            let mut full = vec![0.0; self.setting.code.dimensions.states];
            full.extend_from_slice(theta);
            self.setting.constants(&full)
        } else {
            self.setting.constants(theta)
        }
    }
}

/// Nelder–Mead iterations per start.
const ITERATIONS: u64 = 500;

/// Chooses the gains on `tuning` (its map estimates `maps`), see the module docs, scored by `scoring`.
pub fn tune(setting: &Setting<'_>, tuning: &DataSet, maps: &[Rows], scoring: &Scoring) -> Tuned {
    use rayon::prelude::*;
    let (nx, ny) = (setting.code.dimensions.states, setting.code.dimensions.outputs);
    // Starts: the paper's blend at three strengths, and two constant-gain observers.
    let start = |g: f64, k: f64, schedule: f64| -> Vec<f64> {
        let mut theta = vec![g; nx];
        theta.extend(std::iter::repeat_n(k, 2 * nx * ny)); // K₀ = K: a constant gain
        theta.push(schedule.ln());
        theta
    };
    let starts = [
        start(0.5, 0.0, 3.0),
        start(0.2, 0.0, 3.0),
        start(0.05, 0.0, 10.0),
        start(0.05, 0.1, 3.0),
        start(0.0, 0.05, 2.0),
    ];
    let count = std::sync::atomic::AtomicU64::new(0);
    let criterion = |without_map| Criterion {
        count: &count,
        setting,
        data: tuning,
        maps,
        scoring,
        without_map,
    };
    let start_cost = starts
        .iter()
        .map(|theta| criterion(false).score(&setting.constants(theta)))
        .fold(f64::INFINITY, f64::min);
    // Every start twice: `G` free, and `G = 0` fixed (the same start without its `G`).
    let searches: Vec<(bool, Vec<f64>)> = starts
        .iter()
        .flat_map(|theta| [(false, theta.clone()), (true, theta[nx..].to_vec())])
        .collect();
    let results: Vec<(bool, Vec<f64>, f64)> = searches
        .into_par_iter()
        .map(|(without_map, theta)| {
            let criterion = criterion(without_map);
            // The initial simplex: the start and one step along each coordinate.
            let simplex: Vec<Vec<f64>> = std::iter::once(theta.clone())
                .chain((0..theta.len()).map(|i| {
                    let mut vertex = theta.clone();
                    vertex[i] += if i == theta.len() - 1 { 1.0 } else { 0.1 };
                    vertex
                }))
                .collect();
            let solver = NelderMead::new(simplex)
                .with_sd_tolerance(1e-5)
                .expect("a non-negative tolerance");
            let result = Executor::new(criterion, solver)
                .configure(|state| state.max_iters(ITERATIONS))
                .run()
                .expect("the criterion does not fail");
            let state = result.state();
            let best = state.get_best_param().cloned().unwrap_or(theta);
            (without_map, best, state.get_best_cost())
        })
        .collect();
    let best = |without_map: bool| {
        results
            .iter()
            .filter(|r| r.0 == without_map)
            .fold(None, |best: Option<&(bool, Vec<f64>, f64)>, r| match best {
                Some(b) if b.2 <= r.2 => Some(b),
                _ => Some(r),
            })
            .expect("every start was searched")
    };
    let (free, without) = (best(false), best(true));
    // Reading the map after the start-up costs the chip the map's evaluation every sample: it must
    // pay for itself by more than `CHEAPER_WITHIN`, the rule `auto` applies between kinds.
    let chosen = if without.2 <= free.2 * (1.0 + crate::observers::CHEAPER_WITHIN) {
        without
    } else {
        free
    };
    Tuned {
        constants: criterion(chosen.0).constants(&chosen.1),
        cost: chosen.2,
        start_cost,
        evaluations: count.into_inner(),
        cost_with_map: free.2,
        cost_without_map: without.2,
    }
}
