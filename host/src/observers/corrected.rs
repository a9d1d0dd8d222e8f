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
//! x̂(k) = x̄ + G_j ⊙ (F(Z(k)) − x̄) + K (y(k) − h(x̄, u(k))),    G_j = G + (1 − G) / (1 + j / T),
//! ```
//!
//! `j = k − N + 1` the estimates so far: the blend starts on the map (`G_0 = 1`) and decays to `G`
//! with time constant `T` (in estimates). `K = 0` is the paper's blend; `G = 0` after the start-up is
//! a constant-gain observer started by the map. It needs the full state: it is offered when every
//! state is a target (its expression is the state's name), see [`state_targets`].
//!
//! # Tuning
//!
//! `(G, K, ln T)` minimises the mean over targets of RMSE / spread on the tuning runs, the same
//! criterion as the EKF's, by Nelder–Mead (`argmin`) from a few fixed starts (closed loop: the
//! one-step least-squares criterion is not the closed-loop one). Deterministic: fixed starts, fixed
//! iterations, the best of the starts by cost, the first of equals.

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::neldermead::NelderMead;

use crate::data::{DataSet, Rows, Run};
use crate::plant::{ModelCode, Program};
use crate::spec::Design;

/// The tuned constants.
#[derive(Clone, Debug, PartialEq)]
pub struct Gains {
    /// `G`, per state, after the start-up.
    pub g: Vec<f64>,
    /// `K`, states × outputs, row by row.
    pub k: Vec<f64>,
    /// `T`, the start-up blend's time constant, in estimates.
    pub schedule: f64,
}

/// The tuned observer and how it was chosen.
#[derive(Clone, Debug)]
pub struct Tuned {
    /// The constants.
    pub gains: Gains,
    /// The criterion there (mean normalised RMSE on the tuning runs).
    pub cost: f64,
    /// Cost evaluations over every start.
    pub evaluations: u64,
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

/// What a run of the observer needs besides its gains.
pub struct Setting<'a> {
    /// The model.
    pub code: &'a ModelCode,
    /// `f` alone (the model's derivative program without its Jacobian).
    derivative: Program,
    /// `h` alone.
    output: Program,
    /// Width of one RK4 substep.
    pub h: f64,
    /// Substeps per sample.
    pub substeps: usize,
    /// [`state_targets`].
    pub state_targets: &'a [usize],
    /// The map's first estimate comes at this sample (`N − 1`).
    pub first: usize,
}

impl<'a> Setting<'a> {
    /// The observer of `code` stepped by `substeps` RK4 steps of width `h`, first estimating at
    /// sample `first`.
    pub fn new(code: &'a ModelCode, h: f64, substeps: usize, state_targets: &'a [usize], first: usize) -> Self {
        let values = |program: &Program, n: usize| {
            let mut program = program.clone();
            program.results.truncate(n);
            program.prune();
            program
        };
        Setting {
            code,
            derivative: values(&code.derivative, code.dimensions.states),
            output: values(&code.output, code.dimensions.outputs),
            h,
            substeps,
            state_targets,
            first,
        }
    }

    /// The targets estimated at every sample of `run`, given the map's estimates `map` of it (NaN
    /// before the first); NaN before the first estimate.
    pub fn estimate_run(&self, gains: &Gains, map: &Rows, run: &Run) -> Rows {
        let (nx, ny) = (self.code.dimensions.states, self.code.dimensions.outputs);
        let mut out = Rows::new(self.code.dimensions.targets);
        let mut scratch = Vec::new();
        let nan = vec![f64::NAN; self.code.dimensions.targets];
        let mut x = vec![f64::NAN; nx];
        for k in 0..run.targets.len() {
            if k < self.first {
                out.push(&nan);
                continue;
            }
            let from_map: Vec<f64> = self.state_targets.iter().map(|&t| map[k][t]).collect();
            if k == self.first {
                x = from_map;
            } else {
                let predicted = self.step(&x, &run.inputs[k - 1], &mut scratch);
                let h = self
                    .output
                    .eval(&self.code.parameters, &predicted, &run.inputs[k], &mut scratch);
                let j = (k - self.first) as f64;
                x = (0..nx)
                    .map(|i| {
                        let blend = gains.g[i] + (1.0 - gains.g[i]) / (1.0 + j / gains.schedule);
                        let innovation: f64 = (0..ny)
                            .map(|o| gains.k[i * ny + o] * (run.measurements[k][o] - h[o]))
                            .sum();
                        predicted[i] + blend * (from_map[i] - predicted[i]) + innovation
                    })
                    .collect();
            }
            out.push(&self.code.targets(&x, &run.inputs[k], &mut scratch));
        }
        out
    }

    /// One sampling period of the model from `x` (the order of `firmware::Rk4`'s value path).
    fn step(&self, x: &[f64], u: &[f64], scratch: &mut Vec<f64>) -> Vec<f64> {
        let mut x = x.to_vec();
        let (h, half, sixth) = (self.h, self.h / 2.0, self.h / 6.0);
        for _ in 0..self.substeps {
            let at = |w: f64, k: &[f64]| -> Vec<f64> { x.iter().zip(k).map(|(x, k)| x + w * k).collect() };
            let p = &self.code.parameters;
            let k1 = self.derivative.eval(p, &x, u, scratch);
            let k2 = self.derivative.eval(p, &at(half, &k1), u, scratch);
            let k3 = self.derivative.eval(p, &at(half, &k2), u, scratch);
            let k4 = self.derivative.eval(p, &at(h, &k3), u, scratch);
            for i in 0..x.len() {
                x[i] += sixth * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
            }
        }
        x
    }
}

/// The closed-loop criterion over a data set whose map estimates are given.
struct Criterion<'a> {
    /// Evaluations so far.
    count: &'a std::sync::atomic::AtomicU64,
    setting: &'a Setting<'a>,
    data: &'a DataSet,
    maps: &'a [Rows],
    target_spreads: &'a [f64],
}

/// The gains a search point `θ = (G, K, ln T)` stands for (`G` clamped to `[0, 1]`), `nx` states.
fn gains(nx: usize, theta: &[f64]) -> Gains {
    Gains {
        g: theta[..nx].iter().map(|g| g.clamp(0.0, 1.0)).collect(),
        k: theta[nx..theta.len() - 1].to_vec(),
        schedule: theta[theta.len() - 1].exp(),
    }
}

impl CostFunction for Criterion<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, theta: &Self::Param) -> Result<f64, argmin::core::Error> {
        self.count.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let gains = gains(self.setting.code.dimensions.states, theta);
        let estimates: Vec<Rows> = self
            .data
            .runs
            .iter()
            .zip(self.maps)
            .map(|(run, map)| self.setting.estimate_run(&gains, map, run))
            .collect();
        let first = self.setting.first;
        let mean = (0..self.target_spreads.len())
            .map(|t| {
                super::errors(&self.data.runs, &estimates, t, |run| first..run.targets.len()).0 / self.target_spreads[t]
            })
            .sum::<f64>()
            / self.target_spreads.len() as f64;
        // A diverging candidate is the worst, not a NaN that Nelder–Mead cannot order.
        Ok(if mean.is_finite() { mean } else { 1e30 })
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
        theta.extend(std::iter::repeat_n(k, nx * ny));
        theta.push(schedule.ln());
        theta
    };
    let starts = [
        start(0.5, 0.0, 3.0),
        start(0.2, 0.0, 3.0),
        start(0.05, 0.0, 10.0),
        start(0.05, 0.1, 3.0),
        start(0.0, 0.05, 1.0),
    ];
    let count = std::sync::atomic::AtomicU64::new(0);
    let results: Vec<(Vec<f64>, f64)> = starts
        .into_par_iter()
        .map(|theta| {
            let criterion = Criterion {
                count: &count,
                setting,
                data: tuning,
                maps,
                target_spreads,
            };
            // The initial simplex: the start and one step along each coordinate.
            let simplex: Vec<Vec<f64>> = std::iter::once(theta.clone())
                .chain((0..theta.len()).map(|i| {
                    let mut vertex = theta.clone();
                    vertex[i] += if i == theta.len() - 1 { 1.0 } else { 0.1 };
                    vertex
                }))
                .collect();
            let solver = NelderMead::new(simplex)
                .with_sd_tolerance(1e-7)
                .expect("a non-negative tolerance");
            let result = Executor::new(criterion, solver)
                .configure(|state| state.max_iters(ITERATIONS))
                .run()
                .expect("the criterion does not fail");
            let state = result.state();
            let best = state.get_best_param().cloned().unwrap_or(theta);
            (best, state.get_best_cost())
        })
        .collect();
    let (theta, cost) = results.into_iter().fold(
        (Vec::new(), f64::INFINITY),
        |best, r| if r.1 < best.1 { r } else { best },
    );
    Tuned {
        gains: gains(nx, &theta),
        cost,
        evaluations: count.into_inner(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::simulate::Integrator;

    /// Example 1's model, a validation-like run of it, and a stand-in for the map's estimates (the
    /// true state plus a known offset), so that each case has a closed-form answer.
    fn fixture() -> (Design, ModelCode, Run, Rows) {
        let design = crate::spec::load(std::path::Path::new("specs/vanderpol.toml")).unwrap();
        let code = ModelCode::new(&design).unwrap();
        let data = crate::data::validation_set(&design).unwrap();
        let run = data.runs[0].clone();
        let map: Rows = run.states.iter().map(|x| vec![x[0] + 0.1, x[1] - 0.2]).collect();
        (design, code, run, map)
    }

    #[test]
    fn with_g_one_and_k_zero_it_is_the_map() {
        let (_, code, run, map) = fixture();
        let targets = [0, 1];
        let setting = Setting::new(&code, 0.1, 1, &targets, 9);
        let gains = Gains {
            g: vec![1.0, 1.0],
            k: vec![0.0, 0.0],
            schedule: 2.0,
        };
        let out = setting.estimate_run(&gains, &map, &run);
        assert!(out[8].iter().all(|v| v.is_nan()), "no estimate before N samples");
        for k in 9..run.targets.len() {
            assert_eq!(&out[k], &map[k], "k = {k}");
        }
    }

    #[test]
    fn with_g_and_k_zero_it_is_the_model_from_the_maps_first_estimate() {
        // After the first estimate the blend decays as (1 + j/T)⁻¹; with T tiny it is gone from the
        // second estimate on, leaving the model's open-loop prediction, which an independent
        // integrator (the learning simulation's, 1 substep) gives.
        let (design, code, run, map) = fixture();
        let targets = [0, 1];
        let setting = Setting::new(&code, 0.1, 1, &targets, 9);
        let gains = Gains {
            g: vec![0.0, 0.0],
            k: vec![0.0, 0.0],
            schedule: 1e-12,
        };
        let out = setting.estimate_run(&gains, &map, &run);
        let mut integrator = Integrator::new(&design.model, design.tau, 1);
        let mut x = map[9].to_vec();
        for k in 10..run.targets.len() {
            integrator.advance(&mut x, &run.inputs[k - 1]);
            let gap = (out[k][0] - x[0]).abs().max((out[k][1] - x[1]).abs());
            assert!(
                gap < 1e-9 * (1.0 + x[0].abs() + x[1].abs()),
                "k = {k}: {:?} vs {x:?}",
                &out[k]
            );
        }
    }

    #[test]
    fn the_start_up_blend_follows_its_schedule() {
        // At the second estimate (j = 1) with K = 0: x̂ = x̄ + G₁ (F − x̄), G₁ = G + (1 − G)/(1 + 1/T).
        let (design, code, run, map) = fixture();
        let targets = [0, 1];
        let setting = Setting::new(&code, 0.1, 1, &targets, 9);
        let (g, schedule) = (0.3, 4.0);
        let gains = Gains {
            g: vec![g, g],
            k: vec![0.0, 0.0],
            schedule,
        };
        let out = setting.estimate_run(&gains, &map, &run);
        let mut predicted = map[9].to_vec();
        Integrator::new(&design.model, design.tau, 1).advance(&mut predicted, &run.inputs[9]);
        let blend = g + (1.0 - g) / (1.0 + 1.0 / schedule);
        for i in 0..2 {
            let expected = predicted[i] + blend * (map[10][i] - predicted[i]);
            assert!((out[10][i] - expected).abs() < 1e-12, "state {i}");
        }
    }

    #[test]
    fn a_design_without_every_state_as_a_target_has_no_correction() {
        let mut design = crate::spec::load(std::path::Path::new("specs/vanderpol.toml")).unwrap();
        design.targets.truncate(1);
        let why = state_targets(&design).unwrap_err();
        assert!(why.contains("`x2`"), "{why}");
    }
}
