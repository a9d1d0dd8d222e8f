//! How closely the chip's model follows the plant over one sampling period.
//!
//! Every observer that carries the state with the model (the filters, the map-started and corrected
//! kinds, the MHE, the particle floor) takes one period of `ẋ = f(x, u)` as `sampling.chip_substeps`
//! RK4 steps (`Φ_chip`); the runs it is judged on are simulated with `sampling.substeps` (`Φ_sim`).
//! Where the model is fast against the period (a substrate that runs out within one sample, a stiff
//! pole) one step is far from the plant, and every such observer carries that error as if it were
//! the plant's: a filter's tuned `Q` absorbs it poorly and loses runs. Over every sample `x_k`,
//! `u_k` of the learning runs, per state `i`:
//!
//! ```text
//! e_i = max_k |Φ_chip(x_k, u_k)_i − Φ_sim(x_k, u_k)_i| / s_i,     s_i: state i's range over the runs
//! ```
//!
//! and the design's error is the largest `e_i`. Above [`TOLERANCE`] `gen` warns and names the fewest
//! substeps (1, 2, 4, … up to the simulation's) that bring it under.

use crate::data::simulate::Integrator;
use crate::data::DataSet;
use crate::spec::{Design, MAX_CHIP_SUBSTEPS};

/// The largest one-period error of the chip's model, over a state's range, that passes: 1 %.
pub const TOLERANCE: f64 = 0.01;

/// The chip's one-period model error on a design's learning runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Discretisation {
    /// The chip's RK4 steps per period (`sampling.chip_substeps`).
    pub substeps: usize,
    /// The largest `e_i` (see the module docs).
    pub error: f64,
    /// The state it is largest on.
    pub state: usize,
    /// The fewest steps per period whose error is within [`TOLERANCE`] (1, 2, 4, … and the
    /// simulation's own `sampling.substeps`, up to [`MAX_CHIP_SUBSTEPS`]); `None` when none is.
    pub fewest: Option<usize>,
}

impl Discretisation {
    /// Whether the chip's model passes ([`TOLERANCE`]).
    pub fn passes(&self) -> bool {
        self.error <= TOLERANCE
    }
}

/// The chip's one-period model error of `design` over the samples of `learning` (see the module
/// docs), and the fewest substeps that pass.
pub fn check(design: &Design, learning: &DataSet) -> Discretisation {
    let (largest, state) = error(design, learning, design.chip_substeps);
    let limit = design.substeps.min(MAX_CHIP_SUBSTEPS);
    let fewest = (0..)
        .map(|p| 1usize << p)
        .take_while(|&s| s < limit)
        .chain(std::iter::once(limit))
        .find(|&s| s == design.substeps || error(design, learning, s).0 <= TOLERANCE);
    Discretisation {
        substeps: design.chip_substeps,
        error: largest,
        state,
        fewest,
    }
}

/// The largest `e_i` with `substeps` RK4 steps per period over the learning runs, and its state.
fn error(design: &Design, learning: &DataSet, substeps: usize) -> (f64, usize) {
    let spreads = crate::observers::ekf::state_spreads(learning, design.model.states.len());
    let worst = per_state(design, learning, &spreads, substeps);
    (worst.iter().enumerate()).fold((0.0, 0), |(e, s), (i, &w)| if w > e { (w, i) } else { (e, s) })
}

/// Per state `i`, `max_k |Φ_chip(x_k, u_k)_i − Φ_sim(x_k, u_k)_i| / spreads[i]` over the samples of
/// `data`, the chip taking `substeps` RK4 steps per period (infinite where its step is not finite).
pub fn per_state(design: &Design, data: &DataSet, spreads: &[f64], substeps: usize) -> Vec<f64> {
    let n = design.model.states.len();
    let mut chip = Integrator::new(&design.model, design.tau, substeps);
    let mut plant = Integrator::new(&design.model, design.tau, design.substeps);
    let mut worst = vec![0.0f64; n];
    for run in &data.runs {
        for (x, u) in run.states.iter().zip(run.inputs.iter()) {
            let (mut a, mut b) = (x.to_vec(), x.to_vec());
            chip.advance(&mut a, u);
            plant.advance(&mut b, u);
            for i in 0..n {
                let e = (a[i] - b[i]).abs() / spreads[i];
                // A step that is not finite on the chip is as far as it gets.
                worst[i] = if e.is_nan() { f64::INFINITY } else { worst[i].max(e) };
            }
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::parse;

    /// `ẋ = −λ x` sampled at τ = 1 from x = 1 (one run of 20 samples): one RK4 step gives
    /// `1 − λ + λ²/2 − λ³/6 + λ⁴/24` per period against `e^{−λ}`, a closed form.
    fn decay(lambda: f64, chip_substeps: usize) -> (Design, DataSet) {
        let text = format!(
            r#"
name = "decay"
[model]
states = ["x"]
[model.parameters]
lambda = {lambda}
[model.derivatives]
x = "0 - lambda*x"
[[model.outputs]]
name = "y"
expr = "x"
noise_variance = 0.01
[sampling]
tau = 1.0
substeps = 64
chip_substeps = {chip_substeps}
[learning]
samples = 20
seed = 1
grid.x = {{ value = 1.0 }}
[validation]
trajectories = 2
samples = 20
seed = 2
[map]
horizon = 2
nm = 2
beta = 1.0
epsilon = 0.01
[[targets]]
name = "x"
expr = "x"
"#
        );
        let design = parse(std::path::Path::new("decay.toml"), &text).unwrap();
        let learning = crate::data::learning_set(&design).unwrap();
        (design, learning)
    }

    #[test]
    fn the_error_of_one_step_is_the_closed_form_of_rk4_against_the_exponential() {
        let lambda: f64 = 1.5;
        let (design, learning) = decay(lambda, 1);
        let d = check(&design, &learning);
        // The run's states are e^{−λk}: the range is 1 − e^{−19λ}; the largest error is at x = 1.
        let rk4 = 1.0 - lambda + lambda.powi(2) / 2.0 - lambda.powi(3) / 6.0 + lambda.powi(4) / 24.0;
        let closed = (rk4 - (-lambda).exp()).abs() / (1.0 - (-19.0 * lambda).exp());
        assert!((d.error - closed).abs() < 1e-6 * closed, "{} against {closed}", d.error);
        assert_eq!(d.state, 0);
        assert!(!d.passes(), "{}: one step of λτ = 1.5 is off by more than 1 %", d.error);
    }

    #[test]
    fn the_fewest_substeps_are_the_first_power_of_two_within_the_tolerance() {
        // λτ = 1.5: h = 1.5 / s per step; the one-period error (RK4's, against e^{−1.5}) falls as s⁻⁴.
        let (design, learning) = decay(1.5, 1);
        let error = |s: usize| {
            let (d, l) = decay(1.5, s);
            check(&d, &l).error
        };
        let fewest = check(&design, &learning)
            .fewest
            .expect("the simulation's own steps pass");
        assert!(fewest > 1, "one step of λτ = 1.5 does not pass");
        assert!(error(fewest) <= TOLERANCE, "{fewest} steps: {}", error(fewest));
        assert!(error(fewest / 2) > TOLERANCE, "{} steps pass too", fewest / 2);
        // A slow plant passes with one step, and the design that asks for it is not warned.
        let (slow, learning) = decay(0.05, 1);
        let d = check(&slow, &learning);
        assert!(d.passes() && d.fewest == Some(1), "{d:?}");
        assert_eq!(crate::report::gates::coarse_chip_model(&slow, &learning), None);
    }

    #[test]
    fn the_gate_names_the_state_and_the_fewest_steps() {
        // λτ = 1.5 by one step: RK4's 0.2734 against e^{−1.5} = 0.2231, 5 % of the range; by two,
        // 0.2248: 0.17 %, within 1 %.
        let (design, learning) = decay(1.5, 1);
        let gate = crate::report::gates::coarse_chip_model(&design, &learning).expect("5 % is over 1 %");
        let text = gate.to_string();
        assert!(
            text.contains("5.0 % of `x`'s range") && text.contains("set `sampling.chip_substeps = 2`"),
            "{text}"
        );
        assert!(gate.strict(), "`gen --strict` refuses a design whose chip model is off");
    }
}
