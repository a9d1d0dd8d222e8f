//! The moving-horizon estimate as the chip runs it ([`firmware::mhe::MovingHorizon`]): its
//! constants for a design, and the host's run of the same arithmetic in `f32` or `f64` over a run
//! (the report's `mhe_chip` row; `tests/tests/generated_mhe.rs` checks it against the emitted
//! `mhe()`, bit for bit).

use firmware::{Plant, Rk4};

use super::Setup;
use crate::data::{Rows, Run};
use crate::observers::ekf::{Stepped, MAX_INPUTS};
use crate::plant::Compiled;

/// Gauss–Newton steps per sample the chip's estimator ([`firmware::mhe::MovingHorizon`]) may take:
/// the fewest whose tuning score is within [`CHIP_WITHIN`] of the converged MHE's with the same prior.
pub const CHIP_ITERATIONS: [usize; 5] = [1, 2, 3, 4, 6];
/// See [`CHIP_ITERATIONS`].
pub const CHIP_WITHIN: f64 = 0.05;
/// The chip estimator's Levenberg damping, relative to each diagonal entry of the normal equations.
pub const CHIP_DAMPING: f64 = 1e-6;

/// The chip estimator's constants ([`firmware::mhe::Settings`], in `f64`).
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
        }
    }

    /// The chip estimator's estimates of every target at every sample of `run`, in `T` exactly as
    /// the firmware computes them ([`firmware::mhe::solve_window`] over the model's programs).
    pub fn chip_run<T: firmware::Scalar + firmware::Maths>(&self, constants: &ChipConstants, run: &Run) -> Rows {
        macro_rules! sized {
            ($(($nx:literal, $ny:literal)),*) => {
                match (self.code.dimensions.states, self.code.dimensions.outputs) {
                    $(($nx, $ny) => self.chip_sized::<T, $nx, $ny>(constants, run),)*
                    _ => unreachable!("sizes checked by Setup::new"),
                }
            };
        }
        crate::observers::ekf::host_sizes!(sized)
    }

    fn chip_sized<T: firmware::Scalar + firmware::Maths, const NX: usize, const NY: usize>(
        &self,
        constants: &ChipConstants,
        run: &Run,
    ) -> Rows {
        use firmware::mhe::{solve_window, Settings};
        use firmware::Sample;
        let literal = |v: f64| T::literal(v as f32, v);
        let plant = Stepped {
            step: Rk4::new(Compiled::<T>::new(self.code), literal(self.h)),
            substeps: self.substeps,
        };
        let array = |v: &[f64]| -> [T; NX] { std::array::from_fn(|i| literal(v[i])) };
        let settings: Settings<T, NX, NY> = Settings {
            weights: std::array::from_fn(|i| literal(constants.weights[i])),
            prior: array(&constants.prior),
            lower: array(&constants.lower),
            upper: array(&constants.upper),
            start: array(&constants.start),
            iterations: constants.iterations,
            damping: literal(constants.damping),
        };
        let n = self.horizon;
        let targets = self.code.dimensions.targets;
        let mut rows = Rows::new(targets);
        let nan = vec![f64::NAN; targets];
        // `MovingHorizon::push`, sample by sample: a sample with a non-finite input is not stored; the
        // window is the last `n` stored; the previous solution moves on under the dropped sample's input.
        let mut stored: Vec<Sample<T, NY, MAX_INPUTS>> = Vec::new();
        let mut solved: Option<[T; NX]> = None;
        let mut scratch = Vec::new();
        for (y, u) in run.measurements.iter().zip(run.inputs.iter()) {
            let sample = Sample {
                y: std::array::from_fn(|i| literal(y[i])),
                u: std::array::from_fn(|i| if i < u.len() { literal(u[i]) } else { T::ZERO }),
            };
            if !sample.u.iter().all(|v| v.is_finite()) {
                rows.push(&nan);
                continue;
            }
            let moved = solved.filter(|_| stored.len() >= n).map(|x| {
                let next = Plant::<T, NX, NY, MAX_INPUTS>::step(&plant, &x, &stored[stored.len() - n].u).0;
                firmware::bounds::project(&next, &settings.lower, &settings.upper)
            });
            stored.push(sample);
            if stored.len() < n {
                rows.push(&nan);
                continue;
            }
            let window = &stored[stored.len() - n..];
            let (x, end) = solve_window(
                &plant,
                &settings,
                window,
                &moved.unwrap_or(settings.start),
                moved.is_some(),
            );
            if !x.iter().chain(&end).all(|v| v.is_finite()) {
                rows.push(&nan);
                continue;
            }
            solved = Some(x);
            if !sample.y.iter().all(|v| v.is_finite()) {
                rows.push(&nan); // refused: solved, but reported refused
                continue;
            }
            let values: Vec<f64> = self
                .code
                .targets(&end, &sample.u, &mut scratch)
                .iter()
                .map(|v| v.to_subset().expect("a real"))
                .collect();
            rows.push(&values);
        }
        rows
    }
}
