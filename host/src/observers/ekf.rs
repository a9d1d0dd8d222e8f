//! The EKF peer on the host: the firmware's own [`firmware::Ekf`] in `f64` over the model's programs
//! ([`crate::plant::Compiled`]), tuned on the tuning runs and judged like the map.
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
//! `θ` minimises the [score](super::score) (pooled RMSE and the 95th percentile over runs, per
//! target, over its spread) on the tuning runs from random starts (the filter that starts at the
//! box centre is tuned for starts anywhere in the box; `auto` judges it with the others on the runs
//! from the scenario's start too): first on an isotropic decade grid (`a_i = a`,
//! `b_i = b`, `a ∈ {−8…0}`, `b ∈ {−3…0}`), then by Nelder–Mead (`argmin`) from the
//! [`STARTS`] best grid points, each coordinate free (until the simplex's scores agree within
//! 1e-4). Deterministic: a fixed grid, fixed starts and iterations, the best by cost and the first
//! of equals. The map-started EKF shares `Q` (one filter
//! on the chip) and scales its own start covariance ([`tune_started`]).

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

/// The range of each log-space coordinate of `θ`.
pub const LOG_RANGE: (f64, f64) = (-12.0, 3.0);

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
    )
    .with_bounds(
        std::array::from_fn(|i| code.bounds[i].lower()),
        std::array::from_fn(|i| code.bounds[i].upper()),
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

/// The constants for `θ = (a, b)` (see the module docs), each coordinate clamped to [`LOG_RANGE`].
pub fn constants(design: &Design, centre: &[f64], spreads: &[f64], theta: &[f64]) -> EkfConstants {
    let n = spreads.len();
    let scaled = |logs: &[f64]| -> Vec<f64> {
        logs.iter()
            .zip(spreads)
            .map(|(a, s)| 10f64.powf(a.clamp(LOG_RANGE.0, LOG_RANGE.1)) * s * s)
            .collect()
    };
    EkfConstants {
        x0: centre.to_vec(),
        p0: scaled(&theta[n..2 * n]),
        q: scaled(&theta[..n]),
        r: design.model.outputs.iter().map(|o| o.noise_variance).collect(),
        substeps: design.chip_substeps,
        h: design.tau / design.chip_substeps as f64,
    }
}

/// The filter's estimates of every run of `data`, started at `x0`.
pub fn estimates(code: &ModelCode, constants: &EkfConstants, x0: &[f64], data: &DataSet) -> Option<Vec<Rows>> {
    data.runs
        .iter()
        .map(|run| estimate_run(code, constants, x0, run))
        .collect()
}

/// RMSE per target over the windows of `data` (samples `k ≥ N - 1` of every run), with the filter
/// started at `x0`; NaN where the filter diverged.
pub fn rmse(code: &ModelCode, constants: &EkfConstants, x0: &[f64], data: &DataSet) -> Option<Vec<f64>> {
    let estimates = estimates(code, constants, x0, data)?;
    let windows = |run: &Run| data.horizon.saturating_sub(1)..run.targets.len();
    Some(
        (0..code.dimensions.targets)
            .map(|t| super::errors(&data.runs, &estimates, t, windows).0)
            .collect(),
    )
}

/// The EKF from `constants.x0` (the box centre) over `run`, in `T`, step for step the generated
/// `Ekf::push` (the written-out programs `filter`): per sample the targets of `x̂(k|k)`, or `None`
/// where the sample is refused (a non-finite output or input, or a step whose result is not finite,
/// which is then not taken).
pub fn estimate_box<T: firmware::Scalar + firmware::Maths>(
    filter: &crate::plant::kalman::FilterCode,
    constants: &EkfConstants,
    run: &Run,
    code: &ModelCode,
) -> Vec<Option<Vec<T>>> {
    let mut observer = BoxStep::new(filter, constants, code);
    run.measurements
        .iter()
        .zip(run.inputs.iter())
        .map(|(y, u)| observer.step(y, u))
        .collect()
}

/// [`estimate_box`] one sample at a time: what the filter carries between samples.
pub struct BoxStep<'a, T> {
    filter: &'a crate::plant::kalman::FilterCode,
    code: &'a ModelCode,
    x: Vec<T>,
    p: Vec<T>,
    scratch: Vec<T>,
}

impl<'a, T: firmware::Scalar + firmware::Maths> BoxStep<'a, T> {
    /// At the box centre, before the first sample of a run.
    pub fn new(filter: &'a crate::plant::kalman::FilterCode, constants: &EkfConstants, code: &'a ModelCode) -> Self {
        let literal = |v: &f64| T::literal(*v as f32, *v);
        BoxStep {
            filter,
            code,
            x: constants.x0.iter().map(literal).collect(),
            p: crate::plant::kalman::diagonal_upper(&constants.p0)
                .iter()
                .map(literal)
                .collect(),
            scratch: Vec::new(),
        }
    }

    /// The targets after the sample with outputs `y` and inputs `u` (`None`: refused).
    pub fn step(&mut self, y: &[f64], u: &[f64]) -> Option<Vec<T>> {
        let finite = |x: &[T], p: &[T]| x.iter().chain(p).all(|v| v.is_finite());
        let u: Vec<T> = u.iter().map(|&v| T::literal(v as f32, v)).collect();
        if !u.iter().all(|v| v.is_finite()) {
            return None;
        }
        let y: Vec<T> = y.iter().map(|&v| T::literal(v as f32, v)).collect();
        let measured = y.iter().all(|v| v.is_finite());
        let (estimate, next_x, next_p) = self.filter.run(
            &self.x,
            &self.p,
            measured.then_some(y.as_slice()),
            &u,
            &mut self.scratch,
        );
        let taken = finite(&next_x, &next_p);
        if taken {
            (self.x, self.p) = (next_x, next_p);
        }
        match estimate {
            Some(estimate) if taken => Some(self.code.targets(&estimate, &u, &mut self.scratch)),
            _ => None,
        }
    }
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
    let mut observer = StartedStep::new(filter, p0, state_targets, first, code);
    map.iter()
        .zip(run.measurements.iter().zip(run.inputs.iter()))
        .map(|(row, (y, u))| observer.step(row, y, u))
        .collect()
}

/// [`estimate_started`] one sample at a time.
pub struct StartedStep<'a, T> {
    filter: &'a crate::plant::kalman::FilterCode,
    code: &'a ModelCode,
    /// `P` at the start, its upper triangle.
    upper: Vec<T>,
    scratch: std::cell::RefCell<Vec<T>>,
    shell: super::started::Shell<T, (Vec<T>, Vec<T>)>,
}

impl<'a, T: firmware::Scalar + firmware::Maths> StartedStep<'a, T> {
    /// Before the first sample of a run.
    pub fn new(
        filter: &'a crate::plant::kalman::FilterCode,
        p0: &[f64],
        state_targets: &[usize],
        first: usize,
        code: &'a ModelCode,
    ) -> Self {
        StartedStep {
            filter,
            code,
            upper: crate::plant::kalman::diagonal_upper(p0)
                .iter()
                .map(|&v| T::literal(v as f32, v))
                .collect(),
            scratch: std::cell::RefCell::new(Vec::new()),
            shell: super::started::Shell::new(first, state_targets, code.dimensions.targets),
        }
    }

    /// The targets at the sample with outputs `y` and inputs `u`, the map's estimate there `row`.
    pub fn step(&mut self, row: &[T], y: &[f64], u: &[f64]) -> Vec<T> {
        let StartedStep {
            filter,
            code,
            upper,
            scratch,
            shell,
        } = self;
        let finite = |x: &[T], p: &[T]| x.iter().chain(p).all(|v| v.is_finite());
        shell.step(
            row,
            y,
            u,
            &mut |x, u| {
                let (_, x, p) = filter.run(x, upper, None, u, &mut scratch.borrow_mut());
                finite(&x, &p).then_some((x, p))
            },
            &mut |(x, p): &(Vec<T>, Vec<T>), _, _, y, u| {
                let (estimate, x, p) = filter.run(x, p, Some(y), u, &mut scratch.borrow_mut());
                let estimate = estimate.unwrap_or_else(|| x.clone());
                let targets = code.targets(&estimate, u, &mut scratch.borrow_mut());
                finite(&x, &p).then_some(((x, p), targets))
            },
            // A lost output: the prediction alone (`StartedEkf::predict`).
            &mut |(x, p): &(Vec<T>, Vec<T>), u| {
                let (_, x, p) = filter.run(x, p, None, u, &mut scratch.borrow_mut());
                finite(&x, &p).then_some((x, p))
            },
        )
    }
}

/// The score of the EKF with `constants` from the box centre on `data` (windows `k ≥ N − 1`).
fn score(code: &ModelCode, constants: &EkfConstants, centre: &[f64], data: &DataSet, target_spreads: &[f64]) -> f64 {
    let estimates = estimates(code, constants, centre, data).expect("size checked");
    super::score::of_estimates(&data.runs, &estimates, target_spreads, |run| {
        data.horizon.saturating_sub(1)..run.targets.len()
    })
}

/// The tuning criterion as `argmin` sees it: `θ` to the score.
#[derive(Clone, Copy)]
struct Criterion<'a> {
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
        let score = score(self.code, &constants, self.centre, self.data, self.target_spreads);
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

/// Chooses `Q` and `P(0)` on `tuning` (see the module docs). `target_spreads` normalises each
/// target's errors.
pub fn tune(
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
    super::score::lowest(&START_FACTORS, score)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// E. coli (`ecoli_x0_2`) with its `[model.bounds]` (every concentration ≥ 0) and without them.
    fn ecoli(bounded: bool) -> (Design, ModelCode) {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/ecoli_x0_2.toml");
        let mut text = std::fs::read_to_string(&path).unwrap();
        if !bounded {
            let start = text.find("[model.bounds]").expect("the shipped spec declares bounds");
            let end = start + text[start..].find("\n\n").unwrap();
            text.replace_range(start..end, "");
        }
        let design = crate::spec::parse(&path, &text).unwrap();
        let code = ModelCode::new(&design).unwrap();
        (design, code)
    }

    #[test]
    fn bounds_keep_the_filter_inside_where_the_unbounded_one_leaves() {
        // One filter, constants fixed (a trusting start, a small Q), on the validation runs: without
        // bounds the product P is estimated negative, from where exp(-k_p/P) blows up; with them
        // every estimate of P is ≥ 0 and finite.
        let theta = [-6.0, -6.0, -6.0, -0.5, -0.5, -0.5];
        let lowest = |bounded: bool| -> (f64, bool) {
            let (design, code) = ecoli(bounded);
            let data = crate::data::validation_set(&design).unwrap();
            let spreads = vec![1.0; 3];
            let centre = box_centre(&design);
            let constants = constants(&design, &centre, &spreads, &theta);
            let p = design.targets.iter().position(|t| t.name == "P").unwrap();
            let mut lowest = f64::INFINITY;
            let mut finite = true;
            for run in &data.runs {
                let rows = estimate_run(&code, &constants, &centre, run).unwrap();
                for row in rows.iter() {
                    finite &= row.iter().all(|v| v.is_finite());
                    lowest = lowest.min(row[p]);
                }
            }
            (lowest, finite)
        };
        let (unbounded, _) = lowest(false);
        assert!(
            unbounded < 0.0,
            "the unbounded filter stays inside ({unbounded}): the test shows nothing"
        );
        let (bounded, finite) = lowest(true);
        assert!(bounded >= 0.0, "{bounded}");
        assert!(finite, "a bounded estimate is not finite");
    }
}
