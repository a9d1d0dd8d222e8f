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
//! starts from the map's estimate of every state: a state that no target is has a helper map
//! ([`crate::fit::helpers`]). [`estimate_run`] is `firmware::Started` over the emitted programs
//! ([`crate::observers::kind::corrected::program`]), step for step.
//!
//! Its gains are chosen in closed loop on the tuning runs: [`tuning`] says how.

pub mod tuning;

pub use tuning::{tune, Tuned};

use firmware::emitted::Maths;
use firmware::Scalar;

use crate::data::{Rows, Run};
use crate::observers::kind::corrected::program::{CorrectionCode, CorrectionConstants, Reading};
use crate::observers::lost::Track;
use crate::observers::started::literals;
use crate::plant::ModelCode;
use crate::spec::Design;

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
    /// The map row of every state ([`crate::fit::helpers::state_maps`]).
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
        let maps: Vec<crate::fit::maps::FittedMap> = result.start_maps().map(|t| t.fit.map.clone()).collect();
        Self::for_maps(design, design.map.horizon, &maps, code, state_targets)
    }

    /// [`Setting::for_design`] from the fitted maps alone (the targets', then the helpers') and the
    /// horizon `N`.
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
/// step for step. NaN before the first estimate. With the restarts on the run.
pub fn estimate_run<T: Scalar + Maths>(
    setting: &Setting<'_>,
    code: &CorrectionCode,
    constants: &CorrectionConstants,
    map: &[Vec<T>],
    run: &Run,
) -> Track<Vec<Vec<T>>> {
    let mut observer = CorrectedStep::new(setting, code, constants);
    let rows = map
        .iter()
        .zip(run.measurements.iter().zip(run.inputs.iter()))
        .map(|(row, (y, u))| observer.step(row, y, u))
        .collect();
    Track {
        rows,
        restarts: observer.restarts(),
    }
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
    shell: crate::observers::started::Shell<T, Vec<T>>,
}

impl<'a, T: Scalar + Maths> CorrectedStep<'a, T> {
    /// Before the first sample of a run.
    pub fn new(setting: &'a Setting<'a>, code: &'a CorrectionCode, constants: &'a CorrectionConstants) -> Self {
        CorrectedStep {
            setting,
            code,
            constants,
            lower: literals(&constants.lower),
            upper: literals(&constants.upper),
            blends: constants.blends().iter().map(|row| literals(row)).collect(),
            scratch: std::cell::RefCell::new(Vec::new()),
            shell: crate::observers::started::Shell::new(
                setting.first,
                setting.state_targets,
                setting.code.dimensions.targets,
                (constants.start_up, code.steady_reads_map),
            ),
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
        // `firmware::emitted::clamp`: NaN to the lower end.
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

impl<T: Scalar> CorrectedStep<'_, T> {
    /// Samples refused so far for a bad value, as the chip counts them.
    pub fn refused(&self) -> u32 {
        self.shell.refused()
    }

    /// Restarts so far, as the chip counts them.
    pub fn restarts(&self) -> u32 {
        self.shell.restarts()
    }
}

/// [`estimate_run`] in `f64` over the map's `f64` estimates.
pub fn estimate_rows(
    setting: &Setting<'_>,
    code: &CorrectionCode,
    constants: &CorrectionConstants,
    map: &Rows,
    run: &Run,
) -> Track {
    let map: Vec<Vec<f64>> = map.iter().map(<[f64]>::to_vec).collect();
    Track::from(estimate_run(setting, code, constants, &map, run))
}

#[cfg(test)]
mod tests;
