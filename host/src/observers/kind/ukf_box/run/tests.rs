//! The host's UKF takes samples as the chip's EKF does; tuned by the EKF's search, it is measured
//! against the tuned EKF on Example 1's validation runs, and on E. coli it stays finite and inside
//! the physical bounds.

use std::path::Path;

use super::*;
use crate::data::Runs;
use crate::observers::ekf::box_centre;
use crate::observers::score::errors;

fn load(name: &str) -> (Design, ModelCode) {
    let design = crate::spec::load(&Path::new("specs").join(name)).unwrap();
    let code = ModelCode::new(&design).unwrap();
    (design, code)
}

/// Each target's range over the tuning runs (the score's normalisation, here without the fit's).
fn spreads(runs: &Runs, targets: usize) -> Vec<f64> {
    (0..targets)
        .map(|t| {
            let all = runs
                .tuning
                .runs
                .iter()
                .flat_map(|r| r.targets.iter().map(move |v| v[t]));
            let (low, high) = all.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v), h.max(v)));
            high - low
        })
        .collect()
}

/// RMSE per target over the validation windows.
fn rmse(runs: &Runs, estimates: &[Rows], targets: usize) -> Vec<f64> {
    let windows = |run: &Run| runs.validation.horizon.saturating_sub(1)..run.targets.len();
    (0..targets)
        .map(|t| errors(&runs.validation.runs, estimates, t, windows).0)
        .collect()
}

#[test]
fn it_refuses_and_skips_the_samples_the_ekf_does() {
    let (design, code) = load("vanderpol.toml");
    let mut run = crate::data::validation_set(&design).unwrap().runs.swap_remove(0);
    // 5 and 9 refused (predicted, no estimate). At 20 the output is 1e300: in the UKF's f32 (the
    // chip's) it is infinite, refused; in the f64 EKF the update overflows, the filter restarts and
    // its row keeps the latest estimate (the chip's `estimate()` does).
    for (k, row) in run.measurements.iter_mut().enumerate() {
        row[0] = match k {
            5 => f64::NAN,
            9 => f64::INFINITY,
            20 => 1e300,
            _ => row[0],
        };
    }
    let centre = box_centre(&design);
    let constants = ekf::constants(&design, &centre, &[1.0, 1.0], &[-3.0, -3.0, -1.0, -1.0]);
    let filter = unscented_code(&code, &constants);
    let ukf = estimate_run(&code, &filter, &centre, &constants, &run);
    let ekf = ekf::estimate_run(&code, &constants, &centre, &run).unwrap();
    let missing = |rows: &Rows| -> Vec<usize> {
        rows.iter()
            .enumerate()
            .filter(|(_, r)| r[0].is_nan())
            .map(|(k, _)| k)
            .collect()
    };
    assert_eq!(missing(&ukf), vec![5, 9, 20]);
    assert_eq!(missing(&ekf), vec![5, 9]);
    let track = ekf::track_run(&code, &constants, &centre, &run).unwrap();
    assert_eq!(track.restarts, 1);
    assert_eq!(
        ekf.iter().nth(20),
        ekf.iter().nth(19),
        "the restart keeps the latest estimate"
    );
    // After the refused samples the filter goes on: the last estimate is near the EKF's.
    let (a, b) = (ukf.iter().last().unwrap(), ekf.iter().last().unwrap());
    let truth = run.targets.last().unwrap();
    for t in 0..2 {
        let (a, b, truth) = (a[t], b[t], truth[t]);
        assert!(
            (a - truth).abs() < 0.5 && (b - truth).abs() < 0.5,
            "target {t}: UKF {a}, EKF {b}, true {truth}"
        );
    }
}

#[test]
fn tuned_alike_it_is_within_ten_percent_of_the_ekf_on_example_1() {
    let (design, code) = load("vanderpol.toml");
    let runs = Runs::simulate(&design, 0).unwrap();
    let spreads = spreads(&runs, 2);
    let ukf = tune(&design, &code, &runs.tuning, &runs.learning, &spreads).unwrap();
    let ekf = ekf::tune(&design, &code, &runs.tuning, &runs.learning, &spreads).unwrap();
    let centre = box_centre(&design);
    let ukf_rmse = rmse(
        &runs,
        &estimates(&code, &ukf.constants, &ukf.constants.x0, &runs.validation).unwrap(),
        2,
    );
    let ekf_rmse = rmse(
        &runs,
        &ekf::estimates(&code, &ekf.constants, &centre, &runs.validation).unwrap(),
        2,
    );
    println!("validation RMSE: UKF {ukf_rmse:?}, EKF {ekf_rmse:?}");
    for t in 0..2 {
        assert!(
            ukf_rmse[t] <= 1.1 * ekf_rmse[t],
            "target {t}: UKF {ukf_rmse:?}, EKF {ekf_rmse:?}"
        );
    }
}

#[test]
fn on_e_coli_it_stays_finite_and_inside_the_bounds() {
    let (design, code) = load("ecoli_x0_2.toml");
    let runs = Runs::simulate(&design, 0).unwrap();
    let targets = design.targets.len();
    let ukf = tune(&design, &code, &runs.tuning, &runs.learning, &spreads(&runs, targets)).unwrap();
    // It starts at the box centre (2, 2.5, 0.15), in its log coordinates: ln(x − 0 + 1 % of x).
    let centre = [2.02f64.ln(), 2.525f64.ln(), 0.1515f64.ln()];
    for (x0, z) in ukf.constants.x0.iter().zip(centre) {
        assert!((x0 - z).abs() < 1e-12, "{:?} against {centre:?}", ukf.constants.x0);
    }
    let estimates = estimates(&code, &ukf.constants, &centre, &runs.validation).unwrap();
    let mut lowest = vec![f64::INFINITY; targets];
    for rows in &estimates {
        for (k, row) in rows.iter().enumerate() {
            for (t, v) in row.iter().enumerate() {
                assert!(v.is_finite(), "sample {k}: {row:?}");
                lowest[t] = lowest[t].min(*v);
            }
        }
    }
    // Every target of E. coli is a concentration, bounded below by 0 (`[model.bounds]`).
    assert!(lowest.iter().all(|&v| v >= 0.0), "{lowest:?}");
    println!("E. coli validation RMSE: UKF {:?}", rmse(&runs, &estimates, targets));
}

#[test]
fn with_bounds_the_update_uses_the_projected_points_spread() {
    // On validation runs 2, 23 and 65 of E. coli the substrate runs out. In the plant's coordinates
    // the update's points were projected onto S = 0, and updating the analytic P with the projected
    // points' cross-covariance made P indefinite: the product's estimate was off by 30, 153 and
    // 369 g/L (it never exceeds 0.6 g/L). In log coordinates no point reaches the bound, and with
    // the constants below (the plant's, mapped at the box centre) the error stays below 0.6 g/L.
    let (design, code) = load("ecoli_x0_2.toml");
    let runs = Runs::simulate(&design, 0).unwrap();
    let coordinates = &code.log_coordinates;
    let centre = box_centre(&design);
    let map = |v: Vec<f64>| coordinates.covariance(&crate::plant::Covariance::Diagonal(v), &centre);
    let constants = EkfConstants {
        x0: coordinates.to_filter(&centre),
        p0: map(vec![0.1, 1.0, 0.01]),
        q: map(vec![1e-3, 1e-2, 1e-4]),
        r: vec![0.1, 20.0],
        substeps: 1,
        h: 0.2,
        watch: crate::plant::kalman::Watch::OFF,
    };
    let filter = unscented_code(&code, &constants);
    let mut scratch = Vec::new();
    for index in [2, 23, 65] {
        let run = &runs.validation.runs[index];
        let (mut x, mut p) = (constants.x0.clone(), constants.p0.upper());
        let mut worst = 0.0_f64;
        for (k, (y, u)) in run.measurements.iter().zip(run.inputs.iter()).enumerate() {
            let (estimate, next, covariance) = filter.run(&x, &p, Some(y), u, &mut scratch);
            let estimate = coordinates.to_plant(&estimate.expect("finite"));
            worst = worst.max((estimate[2] - run.states[k][2]).abs());
            (x, p) = (next, covariance);
        }
        assert!(worst < 0.6, "run {index}: the product's estimate is off by {worst} g/L");
    }
}
