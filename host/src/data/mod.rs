//! Learning and validation data: simulated runs, their noisy measurements, and the windows
//! `(Z(k), r(k))` the maps are fitted and judged on.
//!
//! A run of `n` samples has states `x(0) … x(n-1)`; its windows end at `k = N-1 … n-1`, so it holds
//! `n - N + 1` of them (paper eq. `defdenE`: `n_E = n_g (N_s - N + 1)`). The regressor is, newest first
//! and all outputs of one instant together, `Z(k) = (y(k), …, y(k-N+1), u(k), …, u(k-N+1))`.
//! Noise is added to the outputs only; targets are noise-free functions of the current state.

pub mod rows;
pub mod runs;
pub mod simulate;
pub mod tuning;
pub mod uncertain;

pub use rows::Rows;
pub use runs::{MismatchRuns, Runs};
pub use tuning::{edge_starts, tuning_set, MAX_CORNER_STARTS, SCENARIO_TUNING_RUNS};
pub use uncertain::{corner_set, corners, mismatch_seed, mismatch_set};

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};

use crate::data::simulate::{input_sequence, BlowUp, Integrator};
use crate::spec::model::Model;
use crate::spec::{Axis, Design, SpecError};

/// One simulated run, one row per sample.
#[derive(Clone, Debug)]
pub struct Run {
    /// `x(k)`.
    pub states: Rows,
    /// `u(k)` (rows of width 0 when the model has no input).
    pub inputs: Rows,
    /// `y(k)` with noise.
    pub measurements: Rows,
    /// `r(k)` per target, noise-free.
    pub targets: Rows,
    /// The parameter values of the plant it was simulated on, one per parameter of the model in the
    /// order of `Model::parameters`: drawn for the uncertain ones (see [`uncertain`]), nominal for the
    /// others. Empty for a run that was not simulated (recorded data).
    pub parameters: Vec<f64>,
}

/// A set of runs and the horizon that cuts them into windows.
#[derive(Clone, Debug)]
pub struct DataSet {
    /// The runs.
    pub runs: Vec<Run>,
    /// `N`.
    pub horizon: usize,
}

/// One window: run `run`, ending at sample `end`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Window {
    /// Index of the run.
    pub run: usize,
    /// Sample at which the window ends (the "current" instant `k`).
    pub end: usize,
}

impl DataSet {
    /// Every window, run by run, in time order.
    pub fn windows(&self) -> impl Iterator<Item = Window> + '_ {
        self.runs.iter().enumerate().flat_map(move |(run, r)| {
            (self.horizon.saturating_sub(1)..r.states.len()).map(move |end| Window { run, end })
        })
    }

    /// `n_E`, the number of windows.
    pub fn window_count(&self) -> usize {
        self.runs
            .iter()
            .map(|r| (r.states.len() + 1).saturating_sub(self.horizon))
            .sum()
    }

    /// `n_z = N (n_y + n_u)`.
    pub fn regressor_len(&self) -> usize {
        self.runs
            .first()
            .map_or(0, |r| self.horizon * (r.measurements[0].len() + r.inputs[0].len()))
    }

    /// Writes `Z(k)` of `window` into `z` (cleared first).
    pub fn regressor(&self, window: Window, z: &mut Vec<f64>) {
        let run = &self.runs[window.run];
        let lags = (0..self.horizon).map(|lag| window.end - lag);
        z.clear();
        for k in lags.clone() {
            z.extend_from_slice(&run.measurements[k]);
        }
        for k in lags {
            z.extend_from_slice(&run.inputs[k]);
        }
    }

    /// `r(k)` of target `target` at the end of `window`.
    pub fn target(&self, window: Window, target: usize) -> f64 {
        self.runs[window.run].targets[window.end][target]
    }

    /// What `column` holds at the end of `window`.
    pub fn value(&self, window: Window, column: Column) -> f64 {
        match column {
            Column::Target(t) => self.target(window, t),
            Column::State(i) => self.runs[window.run].states[window.end][i],
        }
    }
}

/// What a map is fitted to: a target (its index in the spec) or a state of the model (its index),
/// for a helper map (a state that the map-started kinds start from and no target is).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Column {
    /// The target of this index.
    Target(usize),
    /// The state of this index.
    State(usize),
}

impl From<usize> for Column {
    /// A target's index.
    fn from(target: usize) -> Self {
        Column::Target(target)
    }
}

/// The learning set: one run per point of the grid (the Cartesian product of the axes, the first
/// state varying slowest), each with its own input profile and noise.
///
/// When the model has uncertain parameters, each run's plant draws them first (before its input
/// profile and its noise, from the same generator; see [`uncertain::draw_plant`]); otherwise nothing
/// is drawn for them and the data are those of a model without ranges.
pub fn learning_set(design: &Design) -> Result<DataSet, SpecError> {
    let mut rng = ChaCha8Rng::seed_from_u64(design.learning.seed);
    let grids: Vec<Vec<f64>> = design.learning.axes.iter().map(Axis::grid).collect();
    let mut runs = Vec::new();
    for x0 in cartesian(&grids) {
        let plant = uncertain::draw_plant(&design.model, &mut rng);
        runs.push(simulate_plant(
            design,
            plant.as_ref().unwrap_or(&design.model),
            &x0,
            design.learning.samples,
            &mut rng,
            "learning",
        )?);
    }
    Ok(DataSet {
        runs,
        horizon: design.map.horizon,
    })
}

/// The validation set: `trajectories` runs from states drawn uniformly in the box, with their own
/// inputs and noise (a different seed from the learning set's). Each run draws, in this order from
/// the set's generator: its uncertain parameters (none when the model has none; see
/// [`uncertain::draw_plant`]), its initial state, its inputs, its noise.
pub fn validation_set(design: &Design) -> Result<DataSet, SpecError> {
    random_runs(design, &design.validation, "validation", None)
}

/// Noise draws of the scenario the report judges every observer on ([`scenario_draws`]).
pub const SCENARIO_DRAWS: usize = 50;

/// The scenario again, [`SCENARIO_DRAWS`] times on the nominal plant: its initial state and samples,
/// other inputs and noise (stream 2 of the scenario's seed, never a tuning run's). One run is one
/// noise realisation; these give the scenario's figure pooled and as its tail. `None` without a
/// `[scenario]`.
pub fn scenario_draws(design: &Design) -> Result<Option<DataSet>, SpecError> {
    let Some(scenario) = design.scenario() else {
        return Ok(None);
    };
    let mut rng = ChaCha8Rng::seed_from_u64(scenario.seed);
    rng.set_stream(2);
    let runs = (0..SCENARIO_DRAWS)
        .map(|_| {
            simulate_plant(
                design,
                &design.model,
                &scenario.x0,
                scenario.samples,
                &mut rng,
                "scenario draws",
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Some(DataSet {
        runs,
        horizon: design.map.horizon,
    }))
}

/// `settings.trajectories` runs, each drawing its plant (unless `fixed` gives it, or no parameter is
/// uncertain), then its initial state in the box, then its inputs and noise.
pub(crate) fn random_runs(
    design: &Design,
    settings: &crate::spec::Validation,
    set: &str,
    fixed: Option<&Model>,
) -> Result<DataSet, SpecError> {
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
    let mut runs = Vec::new();
    for _ in 0..settings.trajectories {
        let drawn = match fixed {
            Some(_) => None,
            None => uncertain::draw_plant(&design.model, &mut rng),
        };
        let x0 = random_state(design, &mut rng);
        runs.push(simulate_plant(
            design,
            fixed.or(drawn.as_ref()).unwrap_or(&design.model),
            &x0,
            settings.samples,
            &mut rng,
            set,
        )?);
    }
    Ok(DataSet {
        runs,
        horizon: design.map.horizon,
    })
}

/// An initial state drawn uniformly in the box of the learning grid (fixed axes held).
pub(crate) fn random_state(design: &Design, rng: &mut ChaCha8Rng) -> Vec<f64> {
    design
        .learning
        .axes
        .iter()
        .map(|axis| match *axis {
            Axis::Range { min, max, .. } => rng.random_range(min..=max),
            Axis::Fixed(value) => value,
        })
        .collect()
}

/// Simulates one run of `samples` samples from `x0` on the nominal model: draws its inputs,
/// integrates, evaluates targets and adds output noise, all from `rng` in that order.
pub fn simulate_run(
    design: &Design,
    x0: &[f64],
    samples: usize,
    rng: &mut ChaCha8Rng,
    set: &str,
) -> Result<Run, SpecError> {
    simulate_plant(design, &design.model, x0, samples, rng, set)
}

/// The spec's first scenario's run on `plant` (the nominal model, or another plant of its
/// parameters): its initial state, samples and seed, the noise and inputs drawn as [`simulate_run`]
/// draws them, so that two plants get the same ones. `None` without a `[scenario]`.
pub fn scenario_run(design: &Design, plant: &Model, set: &str) -> Result<Option<Run>, SpecError> {
    design
        .scenario()
        .map(|s| one_scenario(design, s, plant, set))
        .transpose()
}

/// Every scenario's run on the nominal model, in spec order (see [`scenario_run`]).
pub fn scenario_runs(design: &Design) -> Result<Vec<Run>, SpecError> {
    design
        .scenarios
        .iter()
        .map(|s| one_scenario(design, s, &design.model, "scenario"))
        .collect()
}

/// Scenario `s` on `plant`, from its own seed.
fn one_scenario(design: &Design, s: &crate::spec::Scenario, plant: &Model, set: &str) -> Result<Run, SpecError> {
    let mut rng = ChaCha8Rng::seed_from_u64(s.seed);
    simulate_plant(design, plant, &s.x0, s.samples, &mut rng, set)
}

/// [`simulate_run`] on the plant `plant` (the design's model with other parameter values, see
/// `Model::with_parameters`): its states, outputs and targets, the run recording its parameters. A
/// target that reads a parameter uses the plant's value: it is the true quantity of that plant.
pub fn simulate_plant(
    design: &Design,
    plant: &Model,
    x0: &[f64],
    samples: usize,
    rng: &mut ChaCha8Rng,
    set: &str,
) -> Result<Run, SpecError> {
    let at = RunContext { design, plant, x0, set };
    let inputs = input_sequence(&design.learning.inputs, samples, rng);
    let states = Integrator::new(plant, design.tau, design.substeps)
        .run(x0, &inputs)
        .map_err(|e| blow_up_error(&at, e))?;
    let noise: Vec<Normal<f64>> = plant
        .outputs
        .iter()
        .map(|o| Normal::new(0.0, o.noise_variance.sqrt()).expect("variance validated finite and ≥ 0"))
        .collect();
    let mut environment = Vec::new();
    let mut measurements = Rows::new(plant.outputs.len());
    let mut targets = Rows::new(design.targets.len());
    for (k, (x, u)) in states.iter().zip(inputs.iter()).enumerate() {
        let mut y = vec![0.0; plant.outputs.len()];
        plant.outputs(x, u, &mut environment, &mut y);
        let r: Vec<f64> = design.targets.iter().map(|t| t.expr.eval(&environment)).collect();
        if let Some(i) = y.iter().position(|v| !v.is_finite()) {
            return Err(design.error(
                format!("model.outputs[{i}].expr"),
                format!(
                    "output `{}` is {} at sample {k} of {} (x = {x:?})",
                    plant.outputs[i].name,
                    y[i],
                    at.run()
                ),
                "make the output expression finite over the state box, or shrink `learning.grid`",
            ));
        }
        if let Some(i) = r.iter().position(|v| !v.is_finite()) {
            return Err(design.error(
                format!("targets[{i}].expr"),
                format!(
                    "target `{}` is {} at sample {k} of {} (x = {x:?})",
                    design.targets[i].name,
                    r[i],
                    at.run()
                ),
                "make the target expression finite over the state box, or shrink `learning.grid`",
            ));
        }
        for (value, distribution) in y.iter_mut().zip(&noise) {
            *value += distribution.sample(rng);
        }
        measurements.push(&y);
        targets.push(&r);
    }
    Ok(Run {
        states,
        inputs,
        measurements,
        targets,
        parameters: plant.parameter_values(),
    })
}

/// Which run a message is about: its set, its initial state and, when the plant is not the nominal
/// model, the parameters it was simulated with.
struct RunContext<'a> {
    design: &'a Design,
    plant: &'a Model,
    x0: &'a [f64],
    set: &'a str,
}

impl RunContext<'_> {
    /// "a validation run from x0 = [..]" (", on a plant with a = 4.4, b = 1.1" when it is not the
    /// nominal one).
    fn run(&self) -> String {
        let mut text = format!("a {} run from x0 = {:?}", self.set, self.x0);
        let changed: Vec<String> = self
            .plant
            .parameters
            .iter()
            .zip(&self.design.model.parameters)
            .filter(|(p, nominal)| p.1.to_bits() != nominal.1.to_bits())
            .map(|(p, _)| format!("{} = {}", p.0, p.1))
            .collect();
        if !changed.is_empty() {
            text.push_str(&format!(", on a plant with {}", changed.join(", ")));
        }
        text
    }
}

fn blow_up_error(at: &RunContext<'_>, e: BlowUp) -> SpecError {
    let fix = if at.design.model.uncertain.is_empty() {
        "check the derivative expressions, shrink the state box (`learning.grid`), or lower `sampling.tau` / raise `sampling.substeps`"
    } else {
        "check the derivative expressions, shrink the state box (`learning.grid`) or the ranges of the parameters, or lower `sampling.tau` / raise `sampling.substeps`"
    };
    at.design
        .error("model.derivatives", format!("{} blew up: {e}", at.run()), fix)
}

/// The Cartesian product of the grids, the first varying slowest.
fn cartesian(grids: &[Vec<f64>]) -> Vec<Vec<f64>> {
    grids.iter().fold(vec![Vec::new()], |points, grid| {
        points
            .iter()
            .flat_map(|p| grid.iter().map(move |&v| p.iter().copied().chain([v]).collect()))
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// A clock: ẋ = 1, y = x, so Z(k) = (k τ, (k-1) τ, …) exactly when the noise is off.
    const CLOCK: &str = r#"
        name = "clock"
        [model]
        states = ["x"]
        inputs = ["u"]
        derivatives.x = "1"
        outputs = [{ name = "y", expr = "x", noise_variance = 0.0 }]
        [sampling]
        tau = 0.5
        [learning]
        samples = 6
        seed = 3
        grid.x = { min = 0.0, max = 10.0, points = 3 }
        inputs.u = { min = -1.0, max = 1.0, hold = 2 }
        [validation]
        trajectories = 2
        samples = 5
        seed = 4
        [map]
        horizon = 3
        nm = 2
        beta = 1.0
        epsilon = 0.01
        [[targets]]
        name = "x"
        expr = "x"
    "#;

    /// A first-order lag with an input and parameters: `ẋ = (k u - x)/T`, `y = x`.
    const LAG: &str = r#"
        name = "lag"
        [model]
        states = ["x"]
        inputs = ["u"]
        parameters = { k = 2.0, T = 0.7 }
        derivatives.x = "(k*u - x)/T"
        outputs = [{ name = "y", expr = "x", noise_variance = 0.01 }]
        [sampling]
        tau = 0.1
        substeps = 4
        [learning]
        samples = 30
        seed = 5
        grid.x = { min = -1.0, max = 1.0, points = 4 }
        inputs.u = { min = -1.0, max = 1.0, hold = 3 }
        [validation]
        trajectories = 5
        samples = 25
        seed = 6
        [map]
        horizon = 3
        nm = 2
        beta = 1.0
        epsilon = 0.01
        [[targets]]
        name = "x"
        expr = "x"
        [scenario]
        x0 = { x = 0.3 }
        samples = 20
        seed = 8
    "#;

    #[test]
    fn windows_and_regressors_follow_the_convention() {
        let design = crate::spec::parse(Path::new("clock.toml"), CLOCK).unwrap();
        let data = learning_set(&design).unwrap();
        assert_eq!(data.runs.len(), 3);
        assert_eq!(data.window_count(), 3 * (6 - 3 + 1));
        assert_eq!(data.windows().count(), data.window_count());
        assert_eq!(data.regressor_len(), 3 * 2);
        let first = data.windows().next().unwrap();
        assert_eq!(first, Window { run: 0, end: 2 });
        let w = Window { run: 1, end: 4 }; // x0 = 5, so x(k) = 5 + 0.5 k
        let mut z = Vec::new();
        data.regressor(w, &mut z);
        let u = &data.runs[1].inputs;
        let expected = [7.0, 6.5, 6.0, u[4][0], u[3][0], u[2][0]];
        assert!(z.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-12), "{z:?}");
        assert!((data.target(w, 0) - 7.0).abs() < 1e-12);
        // Inputs are held two samples and stay in range.
        assert_eq!(u[2], u[3]);
        assert!(u.iter().all(|v| (-1.0..=1.0).contains(&v[0])));
    }

    #[test]
    fn data_are_deterministic_for_a_seed_and_fresh_for_another() {
        let design = crate::spec::parse(Path::new("clock.toml"), CLOCK).unwrap();
        let a = validation_set(&design).unwrap();
        let b = validation_set(&design).unwrap();
        assert_eq!(a.runs[1].states, b.runs[1].states);
        assert_eq!(a.runs[1].inputs, b.runs[1].inputs);
        let learning = learning_set(&design).unwrap();
        assert_ne!(a.runs[0].inputs, learning.runs[0].inputs);
    }

    /// FNV-1a over the bits of every number of every run, in order: one value that changes when any
    /// state, input, measurement or target of the set changes by one ulp.
    fn fingerprint(data: &DataSet) -> u64 {
        let mut hash = 0xcbf2_9ce4_8422_2325_u64;
        for run in &data.runs {
            for rows in [&run.states, &run.inputs, &run.measurements, &run.targets] {
                for value in rows.iter().flatten() {
                    for byte in value.to_bits().to_le_bytes() {
                        hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
                    }
                }
            }
        }
        hash
    }

    #[test]
    fn scenario_draws_start_where_the_scenario_does_with_noise_of_their_own() {
        let design =
            crate::spec::parse(Path::new("vanderpol.toml"), include_str!("../../specs/vanderpol.toml")).unwrap();
        let draws = scenario_draws(&design).unwrap().expect("Example 1 has a scenario");
        let scenario = design.scenario().unwrap();
        assert_eq!(draws.runs.len(), SCENARIO_DRAWS);
        let tuning = tuning_set(&design).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(scenario.seed);
        let reported = simulate_run(&design, &scenario.x0, scenario.samples, &mut rng, "scenario").unwrap();
        let first = |run: &Run| run.measurements.iter().next().unwrap()[0].to_bits();
        let mut seen: Vec<u64> = tuning
            .runs
            .iter()
            .chain(std::iter::once(&reported))
            .map(first)
            .collect();
        for run in &draws.runs {
            assert_eq!(run.states.iter().next().unwrap(), &scenario.x0[..]);
            assert_eq!(run.measurements.len(), scenario.samples);
            // Noise of its own: no other draw, tuning run or the reported scenario shares it.
            assert!(!seen.contains(&first(run)));
            seen.push(first(run));
        }
    }

    #[test]
    fn the_edge_starts_cover_each_states_ends_and_every_corner() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml");
        let design = crate::spec::parse(&path, &std::fs::read_to_string(&path).unwrap()).unwrap();
        let (x1, x2) = match (design.learning.axes[0], design.learning.axes[1]) {
            (Axis::Range { min: a, max: b, .. }, Axis::Range { min: c, max: d, .. }) => ((a, b), (c, d)),
            other => panic!("{other:?}"),
        };
        let starts = edge_starts(&design, &mut ChaCha8Rng::seed_from_u64(1));
        // 2 n + 2ⁿ = 8 for two states: x1 at each end, x2 at each end, then the four corners.
        assert_eq!(starts.len(), 8);
        let inside = |v: f64, (lo, hi): (f64, f64)| lo <= v && v <= hi;
        assert!(starts[0][0] == x1.0 && starts[1][0] == x1.1);
        assert!(starts[2][1] == x2.0 && starts[3][1] == x2.1);
        assert!(inside(starts[0][1], x2) && inside(starts[2][0], x1));
        let corners: Vec<(f64, f64)> = starts[4..].iter().map(|x| (x[0], x[1])).collect();
        assert_eq!(corners, [(x1.0, x2.0), (x1.1, x2.0), (x1.0, x2.1), (x1.1, x2.1)]);
    }

    /// The data of designs without uncertain parameters, bit for bit: the fingerprints of the learning,
    /// validation and tuning sets (its runs from random starts) and of the scenario run (when there is
    /// one), recorded on commit 8afa2e3, before parameters could have ranges. A change of any number, or of the order in which
    /// the seeded generator is drawn from, changes them.
    #[test]
    fn data_of_designs_without_uncertainty_are_unchanged() {
        let specs: [(&str, &str, &[u64]); 4] = [
            (
                "vanderpol.toml",
                include_str!("../../specs/vanderpol.toml"),
                &[
                    0x1ad9537a3298baae,
                    0x6d07d1944dfba7e4,
                    0x6992cc728e5a9677,
                    0x5f0abdf2051990e3,
                ],
            ),
            (
                "ecoli_x0_0p5.toml",
                include_str!("../../specs/ecoli_x0_0p5.toml"),
                &[
                    0x026701f1120ff900,
                    0xc073017b424c1b4f,
                    0x60667de660fe253f,
                    0xa54e47ab120561eb,
                ],
            ),
            (
                "clock.toml",
                CLOCK,
                &[0xc740017051f01dd6, 0x9785931629337735, 0xb3c6cc57771f8138],
            ),
            (
                "lag.toml",
                LAG,
                &[
                    0x06917c6fe73703f6,
                    0xd5620cc4f76c6d7a,
                    0xba3761529ce2e868,
                    0x039b5b87a69d142a,
                ],
            ),
        ];
        for (name, text, expected) in specs {
            let design = crate::spec::parse(Path::new(name), text).unwrap();
            let mut tuning = tuning_set(&design).unwrap();
            // The runs from the scenario's start and from the box's edges, added since: new runs
            // after the recorded ones.
            let mut from_scenario = tuning.runs.split_off(design.tuning.trajectories);
            let edges = from_scenario.split_off(design.scenarios.len() * SCENARIO_TUNING_RUNS);
            let mut rng = ChaCha8Rng::seed_from_u64(design.tuning.seed);
            rng.set_stream(tuning::EDGE_STREAM);
            let starts = edge_starts(&design, &mut rng);
            assert_eq!(edges.len(), starts.len(), "{name}");
            for (run, x0) in edges.iter().zip(&starts) {
                assert_eq!(run.states.iter().next().unwrap(), &x0[..], "{name}");
            }
            let sets = [learning_set(&design).unwrap(), validation_set(&design).unwrap(), tuning];
            let mut prints: Vec<u64> = sets.iter().map(fingerprint).collect();
            assert_eq!(
                from_scenario.len(),
                if design.scenario().is_some() {
                    SCENARIO_TUNING_RUNS
                } else {
                    0
                },
                "{name}"
            );
            if let Some(s) = design.scenario() {
                let mut rng = ChaCha8Rng::seed_from_u64(s.seed);
                let run = simulate_run(&design, &s.x0, s.samples, &mut rng, "scenario").unwrap();
                // Each starts where the scenario does, with noise of its own (not the scenario's).
                for tuning_run in &from_scenario {
                    assert_eq!(tuning_run.states.iter().next().unwrap(), &s.x0[..], "{name}");
                    assert_eq!(tuning_run.measurements.len(), s.samples, "{name}");
                    assert_ne!(
                        tuning_run.measurements.iter().next(),
                        run.measurements.iter().next(),
                        "{name}"
                    );
                }
                prints.push(fingerprint(&DataSet {
                    runs: vec![run],
                    horizon: 1,
                }));
            }
            assert_eq!(prints, expected, "{name}: learning, validation, tuning, scenario");
        }
    }

    #[test]
    fn cartesian_product_has_every_point_once() {
        let points = cartesian(&[vec![1.0, 2.0], vec![10.0, 20.0, 30.0]]);
        assert_eq!(points.len(), 6);
        assert_eq!(points[0], vec![1.0, 10.0]);
        assert_eq!(points[5], vec![2.0, 30.0]);
    }
}
