//! The observers' constants are chosen on the tuning runs only: poisoning every run they must not read
//! (the validation runs and the scenario) changes the figures measured on them and nothing that was
//! tuned. The closed-loop tuning of the model-corrected map improves its criterion over its start, and
//! the EKF from the box centre is as good as a grid-tuned expert filter on the validation runs.

use host::observers::references::Cost;
use host::observers::{compare, Comparison};
use host::plant::ModelCode;

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

/// What tuning chose: the EKF's constants, the corrected map's, the map-started EKF's `P(N−1)`, the
/// restarted EKF's check, the kind `observer()` is, and the on-line MHE's prior weight, as text that
/// shows every bit.
fn chosen(c: &Comparison) -> String {
    let ekf = c.tuned.ekf_box().expect("Example 1 has an EKF");
    let corrected = c.tuned.corrected().expect("Example 1 has a corrected map");
    let prior: Vec<String> = c
        .references
        .iter()
        .filter_map(|r| match &r.cost {
            Cost::Solver {
                prior: Some((p, score)),
                ..
            } => Some(format!("{:x} {:x}", p.to_bits(), score.to_bits())),
            _ => None,
        })
        .collect();
    assert_eq!(prior.len(), 1, "the host MHE with a tuned prior");
    // The chip MHE's constants hold every bit as text (`{:?}` of an f64 round-trips).
    let chip = c.tuned.mhe().expect("Example 1 has a chip MHE");
    format!(
        "{:?} {:?} {:?} {:?} {:?} {:?} {:?} {:?} {:?} {prior:?} {:?} {:?}",
        ekf.constants.q,
        ekf.constants.p0,
        corrected.constants.g,
        corrected.constants.k,
        corrected.constants.schedule,
        (corrected.cost, corrected.start_cost),
        c.tuned.ekf_map(),
        c.tuned.ekf_restart(),
        c.chosen.0,
        chip.constants,
        chip.prior
    )
}

#[test]
fn tuning_never_reads_the_validation_runs_or_the_scenario() {
    let emitted = integration_tests::shipped("vanderpol");
    let (design, result, clean) = (&emitted.design, &emitted.result, &emitted.comparison);
    let code = ModelCode::new(design).expect("Example 1's model is emittable");

    let mut poisoned = result.clone();
    // Every set but the learning and tuning runs (Example 1 has scenario draws; its parameters are
    // known, so it has no mismatch runs).
    let runs = &mut poisoned.runs;
    poison(&mut runs.validation.runs);
    poison(std::slice::from_mut(&mut runs.scenario));
    poison(&mut runs.scenario_draws.as_mut().expect("Example 1 has a scenario").runs);
    poison(&mut runs.long.runs);
    for target in &mut poisoned.targets {
        target.validation.target_spread = f64::NAN;
        target.validation.map.rmse = f64::NAN;
    }
    let dirty = compare(design, &poisoned, &code, &indicatif::ProgressBar::hidden())
        .expect("poisoned validation still compares");

    assert_eq!(chosen(clean), chosen(&dirty));
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
            assert!(fd.scenario_draws.is_some_and(|(rmse, _)| rmse.is_nan()), "{}", c.kind);
            assert!(fd.drift.first.is_nan() && fd.drift.last.is_nan(), "{}", c.kind);
            assert_eq!(fc.rmse_tuning.to_bits(), fd.rmse_tuning.to_bits(), "{}", c.kind);
        }
    }
    // The references (the on-line MHE, the floor) are judged on the poisoned sets too.
    assert_eq!(clean.references.len(), 3);
    for (c, d) in clean.references.iter().zip(&dirty.references) {
        for (fc, fd) in c.figures.targets.iter().zip(&d.figures.targets) {
            let kind = c.figures.kind;
            assert!(fc.rmse_validation.is_finite() && fd.rmse_validation.is_nan(), "{kind}");
            assert!(fd.rmse_scenario.is_nan(), "{kind}");
        }
    }
    // Example 1's targets for issue 32, on the clean comparison: the floor's particle count is
    // checked (doubling it moves no RMSE by more than 5 %), and the MHE with its tuned prior lands
    // between the map and the floor on every target (measured: map 0.242 / 0.287, MHE with prior
    // 0.064 / 0.118, floor 0.042 / 0.078 at 500 particles).
    let validation = |kind: &str| -> Vec<f64> {
        let figures = clean
            .observers
            .iter()
            .chain(clean.references.iter().map(|r| &r.figures))
            .find(|o| o.kind == kind)
            .expect("every kind and reference");
        figures.targets.iter().map(|f| f.rmse_validation).collect()
    };
    let floor = clean.references.iter().find(|r| r.figures.kind == "floor").unwrap();
    assert!(
        matches!(floor.cost, Cost::Particles { converged: true, .. }),
        "{:?}",
        floor.cost
    );
    let (map, mhe, floor) = (validation("map"), validation("mhe_host_prior"), validation("floor"));
    for t in 0..2 {
        assert!(map[t] > mhe[t] && mhe[t] > floor[t], "{map:?} {mhe:?} {floor:?}");
    }
}

#[test]
fn closed_loop_tuning_improves_on_its_start_and_the_ekf_matches_an_expert() {
    let emitted = integration_tests::shipped("vanderpol");
    let (design, result, comparison) = (&emitted.design, &emitted.result, &emitted.comparison);
    let code = ModelCode::new(design).expect("Example 1's model is emittable");
    ekf_matches_a_grid_tuned_expert(design, result, &code, comparison);
    the_restarted_ekf_is_its_two_parents_and_beats_the_corrected_map_on_validation(design, result, &code, comparison);
    let tuned = comparison.tuned.corrected().expect("Example 1 has a corrected map");
    // Measured: 0.0620 at the best start, 0.0527 tuned. A tuning that did not move would leave them
    // equal; 5 % is far below what Nelder–Mead gains here and far above rounding.
    assert!(
        tuned.cost < 0.95 * tuned.start_cost,
        "{} vs {}",
        tuned.cost,
        tuned.start_cost
    );
}

/// The EKF from the box centre is tuned as well as a grid-tuned expert filter.
fn ekf_matches_a_grid_tuned_expert(
    design: &host::spec::Design,
    result: &host::fit::DesignResult,
    code: &ModelCode,
    comparison: &Comparison,
) {
    // Issue 28's reference point, found outside the project by a plain grid: Q = 3.2e-5 I and P(0)
    // = the box's variance / 4 per state, in the same filter from the box centre. The tuned filter
    // must be within 5 % of it on the validation runs (which neither saw), target by target. With
    // the earlier family `Q = q diag(s²)` on a decade grid this failed (0.0801 / 0.1254 against
    // 0.0747 / 0.1150 here).
    let tuned = comparison.tuned.ekf_box().expect("Example 1 has an EKF");
    let mut grid = tuned.constants.clone();
    grid.q = host::plant::Covariance::Diagonal(vec![3.2e-5, 3.2e-5]);
    // Uniform over [-2, 2] × [-5, 5]: variances 16/12 and 100/12.
    grid.p0 = host::plant::Covariance::Diagonal(vec![16.0 / 12.0 / 4.0, 100.0 / 12.0 / 4.0]);
    let centre = host::observers::ekf::box_centre(design);
    let reference = host::observers::ekf::rmse(code, &grid, &centre, &result.runs.validation).unwrap();
    let ours = host::observers::ekf::rmse(code, &tuned.constants, &centre, &result.runs.validation).unwrap();
    let row = comparison.observers.iter().find(|o| o.kind == "ekf_box").unwrap();
    for t in 0..2 {
        assert_eq!(
            row.targets[t].rmse_validation.to_bits(),
            ours[t].to_bits(),
            "the report's row is this filter"
        );
        assert!(
            ours[t] <= 1.05 * reference[t],
            "target {t}: tuned {} against the grid point's {}",
            ours[t],
            reference[t]
        );
    }
}

/// The restarted EKF is the box-started EKF when it never restarts and the map (from the map's first
/// estimate on) when it always does, each computed by its own code; with the threshold
/// `auto` tuned it beats the corrected map from random starts, on data no tuning saw.
fn the_restarted_ekf_is_its_two_parents_and_beats_the_corrected_map_on_validation(
    design: &host::spec::Design,
    result: &host::fit::DesignResult,
    code: &ModelCode,
    comparison: &Comparison,
) {
    use host::observers::kind::ekf_restart::run as restart;
    use host::observers::{ekf, map_estimates};
    let tuned = comparison.tuned.ekf_box().expect("Example 1 has an EKF");
    let started = comparison.tuned.ekf_map().expect("Example 1 has a map-started EKF");
    let chosen = comparison.tuned.ekf_restart().expect("Example 1 has a restarted EKF");
    let filter = host::plant::kalman::filter_code(code, &tuned.constants);
    let horizon = design.map.horizon;
    let with = |threshold: f64| restart::RestartConstants {
        threshold,
        variances: chosen.variances.clone(),
    };
    let bits =
        |rows: &[Vec<f64>]| -> Vec<Vec<u64>> { rows.iter().map(|r| r.iter().map(|v| v.to_bits()).collect()).collect() };
    let mut restarted_somewhere = false;
    for run in result.runs.validation.runs.iter().take(8) {
        let map: Vec<Vec<f64>> = map_estimates(result, horizon, run)
            .iter()
            .map(<[f64]>::to_vec)
            .collect();
        let run_with = |threshold: f64| {
            restart::estimate::<f64>(
                &filter,
                &tuned.constants,
                &started.p0,
                &with(threshold),
                &started.state_targets,
                &map,
                run,
                code,
            )
            .rows
        };
        let boxed: Vec<Vec<f64>> = ekf::estimate_run(code, &tuned.constants, &tuned.constants.x0, run)
            .unwrap()
            .iter()
            .map(<[f64]>::to_vec)
            .collect();
        assert_eq!(
            bits(&run_with(f64::INFINITY)),
            bits(&boxed),
            "never restarted: the box EKF"
        );
        // Watched at every sample, a filter that always disagrees is restarted at every sample: the
        // map's estimates, from its first on.
        let always = run_with(-1.0);
        assert_eq!(
            bits(&always[horizon - 1..]),
            bits(&map[horizon - 1..]),
            "always: the map"
        );
        assert_eq!(
            bits(&always[..horizon - 1]),
            bits(&boxed[..horizon - 1]),
            "before the check: the box EKF"
        );
        restarted_somewhere |= bits(&run_with(chosen.threshold)) != bits(&boxed);
    }
    assert!(
        restarted_somewhere,
        "the tuned threshold never restarts on these runs: the test shows little"
    );
    let row = |kind: &str| comparison.observers.iter().find(|o| o.kind == kind).unwrap();
    let (ours, corrected) = (row("ekf_restart"), row("corrected"));
    for t in 0..2 {
        let (a, b) = (&ours.targets[t], &corrected.targets[t]);
        // Measured: validation 0.0672 / 0.1038 against 0.0893 / 0.1369. Over the scenario's 50 draws
        // it no longer wins since the map watches it at every sample (issue 50): 0.107 / 0.118 against
        // 0.066 / 0.111, the map's check restarting it where the filter was right; the threshold is
        // tuned on the tuning runs as a whole.
        assert!(a.rmse_validation < b.rmse_validation, "target {t}: {a:?} against {b:?}");
    }
}
