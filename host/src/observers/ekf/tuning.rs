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
//! target, over its spread) on the tuning runs from random starts (the filter that starts at the
//! box centre is tuned for starts anywhere in the box; `auto` judges it with the others on the runs
//! from the scenario's start too): first on an isotropic decade grid (`a_i = a`,
//! `b_i = b`, `a ∈ {−8…0}`, `b ∈ {−3…0}`), then by Nelder–Mead (`argmin`) from the
//! [`STARTS`] best grid points, each coordinate free (until the simplex's scores agree within
//! 1e-4). Deterministic: a fixed grid, fixed starts and iterations, the best by cost and the first
//! of equals. The map-started EKF shares `Q` (one filter
//! on the chip) and scales its own start covariance ([`tune_started`]).

use crate::data::{DataSet, Rows};
use crate::plant::kalman::EkfConstants;
use crate::plant::ModelCode;
use crate::spec::Design;

use super::{box_centre, constants, estimates, state_spreads, supported, LOG_RANGE};

/// The tuned filter and how it was chosen.
#[derive(Clone, Debug)]
pub struct Tuned {
    /// The constants the design's EKF is emitted with.
    pub constants: EkfConstants,
    /// `a`: `log10(Q_ii / s_i²)` per state.
    pub log_q: Vec<f64>,
    /// `b`: `log10(P(0)_ii / s_i²)` per state.
    pub log_p0: Vec<f64>,
    /// The score at the choice (tuning runs).
    pub cost: f64,
    /// The score at the best point of the isotropic grid, before the search.
    pub grid_cost: f64,
    /// Score evaluations, grid and search.
    pub evaluations: u64,
    /// The tuning runs it was chosen on.
    pub runs: usize,
}

/// Grid points the search starts from.
pub const STARTS: usize = 2;

/// Nelder–Mead iterations per start.
const ITERATIONS: u64 = 150;

/// A filter's estimates of every run of a data set, with given constants, from a given start: the
/// EKF's ([`super::estimates`]) or the UKF's ([`crate::observers::ukf::estimates`]), which share
/// their constants and this search.
pub type Estimator = fn(&ModelCode, &EkfConstants, &[f64], &DataSet) -> Option<Vec<Rows>>;

/// The score of the filter with `constants` from the box centre on `data` (windows `k ≥ N − 1`).
fn score(
    estimator: Estimator,
    code: &ModelCode,
    constants: &EkfConstants,
    centre: &[f64],
    data: &DataSet,
    target_spreads: &[f64],
) -> f64 {
    let estimates = estimator(code, constants, centre, data).expect("size checked");
    crate::observers::score::of_estimates(&data.runs, &estimates, target_spreads, |run| {
        data.horizon.saturating_sub(1)..run.targets.len()
    })
}

/// The tuning criterion as `argmin` sees it: `θ` to the score.
#[derive(Clone, Copy)]
struct Criterion<'a> {
    estimator: Estimator,
    design: &'a Design,
    code: &'a ModelCode,
    centre: &'a [f64],
    spreads: &'a [f64],
    data: &'a DataSet,
    target_spreads: &'a [f64],
    count: &'a std::sync::atomic::AtomicU64,
}

impl Criterion<'_> {
    fn at(&self, theta: &[f64]) -> f64 {
        self.count.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let constants = constants(self.design, self.centre, self.spreads, theta);
        let score = score(
            self.estimator,
            self.code,
            &constants,
            self.centre,
            self.data,
            self.target_spreads,
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

/// Chooses the EKF's `Q` and `P(0)` on `tuning` (see the module docs). `target_spreads` normalises
/// each target's errors.
pub fn tune(
    design: &Design,
    code: &ModelCode,
    tuning: &DataSet,
    learning: &DataSet,
    target_spreads: &[f64],
) -> Option<Tuned> {
    tune_with(estimates, design, code, tuning, learning, target_spreads)
}

/// [`tune`] for the filter whose estimates `estimator` gives.
pub fn tune_with(
    estimator: Estimator,
    design: &Design,
    code: &ModelCode,
    tuning: &DataSet,
    learning: &DataSet,
    target_spreads: &[f64],
) -> Option<Tuned> {
    use argmin::core::{Executor, State};
    use argmin::solver::neldermead::NelderMead;
    use rayon::prelude::*;
    if !supported(code) {
        return None;
    }
    let nx = code.dimensions.states;
    let centre = box_centre(design);
    let spreads = state_spreads(learning, nx);
    let count = std::sync::atomic::AtomicU64::new(0);
    let criterion = Criterion {
        estimator,
        design,
        code,
        centre: &centre,
        spreads: &spreads,
        data: tuning,
        target_spreads,
        count: &count,
    };
    let isotropic =
        |a: f64, b: f64| -> Vec<f64> { std::iter::repeat_n(a, nx).chain(std::iter::repeat_n(b, nx)).collect() };
    let grid: Vec<Vec<f64>> = (-8..=0)
        .flat_map(|a| (-3..=0).map(move |b| (f64::from(a), f64::from(b))))
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
    let searched: Vec<(Vec<f64>, f64)> = scored[..STARTS.min(scored.len())]
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
    let (theta, cost) = searched.into_iter().fold(
        (Vec::new(), f64::INFINITY),
        |best, c| if c.1 < best.1 { c } else { best },
    );
    let theta: Vec<f64> = theta.iter().map(|a| a.clamp(LOG_RANGE.0, LOG_RANGE.1)).collect();
    Some(Tuned {
        constants: constants(design, &centre, &spreads, &theta),
        log_q: theta[..nx].to_vec(),
        log_p0: theta[nx..].to_vec(),
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
