//! The written-out UKF against a second implementation written here from the formulas (nalgebra's
//! Cholesky, the library's RK4 step and output of the same model, the centre drawn with its weight
//! 0), on Example 1; against the Kalman
//! filter (the EKF's programs) on a linear model, where the two must agree to rounding; and its
//! pivot floor on an indefinite `P`.

use std::path::Path;

use firmware::{Plant, Rk4};
use nalgebra::{SMatrix, SVector};

use super::*;
use crate::observers::ekf::Stepped;
use crate::plant::kalman::filter_code;
use crate::plant::{Compiled, Covariance};

type Matrix2 = SMatrix<f64, 2, 2>;
type Vector2 = SVector<f64, 2>;

/// `Q` full, as a spec may fix it (the tuned one is diagonal, a special case).
fn constants(substeps: usize) -> EkfConstants {
    EkfConstants {
        x0: vec![0.0; 2],
        p0: Covariance::Diagonal(vec![1.0; 2]),
        q: Covariance::Full(vec![vec![1e-3, 4e-4], vec![4e-4, 2e-3]]),
        r: vec![0.2],
        substeps,
        h: 0.1 / substeps as f64,
        watch: crate::plant::kalman::Watch::OFF,
    }
}

fn triangle(p: &Matrix2) -> Vec<f64> {
    vec![p[(0, 0)], p[(0, 1)], p[(1, 1)]]
}

/// Example 1's weights from the formulas: n = 2, α = 1, β = 0, κ = 0, λ = α²(n + κ) − n = 0.
const SPREAD: f64 = std::f64::consts::SQRT_2; // √(n + λ) = √2
const MEAN0: f64 = 0.0; // λ / (n + λ)
const COVARIANCE0: f64 = 0.0; // + 1 − α² + β
const REST: f64 = 0.25; // 1 / (2 (n + λ))

/// One UKF sample of a model with two states, one output and no input, from the formulas; `plant`
/// steps a whole sample (every substep).
fn reference(
    plant: &impl Plant<f64, 2, 1, 0>,
    constants: &EkfConstants,
    x: Vector2,
    p: Matrix2,
    y: Option<f64>,
) -> (Option<Vector2>, Vector2, Matrix2) {
    let sigma = |x: Vector2, p: Matrix2| -> [Vector2; 5] {
        let l = p.cholesky().expect("positive definite").l();
        [
            x,
            x + SPREAD * l.column(0),
            x + SPREAD * l.column(1),
            x - SPREAD * l.column(0),
            x - SPREAD * l.column(1),
        ]
    };
    let w = |i: usize, zero: f64| if i == 0 { zero } else { REST };
    let (mut x, mut p) = (x, p);
    let estimate = y.map(|y| {
        let points = sigma(x, p);
        let outputs: Vec<f64> = points.iter().map(|s| plant.output(&[s[0], s[1]], &[]).0[0]).collect();
        let predicted: f64 = outputs.iter().enumerate().map(|(i, o)| w(i, MEAN0) * o).sum();
        let s: f64 = outputs
            .iter()
            .enumerate()
            .map(|(i, o)| w(i, COVARIANCE0) * (o - predicted).powi(2))
            .sum::<f64>()
            + constants.r[0];
        let c: Vector2 = points
            .iter()
            .zip(&outputs)
            .enumerate()
            .map(|(i, (point, o))| w(i, COVARIANCE0) * (point - x) * (o - predicted))
            .sum();
        let k = c / s;
        x += k * (y - predicted);
        p -= k * s * k.transpose();
        x
    });
    let moved: Vec<Vector2> = sigma(x, p)
        .iter()
        .map(|point| Vector2::from(plant.step(&[point[0], point[1]], &[]).0))
        .collect();
    let next: Vector2 = moved.iter().enumerate().map(|(i, m)| w(i, MEAN0) * m).sum();
    let mut covariance: Matrix2 = moved
        .iter()
        .enumerate()
        .map(|(i, m)| w(i, COVARIANCE0) * (m - next) * (m - next).transpose())
        .sum();
    covariance += Matrix2::from_fn(|i, j| constants.q.entry(i, j));
    (estimate, next, covariance)
}

/// Largest |a − b| relative to max(1, |b|).
fn gap(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(a, b)| (a - b).abs() / b.abs().max(1.0))
        .fold(0.0, f64::max)
}

fn example_1() -> ModelCode {
    ModelCode::new(&crate::spec::load(Path::new("specs/vanderpol.toml")).unwrap()).unwrap()
}

#[test]
fn the_weights_are_the_scaled_transforms() {
    let (spread, mean0, covariance0, rest) = weights(2);
    assert!(gap(&[spread, mean0, covariance0, rest], &[SPREAD, MEAN0, COVARIANCE0, REST]) < 1e-15);
    // Five states: the cubature rule's ten points x ± √5 Lᵢ, each weighing 1/10, the centre none.
    let (spread, mean0, covariance0, rest) = weights(5);
    assert!(gap(&[spread, mean0, covariance0, rest], &[5f64.sqrt(), 0.0, 0.0, 0.1]) < 1e-15);
    assert!(!centred(2) && !centred(5), "the centre is not drawn");
    for n in 1..8 {
        let (_, mean0, _, rest) = weights(n);
        assert!(
            (mean0 + 2.0 * n as f64 * rest - 1.0).abs() < 1e-14,
            "n = {n}: the mean's weights sum to 1"
        );
    }
}

#[test]
fn the_written_out_sample_is_the_formulas_on_example_1() {
    let code = example_1();
    for substeps in [1, 3] {
        let constants = constants(substeps);
        let written = unscented_code(&code, &constants);
        let plant = Stepped {
            step: Rk4::new(Compiled::new(&code), constants.h),
            substeps,
        };
        let (mut x, mut p) = (Vector2::new(1.5, -2.0), Matrix2::new(0.8, 0.3, 0.3, 2.5));
        for k in 0..40 {
            // A measurement at most samples, a refused one now and then.
            let y = (k % 7 != 3).then(|| (0.37 * k as f64).sin() * 2.0);
            let (estimate, next, covariance) = written.run(
                x.as_slice(),
                &triangle(&p),
                y.as_ref().map(std::slice::from_ref),
                &[],
                &mut Vec::new(),
            );
            let (expected_estimate, expected_next, expected_covariance) = reference(&plant, &constants, x, p, y);
            let what = format!("{substeps} substeps, sample {k}");
            assert_eq!(estimate.is_some(), expected_estimate.is_some(), "{what}");
            if let (Some(a), Some(b)) = (&estimate, expected_estimate) {
                assert!(gap(a, b.as_slice()) < 1e-11, "{what}: x̂ {a:?} against {b:?}");
            }
            assert!(gap(&next, expected_next.as_slice()) < 1e-11, "{what}: x⁺");
            assert!(gap(&covariance, &triangle(&expected_covariance)) < 1e-11, "{what}: P⁺");
            x = Vector2::from_column_slice(&next);
            p = Matrix2::new(covariance[0], covariance[1], covariance[1], covariance[2]);
        }
    }
}

#[test]
fn on_a_linear_model_it_is_the_kalman_filter() {
    // Example 1 with a linear x2' and a linear output: RK4 is then a linear map A and the sigma points
    // carry P exactly through it (A P Aᵀ + Q), and through the output (H P Hᵀ + R, P Hᵀ): the UKF is
    // the Kalman filter, which the EKF's programs are on a linear model.
    let text = std::fs::read_to_string("specs/vanderpol.toml").unwrap();
    let linear = text.replace("x2 = \"4*x1 + (1 - x1^2)*x2\"", "x2 = \"4*x1 - 0.5*x2\"");
    assert_ne!(linear, text, "the derivative to replace");
    let design = crate::spec::parse(Path::new("linear.toml"), &linear).unwrap();
    let code = ModelCode::new(&design).unwrap();
    let constants = constants(2);
    let (unscented, kalman) = (unscented_code(&code, &constants), filter_code(&code, &constants));
    let (mut x, mut p) = (vec![1.0, -1.0], vec![2.0, 0.5, 1.0]);
    let mut worst = 0.0f64;
    for k in 0..60 {
        let y = [(0.21 * k as f64).cos()];
        let measured = (k % 5 != 2).then_some(&y[..]);
        let (a, next, covariance) = unscented.run(&x, &p, measured, &[], &mut Vec::new());
        let (b, expected_next, expected_covariance) = kalman.run(&x, &p, measured, &[], &mut Vec::new());
        if let (Some(a), Some(b)) = (&a, &b) {
            worst = worst.max(gap(a, b));
        }
        worst = worst
            .max(gap(&next, &expected_next))
            .max(gap(&covariance, &expected_covariance));
        (x, p) = (next, covariance);
    }
    assert!(worst < 1e-12, "the UKF and the Kalman filter differ by {worst:e}");
}

#[test]
fn an_indefinite_covariance_still_gives_finite_sigma_points() {
    // [[1, 2], [2, 1]] has eigenvalues 3 and −1: the second pivot is 1 − 4 = −3, whose square root is
    // NaN without the floor.
    let code = example_1();
    let written = unscented_code(&code, &constants(1));
    let (estimate, next, covariance) = written.run(&[0.5, 0.5], &[1.0, 2.0, 1.0], Some(&[1.0]), &[], &mut Vec::new());
    let all: Vec<f64> = estimate.unwrap().into_iter().chain(next).chain(covariance).collect();
    assert!(all.iter().all(|v| v.is_finite()), "{all:?}");
}

#[test]
fn in_single_precision_it_follows_the_double_precision_run() {
    // α = 1 keeps every weight of order one: over 100 samples of Example 1 the f32 run stays within
    // 1e-3 of the f64 run (the states span about 4 and 10). With α = 10⁻³ (W₀ᵐ ≈ −10⁶, the centre
    // then drawn) the same run strays further: this check fails.
    let code = example_1();
    let written = unscented_code(&code, &constants(1));
    let (mut x64, mut p64) = (vec![1.5, -2.0], vec![0.8, 0.3, 2.5]);
    let (mut x32, mut p32): (Vec<f32>, Vec<f32>) = (vec![1.5, -2.0], vec![0.8, 0.3, 2.5]);
    let mut worst = 0.0f64;
    for k in 0..100 {
        let y = (0.37 * k as f64).sin() * 2.0;
        let (_, next, covariance) = written.run(&x64, &p64, Some(&[y]), &[], &mut Vec::new());
        let (_, next32, covariance32) = written.run(&x32, &p32, Some(&[y as f32]), &[], &mut Vec::new());
        worst = next
            .iter()
            .zip(&next32)
            .map(|(a, b)| (a - f64::from(*b)).abs())
            .fold(worst, f64::max);
        (x64, p64, x32, p32) = (next, covariance, next32, covariance32);
    }
    assert!(worst < 1e-3, "f32 against f64: {worst:e}");
    println!("largest |f32 − f64| of the state over 100 samples: {worst:e}");
}

#[test]
fn a_bank_members_sample_is_the_ukfs_with_the_root_of_det_s() {
    // Example 1's output y = x1 + x2 from P = [[2, 0.5], [0.5, 1]]: on the sigma points (their spread
    // is P's, exactly, for a linear output) S = H P Hᵀ + r = 2 + 1 + 1 + 0.2 = 4.2, one output: √det S
    // = √4.2; the normalised innovation squared is (y − x1 − x2)² / 4.2.
    let code = example_1();
    let constants = constants(1);
    let (ukf, member) = (unscented_code(&code, &constants), member_code(&code, &constants));
    let (x, p, y) = ([0.5, -0.25], [2.0, 0.5, 1.0], [1.5]);
    let (sampled, scalars) = member.run_scored(&x, &p, &y, &[], &mut Vec::new());
    assert_eq!(member.scalars, 2);
    assert!((scalars[1] - 4.2f64.sqrt()).abs() < 1e-12, "{scalars:?}");
    assert!((scalars[0] - 1.25f64.powi(2) / 4.2).abs() < 1e-12, "{scalars:?}");
    // Everything else is the UKF's sample, to the bit.
    let ((estimate, next, covariance), nis) = ukf.run_watched(&x, &p, Some(&y), &[], &mut Vec::new());
    assert_eq!(ukf.scalars, 1);
    assert_eq!((sampled.0, sampled.1, sampled.2), (estimate, next, covariance));
    assert_eq!(nis, Some(scalars[0]));
}
