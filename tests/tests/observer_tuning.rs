//! The observers' constants are chosen on the tuning runs only: poisoning every run they must not read
//! (the validation runs and the scenario) changes the figures measured on them and nothing that was
//! tuned. And the closed-loop tuning of the model-corrected map improves its criterion over its start.

use host::observers::{compare, Comparison};
use host::plant::ModelCode;
use integration_tests::{build, load_relative};

/// Every measurement, state and target of `runs` set to NaN.
fn poison(runs: &mut [host::data::Run]) {
    for run in runs {
        for rows in [&mut run.measurements, &mut run.states, &mut run.targets] {
            for row in rows.iter_mut() {
                row.fill(f64::NAN);
            }
        }
    }
}

/// What tuning chose: the EKF's constants, the corrected map's, the map-started EKF's `P(N−1)`, and
/// the kind `observer()` is, as text that shows every bit.
fn chosen(c: &Comparison) -> String {
    let ekf = c.ekf.as_ref().expect("Example 1 has an EKF");
    let corrected = c.corrected.as_ref().expect("Example 1 has a corrected map");
    format!(
        "{:?} {:?} {:?} {:?} {:?} {:?} {:?} {:?}",
        ekf.constants.q,
        ekf.constants.p0,
        corrected.constants.g,
        corrected.constants.k,
        corrected.constants.schedule,
        (corrected.cost, corrected.start_cost),
        c.started,
        c.chosen.0
    )
}

#[test]
fn tuning_never_reads_the_validation_runs_or_the_scenario() {
    let design = load_relative("host/specs/vanderpol.toml");
    let result = build(&design);
    let code = ModelCode::new(&design).expect("Example 1's model is emittable");
    let clean = compare(&design, &result, &code).expect("Example 1 compares");

    let mut poisoned = (*result).clone();
    poison(&mut poisoned.validation.runs);
    poison(std::slice::from_mut(&mut poisoned.scenario));
    for target in &mut poisoned.targets {
        target.validation.target_spread = f64::NAN;
        target.validation.map.rmse = f64::NAN;
    }
    let dirty = compare(&design, &poisoned, &code).expect("poisoned validation still compares");

    assert_eq!(chosen(&clean), chosen(&dirty));
    // The poison reached what the validation figures read: every kind's validation RMSE is NaN
    // where it was finite, and its tuning RMSE is unchanged.
    for (c, d) in clean.observers.iter().zip(&dirty.observers) {
        for (fc, fd) in c.targets.iter().zip(&d.targets) {
            assert!(
                fc.rmse_validation.is_finite() && fd.rmse_validation.is_nan(),
                "{}",
                c.kind
            );
            assert!(fd.rmse_scenario.is_nan(), "{}", c.kind);
            assert_eq!(fc.rmse_tuning.to_bits(), fd.rmse_tuning.to_bits(), "{}", c.kind);
        }
    }
}

#[test]
fn closed_loop_tuning_improves_on_its_start() {
    let design = load_relative("host/specs/vanderpol.toml");
    let result = build(&design);
    let code = ModelCode::new(&design).expect("Example 1's model is emittable");
    let comparison = compare(&design, &result, &code).expect("Example 1 compares");
    let tuned = comparison.corrected.expect("Example 1 has a corrected map");
    // Measured: 0.0620 at the best start, 0.0527 tuned. A tuning that did not move would leave them
    // equal; 5 % is far below what Nelder–Mead gains here and far above rounding.
    assert!(
        tuned.cost < 0.95 * tuned.start_cost,
        "{} vs {}",
        tuned.cost,
        tuned.start_cost
    );
}
