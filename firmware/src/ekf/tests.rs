//! The filter on linear plants, where the Kalman filter is known independently: the steady-state
//! covariance in closed form (scalar Riccati equation), and a textbook filter written with nalgebra
//! matrices and a matrix inverse instead of sequential scalar Joseph updates.

use nalgebra::{Matrix2, Matrix2x1, Vector2};

use super::*;

/// `x⁺ = 0.9 x`, `y = 2 x`.
#[derive(Clone, Copy, Debug)]
struct Scalar1;

const A1: f64 = 0.9;
const C1: f64 = 2.0;

impl Plant<f64, 1, 1, 0> for Scalar1 {
    fn step(&self, x: &[f64; 1], _: &[f64; 0]) -> ([f64; 1], [[f64; 1]; 1]) {
        ([A1 * x[0]], [[A1]])
    }
    fn output(&self, x: &[f64; 1], _: &[f64; 0]) -> ([f64; 1], [[f64; 1]; 1]) {
        ([C1 * x[0]], [[C1]])
    }
}

/// The steady-state prior variance of the scalar filter: the positive root of
/// `c² P² + (r (1 - a²) - q c²) P - q r = 0`.
fn riccati_scalar(a: f64, c: f64, q: f64, r: f64) -> f64 {
    let b = r * (1.0 - a * a) - q * c * c;
    (-b + (b * b + 4.0 * c * c * q * r).sqrt()) / (2.0 * c * c)
}

#[test]
fn the_covariance_converges_to_the_closed_form_riccati_solution() {
    let (q, r) = (0.1, 0.5);
    let mut filter: Ekf<f64, Scalar1, 1, 1, 0> = Ekf::new(Scalar1, [3.0], [[10.0]], [[q]], [r]);
    for k in 0..300 {
        // The covariance does not depend on the measurements: any finite values.
        filter.push(&[(k as f64).sin()], &[]).unwrap();
    }
    let expected = riccati_scalar(A1, C1, q, r);
    let prior = filter.covariance()[0][0];
    assert!((prior - expected).abs() < 1e-12 * expected, "{prior} vs {expected}");
}

/// `x⁺ = A x`, `y = x₁ + v`: coupled states, one output.
#[derive(Clone, Copy, Debug)]
struct Coupled;

fn a2() -> Matrix2<f64> {
    Matrix2::new(1.0, 0.1, -0.2, 0.95)
}

impl Plant<f64, 2, 1, 1> for Coupled {
    fn step(&self, x: &[f64; 2], u: &[f64; 1]) -> ([f64; 2], [[f64; 2]; 2]) {
        let a = a2();
        let next = a * Vector2::new(x[0], x[1]) + Vector2::new(0.0, 0.1 * u[0]);
        ([next[0], next[1]], [[a[(0, 0)], a[(0, 1)]], [a[(1, 0)], a[(1, 1)]]])
    }
    fn output(&self, x: &[f64; 2], _: &[f64; 1]) -> ([f64; 1], [[f64; 2]; 1]) {
        ([x[0]], [[1.0, 0.0]])
    }
}

#[test]
fn sequential_joseph_updates_match_a_textbook_filter_with_a_matrix_inverse() {
    let (q, r) = (Matrix2::new(0.01, 0.002, 0.002, 0.02), 0.3);
    let mut filter: Ekf<f64, Coupled, 2, 1, 1> = Ekf::new(
        Coupled,
        [0.5, -1.0],
        [[2.0, 0.1], [0.1, 1.0]],
        [[q[(0, 0)], q[(0, 1)]], [q[(1, 0)], q[(1, 1)]]],
        [r],
    );
    // The textbook form: K = P Cᵀ (C P Cᵀ + R)⁻¹, x += K (y - C x), P = (I - K C) P; then predict.
    let (a, c) = (a2(), Matrix2x1::new(1.0, 0.0).transpose());
    let (mut x, mut p) = (Vector2::new(0.5, -1.0), Matrix2::new(2.0, 0.1, 0.1, 1.0));
    for k in 0..200 {
        let (y, u) = ((k as f64 * 0.37).cos(), (k as f64 * 0.11).sin());
        let s = (c * p * c.transpose())[(0, 0)] + r;
        let gain = p * c.transpose() * s.recip();
        x += gain * (y - (c * x)[(0, 0)]);
        p = (Matrix2::identity() - gain * c) * p;
        let estimate = filter.push(&[y], &[u]).unwrap();
        assert!(
            (estimate[0] - x[0]).abs() < 1e-10 && (estimate[1] - x[1]).abs() < 1e-10,
            "k = {k}"
        );
        x = a * x + Vector2::new(0.0, 0.1 * u);
        p = a * p * a.transpose() + q;
        let ours = filter.covariance();
        for (row, col) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            assert!(
                (ours[row][col] - p[(row, col)]).abs() < 1e-10,
                "k = {k} P[{row}][{col}]"
            );
        }
    }
}

#[test]
fn the_covariance_stays_symmetric_and_positive_with_an_almost_exact_sensor() {
    // r = 1e-14 after P = 1e6: an almost exact sensor, where the short update (I - K H) P is prone to
    // lose symmetry and positivity to rounding; the Joseph form with the copied triangle must not.
    let mut filter: Ekf<f64, Coupled, 2, 1, 1> = Ekf::new(
        Coupled,
        [0.0, 0.0],
        [[1e6, 0.0], [0.0, 1e6]],
        [[1e-9, 0.0], [0.0, 1e-9]],
        [1e-14],
    );
    for k in 0..500 {
        filter.push(&[(k as f64).sin()], &[0.0]).unwrap();
        let p = filter.covariance();
        assert_eq!(p[0][1].to_bits(), p[1][0].to_bits(), "k = {k}");
        let (trace, det) = (p[0][0] + p[1][1], p[0][0] * p[1][1] - p[0][1] * p[1][0]);
        assert!(
            p[0][0] >= 0.0 && p[1][1] >= 0.0 && trace >= 0.0 && det >= -1e-12 * trace * trace,
            "k = {k}: {p:?}"
        );
    }
}

#[test]
fn a_non_finite_measurement_is_refused_and_only_the_prediction_runs() {
    let (q, r) = (0.1, 0.5);
    let mut filter: Ekf<f64, Scalar1, 1, 1, 0> = Ekf::new(Scalar1, [3.0], [[2.0]], [[q]], [r]);
    for y in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let (x, p) = (filter.state()[0], filter.covariance()[0][0]);
        assert_eq!(filter.push(&[y], &[]), Err(crate::rules::Refused::Value));
        assert_eq!(filter.state(), [A1 * x]);
        assert_eq!(filter.covariance(), [[A1 * p * A1 + q]]);
    }
    // And a finite sample afterwards is taken as usual.
    assert!(filter.push(&[1.0], &[]).is_ok() && filter.state()[0].is_finite());
}

#[test]
fn a_non_finite_input_changes_nothing() {
    let mut filter: Ekf<f64, Coupled, 2, 1, 1> = Ekf::new(
        Coupled,
        [0.5, -1.0],
        [[2.0, 0.1], [0.1, 1.0]],
        [[0.01, 0.0], [0.0, 0.02]],
        [0.3],
    );
    let before = filter;
    assert_eq!(filter.push(&[0.2], &[f64::NAN]), Err(crate::rules::Refused::Value));
    assert_eq!(
        (filter.state(), filter.covariance()),
        (before.state(), before.covariance())
    );
}

/// `x⁺ = A x`, `y = C x + v` with two outputs: the sequential scalar updates of a diagonal `R`.
#[derive(Clone, Copy, Debug)]
struct TwoOutputs;

fn c2() -> Matrix2<f64> {
    Matrix2::new(1.0, 0.5, 0.0, 1.0)
}

impl Plant<f64, 2, 2, 0> for TwoOutputs {
    fn step(&self, x: &[f64; 2], _: &[f64; 0]) -> ([f64; 2], [[f64; 2]; 2]) {
        let a = a2();
        let next = a * Vector2::new(x[0], x[1]);
        ([next[0], next[1]], [[a[(0, 0)], a[(0, 1)]], [a[(1, 0)], a[(1, 1)]]])
    }
    fn output(&self, x: &[f64; 2], _: &[f64; 0]) -> ([f64; 2], [[f64; 2]; 2]) {
        let c = c2();
        let y = c * Vector2::new(x[0], x[1]);
        ([y[0], y[1]], [[c[(0, 0)], c[(0, 1)]], [c[(1, 0)], c[(1, 1)]]])
    }
}

/// The stabilising solution of the filter's discrete algebraic Riccati equation (the steady prior
/// covariance) `P = A P Aᵀ − A P Cᵀ (C P Cᵀ + R)⁻¹ C P Aᵀ + Q`, by the structured doubling algorithm
/// (Chu, Fan, Lin 2005) on its dual control form: `A₀ = Aᵀ`, `G₀ = Cᵀ R⁻¹ C`, `H₀ = Q`, then
/// `W = I + G H`, `A ← A W⁻¹ A`, `G ← G + A W⁻¹ G Aᵀ`, `H ← H + Aᵀ H W⁻¹ A`; `H → P` quadratically.
/// Nothing of it is the filter's recursion.
fn riccati_doubling(a: Matrix2<f64>, c: Matrix2<f64>, q: Matrix2<f64>, r: Matrix2<f64>) -> Matrix2<f64> {
    let (mut a_k, mut g, mut h) = (a.transpose(), c.transpose() * r.try_inverse().unwrap() * c, q);
    for _ in 0..30 {
        let w = (Matrix2::identity() + g * h).try_inverse().unwrap();
        let (a_next, g_next, h_next) = (
            a_k * w * a_k,
            g + a_k * w * g * a_k.transpose(),
            h + a_k.transpose() * h * w * a_k,
        );
        (a_k, g, h) = (a_next, g_next, h_next);
    }
    h
}

fn riccati_residual(p: Matrix2<f64>, a: Matrix2<f64>, c: Matrix2<f64>, q: Matrix2<f64>, r: Matrix2<f64>) -> f64 {
    let s = c * p * c.transpose() + r;
    let right = a * p * a.transpose() - a * p * c.transpose() * s.try_inverse().unwrap() * c * p * a.transpose() + q;
    (right - p).abs().max()
}

#[test]
fn the_covariance_converges_to_the_two_state_riccati_solution_by_doubling() {
    let (q, r) = (
        Matrix2::new(0.01, 0.002, 0.002, 0.02),
        Matrix2::new(0.3, 0.0, 0.0, 0.05),
    );
    let expected = riccati_doubling(a2(), c2(), q, r);
    // The doubling solution is the equation's: its residual is rounding.
    assert!(riccati_residual(expected, a2(), c2(), q, r) < 1e-14);
    let mut filter: Ekf<f64, TwoOutputs, 2, 2, 0> = Ekf::new(
        TwoOutputs,
        [1.0, -1.0],
        [[5.0, 0.0], [0.0, 5.0]],
        [[q[(0, 0)], q[(0, 1)]], [q[(1, 0)], q[(1, 1)]]],
        [r[(0, 0)], r[(1, 1)]],
    );
    for k in 0..400 {
        filter
            .push(&[(k as f64 * 0.3).sin(), (k as f64 * 0.7).cos()], &[])
            .unwrap();
    }
    let prior = filter.covariance();
    let gap = (0..4)
        .map(|k| (prior[k / 2][k % 2] - expected[(k / 2, k % 2)]).abs())
        .fold(0.0, f64::max);
    assert!(gap < 1e-12, "filter vs doubling: {gap:e}");
    // The tolerance bites: the Riccati solution with the second output's variance 1 % off moves by
    // more than 1e-6, so a filter that mishandled one of its sequential updates could not pass.
    let nearby = riccati_doubling(a2(), c2(), q, Matrix2::new(0.3, 0.0, 0.0, 0.0505));
    assert!((nearby - expected).abs().max() > 1e-6);
}

/// `x⁺ = exp(x)`, `y = x`: overflows `f64` within a few steps from `x = 5`.
#[derive(Clone, Copy, Debug)]
struct Exploding;

impl Plant<f64, 1, 1, 0> for Exploding {
    fn step(&self, x: &[f64; 1], _: &[f64; 0]) -> ([f64; 1], [[f64; 1]; 1]) {
        ([x[0].exp()], [[x[0].exp()]])
    }
    fn output(&self, x: &[f64; 1], _: &[f64; 0]) -> ([f64; 1], [[f64; 1]; 1]) {
        ([x[0]], [[1.0]])
    }
}

#[test]
fn a_step_that_overflows_is_not_taken() {
    // No measurements (refused): the prediction alone runs, 5 → e⁵ → e^(e⁵) ≈ 3e64 → ∞.
    let mut filter: Ekf<f64, Exploding, 1, 1, 0> = Ekf::new(Exploding, [5.0], [[1e-6]], [[0.0]], [1.0]);
    let mut states = vec![];
    for _ in 0..5 {
        assert!(filter.push(&[f64::NAN], &[]).is_err());
        states.push(filter.state()[0]);
        assert!(filter.covariance()[0][0].is_finite());
    }
    assert_eq!(states[0], 5.0_f64.exp());
    assert_eq!(states[1], 5.0_f64.exp().exp());
    assert!(states[1].exp().is_infinite(), "the next step overflows");
    // Not taken, then or after: the filter keeps the last finite state.
    assert_eq!(&states[2..], &[states[1]; 3]);
}
