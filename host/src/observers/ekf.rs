//! The EKF peer on the host: the firmware's own [`firmware::Ekf`] in `f64` over the model's programs
//! ([`crate::plant::Compiled`]), tuned on the tuning runs and judged like the map.
//!
//! Its constants are chosen on the tuning runs as an expert tunes a filter: [`tuning`] says how.
//! [`steps`] runs the same filter over the written-out programs by the firmware's own rules, as the chip does.

pub mod steps;
pub mod tuning;

pub use steps::{estimate_box, estimate_started, BoxStep, StartedStep};
pub use tuning::{tune, tune_started, tune_with, Estimator, Tuned, STARTS, START_FACTORS};

use firmware::{Ekf, Plant, Rk4};

use crate::data::{DataSet, Rows, Run};
use crate::observers::lost::{Track, Tracker};
use crate::plant::kalman::{EkfConstants, Watch};
use crate::plant::{Compiled, Covariance, ModelCode};
use crate::spec::{Axis, Design, FixedFilter};

/// Most states and outputs the host's EKF is instantiated for (the filter's dimensions are types).
pub const MAX_STATES: usize = 6;
/// See [`MAX_STATES`].
pub const MAX_OUTPUTS: usize = 4;
/// Inputs are passed padded to this many (the model reads its own).
pub const MAX_INPUTS: usize = 4;

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

/// Where a filter starts: the spec's fixed `x0` (`[observer.<filter>]`), else the
/// centre of the state box.
pub fn start(design: &Design, fixed: &FixedFilter) -> Vec<f64> {
    fixed.x0.clone().unwrap_or_else(|| box_centre(design))
}

/// The range of each state over `data` (1 where it is constant).
pub fn state_spreads(data: &DataSet, states: usize) -> Vec<f64> {
    spreads_in(data, &crate::plant::Coordinates::plant(states))
}

/// The range of each coordinate of `coordinates` over the states of `data` (1 where it is constant).
pub fn spreads_in(data: &DataSet, coordinates: &crate::plant::Coordinates) -> Vec<f64> {
    let n = coordinates.0.len();
    let (mut low, mut high) = (vec![f64::INFINITY; n], vec![f64::NEG_INFINITY; n]);
    for x in data.runs.iter().flat_map(|run| run.states.iter()) {
        for (i, v) in coordinates.to_filter(x).into_iter().enumerate() {
            (low[i], high[i]) = (low[i].min(v), high[i].max(v));
        }
    }
    low.iter()
        .zip(&high)
        .map(|(low, high)| if high > low { high - low } else { 1.0 })
        .collect()
}

/// One sampling period of the model in `substeps` RK4 steps: the firmware's one-step [`Rk4`] composed
/// (the chip's `Rk4<_, _, CHIP_SUBSTEPS>` does the same products in the same order).
pub(crate) struct Stepped<'a, T = f64> {
    pub(crate) step: Rk4<T, Compiled<'a, T>, 1>,
    pub(crate) substeps: usize,
}

impl<T: firmware::Scalar + firmware::emitted::Maths, const NX: usize, const NY: usize, const NU: usize>
    Plant<T, NX, NY, NU> for Stepped<'_, T>
{
    fn step(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NX], [[T; NX]; NX]) {
        let (mut x, mut jacobian) = Plant::<T, NX, NY, NU>::step(&self.step, x, u);
        for _ in 1..self.substeps {
            let (next, d) = Plant::<T, NX, NY, NU>::step(&self.step, &x, u);
            x = next;
            jacobian = firmware::emitted::product(&d, &jacobian);
        }
        (x, jacobian)
    }

    fn output(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NY], [[T; NX]; NY]) {
        Plant::<T, NX, NY, NU>::output(&self.step, x, u)
    }
}

/// Calls macro `$sized` with every (states, outputs) pair the host instantiates its filters and
/// moving-horizon estimators for (up to [`MAX_STATES`] × [`MAX_OUTPUTS`]), as `(NX, NY)` literals:
/// each caller matches the model's sizes against them to pick its const-generic instance.
macro_rules! host_sizes {
    ($sized:ident) => {
        $sized!(
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
    };
}
pub(crate) use host_sizes;
const _: () = assert!(MAX_STATES == 6 && MAX_OUTPUTS == 4, "host_sizes! lists these sizes");

/// The targets estimated at every sample of `run` by the EKF with `constants` started at `x0`.
/// `None` when the model is larger than the host's instantiations ([`supported`]).
pub fn estimate_run(code: &ModelCode, constants: &EkfConstants, x0: &[f64], run: &Run) -> Option<Rows> {
    track_run(code, constants, x0, run).map(|track| track.rows)
}

/// [`estimate_run`], with the restarts on the run.
pub fn track_run(code: &ModelCode, constants: &EkfConstants, x0: &[f64], run: &Run) -> Option<Track> {
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
    crate::observers::ekf::host_sizes!(sized)
}

fn run_sized<const NX: usize, const NY: usize>(
    code: &ModelCode,
    constants: &EkfConstants,
    x0: &[f64],
    run: &Run,
) -> Track {
    let plant = Stepped {
        step: Rk4::new(Compiled::new(code), constants.h),
        substeps: constants.substeps,
    };
    let full = |c: &Covariance| -> [[f64; NX]; NX] { std::array::from_fn(|i| std::array::from_fn(|j| c.entry(i, j))) };
    let mut filter: Ekf<f64, Stepped<'_>, NX, NY, MAX_INPUTS> = Ekf::new(
        plant,
        std::array::from_fn(|i| x0[i]),
        full(&constants.p0),
        full(&constants.q),
        std::array::from_fn(|i| constants.r[i]),
    )
    .with_bounds(
        std::array::from_fn(|i| code.bounds[i].lower()),
        std::array::from_fn(|i| code.bounds[i].upper()),
    );
    if let Some(w) = constants.watch.constants(NY) {
        filter = filter.with_watch(w.gain, w.limit);
    }
    let mut track = Tracker::new(code.dimensions.targets);
    let mut scratch = Vec::new();
    for (y, u) in run.measurements.iter().zip(run.inputs.iter()) {
        let mut padded = [0.0; MAX_INPUTS];
        padded[..u.len()].copy_from_slice(u);
        match filter.push(&std::array::from_fn(|i| y[i]), &padded) {
            Ok(x) => track.estimate(code.targets(&x, u, &mut scratch)),
            Err(firmware::rules::Refused::Restarted) => track.restarted(),
            Err(_) => track.refused(),
        }
    }
    track.finish()
}

/// The constants for `θ = (a, b)` (see [`tuning`]), each coordinate clamped to [`LOG_RANGE`].
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
        p0: Covariance::Diagonal(scaled(&theta[n..2 * n])),
        q: Covariance::Diagonal(scaled(&theta[..n])),
        r: design.model.outputs.iter().map(|o| o.noise_variance).collect(),
        substeps: design.chip_substeps,
        h: design.tau / design.chip_substeps as f64,
        watch: Watch {
            window: design.map.horizon,
            threshold: f64::INFINITY,
        },
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
            .map(|t| super::score::errors(&data.runs, &estimates, t, windows).0)
            .collect(),
    )
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
