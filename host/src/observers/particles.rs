//! The floor: a sequential Monte Carlo sampler over what the runs do not tell the observers, the
//! start and the uncertain parameters, as close to the best estimate any observer could give as the
//! host can afford. Not embeddable: thousands of model steps per sample.
//!
//! # Why over the start
//!
//! The plants have no process noise: a run's state at every sample is the model's image of its start
//! `x(0)` and parameters `θ`, so the posterior of the state given the samples so far is the image of
//! that of `z = (x(0), θ)`. A particle is a `z`, drawn from the prior every run's start is drawn from
//! (uniform in the learning box, uncertain parameters uniform in their ranges), with its state carried
//! along by the model the observers carry (the chip's RK4 substeps); the posterior mean of each target
//! is the weighted mean over particles. This is Chopin's iterated batch importance sampling (*A
//! sequential particle filter method for static models*, Biometrika 2002) with Gilks & Berzuini's
//! resample-move (*Following a moving target*, JRSS B 2001): the moves are exact, so no artificial
//! noise enters (the regularised filter's kernel, which spreads resampled particles where the
//! previous samples ruled them out, let a cloud drift away on the E. coli design).
//!
//! The sensors are precise: one sample's likelihood is often hundreds of noise deviations narrower
//! than the learning box, so particles drawn from the box alone leave a handful (or none) where the
//! first measurements put the state (a 4-tank design: 100–1000× worse than the observers it should
//! bound). So each sample's likelihood is brought in by stages, each raising its exponent only as
//! far as keeps half the particles' effective count, with a resampling and moves between stages
//! (likelihood tempering: Neal, *Annealed importance sampling*, 2001; Del Moral, Doucet & Jasra,
//! *Sequential Monte Carlo samplers*, JRSS B 2006; the exponent found by bisection on the effective
//! count as in Jasra, Stephens, Doucet & Tsagaris, *Inference for Lévy-driven stochastic volatility
//! models via adaptive sequential Monte Carlo*, Scand. J. Stat. 2011). A point-mass grid would need
//! the noise's resolution over the whole box in 4 states and the parameters, and the models have no
//! linear substructure to Rao–Blackwellise.
//!
//! # The sampler
//!
//! At each sample `k`, with `ℓ_j(z) = −½ Σ_i (y_i(j) − h_i(x_z(j), u(j)))² / σ_i²` (−∞ where `h` is
//! not finite; outputs that are not finite skipped) and `Λ(z) = Σ_{j<k} ℓ_j(z)`:
//!
//! ```text
//! correct    while the effective count of w_p e^{(1−φ) ℓ_k(z_p)} is below M / 2 ([`KEEP`]):
//!              the largest δ keeping it at M / 2 (bisection), w_p ← w_p e^{δ ℓ_k(z_p)}, φ ← φ + δ,
//!              systematic resampling, a move leaving prior(z) e^{Λ(z) + φ ℓ_k(z)} invariant;
//!            then w_p ← w_p e^{(1−φ) ℓ_k(z_p)}                                    (normalised)
//! estimate   r̂ = Σ_p w_p r(x_p(k))                                      (the posterior mean)
//! rejuvenate when the effective count 1 / Σ w_p² < M / 2: systematic resampling and a move leaving
//!            prior(z) e^{Λ(z) + ℓ_k(z)} invariant
//! predict    x_p ← one sampling period of the model, projected onto the physical bounds
//! ```
//!
//! A move is one random-walk Metropolis–Hastings step in the coordinates of `z` the prior does not
//! fix, the step the cloud's covariance scaled by `2.38 / √d` (Roberts, Gelman & Gilks, *Weak
//! convergence and optimal scaling of random walk Metropolis algorithms*, 1997); a proposal is run
//! from the start through sample `k`, so a move at sample `k` costs `k` samples of the model. One step
//! per stage (on `ecoli_x0_2`, five gave the same validation RMSE, 0.0223 / 0.0122 against 0.0212 /
//! 0.0124, for five times the cost), but [`FIRST_STEPS`] at the first sample, where a step runs no
//! model and the cloud must spread over the box in the directions the sample says nothing of. At
//! most [`MAX_STAGES`] stages per sample.
//!
//! The host's time is bounded: a run's moves re-run at most [`MOVE_BUDGET`] times its samples per
//! particle (the first sample's run no model), so the moves at most double the filter's cost. They
//! are spent first where they are needed first, on the first samples; past the budget the sampler
//! goes on without moves (importance sampling with resampling, still exact as the count grows, but
//! poorer in distinct particles), and the doubling check says whether that is still converged. Where
//! information keeps arriving late (the E. coli designs: the substrate running out), unlimited
//! moves made the floor converge at 500 particles on `ecoli_x0_2` (validation RMSE 0.0211 / 0.0125)
//! but added about two minutes of CPU to `gen`; with the budget it does not converge there, and the
//! report says so.
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
use stages::Stages;
use weights::{effective, effective_tempered, normalised, spread, systematic, temper};

/// The filter's seed (each run a stream of its own).
pub const SEED: u64 = 0x5eed_f100;

/// The share of the particles' count a tempering stage keeps effective, and the effective count
/// below which the sampler rejuvenates: the usual half.
pub const KEEP: f64 = 0.5;

/// The most tempering stages at one sample. With half the effective count kept per stage, a stage
/// takes about ln 2 of the likelihood's information or more: 100 stages cover likelihoods `e^70`
/// times narrower than the cloud.
pub const MAX_STAGES: usize = 100;

/// Metropolis–Hastings steps per move at the first sample, where a proposal runs no model (one
/// later).
pub const FIRST_STEPS: usize = 10;

/// The most samples a run's moves re-run per particle, in multiples of the run's samples: the moves
/// then at most double the filter's cost.
pub const MOVE_BUDGET: usize = 1;

/// Bisection steps for a stage's exponent.
const BISECTIONS: usize = 30;

/// The particle filter of a design.
pub struct Floor<'a> {
    code: &'a ModelCode,
    /// `f`, `h` and `r` alone (no Jacobian).
    field: Program,
    output: Program,
    /// The uncertain parameters (indices into the model's), each a coordinate of the particles after
    /// the states: the plant's value is unknown within its range, as the runs draw it.
    uncertain: Vec<usize>,
    /// Each coordinate's `(min, max)` in the prior: the learning box (a fixed state: its value twice),
    /// then each uncertain parameter's range.
    ranges: Vec<(f64, f64)>,
    weights: Vec<f64>,
    /// RK4 step and substeps per sample.
    h: f64,
    substeps: usize,
    /// Particles.
    pub count: usize,
}

/// The particles: each one's start and parameters, its state now and its log-likelihoods.
struct Cloud {
    /// `z`: the start's states, then the uncertain parameters, coordinate by coordinate.
    z: Vec<Vec<f64>>,
    /// The state at the current sample.
    x: Vec<Vec<f64>>,
    /// `Λ`: the log-likelihood of the samples before the current one.
    past: Vec<f64>,
    /// `ℓ_k`: that of the current sample.
    now: Vec<f64>,
}

impl Cloud {
    /// The particles `picked`.
    fn pick(&mut self, picked: &[usize]) {
        for coordinate in self.z.iter_mut().chain(self.x.iter_mut()) {
            *coordinate = picked.iter().map(|&p| coordinate[p]).collect();
        }
        self.past = picked.iter().map(|&p| self.past[p]).collect();
        self.now = picked.iter().map(|&p| self.now[p]).collect();
    }
}

/// Buffers for the model's programs.
struct Work {
    values: Vec<f64>,
    outputs: Vec<Vec<f64>>,
    targets: Vec<Vec<f64>>,
    integrator: Stages,
    /// What is left of the run's [`MOVE_BUDGET`], in samples per particle.
    budget: usize,
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
        let z: Vec<Vec<f64>> = self
            .ranges
            .iter()
            .map(|&(low, high)| (0..m).map(|_| low + (high - low) * rng.random::<f64>()).collect())
            .collect();
        let mut cloud = Cloud {
            x: z[..d.states].to_vec(),
            z,
            past: vec![0.0; m],
            now: vec![0.0; m],
        };
        let mut log_weights = vec![0.0; m];
        let mut work = Work {
            values: Vec::new(),
            outputs: vec![Vec::new(); d.outputs],
            targets: vec![Vec::new(); d.targets],
            integrator: Stages::new(d.states, m),
            budget: MOVE_BUDGET * run.measurements.len(),
        };
        let mut estimates = Rows::new(d.targets);
        for k in 0..run.measurements.len() {
            cloud.now = self.log_likelihood(&cloud.x, &cloud.z, (&run.measurements[k], &run.inputs[k]), &mut work);
            self.correct(&mut cloud, &mut log_weights, run, k, &mut rng, &mut work);
            let weights = normalised(&log_weights);
            self.code.targets.eval_many(
                &self.code.parameters,
                &self.varying(&cloud.z),
                &cloud.x,
                &run.inputs[k],
                &mut work.values,
                &mut work.targets,
            );
            let row: Vec<f64> = (work.targets.iter())
                .map(|values| values.iter().zip(&weights).map(|(v, w)| v * w).sum())
                .collect();
            estimates.push(&row);
            if effective(&weights) < KEEP * m as f64 {
                cloud.pick(&systematic(&weights, &mut rng));
                log_weights.fill(0.0);
                self.moves(&mut cloud, 1.0, run, k, &mut rng, &mut work);
            } else {
                for (lw, w) in log_weights.iter_mut().zip(&weights) {
                    *lw = w.ln();
                }
            }
            for (past, now) in cloud.past.iter_mut().zip(&cloud.now) {
                *past += now;
            }
            let varying = self.varying(&cloud.z);
            work.integrator
                .advance(self, &mut cloud.x, &varying, &run.inputs[k], &mut work.values);
        }
        estimates
    }

    /// Bayes' rule for sample `k`, tempered (see the module's documentation); `cloud.now` holds its
    /// log-likelihood.
    fn correct(
        &self,
        cloud: &mut Cloud,
        log_weights: &mut [f64],
        run: &Run,
        k: usize,
        rng: &mut ChaCha8Rng,
        work: &mut Work,
    ) {
        let keep = KEEP * log_weights.len() as f64;
        let mut left = 1.0;
        for _ in 0..MAX_STAGES {
            if work.budget < k {
                break; // no move left: the rest at once
            }
            if effective_tempered(log_weights, &cloud.now, left) >= keep {
                break;
            }
            // The smallest exponent tried whose effective count fell below `keep`: positive, so
            // that particles the sample rules out (ℓ = −∞) go at this stage.
            let (mut low, mut high) = (0.0, left);
            for _ in 0..BISECTIONS {
                let middle = 0.5 * (low + high);
                if effective_tempered(log_weights, &cloud.now, middle) >= keep {
                    low = middle;
                } else {
                    high = middle;
                }
            }
            temper(log_weights, &cloud.now, high);
            left -= high;
            cloud.pick(&systematic(&normalised(log_weights), rng));
            log_weights.fill(0.0);
            self.moves(cloud, 1.0 - left, run, k, rng, work);
        }
        temper(log_weights, &cloud.now, left);
    }

    /// Each particle's log-likelihood of the sample `(y, u)` at states `x` (outputs that are not
    /// finite ignored).
    fn log_likelihood(&self, x: &[Vec<f64>], z: &[Vec<f64>], (y, u): (&[f64], &[f64]), work: &mut Work) -> Vec<f64> {
        let mut likelihood = vec![0.0; x.first().map_or(0, Vec::len)];
        if !y.iter().any(|y| y.is_finite()) {
            return likelihood; // a refused sample carries no information
        }
        self.output.eval_many(
            &self.code.parameters,
            &self.varying(z),
            x,
            u,
            &mut work.values,
            &mut work.outputs,
        );
        for ((&yi, &w), predicted) in y.iter().zip(&self.weights).zip(&work.outputs) {
            if !yi.is_finite() {
                continue;
            }
            for (l, &p) in likelihood.iter_mut().zip(predicted) {
                let r = yi - p;
                // A particle whose output is not finite has no weight.
                *l += if r.is_finite() {
                    -0.5 * w * r * r
                } else {
                    f64::NEG_INFINITY
                };
            }
        }
        likelihood
    }

    /// A move at sample `k`: [`FIRST_STEPS`] Metropolis–Hastings steps at the first sample, one later,
    /// none past the run's budget.
    fn moves(&self, cloud: &mut Cloud, exponent: f64, run: &Run, k: usize, rng: &mut ChaCha8Rng, work: &mut Work) {
        if work.budget < k {
            return;
        }
        work.budget -= k;
        for _ in 0..if k == 0 { FIRST_STEPS } else { 1 } {
            self.metropolis(cloud, exponent, run, k, rng, work);
        }
    }

    /// One random-walk Metropolis–Hastings step leaving `prior(z) e^{Λ(z) + exponent ℓ_k(z)}`
    /// invariant (fixed coordinates stay); each proposal run from the start through sample `k`.
    fn metropolis(&self, cloud: &mut Cloud, exponent: f64, run: &Run, k: usize, rng: &mut ChaCha8Rng, work: &mut Work) {
        let moving: Vec<usize> = (0..cloud.z.len())
            .filter(|&i| self.ranges[i].0 < self.ranges[i].1)
            .collect();
        let Some(root) = spread(&cloud.z, &moving) else {
            return; // not finite: left as resampled
        };
        let n = self.code.dimensions.states;
        let m = cloud.past.len();
        let scale = 2.38 / (moving.len() as f64).sqrt();
        let mut proposal = cloud.z.clone();
        let mut draw = vec![0.0; moving.len()];
        #[allow(clippy::needless_range_loop)] // particle p of every coordinate
        for p in 0..m {
            draw.iter_mut().for_each(|d| *d = rng.sample::<f64, _>(StandardNormal));
            for (a, &i) in moving.iter().enumerate() {
                let step: f64 = (0..=a).map(|b| root[(a, b)] * draw[b]).sum();
                proposal[i][p] = cloud.z[i][p] + scale * step;
            }
        }
        // The proposals' trajectories through sample k.
        let mut x = proposal[..n].to_vec();
        let mut past = vec![0.0; m];
        let mut now = Vec::new();
        for j in 0..=k {
            let sample = (&run.measurements[j][..], &run.inputs[j][..]);
            let likelihood = self.log_likelihood(&x, &proposal, sample, work);
            if j < k {
                past.iter_mut().zip(&likelihood).for_each(|(a, l)| *a += l);
                let varying = self.varying(&proposal);
                work.integrator
                    .advance(self, &mut x, &varying, sample.1, &mut work.values);
            } else {
                now = likelihood;
            }
        }
        let target = |past: f64, now: f64| if exponent > 0.0 { past + exponent * now } else { past };
        for p in 0..m {
            let uniform: f64 = rng.random();
            let inside = moving.iter().all(|&i| {
                let (low, high) = self.ranges[i];
                (low..=high).contains(&proposal[i][p])
            });
            let (new, old) = (target(past[p], now[p]), target(cloud.past[p], cloud.now[p]));
            if inside && new > f64::NEG_INFINITY && (old == f64::NEG_INFINITY || uniform.ln() < new - old) {
                moving.iter().for_each(|&i| cloud.z[i][p] = proposal[i][p]);
                (0..n).for_each(|i| cloud.x[i][p] = x[i][p]);
                (cloud.past[p], cloud.now[p]) = (past[p], now[p]);
            }
        }
    }

    /// The uncertain parameters' values at every particle (`z`'s coordinates after the states), as
    /// [`Program::eval_many`] takes them.
    fn varying<'c>(&self, z: &'c [Vec<f64>]) -> Vec<(usize, &'c [f64])> {
        let drawn = &z[self.code.dimensions.states..];
        self.uncertain
            .iter()
            .zip(drawn)
            .map(|(&k, v)| (k, v.as_slice()))
            .collect()
    }
}

mod stages;
#[cfg(test)]
mod tests;
mod weights;
