//! The moving-horizon estimate on-line: what the paper's map replaces, solved on the host window by
//! window to convergence, so that the report shows what the map loses to it.
//!
//! At every sample `k ≥ N − 1` the window `(y(j), u(j))`, `j = k − N + 1 … k`, gives the paper's
//! problem ([`firmware::mhe`]): the start `x` minimising the noise-weighted output error (weights
//! `1/σ²`), inside the box the learning runs cover (the learning box widened to every learning state,
//! intersected with the physical bounds), propagated to the window's end by the model the observers
//! carry (the chip's RK4 substeps); the estimate is the targets at `x(N−1)`, projected onto the same
//! box (the textbook MHE bounds every state of the window; this bounds the first and the last, as a
//! chip would: a start on the box's edge may otherwise be carried by a coarse model step far
//! outside). [`solve`] minimises it by projected Levenberg–Marquardt:
//!
//! * the first window of a run from [`starts`] (the box centre and points a quarter inside its
//!   corners) against local minima, keeping the best;
//! * every later window from the previous solution moved one sample on, `x̄ = f(x̂, u)`;
//! * with a prior ([`Prior`]), the term `Σ_i p (x_i − x̄_i)² / s_i²` is added (`s_i` the state's spread
//!   over the learning runs, `p` one weight tuned on the tuning runs, [`tune_prior`]): the paper's
//!   first remark's regularisation, anchored on the model's prediction as an arrival cost.

pub mod chip;
pub mod solve;

pub use chip::{ChipConstants, ChipTuned, CHIP_DAMPING, CHIP_ITERATIONS, CHIP_WITHIN};

use std::time::Instant;

use firmware::{Plant, Rk4};

use crate::data::{DataSet, Rows, Run};
use crate::plant::{Compiled, ModelCode};
use crate::spec::{Axis, Design};

use crate::observers::ekf::{Stepped, MAX_INPUTS};

/// The prior's weights tried first on the tuning runs (`p`, on states normalised by their spread),
/// every second decade from 10⁻² to 10⁴; then the decades either side of the best ([`tune_prior`]).
pub const PRIOR_WEIGHTS: [f64; 4] = [1e-2, 1.0, 1e2, 1e4];

/// Whether the prior is on, and its weight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Prior {
    /// The paper's problem as it stands.
    None,
    /// `Σ_i p (x_i − x̄_i)² / s_i²` added from the second window of a run.
    Weight(f64),
}

/// A design's moving-horizon problem: everything but the window.
pub struct Setup<'a> {
    code: &'a ModelCode,
    horizon: usize,
    lower: Vec<f64>,
    upper: Vec<f64>,
    weights: Vec<f64>,
    spreads: Vec<f64>,
    starts: Vec<Vec<f64>>,
    h: f64,
    substeps: usize,
}

/// A run's estimates and what the solver took for each window.
#[derive(Clone, Debug, Default)]
pub struct Solved {
    /// Every target at every sample (NaN before the first window).
    pub rows: Rows,
    /// Seconds per window.
    pub seconds: Vec<f64>,
    /// Iterations per window (the first window's summed over its starts).
    pub iterations: Vec<usize>,
}

/// The starts of a run's first window: the centre of the learning box and, with at most 4 varying
/// states, the `2ⁿ` points a quarter inside its corners; with more, the centre moved a quarter of the
/// box along each axis both ways.
pub fn starts(design: &Design) -> Vec<Vec<f64>> {
    let axes: Vec<(f64, f64)> = design
        .learning
        .axes
        .iter()
        .map(|axis| match *axis {
            Axis::Range { min, max, .. } => (min, max),
            Axis::Fixed(value) => (value, value),
        })
        .collect();
    let centre: Vec<f64> = axes.iter().map(|(a, b)| 0.5 * (a + b)).collect();
    let varying: Vec<usize> = (0..axes.len()).filter(|&i| axes[i].1 > axes[i].0).collect();
    let mut starts = vec![centre.clone()];
    let quarter = |i: usize, side: bool| {
        let (a, b) = axes[i];
        if side {
            a + 0.75 * (b - a)
        } else {
            a + 0.25 * (b - a)
        }
    };
    if varying.len() <= 4 {
        for corner in 0..1usize << varying.len() {
            let mut x = centre.clone();
            for (bit, &i) in varying.iter().enumerate() {
                x[i] = quarter(i, corner >> bit & 1 == 1);
            }
            starts.push(x);
        }
    } else {
        for &i in &varying {
            for side in [false, true] {
                let mut x = centre.clone();
                x[i] = quarter(i, side);
                starts.push(x);
            }
        }
    }
    starts
}

impl<'a> Setup<'a> {
    /// The problem of `design` (its box from the learning runs `learning`); `None` when the model is
    /// beyond the host's sizes ([`crate::observers::ekf::supported`]).
    pub fn new(design: &Design, code: &'a ModelCode, learning: &DataSet) -> Option<Self> {
        if !crate::observers::ekf::supported(code) {
            return None;
        }
        let states = code.dimensions.states;
        let (mut lower, mut upper): (Vec<f64>, Vec<f64>) = design
            .learning
            .axes
            .iter()
            .map(|axis| match *axis {
                Axis::Range { min, max, .. } => (min, max),
                Axis::Fixed(value) => (value, value),
            })
            .unzip();
        for run in &learning.runs {
            for x in run.states.iter() {
                for i in 0..states {
                    lower[i] = lower[i].min(x[i]);
                    upper[i] = upper[i].max(x[i]);
                }
            }
        }
        for (i, bounds) in code.bounds.iter().enumerate() {
            lower[i] = lower[i].max(bounds.lower());
            upper[i] = upper[i].min(bounds.upper());
        }
        Some(Setup {
            code,
            horizon: design.map.horizon,
            lower,
            upper,
            weights: design
                .model
                .outputs
                .iter()
                .map(|o| 1.0 / o.noise_variance.max(1e-300))
                .collect(),
            spreads: crate::observers::ekf::state_spreads(learning, states),
            starts: starts(design),
            h: design.tau / design.chip_substeps as f64,
            substeps: design.chip_substeps,
        })
    }

    /// The estimates of every window of `run`, solved to convergence.
    pub fn run(&self, prior: Prior, run: &Run) -> Solved {
        macro_rules! sized {
            ($(($nx:literal, $ny:literal)),*) => {
                match (self.code.dimensions.states, self.code.dimensions.outputs) {
                    $(($nx, $ny) => self.run_sized::<$nx, $ny>(prior, run),)*
                    _ => unreachable!("sizes checked by Setup::new"),
                }
            };
        }
        crate::observers::ekf::host_sizes!(sized)
    }

    fn run_sized<const NX: usize, const NY: usize>(&self, prior: Prior, run: &Run) -> Solved {
        let plant = Stepped {
            step: Rk4::new(Compiled::new(self.code), self.h),
            substeps: self.substeps,
        };
        let samples: Vec<([f64; NY], [f64; MAX_INPUTS])> = run
            .measurements
            .iter()
            .zip(run.inputs.iter())
            .map(|(y, u)| {
                let mut padded = [0.0; MAX_INPUTS];
                padded[..u.len()].copy_from_slice(u);
                (std::array::from_fn(|i| y[i]), padded)
            })
            .collect();
        let array = |v: &[f64]| -> [f64; NX] { std::array::from_fn(|i| v[i]) };
        let (lower, upper) = (array(&self.lower), array(&self.upper));
        let mut problem = solve::Problem {
            lower,
            upper,
            weights: std::array::from_fn(|i| self.weights[i]),
            spreads: &self.spreads,
            prior: None,
        };
        let n = self.horizon;
        let mut solved = Solved {
            rows: Rows::new(self.code.dimensions.targets),
            ..Solved::default()
        };
        let nan = vec![f64::NAN; self.code.dimensions.targets];
        for _ in 0..(n - 1).min(samples.len()) {
            solved.rows.push(&nan);
        }
        let mut previous: Option<[f64; NX]> = None;
        let mut scratch = Vec::new();
        for k in n - 1..samples.len() {
            let window = &samples[k + 1 - n..=k];
            let clock = Instant::now();
            // The previous start moved one sample on: the warm start, and the prior's centre.
            let moved = previous
                .map(|x| {
                    let next = Plant::<f64, NX, NY, MAX_INPUTS>::step(&plant, &x, &samples[k - n].1).0;
                    firmware::emitted::project(&next, &lower, &upper)
                })
                .filter(|x| x.iter().all(|v| v.is_finite()));
            let best = match moved {
                Some(centre) => {
                    problem.prior = match prior {
                        Prior::None => None,
                        Prior::Weight(p) => {
                            Some((centre, std::array::from_fn(|i| p / (self.spreads[i] * self.spreads[i]))))
                        }
                    };
                    solve::minimise(&plant, &problem, window, &centre)
                }
                None => {
                    problem.prior = None;
                    let mut iterations = 0;
                    let mut best = self
                        .starts
                        .iter()
                        .map(|s| {
                            let solution = solve::minimise(&plant, &problem, window, &array(s));
                            iterations += solution.iterations;
                            solution
                        })
                        .min_by(|a, b| a.cost.total_cmp(&b.cost))
                        .expect("at least the centre");
                    best.iterations = iterations;
                    best
                }
            };
            solved.seconds.push(clock.elapsed().as_secs_f64());
            solved.iterations.push(best.iterations);
            previous = Some(best.start);
            let end = firmware::emitted::project(&best.end, &lower, &upper);
            solved.rows.push(&self.code.targets(&end, &run.inputs[k], &mut scratch));
        }
        solved
    }
}

/// The prior's weight with the lowest `score` of the estimates it gives on the tuning runs, and that
/// score: the best of [`PRIOR_WEIGHTS`], then of the decades either side of it (10⁻³ … 10⁵ in all,
/// six weights scored instead of nine).
pub fn tune_prior(setup: &Setup<'_>, tuning: &[Run], score: impl Fn(&[Rows]) -> f64) -> (f64, f64) {
    use rayon::prelude::*;
    let scored = |p: f64| {
        let rows: Vec<Rows> = tuning
            .par_iter()
            .map(|run| setup.run(Prior::Weight(p), run).rows)
            .collect();
        (p, score(&rows))
    };
    let best = |a: (f64, f64), b: (f64, f64)| if b.1 < a.1 { b } else { a };
    let coarse = PRIOR_WEIGHTS
        .iter()
        .map(|&p| scored(p))
        .reduce(best)
        .expect("weights to try");
    [coarse.0 / 10.0, coarse.0 * 10.0]
        .into_iter()
        .map(scored)
        .fold(coarse, best)
}
