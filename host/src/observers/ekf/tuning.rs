//! The EKF's tuning: the search for its `Q` and `P(0)`, and for the map-started EKF's start
//! covariance, on the tuning runs. Kept apart from the filter it tunes ([`super`]), which every
//! other caller runs with constants already chosen.
//!
//! # Tuning, as an expert tunes a filter
//!
//! `R` is the outputs' noise variances (the spec states them) and the filter starts at the centre of
//! the state box. `Q` and `P(0)` are diagonal, one free value per state, searched in log-space and
//! scaled by `s_i²`, `s_i` the spread of state `i` over the learning runs (its range; 1 where it
//! never moves), so that the search's steps mean the same for every state:
//!
//! ```text
//! Q = diag(10^{a_i} s_i²),   P(0) = diag(10^{b_i} s_i²),   θ = (a, b) ∈ [−12, 3]^{2 n_x}.
//! ```
//!
//! `θ` minimises the [score](crate::observers::score) (pooled RMSE and the 95th percentile over runs, per
//! target, over its spread, averaged over the tuning set's regimes: random starts, each scenario's
//! start, the start-up) on the tuning runs, the criterion every kind and `auto` share: first on an
//! isotropic decade grid (`a_i = a`,
//! `b_i = b`, `a ∈ {−8…0}`, `b ∈ {−3…0}`), then by Nelder–Mead (`argmin`) from the
//! [`STARTS`] best grid points, each coordinate free (until the simplex's scores agree within
//! 1e-4). Deterministic: a fixed grid, fixed starts and iterations, the best by cost and the first
//! of equals. The map-started EKF shares `Q` (one filter
//! on the chip) and scales its own start covariance ([`tune_started`]).
//!
//! Then the χ² watch's threshold `τ` (`firmware::watch`, over a window of `N` samples, the map's
//! horizon) from [`WATCH_THRESHOLDS`] on the same runs, the constants above fixed: the lowest score,
//! of equals the largest finite `τ` (where no restart fires on the tuning runs, the watch that
//! interferes least), no watch (`τ = ∞`) only where it is strictly best.

use crate::data::{DataSet, Rows};
use crate::observers::score::Scoring;
use crate::plant::kalman::EkfConstants;
use crate::plant::ModelCode;
use crate::spec::{Design, FixedFilter};

use super::{constants, estimates, spreads_in, start, supported, LOG_RANGE};

/// The tuned filter and how it was chosen.
#[derive(Clone, Debug)]
pub struct Tuned {
    /// The constants the design's EKF is emitted with.
    pub constants: EkfConstants,
    /// `a`: `log10(Q_ii / s_i²)` per state (of the spec's `Q` where it fixes it).
    pub log_q: Vec<f64>,
    /// `b`: `log10(P(0)_ii / s_i²)` per state (of the spec's `P(0)` where it fixes it).
    pub log_p0: Vec<f64>,
    /// The constants the spec fixed (`"x0"`, `"q"`, `"p0"`): the search chose the others.
    pub fixed: Vec<&'static str>,
    /// The score at the choice (tuning runs).
    pub cost: f64,
    /// The score at the best point of the isotropic grid, before the search.
    pub grid_cost: f64,
    /// Score evaluations, grid and search.
    pub evaluations: u64,
    /// The tuning runs it was chosen on.
    pub runs: usize,
}

/// The watch thresholds [`tune_with`] tries, in the order that decides between equal scores: from
/// the most tolerant down, then no watch.
pub const WATCH_THRESHOLDS: [f64; 8] = [1024.0, 256.0, 64.0, 16.0, 8.0, 4.0, 2.0, f64::INFINITY];

/// Grid points the search starts from.
pub const STARTS: usize = 2;

/// Nelder–Mead iterations per start.
const ITERATIONS: u64 = 150;

/// A filter's estimates of every run of a data set, with given constants, from a given start: the
/// EKF's ([`super::estimates`]) or another box filter's (its kind's `run.rs`), which share their
/// constants and this search.
pub type Estimator = fn(&ModelCode, &EkfConstants, &[f64], &DataSet) -> Option<Vec<Rows>>;

/// The score of the filter with `constants` from the box centre on `data` (windows `k ≥ N − 1`), its
/// lost runs counted first ([`crate::observers::score::Score::objective`]): a candidate that loses a
/// tuning run never beats one that loses none.
fn score(
    estimator: Estimator,
    code: &ModelCode,
    constants: &EkfConstants,
    centre: &[f64],
    data: &DataSet,
    scoring: &Scoring,
) -> f64 {
    let estimates = estimator(code, constants, centre, data).expect("size checked");
    scoring.score(&data.runs, &estimates).objective()
}

/// The tuning criterion as `argmin` sees it: `θ` to the score.
#[derive(Clone, Copy)]
struct Criterion<'a> {
    estimator: Estimator,
    design: &'a Design,
    fixed: &'a FixedFilter,
    code: &'a ModelCode,
    centre: &'a [f64],
    spreads: &'a [f64],
    data: &'a DataSet,
    scoring: &'a Scoring,
    count: &'a std::sync::atomic::AtomicU64,
}

impl Criterion<'_> {
    fn at(&self, theta: &[f64]) -> f64 {
        self.count.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let constants = with_fixed(self.design, self.fixed, self.centre, self.spreads, theta);
        let score = score(
            self.estimator,
            self.code,
            &constants,
            self.centre,
            self.data,
            self.scoring,
        );
        // Nelder–Mead must be able to order a diverging candidate: the worst, not infinity.
        score.min(1e30)
    }
}

impl argmin::core::CostFunction for Criterion<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, theta: &Self::Param) -> Result<f64, argmin::core::Error> {
        Ok(self.at(theta))
    }
}

/// Chooses the EKF's `Q` and `P(0)` on `tuning` (see the module docs), those the spec does not fix
/// (`[observer.ekf]`). `target_spreads` normalises each target's errors.
pub fn tune(
    design: &Design,
    code: &ModelCode,
    tuning: &DataSet,
    learning: &DataSet,
    target_spreads: &[f64],
) -> Option<Tuned> {
    tune_with(
        estimates,
        design.filters.of("observer.ekf"),
        design,
        code,
        &crate::plant::Coordinates::plant(code.dimensions.states),
        tuning,
        learning,
        &Scoring::of_tuning(design, target_spreads, tuning.runs.len()),
    )
}

/// `θ = (a, b)` of the free coordinates `theta` (`a` unless the spec fixes `Q`, then `b` unless it
/// fixes `P(0)`), a fixed half given by the spec's covariance's place in the search's coordinates.
fn halves(fixed: &FixedFilter, spreads: &[f64], theta: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let n = spreads.len();
    let mut free = theta.iter().copied();
    let mut half = |fixed: &Option<crate::plant::Covariance>| match fixed {
        Some(covariance) => logs(covariance, spreads),
        None => free.by_ref().take(n).collect(),
    };
    (half(&fixed.q), half(&fixed.p0))
}

/// The constants of the free coordinates `theta` ([`halves`]) with the spec's `fixed` ones, started
/// at `start`.
fn with_fixed(design: &Design, fixed: &FixedFilter, start: &[f64], spreads: &[f64], theta: &[f64]) -> EkfConstants {
    let (a, b) = halves(fixed, spreads, theta);
    let mut constants = constants(design, start, spreads, &[a, b].concat());
    if let Some(q) = &fixed.q {
        constants.q = q.clone();
    }
    if let Some(p0) = &fixed.p0 {
        constants.p0 = p0.clone();
    }
    constants
}

/// `log10(c_ii / s_i²)` per state: where a covariance sits in the search's coordinates.
fn logs(covariance: &crate::plant::Covariance, spreads: &[f64]) -> Vec<f64> {
    covariance
        .diagonal()
        .iter()
        .zip(spreads)
        .map(|(c, s)| (c / (s * s)).log10())
        .collect()
}

/// [`tune`] for the filter whose estimates `estimator` gives, with `fixed` its constants the spec
/// fixes (the search runs over the others; with none left, the fixed filter is scored alone), its
/// state in `coordinates` (the plant's, or the model's log coordinates: [`crate::plant::coordinates`]).
#[allow(clippy::too_many_arguments)]
pub fn tune_with(
    estimator: Estimator,
    fixed: &FixedFilter,
    design: &Design,
    code: &ModelCode,
    coordinates: &crate::plant::Coordinates,
    tuning: &DataSet,
    learning: &DataSet,
    scoring: &Scoring,
) -> Option<Tuned> {
    use argmin::core::{Executor, State};
    use argmin::solver::neldermead::NelderMead;
    use rayon::prelude::*;
    if !supported(code) {
        return None;
    }
    // The search runs in the filter's `coordinates`: its start, the spec's covariances (mapped by
    // the slopes at the start) and the spreads that scale them.
    let nx = code.dimensions.states;
    let plant_start = start(design, fixed);
    let centre = coordinates.to_filter(&plant_start);
    let fixed = &FixedFilter {
        x0: fixed.x0.as_ref().map(|_| centre.clone()),
        q: fixed.q.as_ref().map(|q| coordinates.covariance(q, &plant_start)),
        p0: fixed.p0.as_ref().map(|p0| coordinates.covariance(p0, &plant_start)),
    };
    let spreads = spreads_in(learning, coordinates);
    let count = std::sync::atomic::AtomicU64::new(0);
    let criterion = Criterion {
        estimator,
        design,
        fixed,
        code,
        centre: &centre,
        spreads: &spreads,
        data: tuning,
        scoring,
        count: &count,
    };
    // The decades of each free half: `a` over −8…0 unless `Q` is fixed, `b` over −3…0 unless `P(0)` is.
    let (q_free, p0_free) = (fixed.q.is_none(), fixed.p0.is_none());
    let decades = |free: bool, low: i32| -> Vec<Option<f64>> {
        if free {
            (low..=0).map(|d| Some(f64::from(d))).collect()
        } else {
            vec![None]
        }
    };
    let isotropic = |a: Option<f64>, b: Option<f64>| -> Vec<f64> {
        let half = |v: Option<f64>| v.map_or(Vec::new(), |v| vec![v; nx]);
        [half(a), half(b)].concat()
    };
    let grid: Vec<Vec<f64>> = decades(q_free, -8)
        .into_iter()
        .flat_map(|a| decades(p0_free, -3).into_iter().map(move |b| (a, b)))
        .map(|(a, b)| isotropic(a, b))
        .collect();
    let mut scored: Vec<(Vec<f64>, f64)> = grid
        .into_par_iter()
        .map(|theta| {
            let cost = criterion.at(&theta);
            (theta, cost)
        })
        .collect();
    // Best first; the first of equals (a stable sort), so the choice does not depend on threads.
    scored.sort_by(|a, b| a.1.total_cmp(&b.1));
    let grid_cost = scored[0].1;
    if grid_cost >= 1e30 {
        return None; // diverged everywhere
    }
    // Nothing left to search when the spec fixes both.
    let starts = if q_free || p0_free { STARTS } else { 0 };
    let searched: Vec<(Vec<f64>, f64)> = scored[..starts.min(scored.len())]
        .par_iter()
        .map(|(theta, cost)| {
            let simplex: Vec<Vec<f64>> = std::iter::once(theta.clone())
                .chain((0..theta.len()).map(|i| {
                    let mut vertex = theta.clone();
                    vertex[i] += 1.0;
                    vertex
                }))
                .collect();
            let solver = NelderMead::new(simplex)
                .with_sd_tolerance(1e-4)
                .expect("a non-negative tolerance");
            let result = Executor::new(criterion, solver)
                .configure(|state| state.max_iters(ITERATIONS))
                .run()
                .expect("the criterion does not fail");
            let state = result.state();
            match state.get_best_param() {
                Some(best) if state.get_best_cost() < *cost => (best.clone(), state.get_best_cost()),
                _ => (theta.clone(), *cost),
            }
        })
        .collect();
    let (theta, _) = searched
        .into_iter()
        .fold(scored[0].clone(), |best, c| if c.1 < best.1 { c } else { best });
    let theta: Vec<f64> = theta.iter().map(|a| a.clamp(LOG_RANGE.0, LOG_RANGE.1)).collect();
    let (log_q, log_p0) = halves(fixed, &spreads, &theta);
    let mut constants = with_fixed(design, fixed, &centre, &spreads, &theta);
    let watched = |threshold: f64| {
        let mut constants = constants.clone();
        constants.watch.threshold = threshold;
        constants
    };
    let (threshold, cost) = crate::observers::score::lowest(&WATCH_THRESHOLDS, |t| {
        score(estimator, code, &watched(t), &centre, tuning, scoring)
    });
    constants.watch.threshold = threshold;
    Some(Tuned {
        constants,
        log_q,
        log_p0,
        fixed: fixed.fixed(),
        cost,
        grid_cost,
        evaluations: count.into_inner(),
        runs: tuning.runs.len(),
    })
}

/// The factors of the map-started EKF's start covariance tried by [`tune_started`]: half-decades from
/// 10⁻² to 10².
pub const START_FACTORS: [f64; 9] = [
    1e-2,
    0.031_622_776_601_683_79,
    0.1,
    0.316_227_766_016_837_9,
    1.0,
    3.162_277_660_168_379,
    10.0,
    31.622_776_601_683_79,
    100.0,
];

/// Chooses the factor `c` of the map-started EKF's start covariance `P(N−1) = c · diag(e_i²)`, `e_i`
/// the map's RMSE of state `i` on the tuning runs: the [`START_FACTORS`] value of lowest `score(c)`,
/// the first of equals. Returns `(c, score)`.
pub fn tune_started(score: impl Fn(f64) -> f64 + Sync) -> (f64, f64) {
    crate::observers::score::lowest(&START_FACTORS, score)
}
