//! Tests of the drawn plants and of the mismatch set, on a first-order lag whose sampled solution is
//! known in closed form (so that a run's states say which plant they came from without going through
//! the integrator or the model's expressions).

use std::path::Path;

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use super::*;
use crate::data::{learning_set, tuning_set, validation_set, Run};

/// `ẋ = (k u - x)/T`, `y = b x`, with `T` (index 0) and `k` (index 2) uncertain, `b` (index 1) known.
/// The target `kx = k x` reads a parameter: it is the true plant's, like the states.
const LAG: &str = r#"
    name = "lag"
    [model]
    states = ["x"]
    inputs = ["u"]
    derivatives.x = "(k*u - x)/T"
    outputs = [{ name = "y", expr = "b*x", noise_variance = 0.01 }]
    [model.parameters]
    k = { value = 2.0, min = 1.5, max = 2.5 }
    T = { value = 0.7, min = 0.5, max = 0.9 }
    b = 3.0
    [sampling]
    tau = 0.1
    substeps = 10
    [learning]
    samples = 30
    seed = 5
    grid.x = { min = -1.0, max = 1.0, points = 4 }
    inputs.u = { min = -1.0, max = 1.0, hold = 3 }
    [validation]
    trajectories = 6
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
    [[targets]]
    name = "kx"
    expr = "k*x"
"#;

fn design() -> Design {
    crate::spec::parse(Path::new("lag.toml"), LAG).unwrap()
}

/// The run's states are the exact sampled solution of its own plant, `x⁺ = k u + (x - k u) e^{-τ/T}`
/// (RK4 with 10 steps per sample is within 1e-8 of it here), and its targets are `x` and `k x`.
fn follows_its_plant(run: &Run) -> Result<(), String> {
    let [t, b, k] = run.parameters[..] else {
        return Err(format!("parameters {:?}", run.parameters));
    };
    if b != 3.0 {
        return Err(format!("the known b is {b}"));
    }
    for step in 1..run.states.len() {
        let (x, u) = (run.states[step - 1][0], run.inputs[step - 1][0]);
        let exact = k * u + (x - k * u) * (-0.1 / t).exp();
        if (run.states[step][0] - exact).abs() > 1e-8 {
            return Err(format!(
                "x({step}) = {} where T = {t}, k = {k} give {exact}",
                run.states[step][0]
            ));
        }
    }
    for (x, r) in run.states.iter().zip(run.targets.iter()) {
        if r != [x[0], k * x[0]] {
            return Err(format!("targets {r:?} at x = {x:?}, k = {k}"));
        }
    }
    Ok(())
}

#[test]
fn every_run_draws_its_plant_in_the_ranges() {
    let design = design();
    for (name, set) in [
        ("learning", learning_set(&design).unwrap()),
        ("validation", validation_set(&design).unwrap()),
        ("tuning", tuning_set(&design).unwrap()),
    ] {
        let mut seen: Vec<[f64; 2]> = Vec::new();
        for (i, run) in set.runs.iter().enumerate() {
            let (t, k) = (run.parameters[0], run.parameters[2]);
            assert!(
                (0.5..=0.9).contains(&t) && (1.5..=2.5).contains(&k),
                "{name} run {i}: T = {t}, k = {k}"
            );
            assert!(
                seen.iter().all(|p| p[0] != t && p[1] != k),
                "{name} run {i} repeats a draw"
            );
            seen.push([t, k]);
            follows_its_plant(run).unwrap_or_else(|e| panic!("{name} run {i}: {e}"));
        }
        // Not stuck near the nominal values: the draws spread over the ranges.
        let spread = |j: usize| {
            let values = seen.iter().map(|p| p[j]);
            values.clone().fold(f64::MIN, f64::max) - values.fold(f64::MAX, f64::min)
        };
        assert!(spread(0) > 0.1 && spread(1) > 0.25, "{name}: {seen:?}");
    }
}

/// The documented order: a random run draws its parameters (in the order of `Model::uncertain`),
/// then its initial state; a grid run its parameters, then its first input.
#[test]
fn the_parameters_are_drawn_first_in_each_run() {
    let design = design();
    let mut rng = ChaCha8Rng::seed_from_u64(design.validation.seed);
    let t: f64 = rng.random_range(0.5..=0.9);
    let k: f64 = rng.random_range(1.5..=2.5);
    let x0: f64 = rng.random_range(-1.0..=1.0);
    let first = &validation_set(&design).unwrap().runs[0];
    assert_eq!(
        (first.parameters.as_slice(), first.states[0][0]),
        (&[t, 3.0, k][..], x0)
    );

    let mut rng = ChaCha8Rng::seed_from_u64(design.learning.seed);
    let t: f64 = rng.random_range(0.5..=0.9);
    let k: f64 = rng.random_range(1.5..=2.5);
    let u0: f64 = rng.random_range(-1.0..=1.0);
    let first = &learning_set(&design).unwrap().runs[0];
    assert_eq!(
        (first.parameters.as_slice(), first.inputs[0][0]),
        (&[t, 3.0, k][..], u0)
    );
    assert_eq!(first.states[0][0], -1.0, "a grid run starts at its grid point");
}

#[test]
fn the_same_seed_gives_the_same_plants_and_data() {
    let design = design();
    let (a, b) = (validation_set(&design).unwrap(), validation_set(&design).unwrap());
    for (x, y) in a.runs.iter().zip(&b.runs) {
        assert_eq!(
            (&x.parameters, &x.states, &x.measurements),
            (&y.parameters, &y.states, &y.measurements)
        );
    }
    let (a, b) = (
        mismatch_set(&design).unwrap().unwrap(),
        mismatch_set(&design).unwrap().unwrap(),
    );
    assert!(a
        .runs
        .iter()
        .zip(&b.runs)
        .all(|(x, y)| x.states == y.states && x.measurements == y.measurements));
    // Another seed, other plants.
    let mut other = design.clone();
    other.validation.seed += 1;
    let c = validation_set(&other).unwrap();
    assert_ne!(
        c.runs[0].parameters,
        validation_set(&design).unwrap().runs[0].parameters
    );
}

#[test]
fn corners_are_every_combination_of_the_bounds() {
    let design = design();
    let corners = corners(&design.model);
    // Uncertain order is table order: T, then k; T varies slowest.
    assert_eq!(corners, [[0.5, 1.5], [0.5, 2.5], [0.9, 1.5], [0.9, 2.5]]);
    let only_k = LAG.replace("T = { value = 0.7, min = 0.5, max = 0.9 }", "T = 0.7");
    let only_k = crate::spec::parse(Path::new("lag.toml"), &only_k).unwrap();
    assert_eq!(corners_of(&only_k), [[1.5], [2.5]]);
    let certain = crate::spec::parse(
        Path::new("lag.toml"),
        &LAG.replace("T = { value = 0.7, min = 0.5, max = 0.9 }", "T = 0.7")
            .replace("k = { value = 2.0, min = 1.5, max = 2.5 }", "k = 2.0"),
    )
    .unwrap();
    assert!(corners_of(&certain).is_empty());
    assert!(mismatch_set(&certain).unwrap().is_none());
    // Nothing uncertain: every run is on the nominal plant.
    let runs = validation_set(&certain).unwrap().runs;
    assert!(runs.iter().all(|r| r.parameters == [0.7, 3.0, 2.0]));
}

fn corners_of(design: &Design) -> Vec<Vec<f64>> {
    corners(&design.model)
}

#[test]
fn the_mismatch_set_runs_the_validation_settings_at_every_corner() {
    let design = design();
    let set = mismatch_set(&design).unwrap().unwrap();
    let per_corner = design.validation.trajectories;
    assert_eq!(set.runs.len(), 4 * per_corner);
    assert_eq!(set.horizon, design.map.horizon);
    let validation = validation_set(&design).unwrap();
    for (c, corner) in corners(&design.model).iter().enumerate() {
        let runs = &set.runs[c * per_corner..(c + 1) * per_corner];
        for (i, run) in runs.iter().enumerate() {
            assert_eq!(run.parameters, [corner[0], 3.0, corner[1]], "corner {c}, run {i}");
            follows_its_plant(run).unwrap_or_else(|e| panic!("corner {c}, run {i}: {e}"));
            assert_eq!(run.states.len(), design.validation.samples);
            assert!((-1.0..=1.0).contains(&run.states[0][0]));
            // Every corner replays the same initial states, inputs and noise ...
            let same = &set.runs[i];
            assert_eq!((run.states[0][0], &run.inputs), (same.states[0][0], &same.inputs));
            let noise = |r: &Run, k: usize| r.measurements[k][0] - 3.0 * r.states[k][0];
            assert!((0..run.states.len()).all(|k| (noise(run, k) - noise(same, k)).abs() < 1e-12));
            // ... and they are not the validation runs.
            assert_ne!(run.states[0][0], validation.runs[i].states[0][0]);
        }
    }
    // A corner on its own: the same runs as its block of the mismatch set.
    let all_max = corner_set(&design, &[0.9, 2.5]).unwrap();
    let last = &set.runs[3 * per_corner..];
    assert_eq!(all_max.runs.len(), per_corner);
    assert!(all_max
        .runs
        .iter()
        .zip(last)
        .all(|(a, b)| a.states == b.states && a.measurements == b.measurements && a.parameters == b.parameters));
}

#[test]
fn the_mismatch_seed_is_none_of_the_others() {
    let mut design = design();
    // Learning 5, validation 6, tuning 1006 (the default): 2006.
    assert_eq!(design.tuning.seed, 1006);
    assert_eq!(mismatch_seed(&design), 2006);
    design.learning.seed = 2006;
    assert_eq!(mismatch_seed(&design), 3006);
}

#[test]
fn the_long_runs_have_their_own_seed_and_the_plant_asked_for() {
    let mut design = design();
    assert_eq!(free_seed(&design, 0), 2006);
    assert_eq!(free_seed(&design, 1), 3006);
    design.learning.seed = 3006;
    assert_eq!(free_seed(&design, 1), 4006);
    let nominal_values = nominal(&design.model);
    assert_eq!(
        nominal_values,
        vec![0.7, 2.0],
        "T then k, in the order of Model::uncertain"
    );
    let on_nominal = long_set(&design, None, 40).unwrap();
    let at_corner = long_set(&design, Some(&[0.9, 2.5]), 40).unwrap();
    assert_eq!(on_nominal.runs.len(), design.validation.trajectories);
    for (a, b) in on_nominal.runs.iter().zip(&at_corner.runs) {
        assert_eq!(a.targets.len(), 40);
        assert_eq!(
            a.parameters,
            vec![0.7, 3.0, 2.0],
            "T, b, k of Model::parameters, nominal"
        );
        assert_eq!(b.parameters, vec![0.9, 3.0, 2.5]);
        // Same initial state and inputs, another plant.
        assert_eq!(a.states[0], b.states[0]);
        assert_eq!(a.inputs[5], b.inputs[5]);
        assert_ne!(a.states[5], b.states[5]);
    }
    // Not the mismatch runs' initial states.
    let mismatch = corner_set(&design, &nominal_values).unwrap();
    assert_ne!(mismatch.runs[0].states[0], on_nominal.runs[0].states[0]);
}

#[test]
#[should_panic(expected = "1 values for the 2 uncertain parameters")]
fn a_corner_has_one_value_per_uncertain_parameter() {
    let _ = corner_set(&design(), &[1.0]);
}

/// A run whose drawn plant blows up says which plant it was.
#[test]
fn a_blow_up_names_the_drawn_parameters() {
    let text = LAG.replace(
        "derivatives.x = \"(k*u - x)/T\"",
        "derivatives.x = \"(k*u - x)/T + x^2*k^8\"",
    );
    let design = crate::spec::parse(Path::new("lag.toml"), &text).unwrap();
    let error = validation_set(&design).unwrap_err();
    assert_eq!(error.field, "model.derivatives");
    assert!(error.problem.contains("on a plant with T = 0."), "{error}");
    assert!(error.fix.contains("ranges of the parameters"), "{error}");
}
