//! The RK4 step and its Jacobian against independent truth: on a linear model the step is the
//! degree-4 Taylor polynomial of `e^{hA}` (closed form), and on a nonlinear one its Jacobian equals
//! central differences of the step itself.

use super::*;

/// `ẋ = A x + (0, u)`, `y = x₀`.
#[derive(Clone, Copy, Debug)]
struct Linear;

const A: [[f64; 2]; 2] = [[0.3, -1.2], [0.8, -0.5]];

impl Model<f64, 2, 1, 1> for Linear {
    fn derivative(&self, x: &[f64; 2], u: &[f64; 1]) -> ([f64; 2], [[f64; 2]; 2]) {
        (
            [A[0][0] * x[0] + A[0][1] * x[1], A[1][0] * x[0] + A[1][1] * x[1] + u[0]],
            A,
        )
    }
    fn output(&self, x: &[f64; 2], _: &[f64; 1]) -> ([f64; 1], [[f64; 2]; 1]) {
        ([x[0]], [[1.0, 0.0]])
    }
}

/// The Van der Pol oscillator of the paper's Example 1, with a forcing input on `ẋ₂`.
#[derive(Clone, Copy, Debug)]
struct VanDerPol;

impl Model<f64, 2, 1, 1> for VanDerPol {
    fn derivative(&self, x: &[f64; 2], u: &[f64; 1]) -> ([f64; 2], [[f64; 2]; 2]) {
        let [x1, x2] = *x;
        (
            [-x2, 4.0 * x1 + (1.0 - x1 * x1) * x2 + u[0]],
            [[0.0, -1.0], [4.0 - 2.0 * x1 * x2, 1.0 - x1 * x1]],
        )
    }
    fn output(&self, x: &[f64; 2], _: &[f64; 1]) -> ([f64; 1], [[f64; 2]; 1]) {
        ([x[0] + x[1]], [[1.0, 1.0]])
    }
}

#[test]
fn on_a_linear_model_the_step_is_the_fourth_order_taylor_polynomial() {
    // With u = 0, RK4 gives x⁺ = T x with T = I + hA + (hA)²/2 + (hA)³/6 + (hA)⁴/24, and F = T
    // (two substeps: T(h/2)²).
    let tau = 0.3;
    for substeps in [1, 2] {
        let h = tau / substeps as f64;
        let ha = A.map(|row| row.map(|v| v * h));
        let mut term = identity::<f64, 2>();
        let mut taylor = identity::<f64, 2>();
        for n in 1..=4 {
            term = product(&term, &ha).map(|row| row.map(|v| v / n as f64));
            for i in 0..2 {
                for j in 0..2 {
                    taylor[i][j] += term[i][j];
                }
            }
        }
        let expected = if substeps == 1 {
            taylor
        } else {
            product(&taylor, &taylor)
        };
        let x = [0.7, -1.3];
        let (next, jacobian) = match substeps {
            1 => Rk4::<f64, _, 1>::new(Linear, h).step(&x, &[0.0]),
            _ => Rk4::<f64, _, 2>::new(Linear, h).step(&x, &[0.0]),
        };
        for i in 0..2 {
            let value = expected[i][0] * x[0] + expected[i][1] * x[1];
            assert!((next[i] - value).abs() < 1e-14, "substeps {substeps}: x⁺[{i}]");
            for j in 0..2 {
                assert!(
                    (jacobian[i][j] - expected[i][j]).abs() < 1e-14,
                    "substeps {substeps}: F[{i}][{j}]"
                );
            }
        }
    }
}

#[test]
fn the_jacobian_of_the_step_matches_central_differences() {
    let plant = Rk4::<f64, _, 3>::new(VanDerPol, 0.1 / 3.0);
    let mut worst = 0.0_f64;
    for k in 0..200 {
        let x = [2.0 * (k as f64 * 0.731).sin(), 5.0 * (k as f64 * 0.377).cos()];
        let u = [(k as f64 * 0.19).sin()];
        let (_, jacobian) = plant.step(&x, &u);
        for j in 0..2 {
            let delta = 1e-5;
            let (mut up, mut down) = (x, x);
            up[j] += delta;
            down[j] -= delta;
            let (a, b) = (plant.step(&up, &u).0, plant.step(&down, &u).0);
            for i in 0..2 {
                let difference = (a[i] - b[i]) / (2.0 * delta);
                worst = worst.max((difference - jacobian[i][j]).abs() / (1.0 + difference.abs()));
            }
        }
    }
    // Central differences are accurate to O(δ²·x''') ≈ 1e-9 here; a wrong stage chain is off by O(h²).
    assert!(worst < 1e-8, "worst relative difference {worst:e}");
}

#[test]
fn the_output_is_the_model_s() {
    let plant = Rk4::<f64, _, 1>::new(VanDerPol, 0.1);
    assert_eq!(plant.output(&[0.25, 0.5], &[0.0]), ([0.75], [[1.0, 1.0]]));
}
