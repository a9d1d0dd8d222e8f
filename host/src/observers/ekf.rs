//! The EKF peer on the host: the firmware's own [`firmware::Ekf`] in `f64` over the model's programs
//! ([`crate::plant::Compiled`]), tuned on the tuning runs and judged like the map.
//!
//! # Tuning
//!
//! With `s_i` the spread of state `i` over the learning runs (its range; 1 where it never moves),
//! `Q = q · diag(s_i²)` and `P(0) = p · diag(s_i²)`; `R` is the outputs' noise variances and the filter
//! starts at the centre of the state box. `(q, p)` minimises the mean over targets of RMSE / spread
//! on the tuning runs: first on the grid `q ∈ 10^{-8…0}`, `p ∈ 10^{-3…0}` (decades), then once more on
//! the half-decades around the best point. Deterministic: no random search.

use firmware::{Ekf, Plant, Rk4};

use crate::data::{DataSet, Rows, Run};
use crate::plant::kalman::EkfConstants;
use crate::plant::{Compiled, ModelCode};
use crate::spec::{Axis, Design};

/// Most states and outputs the host's EKF is instantiated for (the filter's dimensions are types).
pub const MAX_STATES: usize = 6;
/// See [`MAX_STATES`].
pub const MAX_OUTPUTS: usize = 4;
/// Inputs are passed padded to this many (the model reads its own).
pub const MAX_INPUTS: usize = 4;

/// The tuned filter and how it was chosen.
#[derive(Clone, Debug)]
pub struct Tuned {
    /// The constants the design's EKF is emitted with.
    pub constants: EkfConstants,
    /// The chosen `q` and `p`.
    pub q: f64,
    /// See `q`.
    pub p: f64,
    /// The criterion at the chosen point (mean normalised RMSE on the tuning runs).
    pub cost: f64,
    /// Candidates evaluated.
    pub candidates: usize,
}

/// Whether the host can run an EKF of this size.
pub fn supported(code: &ModelCode) -> bool {
    let d = code.dimensions;
    (1..=MAX_STATES).contains(&d.states) && (1..=MAX_OUTPUTS).contains(&d.outputs) && d.inputs <= MAX_INPUTS
}

/// The centre of the state box (the held value for a fixed state).
pub fn box_centre(design: &Design) -> Vec<f64> {
    design
        .learning
        .axes
        .iter()
        .map(|axis| match *axis {
            Axis::Range { min, max, .. } => 0.5 * (min + max),
            Axis::Fixed(value) => value,
        })
        .collect()
}

/// The range of each state over `data` (1 where it is constant).
pub fn state_spreads(data: &DataSet, states: usize) -> Vec<f64> {
    (0..states)
        .map(|i| {
            let (low, high) = data
                .runs
                .iter()
                .flat_map(|run| run.states.iter().map(move |x| x[i]))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v), h.max(v)));
            if high > low {
                high - low
            } else {
                1.0
            }
        })
        .collect()
}

/// One sampling period of the model in `substeps` RK4 steps: the firmware's one-step [`Rk4`] composed
/// (the chip's `Rk4<_, _, CHIP_SUBSTEPS>` does the same products in the same order).
pub(crate) struct Stepped<'a> {
    pub(crate) step: Rk4<f64, Compiled<'a, f64>, 1>,
    pub(crate) substeps: usize,
}

impl<const NX: usize, const NY: usize, const NU: usize> Plant<f64, NX, NY, NU> for Stepped<'_> {
    fn step(&self, x: &[f64; NX], u: &[f64; NU]) -> ([f64; NX], [[f64; NX]; NX]) {
        let (mut x, mut jacobian) = Plant::<f64, NX, NY, NU>::step(&self.step, x, u);
        for _ in 1..self.substeps {
            let (next, d) = Plant::<f64, NX, NY, NU>::step(&self.step, &x, u);
            x = next;
            jacobian = firmware::model::product(&d, &jacobian);
        }
        (x, jacobian)
    }

    fn output(&self, x: &[f64; NX], u: &[f64; NU]) -> ([f64; NY], [[f64; NX]; NY]) {
        Plant::<f64, NX, NY, NU>::output(&self.step, x, u)
    }
}

/// The targets estimated at every sample of `run` by the EKF with `constants` started at `x0`.
/// `None` when the model is larger than the host's instantiations ([`supported`]).
pub fn estimate_run(code: &ModelCode, constants: &EkfConstants, x0: &[f64], run: &Run) -> Option<Rows> {
    macro_rules! sized {
        ($(($nx:literal, $ny:literal)),*) => {
            match (code.dimensions.states, code.dimensions.outputs) {
                $(($nx, $ny) => Some(run_sized::<$nx, $ny>(code, constants, x0, run)),)*
                _ => None,
            }
        };
    }
    if code.dimensions.inputs > MAX_INPUTS {
        return None;
    }
    sized!(
        (1, 1),
        (1, 2),
        (1, 3),
        (1, 4),
        (2, 1),
        (2, 2),
        (2, 3),
        (2, 4),
        (3, 1),
        (3, 2),
        (3, 3),
        (3, 4),
        (4, 1),
        (4, 2),
        (4, 3),
        (4, 4),
        (5, 1),
        (5, 2),
        (5, 3),
        (5, 4),
        (6, 1),
        (6, 2),
        (6, 3),
        (6, 4)
    )
}

fn run_sized<const NX: usize, const NY: usize>(
    code: &ModelCode,
    constants: &EkfConstants,
    x0: &[f64],
    run: &Run,
) -> Rows {
    let plant = Stepped {
        step: Rk4::new(Compiled::new(code), constants.h),
        substeps: constants.substeps,
    };
    let diagonal = |values: &[f64]| -> [[f64; NX]; NX] {
        std::array::from_fn(|i| std::array::from_fn(|j| if i == j { values[i] } else { 0.0 }))
    };
    let mut filter: Ekf<f64, Stepped<'_>, NX, NY, MAX_INPUTS> = Ekf::new(
        plant,
        std::array::from_fn(|i| x0[i]),
        diagonal(&constants.p0),
        diagonal(&constants.q),
        std::array::from_fn(|i| constants.r[i]),
    );
    let mut estimates = Rows::new(code.dimensions.targets);
    let mut scratch = Vec::new();
    for (y, u) in run.measurements.iter().zip(run.inputs.iter()) {
        let mut padded = [0.0; MAX_INPUTS];
        padded[..u.len()].copy_from_slice(u);
        let x = match filter.push(&std::array::from_fn(|i| y[i]), &padded) {
            Ok(x) => x,
            Err(_) => [f64::NAN; NX],
        };
        estimates.push(&code.targets(&x, u, &mut scratch));
    }
    estimates
}

/// The constants for `(q, p)`.
pub fn constants(design: &Design, centre: &[f64], spreads: &[f64], q: f64, p: f64) -> EkfConstants {
    let squares = |scale: f64| spreads.iter().map(|s| scale * s * s).collect();
    EkfConstants {
        x0: centre.to_vec(),
        p0: squares(p),
        q: squares(q),
        r: design.model.outputs.iter().map(|o| o.noise_variance).collect(),
        substeps: design.chip_substeps,
        h: design.tau / design.chip_substeps as f64,
    }
}

/// RMSE per target over the windows of `data` (samples `k ≥ N - 1` of every run), with the filter
/// started at `x0`; NaN where the filter diverged.
pub fn rmse(code: &ModelCode, constants: &EkfConstants, x0: &[f64], data: &DataSet) -> Option<Vec<f64>> {
    let estimates = data
        .runs
        .iter()
        .map(|run| estimate_run(code, constants, x0, run))
        .collect::<Option<Vec<Rows>>>()?;
    let windows = |run: &Run| data.horizon.saturating_sub(1)..run.targets.len();
    Some(
        (0..code.dimensions.targets)
            .map(|t| super::errors(&data.runs, &estimates, t, windows).0)
            .collect(),
    )
}

/// The EKF started by the map (the generated `StartedEkf` in `firmware::Started`, step for step,
/// [`super::started::run`]) in `T`: at sample `first` the map's estimate, from which `(x, P)` is
/// predicted with `P` = `p0` on the diagonal; then `filter`'s measured samples.
pub fn estimate_started<T: firmware::Scalar + firmware::Maths>(
    filter: &crate::plant::kalman::FilterCode,
    p0: &[f64],
    state_targets: &[usize],
    first: usize,
    map: &[Vec<T>],
    run: &Run,
    code: &ModelCode,
) -> Vec<Vec<T>> {
    let nx = p0.len();
    let upper: Vec<T> = (0..nx)
        .flat_map(|r| (r..nx).map(move |c| (r, c)))
        .map(|(r, c)| {
            if r == c {
                T::literal(p0[r] as f32, p0[r])
            } else {
                T::ZERO
            }
        })
        .collect();
    let finite = |x: &[T], p: &[T]| x.iter().chain(p).all(|v| v.is_finite());
    let scratch = std::cell::RefCell::new(Vec::new());
    super::started::run(
        first,
        state_targets,
        map,
        run,
        |x, u| {
            let (_, x, p) = filter.run(x, &upper, None, u, &mut scratch.borrow_mut());
            finite(&x, &p).then_some((x, p))
        },
        |(x, p): &(Vec<T>, Vec<T>), _, _, y, u| {
            let (estimate, x, p) = filter.run(x, p, Some(y), u, &mut scratch.borrow_mut());
            let estimate = estimate.unwrap_or_else(|| x.clone());
            let targets = code.targets(&estimate, u, &mut scratch.borrow_mut());
            finite(&x, &p).then_some(((x, p), targets))
        },
        // A lost output: the prediction alone (`StartedEkf::predict`).
        |(x, p): &(Vec<T>, Vec<T>), u| {
            let (_, x, p) = filter.run(x, p, None, u, &mut scratch.borrow_mut());
            finite(&x, &p).then_some((x, p))
        },
    )
}

/// Chooses `(q, p)` on `tuning` (see the module docs). `target_spreads` normalises each target's RMSE.
pub fn tune(
    design: &Design,
    code: &ModelCode,
    tuning: &DataSet,
    learning: &DataSet,
    target_spreads: &[f64],
) -> Option<Tuned> {
    use rayon::prelude::*;
    if !supported(code) {
        return None;
    }
    let centre = box_centre(design);
    let spreads = state_spreads(learning, code.dimensions.states);
    let cost = |(q, p): (f64, f64)| -> f64 {
        let constants = constants(design, &centre, &spreads, q, p);
        let rmse = rmse(code, &constants, &centre, tuning).expect("size checked");
        let mean = rmse
            .iter()
            .zip(target_spreads)
            .map(|(e, s)| e / s.max(f64::MIN_POSITIVE))
            .sum::<f64>()
            / rmse.len() as f64;
        if mean.is_finite() {
            mean
        } else {
            f64::INFINITY
        }
    };
    let best = |candidates: Vec<(f64, f64)>| -> ((f64, f64), f64) {
        candidates
            .into_par_iter()
            .map(|c| (c, cost(c)))
            .collect::<Vec<_>>()
            .into_iter()
            // The first of equals, so that the choice does not depend on the thread schedule.
            .fold(((f64::NAN, f64::NAN), f64::INFINITY), |best, c| {
                if c.1 < best.1 {
                    c
                } else {
                    best
                }
            })
    };
    let decade = |e: f64| 10f64.powf(e);
    let coarse: Vec<(f64, f64)> = (-8..=0)
        .flat_map(|a| (-3..=0).map(move |b| (decade(f64::from(a)), decade(f64::from(b)))))
        .collect();
    let mut candidates = coarse.len();
    let ((q0, p0), _) = best(coarse);
    if q0.is_nan() {
        return None; // diverged everywhere
    }
    let fine: Vec<(f64, f64)> = [-0.5, 0.0, 0.5]
        .iter()
        .flat_map(|a| [-0.5, 0.0, 0.5].map(|b| (q0 * decade(*a), p0 * decade(b))))
        .collect();
    candidates += fine.len();
    let ((q, p), cost) = best(fine);
    Some(Tuned {
        constants: constants(design, &centre, &spreads, q, p),
        q,
        p,
        cost,
        candidates,
    })
}
