//! Upper bounds of every size a spec sets, and an overall budget of the work it asks for, checked
//! before anything runs: a mistyped exponent is a spec error in milliseconds, not an allocation abort
//! or an hour of simulation.
//!
//! The bounds are far above what the method needs (the paper uses N ≤ 10, n_m = 5, a few hundred
//! runs): they only keep a typo from taking the machine down.

use super::{Axis, Design, SpecError};

/// Most past samples in the regressor (`map.horizon`).
pub const MAX_HORIZON: usize = 1_000;
/// Most basis functions per side (`map.nm`): the QP has `2 n_m - 1` unknowns in `μ`.
pub const MAX_NM: usize = 50;
/// Most points of the monotonicity grid (`map.monotonicity_grid`), one constraint each.
pub const MAX_MONOTONICITY_GRID: usize = 100_001;
/// Most points of one learning-grid axis.
pub const MAX_AXIS_POINTS: usize = 10_000;
/// Most RK4 steps per sample (`sampling.substeps`).
pub const MAX_SUBSTEPS: usize = 10_000;
/// Most samples of one run (`learning.samples`, `validation.samples`, `scenario.samples`).
pub const MAX_RUN_SAMPLES: usize = 10_000_000;
/// Most scenarios (`[[scenario]]`): each is simulated, judged for every observer and tuned on.
pub const MAX_SCENARIOS: usize = 8;
/// Most validation runs (`validation.trajectories`).
pub const MAX_TRAJECTORIES: usize = 1_000_000;
/// Most parameters with a range (`{ value, min, max }`): the mismatch set runs the validation runs at
/// every corner of their box, `2^p` times over (256 times for 8).
pub const MAX_UNCERTAIN: usize = 8;
/// Most RK4 steps of one `gen` of the design: learning, validation and scenario runs together
/// (about a minute of simulation on one core for a small model).
pub const MAX_SIMULATION_STEPS: f64 = 1e9;
/// Most values the simulated runs hold in memory (states, outputs and inputs of every sample of
/// every run, 8 bytes each: 400 MB).
pub const MAX_STORED_VALUES: f64 = 5e7;

/// The work `design` asks of `gen`, against [`MAX_SIMULATION_STEPS`] and [`MAX_STORED_VALUES`]
/// (in `f64`, so that no product overflows).
pub(super) fn check_budget(design: &Design) -> Result<(), SpecError> {
    let learning_runs: f64 = design
        .learning
        .axes
        .iter()
        .map(|axis| match axis {
            Axis::Range { points, .. } => *points as f64,
            Axis::Fixed(_) => 1.0,
        })
        .product();
    // The first scenario and its noise draws; every scenario's run and the tuning runs from its start.
    let draws = design
        .scenario()
        .map_or(0.0, |s| (crate::data::SCENARIO_DRAWS * s.samples) as f64);
    let scenario = draws
        + design
            .scenarios
            .iter()
            .map(|s| (1 + crate::data::SCENARIO_TUNING_RUNS) as f64 * s.samples as f64)
            .sum::<f64>();
    let validation = design.validation.trajectories as f64 * design.validation.samples as f64;
    // The mismatch set: the validation runs again at every corner of the parameter box (none when
    // every parameter is known).
    let corners = match design.model.uncertain.len() {
        0 => 0.0,
        p => 2f64.powi(p as i32),
    };
    let learning = learning_runs * design.learning.samples as f64;
    let ranged = design
        .learning
        .axes
        .iter()
        .filter(|a| matches!(a, crate::spec::Axis::Range { .. }))
        .count();
    // The tuning set's runs from the box's edges (`data::edge_starts`) count in the total, not in
    // which section is named: the user sets the random runs' number, not theirs.
    let edges = 2 * ranged + (1usize << ranged.min(8)).min(crate::data::MAX_CORNER_STARTS);
    let tuning = design.tuning.trajectories as f64 * design.tuning.samples as f64;
    let samples =
        learning + validation + tuning + edges as f64 * design.tuning.samples as f64 + scenario + corners * validation;
    // The error names the section that asks for the most: where the fix has the most effect.
    let largest_scenario = design
        .scenarios
        .iter()
        .enumerate()
        .max_by_key(|(_, s)| s.samples)
        .map_or(0, |(i, _)| i);
    // Named as `starts::scenario_section` names it (not imported: `starts` reads the validated filters).
    let largest_scenario = match design.scenarios.len() {
        0 | 1 => "scenario.samples".to_owned(),
        _ => format!("scenario[{largest_scenario}].samples"),
    };
    let shares = [
        (learning, "learning".to_owned()),
        (validation, "validation".to_owned()),
        (tuning, "tuning".to_owned()),
        (scenario, largest_scenario),
        (corners * validation, "model.parameters".to_owned()),
    ];
    let field = shares
        .iter()
        .fold((f64::NEG_INFINITY, "learning".to_owned()), |best, (share, field)| {
            if *share > best.0 {
                (*share, field.clone())
            } else {
                best
            }
        })
        .1;
    let steps = samples * design.substeps as f64;
    let model = &design.model;
    let values = samples * (model.states.len() + model.outputs.len() + model.inputs.len()) as f64;
    let mismatch = if corners > 0.0 {
        format!(", the validation runs again at {corners:.0} corners of the parameter box")
    } else {
        String::new()
    };
    let mut fix = String::from(
        "fewer learning grid points, shorter runs, fewer validation or tuning runs or fewer `sampling.substeps`",
    );
    if corners > 0.0 {
        fix.push_str(", or fewer parameters with a range");
    }
    if scenario > 0.0 {
        fix.push_str(", or shorter scenarios (`scenario.samples`)");
    }
    let scenarios = if scenario > 0.0 {
        format!(", {scenario:.2e} samples of scenario runs (each scenario, its tuning runs and noise draws)")
    } else {
        String::new()
    };
    if steps > MAX_SIMULATION_STEPS {
        return Err(design.error(
            field,
            format!(
                "the runs take {steps:.2e} RK4 steps ({learning_runs:.0} learning runs of {} samples, {} validation runs of {}, {} tuning runs of {} and {edges} from the box's edges{}{}, {} substeps), above the budget of {MAX_SIMULATION_STEPS:.0e}",
                design.learning.samples,
                design.validation.trajectories,
                design.validation.samples,
                design.tuning.trajectories,
                design.tuning.samples,
                scenarios,
                mismatch,
                design.substeps
            ),
            fix.clone(),
        ));
    }
    if values > MAX_STORED_VALUES {
        return Err(design.error(
            field,
            format!(
                "the runs hold {values:.2e} values ({samples:.2e} samples{scenarios}), above the budget of {MAX_STORED_VALUES:.0e} (400 MB)"
            ),
            fix,
        ));
    }
    Ok(())
}
