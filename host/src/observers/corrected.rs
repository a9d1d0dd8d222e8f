//! The map corrected by the model: the paper's remark on λ (its eq. `defdelambda` blends the map
//! `F(Z)` with the model's prediction), generalised with an output-innovation gain and tuned in
//! closed loop on the tuning runs.
//!
//! # The observer
//!
//! No estimate before `N` samples; then `x̂(N−1) = F(Z(N−1))` (the map: no initial guess), and for
//! `k ≥ N`, with `x̄ = f(x̂(k−1), u(k−1))` one sampling period of the model (RK4, the chip's substeps):
//!
//! ```text
//! x̂(k) = clamp(x̄ + g_j ⊙ (F(Z(k)) − x̄) + K (y(k) − h(x̄, u(k)))),    g_j = G + (1 − G) / (1 + j / T),
//! ```
//!
//! `j = k − N + 1` the estimates so far: the blend starts on the map (`g_0 = 1`) and decays to `G`
//! with time constant `T`; it is cut to `G` after `J = 3N` estimates ([`START_UP_HORIZONS`]), from
//! when on the chip does not evaluate the map at all where `G = 0`. The clamp is each state's learning range, so the estimate is bounded as the
//! map's. `K = 0` is the paper's blend; `G = 0` is a constant-gain observer started by the map. It
//! needs the full state: it is offered when every state is a target (its expression is the state's
//! name), see [`state_targets`]. [`estimate_run`] is `firmware::Started` over the emitted programs
//! ([`crate::plant::correction`]), step for step.
//!
//! # Tuning
//!
//! `(G, K, K₀, ln T)` minimises the [score](super::score) on the tuning runs (pooled RMSE and the
//! 95th percentile over runs, per target over its spread), the same criterion as the EKF's, by
//! Nelder–Mead (`argmin`) from a few fixed starts (closed loop: the
//! one-step least-squares criterion is not the closed-loop one), once with `G` free and once with
//! `G = 0` (no map after the start-up: the chip's steady sample is then the model and `K` alone);
//! `G = 0` is kept unless `G` free does better by more than
//! [`CHEAPER_WITHIN`](super::CHEAPER_WITHIN). Deterministic: fixed starts, fixed iterations, the best
//! of the starts by cost, the first of equals.

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::neldermead::NelderMead;
use firmware::{Maths, Scalar};

use crate::data::{DataSet, Rows, Run};
use crate::plant::correction::{correction_code, CorrectionCode, CorrectionConstants, Reading};
use crate::plant::ModelCode;
use crate::spec::Design;

/// The tuned observer and how it was chosen.
#[derive(Clone, Debug)]
pub struct Tuned {
    /// The constants.
    pub constants: CorrectionConstants,
    /// The criterion there (the [score](super::score) on the tuning runs).
    pub cost: f64,
    /// The criterion at the best start before the search.
    pub start_cost: f64,
    /// Cost evaluations over every start.
    pub evaluations: u64,
    /// The best criterion with `G` free (the chip reads the map after the start-up where `G ≠ 0`).
    pub cost_with_map: f64,
    /// The best with `G = 0` (no map after the start-up): chosen when within
    /// [`CHEAPER_WITHIN`](super::CHEAPER_WITHIN) of [`Tuned::cost_with_map`].
    pub cost_without_map: f64,
}

/// For every state, the target that is that state (`None` with the reason when one is missing).
pub fn state_targets(design: &Design) -> Result<Vec<usize>, String> {
    design
        .model
        .states
        .iter()
        .map(|state| {
            design
                .targets
                .iter()
                .position(|t| t.expr.text().trim() == state)
                .ok_or_else(|| {
                    format!("state `{state}` is not a target: a model correction needs the full state (add a target with expr = \"{state}\")")
                })
        })
        .collect()
}

/// The start-up lasts this many horizons `N` of estimates: long enough for the tail of the blend
/// (`(1 − G)/(1 + 3N/T)`, below 0.02 for `N = 10` and the `T ≈ 0.5` Example 1 tunes to), short
/// enough that a table of it is small.
pub const START_UP_HORIZONS: usize = 3;

/// What a run of the observer needs besides its gains.
pub struct Setting<'a> {
    /// The model.
    pub code: &'a ModelCode,
    /// Width of one RK4 substep.
    pub h: f64,
    /// Substeps per sample.
    pub substeps: usize,
    /// [`state_targets`].
    pub state_targets: &'a [usize],
    /// The map's first estimate comes at this sample (`N − 1`).
    pub first: usize,
    /// Each state's clamp: its map's range, within the state's bounds (`[model.bounds]`).
    pub lower: Vec<f64>,
    /// See [`Setting::lower`].
    pub upper: Vec<f64>,
}

impl<'a> Setting<'a> {
    /// The setting of `design`'s observer: the chip's model and substeps, the first estimate at
    /// `N − 1`, each state clamped to its map's learning range.
    pub fn for_design(
        design: &Design,
        result: &crate::fit::DesignResult,
        code: &'a ModelCode,
        state_targets: &'a [usize],
    ) -> Self {
        let maps: Vec<crate::fit::maps::FittedMap> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
        Self::for_maps(design, design.map.horizon, &maps, code, state_targets)
    }

    /// [`Setting::for_design`] from the fitted maps alone (one per target) and the horizon `N`.
    pub fn for_maps(
        design: &Design,
        horizon: usize,
        maps: &[crate::fit::maps::FittedMap],
        code: &'a ModelCode,
        state_targets: &'a [usize],
    ) -> Self {
        // The map's range, within the state's physical bounds where the spec declares them.
        let (lower, upper) = state_targets
            .iter()
            .zip(&design.state_bounds)
            .map(|(&t, b)| (maps[t].r_min.max(b.lower()), maps[t].r_max.min(b.upper())))
            .unzip();
        Setting {
            code,
            h: design.tau / design.chip_substeps as f64,
            substeps: design.chip_substeps,
            state_targets,
            first: horizon - 1,
            lower,
            upper,
        }
    }

    /// The constants a search point `θ = (G, K, K₀, ln T)` stands for (`G` clamped to `[0, 1]`).
    pub fn constants(&self, theta: &[f64]) -> CorrectionConstants {
        let (nx, ny) = (self.code.dimensions.states, self.code.dimensions.outputs);
        CorrectionConstants {
            g: theta[..nx].iter().map(|g| g.clamp(0.0, 1.0)).collect(),
            k: theta[nx..nx + nx * ny].to_vec(),
            k_start: theta[nx + nx * ny..nx + 2 * nx * ny].to_vec(),
            schedule: theta[theta.len() - 1].exp(),
            start_up: START_UP_HORIZONS * (self.first + 1),
            lower: self.lower.clone(),
            upper: self.upper.clone(),
            substeps: self.substeps,
            h: self.h,
        }
    }
}

/// The targets estimated at every sample of `run` in `T` by the observer with `constants` (its
/// programs `code`), given the map's estimates `map` (NaN before the first): `firmware::Started`
/// step for step. NaN before the first estimate.
pub fn estimate_run<T: Scalar + Maths>(
    setting: &Setting<'_>,
    code: &CorrectionCode,
    constants: &CorrectionConstants,
    map: &[Vec<T>],
    run: &Run,
) -> Vec<Vec<T>> {
    let mut observer = CorrectedStep::new(setting, code, constants);
    map.iter()
        .zip(run.measurements.iter().zip(run.inputs.iter()))
        .map(|(row, (y, u))| observer.step(row, y, u))
        .collect()
}

/// [`estimate_run`] one sample at a time.
pub struct CorrectedStep<'a, T> {
    setting: &'a Setting<'a>,
    code: &'a CorrectionCode,
    constants: &'a CorrectionConstants,
    lower: Vec<T>,
    upper: Vec<T>,
    blends: Vec<Vec<T>>,
    scratch: std::cell::RefCell<Vec<T>>,
    shell: super::started::Shell<T, Vec<T>>,
}

impl<'a, T: Scalar + Maths> CorrectedStep<'a, T> {
    /// Before the first sample of a run.
    pub fn new(setting: &'a Setting<'a>, code: &'a CorrectionCode, constants: &'a CorrectionConstants) -> Self {
        let to_t = |row: &[f64]| row.iter().map(|&v| T::literal(v as f32, v)).collect::<Vec<T>>();
        CorrectedStep {
            setting,
            code,
            constants,
            lower: to_t(&constants.lower),
            upper: to_t(&constants.upper),
            blends: constants.blends().iter().map(|row| to_t(row)).collect(),
            scratch: std::cell::RefCell::new(Vec::new()),
            shell: super::started::Shell::new(setting.first, setting.state_targets, setting.code.dimensions.targets),
        }
    }

    /// The targets at the sample with outputs `y` and inputs `u`, the map's estimate there `row`.
    pub fn step(&mut self, row: &[T], y: &[f64], u: &[f64]) -> Vec<T> {
        let CorrectedStep {
            setting,
            code,
            constants,
            lower,
            upper,
            blends,
            scratch,
            shell,
        } = self;
        let no: [T; 0] = [];
        let predict = |x: &[T], u: &[T]| {
            let at = Reading {
                x,
                u,
                y: &no,
                map: &no,
                blend: &no,
            };
            let next = code.run(&code.predict, &at, &mut scratch.borrow_mut());
            next.iter().all(|v| v.is_finite()).then_some(next)
        };
        // `firmware::started::clamp`: NaN to the lower end.
        let clamp = |raw: &[T]| -> Vec<T> {
            raw.iter()
                .zip(lower.iter().zip(upper.iter()))
                .map(|(&v, (&lo, &hi))| {
                    if v.partial_cmp(&lo).is_none_or(|o| o.is_lt()) {
                        lo
                    } else if v > hi {
                        hi
                    } else {
                        v
                    }
                })
                .collect()
        };
        shell.step(
            row,
            y,
            u,
            &mut |x, u| predict(x, u),
            &mut |predicted: &Vec<T>, j, from_map, y, u| {
                let blend = blends.get(j.wrapping_sub(1)).map_or(&[][..], Vec::as_slice);
                let at = Reading {
                    x: predicted,
                    u,
                    y,
                    map: from_map,
                    blend,
                };
                let program = if j <= constants.start_up {
                    &code.start_up
                } else {
                    &code.steady
                };
                let x = clamp(&code.run(program, &at, &mut scratch.borrow_mut()));
                let next = predict(&x, u)?;
                let targets = setting.code.targets(&x, u, &mut scratch.borrow_mut());
                Some((next, targets))
            },
            // A lost output: the model's period from `x̄` (`Corrector::predict`).
            &mut |predicted: &Vec<T>, u| predict(predicted, u),
        )
    }
}

/// [`estimate_run`] in `f64` over the map's `f64` estimates.
pub fn estimate_rows(
    setting: &Setting<'_>,
    code: &CorrectionCode,
    constants: &CorrectionConstants,
    map: &Rows,
    run: &Run,
) -> Rows {
    let map: Vec<Vec<f64>> = map.iter().map(<[f64]>::to_vec).collect();
    Rows::from(estimate_run(setting, code, constants, &map, run))
}

/// The closed-loop criterion over a data set whose map estimates are given.
struct Criterion<'a> {
    /// Evaluations so far.
    count: &'a std::sync::atomic::AtomicU64,
    setting: &'a Setting<'a>,
    data: &'a DataSet,
    maps: &'a [Rows],
    target_spreads: &'a [f64],
    /// Whether `G = 0` is fixed (and left out of `θ`): the chip reads no map after the start-up.
    without_map: bool,
}

impl Criterion<'_> {
    /// The [score](super::score) with `constants`.
    fn score(&self, constants: &CorrectionConstants) -> f64 {
        self.count.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let code = correction_code(self.setting.code, constants);
        let estimates: Vec<Rows> = self
            .data
            .runs
            .iter()
            .zip(self.maps)
            .map(|(run, map)| estimate_rows(self.setting, &code, constants, map, run))
            .collect();
        let first = self.setting.first;
        let score = super::score::of_estimates(&self.data.runs, &estimates, self.target_spreads, |run| {
            first..run.targets.len()
        });
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

/// Chooses the gains on `tuning` (its map estimates `maps`), see the module docs.
pub fn tune(setting: &Setting<'_>, tuning: &DataSet, maps: &[Rows], target_spreads: &[f64]) -> Tuned {
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
        target_spreads,
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
    let chosen = if without.2 <= free.2 * (1.0 + super::CHEAPER_WITHIN) {
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

#[cfg(test)]
mod tests;
