//! The moving-horizon estimate as the chip runs it ([`firmware::mhe::Observer`]): its
//! constants for a design, and the host's run of the same arithmetic in `f32` or `f64` over a run
//! (the report's `mhe` row; `tests/tests/integration/generated_mhe.rs` checks it against the emitted
//! `MheObserver`, bit for bit).

use firmware::{Plant, Rk4};

use super::Setup;
use crate::data::{Rows, Run};
use crate::observers::ekf::{Stepped, MAX_INPUTS};
use crate::observers::lost::Track;
use crate::observers::started::literal;
use crate::plant::kalman::Watch;
use crate::plant::{Compiled, ModelCode};

/// Gauss–Newton steps per sample the chip's estimator ([`firmware::mhe::Observer`]) may take:
/// the fewest whose tuning score is within [`CHIP_WITHIN`] of the converged MHE's with the same prior.
pub const CHIP_ITERATIONS: [usize; 5] = [1, 2, 3, 4, 6];
/// See [`CHIP_ITERATIONS`].
pub const CHIP_WITHIN: f64 = 0.05;
/// The chip estimator's Levenberg damping, relative to each diagonal entry of the normal equations.
pub const CHIP_DAMPING: f64 = 1e-6;

/// The chip estimator's constants ([`firmware::emitted::mhe::Settings`], in `f64`).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ChipConstants {
    /// `1 / σ²` per output.
    pub weights: Vec<f64>,
    /// The prior's weight per state, `p / s²`.
    pub prior: Vec<f64>,
    /// The box's lower bounds.
    pub lower: Vec<f64>,
    /// Its upper bounds.
    pub upper: Vec<f64>,
    /// The first window's start: the learning box's centre.
    pub start: Vec<f64>,
    /// Gauss–Newton steps per sample.
    pub iterations: usize,
    /// Levenberg's damping.
    pub damping: f64,
    /// The model's RK4 step, `tau / substeps`.
    pub h: f64,
    /// RK4 steps per sample (`chip_substeps`).
    pub substeps: usize,
    /// The χ² watch over the windows' output costs (`firmware::watch`; `window`: its `W`, in samples;
    /// not watched where the threshold is `+∞`).
    #[serde(default)]
    pub watch: Watch,
}

/// The chip estimator as `gen` tuned it (the `mhe` kind, [`crate::observers::kind`]).
#[derive(Clone, Debug)]
pub struct ChipTuned {
    /// The prior's weight `p`, tuned with the converged estimate, and that estimate's tuning score.
    pub prior: (f64, f64),
    /// The constants the chip runs on (`iterations`: the fewest within [`CHIP_WITHIN`]).
    pub constants: ChipConstants,
    /// The tuning score at each step count tried.
    pub scores: Vec<(usize, f64)>,
}

impl Setup<'_> {
    /// The chip estimator's constants with prior weight `p` and `iterations` steps.
    pub fn chip_constants(&self, p: f64, iterations: usize) -> ChipConstants {
        ChipConstants {
            weights: self.weights.clone(),
            prior: self.spreads.iter().map(|s| p / (s * s)).collect(),
            lower: self.lower.clone(),
            upper: self.upper.clone(),
            start: self.starts[0].clone(),
            iterations,
            damping: CHIP_DAMPING,
            h: self.h,
            substeps: self.substeps,
            watch: Watch::OFF,
        }
    }

    /// The chip estimator's estimates of every target at every sample of `run`, in `T` exactly as
    /// the firmware computes them ([`chip_run`]).
    pub fn chip_run<T: firmware::Scalar + firmware::emitted::Maths>(
        &self,
        constants: &ChipConstants,
        run: &Run,
    ) -> Track {
        chip_run::<T>(self.code, self.horizon, constants, run)
    }
}

/// The estimates of every target at every sample of `run` of the chip's moving-horizon observer of a
/// model `code` (windows of `horizon` samples) with `constants`, in `T` exactly as
/// [`firmware::mhe::Observer`] computes them ([`chip_stepper`]): NaN where it gives none or refuses the
/// sample. With the restarts on the run.
pub fn chip_run<T: firmware::Scalar + firmware::emitted::Maths>(
    code: &ModelCode,
    horizon: usize,
    constants: &ChipConstants,
    run: &Run,
) -> Track {
    let mut stepper = chip_stepper::<T>(code, horizon, constants);
    let mut rows = Rows::new(code.dimensions.targets);
    let nan = vec![f64::NAN; code.dimensions.targets];
    for (y, u) in run.measurements.iter().zip(run.inputs.iter()) {
        rows.push(stepper.step(y, u).as_deref().unwrap_or(&nan));
    }
    Track {
        rows,
        restarts: stepper.restarts(),
    }
}

/// The chip's moving-horizon observer on the host, one sample at a time ([`chip_stepper`]).
pub trait ChipStep {
    /// Takes the sample `(y, u)`: the targets at it, or `None` where the chip gives no estimate yet
    /// or refuses the sample; on a restart, the latest estimate (the chip's `estimate` keeps it).
    fn step(&mut self, y: &[f64], u: &[f64]) -> Option<Vec<f64>>;

    /// Restarts so far (samples whose solution was not finite), as the chip counts them.
    fn restarts(&self) -> u32;
}

/// A fresh [`ChipStep`] in `T` of the model `code` with `constants` over windows of `horizon` samples.
pub fn chip_stepper<'a, T: firmware::Scalar + firmware::emitted::Maths + 'a>(
    code: &'a ModelCode,
    horizon: usize,
    constants: &ChipConstants,
) -> Box<dyn ChipStep + 'a> {
    macro_rules! sized {
        ($(($nx:literal, $ny:literal)),*) => {
            match (code.dimensions.states, code.dimensions.outputs) {
                $(($nx, $ny) => Box::new(Stepper::<T, $nx, $ny>::new(code, horizon, constants)),)*
                _ => unreachable!("sizes checked by Setup::new and the saved tables"),
            }
        };
    }
    crate::observers::ekf::host_sizes!(sized)
}

/// [`firmware::mhe::Observer`]'s state, with the constants as values.
struct Stepper<'a, T, const NX: usize, const NY: usize> {
    code: &'a ModelCode,
    horizon: usize,
    plant: Stepped<'a, T>,
    settings: firmware::emitted::mhe::Settings<T, NX, NY>,
    /// The samples stored, the newest last (the window: the last `horizon`).
    stored: std::collections::VecDeque<firmware::Sample<T, NY, MAX_INPUTS>>,
    solved: Option<[T; NX]>,
    /// The watched mean of the windows' costs, once a window was solved since the last (re)start.
    chi: Option<T>,
    /// The latest estimate (what the chip's `estimate` returns after a restart).
    latest: Option<Vec<f64>>,
    restarts: u32,
    scratch: Vec<T>,
}

impl<'a, T: firmware::Scalar + firmware::emitted::Maths, const NX: usize, const NY: usize> Stepper<'a, T, NX, NY> {
    fn new(code: &'a ModelCode, horizon: usize, constants: &ChipConstants) -> Self {
        let array = |v: &[f64]| -> [T; NX] { std::array::from_fn(|i| literal(v[i])) };
        Stepper {
            code,
            horizon,
            plant: Stepped {
                step: Rk4::new(Compiled::<T>::new(code), literal(constants.h)),
                substeps: constants.substeps,
            },
            settings: firmware::emitted::mhe::Settings {
                weights: std::array::from_fn(|i| literal(constants.weights[i])),
                prior: array(&constants.prior),
                lower: array(&constants.lower),
                upper: array(&constants.upper),
                start: array(&constants.start),
                iterations: constants.iterations,
                damping: literal(constants.damping),
                // The window cost's mean is `N m`.
                watch: (constants.watch.constants(horizon * NY)).map(|w| firmware::emitted::mhe::Watch {
                    start: literal(w.start),
                    gain: literal(w.gain),
                    limit: literal(w.limit),
                }),
            },
            stored: std::collections::VecDeque::with_capacity(horizon + 1),
            solved: None,
            chi: None,
            latest: None,
            restarts: 0,
            scratch: Vec::new(),
        }
    }
}

impl<T: firmware::Scalar + firmware::emitted::Maths, const NX: usize, const NY: usize> ChipStep
    for Stepper<'_, T, NX, NY>
{
    /// `firmware::mhe::Observer::push`: a sample with a non-finite value is not stored; the window is
    /// the last `horizon` stored; the previous solution moves on under the dropped sample's input.
    fn step(&mut self, y: &[f64], u: &[f64]) -> Option<Vec<f64>> {
        use firmware::emitted::mhe::solve_window;
        let sample = firmware::Sample {
            y: std::array::from_fn(|i| literal(y[i])),
            u: std::array::from_fn(|i| if i < u.len() { literal(u[i]) } else { T::ZERO }),
        };
        if !sample.y.iter().chain(&sample.u).all(|v| v.is_finite()) {
            return None;
        }
        let (n, s) = (self.horizon, &self.settings);
        let moved = self.solved.filter(|_| self.stored.len() == n).map(|x| {
            let next = Plant::<T, NX, NY, MAX_INPUTS>::step(&self.plant, &x, &self.stored[0].u).0;
            firmware::emitted::project(&next, &s.lower, &s.upper)
        });
        self.stored.push_back(sample);
        if self.stored.len() > n {
            self.stored.pop_front();
        }
        if self.stored.len() < n {
            return None;
        }
        let window = self.stored.make_contiguous();
        let solved = solve_window(&self.plant, s, window, &moved.unwrap_or(s.start), moved.is_some());
        let (x, end) = (solved.start, solved.end);
        let values: Vec<f64> = self
            .code
            .targets(&end, &sample.u, &mut self.scratch)
            .iter()
            .map(|v| v.to_subset().expect("a real"))
            .collect();
        let (chi, watch_passes) = firmware::emitted::mhe::Watch::after(s.watch, self.chi, solved.cost);
        // A solution or targets the model overflows in, or windows the watch finds implausible:
        // restarted, the next window solved from the start; the latest estimate stays.
        if !(x.iter().chain(&end).all(|v| v.is_finite()) && values.iter().all(|v| v.is_finite()) && watch_passes) {
            self.solved = None;
            self.chi = None;
            self.restarts = self.restarts.saturating_add(1);
            return self.latest.clone();
        }
        self.solved = Some(x);
        self.chi = chi;
        self.latest = Some(values.clone());
        Some(values)
    }

    fn restarts(&self) -> u32 {
        self.restarts
    }
}
