//! The floor: a bootstrap particle filter (Gordon, Salmond & Smith, *Novel approach to
//! nonlinear/non-Gaussian Bayesian state estimation*, 1993) from the state box, as close to the
//! best estimate any observer could give as the host can afford. Not embeddable: thousands of model
//! steps per sample.
//!
//! # The filter
//!
//! `M` particles are drawn uniformly in the learning box (the prior every run's start is drawn from),
//! with equal weights; with uncertain parameters, each particle also draws their values uniformly in
//! their ranges (as every run's plant does) and carries them as constant coordinates, so that the
//! floor knows what the runs' plants are drawn from and nothing more. At each sample `(y, u)`:
//!
//! ```text
//! weight     w_p ← w_p · exp(−½ Σ_i (y_i − h_i(x_p, u))² / σ_i²)        (normalised)
//! estimate   r̂ = Σ_p w_p r(x_p, u)                                      (the posterior mean)
//! resample   when the effective count 1 / Σ w_p² < M / 2: systematic resampling, then every particle
//!            moved by the kernel x ← a x + (1 − a) m + h L ξ, ξ ~ N(0, I), with m and L Lᵀ the
//!            cloud's mean and covariance, h = (4 / (M (n + 2)))^(1/(n+4)) ([`bandwidth`]) and
//!            a = √(1 − h²), projected onto the physical bounds
//! predict    x_p ← one sampling period of the model the observers carry (the chip's RK4 substeps)
//! ```
//!
//! The plants have no process noise, so resampled particles would otherwise collapse onto a few:
//! the move is the regularised particle filter's (Musso, Oudjane & Le Gland 2001) with Liu & West's
//! shrinkage (*Combined parameter and state estimation in simulation-based filtering*, 2001), which
//! keeps the cloud's mean and covariance as they are while spreading it.
//!
//! The posterior mean minimises the expected squared error, so with enough particles no observer
//! of the same model and noise does better on average. Every run has its own random stream of one
//! fixed seed ([`SEED`]), so the floor is reproducible bit for bit; the model's programs are
//! evaluated for all particles at once ([`crate::plant::Program::eval_many`]).

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;

use crate::data::{Rows, Run};
use crate::plant::{ModelCode, Program};
use crate::spec::{Axis, Design};

/// The filter's seed (each run a stream of its own).
pub const SEED: u64 = 0x5eed_f100;

/// The particle filter of a design.
pub struct Floor<'a> {
    code: &'a ModelCode,
    /// `f`, `h` and `r` alone (no Jacobian).
    field: Program,
    output: Program,
    /// The uncertain parameters (indices into the model's), each a coordinate of the particles after
    /// the states: the plant's value is unknown within its range, as the runs draw it.
    uncertain: Vec<usize>,
    /// Each coordinate's `(min, max)` at the start: the learning box (a fixed state: its value twice),
    /// then each uncertain parameter's range.
    ranges: Vec<(f64, f64)>,
    /// Each coordinate's limits after a move: the physical bounds, then each parameter's range.
    limits: Vec<(f64, f64)>,
    weights: Vec<f64>,
    /// RK4 step and substeps per sample.
    h: f64,
    substeps: usize,
    /// Particles.
    pub count: usize,
}

impl<'a> Floor<'a> {
    /// The filter of `design` with `count` particles.
    pub fn new(design: &Design, code: &'a ModelCode, count: usize) -> Self {
        let d = code.dimensions;
        Floor {
            code,
            field: code.derivative.first_results(d.states),
            output: code.output.first_results(d.outputs),
            uncertain: design.model.uncertain.iter().map(|u| u.index).collect(),
            ranges: design
                .learning
                .axes
                .iter()
                .map(|axis| match *axis {
                    Axis::Range { min, max, .. } => (min, max),
                    Axis::Fixed(value) => (value, value),
                })
                .chain(design.model.uncertain.iter().map(|u| (u.min, u.max)))
                .collect(),
            limits: code
                .bounds
                .iter()
                .map(|b| (b.lower(), b.upper()))
                .chain(design.model.uncertain.iter().map(|u| (u.min, u.max)))
                .collect(),
            weights: design
                .model
                .outputs
                .iter()
                .map(|o| 1.0 / o.noise_variance.max(1e-300))
                .collect(),
            h: design.tau / design.chip_substeps as f64,
            substeps: design.chip_substeps,
            count,
        }
    }

    /// The posterior mean of every target at every sample of `run`, on the random stream `stream`.
    pub fn estimate_run(&self, run: &Run, stream: u64) -> Rows {
        let d = self.code.dimensions;
        let m = self.count;
        let mut rng = ChaCha8Rng::seed_from_u64(SEED);
        rng.set_stream(stream);
        let mut x: Vec<Vec<f64>> = self
            .ranges
            .iter()
            .map(|&(low, high)| (0..m).map(|_| low + (high - low) * rng.random::<f64>()).collect())
            .collect();
        let mut log_weights = vec![0.0; m];
        let mut weights = vec![0.0; m];
        let mut values = Vec::new();
        let mut predicted = vec![Vec::new(); d.outputs];
        let mut targets = vec![Vec::new(); d.targets];
        let mut estimates = Rows::new(d.targets);
        let mut integrator = Stages::new(d.states, m);
        let n = d.states;
        let parameters = &self.code.parameters;
        for (y, u) in run.measurements.iter().zip(run.inputs.iter()) {
            let (states, drawn) = x.split_at(n);
            let varying = self.varying(drawn);
            self.output
                .eval_many(parameters, &varying, states, u, &mut values, &mut predicted);
            for (i, (&yi, &w)) in y.iter().zip(&self.weights).enumerate() {
                if !yi.is_finite() {
                    continue; // a refused sample carries no information
                }
                for (lw, &p) in log_weights.iter_mut().zip(&predicted[i]) {
                    let r = yi - p;
                    // A particle whose output is not finite has no weight.
                    *lw += if r.is_finite() {
                        -0.5 * w * r * r
                    } else {
                        f64::NEG_INFINITY
                    };
                }
            }
            let top = log_weights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            if !top.is_finite() {
                // Every particle lost (none explains the sample): their weights made equal again.
                log_weights.fill(0.0);
            }
            let top = if top.is_finite() { top } else { 0.0 };
            let mut total = 0.0;
            for (w, &lw) in weights.iter_mut().zip(&log_weights) {
                *w = (lw - top).exp();
                total += *w;
            }
            weights.iter_mut().for_each(|w| *w /= total);
            self.code
                .targets
                .eval_many(parameters, &varying, states, u, &mut values, &mut targets);
            let row: Vec<f64> = targets
                .iter()
                .map(|values| values.iter().zip(&weights).map(|(v, w)| v * w).sum())
                .collect();
            estimates.push(&row);
            let effective = 1.0 / weights.iter().map(|w| w * w).sum::<f64>();
            if effective < 0.5 * m as f64 {
                self.resample(&mut x, &weights, &mut rng);
                log_weights.fill(0.0);
            } else {
                for (lw, w) in log_weights.iter_mut().zip(&weights) {
                    *lw = w.ln();
                }
            }
            let (states, drawn) = x.split_at_mut(n);
            integrator.advance(self, states, &self.varying(drawn), u, &mut values);
        }
        estimates
    }

    /// The uncertain parameters' values at every particle, as [`Program::eval_many`] takes them.
    fn varying<'c>(&self, drawn: &'c [Vec<f64>]) -> Vec<(usize, &'c [f64])> {
        self.uncertain
            .iter()
            .zip(drawn)
            .map(|(&k, v)| (k, v.as_slice()))
            .collect()
    }

    /// Systematic resampling, then the regularisation step (see the module's documentation).
    fn resample(&self, x: &mut [Vec<f64>], weights: &[f64], rng: &mut ChaCha8Rng) {
        let m = weights.len();
        let n = x.len();
        let offset: f64 = rng.random::<f64>();
        let mut picked = Vec::with_capacity(m);
        let (mut cumulative, mut p) = (weights[0], 0);
        for j in 0..m {
            let point = (j as f64 + offset) / m as f64;
            while point > cumulative && p + 1 < m {
                p += 1;
                cumulative += weights[p];
            }
            picked.push(p);
        }
        for state in x.iter_mut() {
            let resampled: Vec<f64> = picked.iter().map(|&p| state[p]).collect();
            *state = resampled;
        }
        // The cloud's mean and covariance, and a square root of it (a constant state: a tiny variance).
        let mean: Vec<f64> = x.iter().map(|s| s.iter().sum::<f64>() / m as f64).collect();
        let covariance = nalgebra::DMatrix::from_fn(n, n, |i, j| {
            let c = x[i]
                .iter()
                .zip(&x[j])
                .map(|(a, b)| (a - mean[i]) * (b - mean[j]))
                .sum::<f64>()
                / m as f64;
            if i == j {
                c + 1e-24 * (1.0 + mean[i] * mean[i])
            } else {
                c
            }
        });
        let Some(root) = covariance.cholesky().map(|c| c.l()) else {
            return; // not finite: left as resampled
        };
        let h = bandwidth(m, n);
        let shrink = (1.0 - h * h).sqrt();
        let mut draw = vec![0.0; n];
        #[allow(clippy::needless_range_loop)] // particle p of every coordinate
        for p in 0..m {
            draw.iter_mut().for_each(|d| *d = rng.sample::<f64, _>(StandardNormal));
            for i in 0..n {
                let kick: f64 = (0..=i).map(|j| root[(i, j)] * draw[j]).sum();
                let moved = shrink * x[i][p] + (1.0 - shrink) * mean[i] + h * kick;
                let (low, high) = self.limits[i];
                x[i][p] = moved.clamp(low, high);
            }
        }
    }
}

/// The kernel's bandwidth `h`: Silverman's rule for a Gaussian kernel, `(4 / (M (n + 2)))^(1/(n + 4))`
/// (Musso, Oudjane & Le Gland, *Improving regularised particle filters*, 2001).
pub fn bandwidth(particles: usize, states: usize) -> f64 {
    (4.0 / (particles as f64 * (states as f64 + 2.0))).powf(1.0 / (states as f64 + 4.0))
}

/// RK4's stages for every particle.
struct Stages {
    k: [Vec<Vec<f64>>; 4],
    probe: Vec<Vec<f64>>,
}

impl Stages {
    fn new(states: usize, count: usize) -> Self {
        let zeros = || vec![vec![0.0; count]; states];
        Stages {
            k: std::array::from_fn(|_| zeros()),
            probe: zeros(),
        }
    }

    /// One sampling period of the model for every particle, in the chip's RK4 substeps (the model
    /// every observer carries: the floor is that of an observer of this model).
    fn advance(
        &mut self,
        floor: &Floor<'_>,
        x: &mut [Vec<f64>],
        varying: &[(usize, &[f64])],
        u: &[f64],
        values: &mut Vec<f64>,
    ) {
        let h = floor.h;
        let parameters = &floor.code.parameters;
        for _ in 0..floor.substeps {
            let [k1, k2, k3, k4] = &mut self.k;
            floor.field.eval_many(parameters, varying, x, u, values, k1);
            for ((probe, x), k) in self.probe.iter_mut().zip(x.iter()).zip(k1.iter()) {
                for ((p, &x), &k) in probe.iter_mut().zip(x).zip(k) {
                    *p = x + 0.5 * h * k;
                }
            }
            floor.field.eval_many(parameters, varying, &self.probe, u, values, k2);
            for ((probe, x), k) in self.probe.iter_mut().zip(x.iter()).zip(k2.iter()) {
                for ((p, &x), &k) in probe.iter_mut().zip(x).zip(k) {
                    *p = x + 0.5 * h * k;
                }
            }
            floor.field.eval_many(parameters, varying, &self.probe, u, values, k3);
            for ((probe, x), k) in self.probe.iter_mut().zip(x.iter()).zip(k3.iter()) {
                for ((p, &x), &k) in probe.iter_mut().zip(x).zip(k) {
                    *p = x + h * k;
                }
            }
            floor.field.eval_many(parameters, varying, &self.probe, u, values, k4);
            for (i, x) in x.iter_mut().enumerate() {
                for (p, x) in x.iter_mut().enumerate() {
                    *x += h / 6.0 * (k1[i][p] + 2.0 * k2[i][p] + 2.0 * k3[i][p] + k4[i][p]);
                }
            }
        }
        // A particle the model sent to a non-finite state is kept at the bound it crossed, or dropped
        // to weight zero by its output at the next sample.
        for (state, bounds) in x.iter_mut().zip(&floor.code.bounds) {
            for v in state.iter_mut() {
                *v = v.clamp(bounds.lower(), bounds.upper());
            }
        }
    }
}

#[cfg(test)]
mod tests;
