//! The normal equations against independent truth: on a linear plant one Gauss–Newton step from any
//! start is the least-squares solution of the stacked observability system (solved by nalgebra's
//! SVD); on a nonlinear plant the gradient is the finite-difference derivative of the cost. The
//! Cholesky solve against nalgebra's LU.

use nalgebra::{Matrix2, Matrix3, SMatrix, SVector, Vector2, Vector3};

use super::*;
use crate::Plant;
use crate::RejectedSample;

/// `x⁺ = A x + (0, 0.1 u)`, `y = (x₁, x₁ + x₂)`.
struct Linear;

fn a() -> Matrix2<f64> {
    Matrix2::new(1.0, 0.1, -0.2, 0.95)
}

impl Plant<f64, 2, 2, 1> for Linear {
    fn step(&self, x: &[f64; 2], u: &[f64; 1]) -> ([f64; 2], [[f64; 2]; 2]) {
        let m = a();
        let next = m * Vector2::new(x[0], x[1]) + Vector2::new(0.0, 0.1 * u[0]);
        ([next[0], next[1]], [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]])
    }
    fn output(&self, x: &[f64; 2], _: &[f64; 1]) -> ([f64; 2], [[f64; 2]; 2]) {
        ([x[0], x[0] + x[1]], [[1.0, 0.0], [1.0, 1.0]])
    }
}

/// The Van der Pol oscillator of the paper's Example 1, one explicit Euler step of 0.1: nonlinear.
struct VanDerPol;

impl Plant<f64, 2, 1, 0> for VanDerPol {
    fn step(&self, x: &[f64; 2], _: &[f64; 0]) -> ([f64; 2], [[f64; 2]; 2]) {
        let h = 0.1;
        let (x1, x2) = (x[0], x[1]);
        (
            [x1 - h * x2, x2 + h * (4.0 * x1 + (1.0 - x1 * x1) * x2)],
            [[1.0, -h], [h * (4.0 - 2.0 * x1 * x2), 1.0 + h * (1.0 - x1 * x1)]],
        )
    }
    fn output(&self, x: &[f64; 2], _: &[f64; 0]) -> ([f64; 1], [[f64; 2]; 1]) {
        ([x[0] + x[1]], [[1.0, 1.0]])
    }
}

fn window() -> (Vec<[f64; 2]>, Vec<[f64; 1]>) {
    let ys = (0..8)
        .map(|k| [(k as f64 * 0.7).sin(), (k as f64 * 0.3).cos()])
        .collect();
    let us = (0..8).map(|k| [(k as f64 * 0.5).cos()]).collect();
    (ys, us)
}

/// The weighted least-squares start of the window `(ys, us)` of [`Linear`], from the stacked system
/// `y(j) − C Σ_{m<j} A^{j−1−m} B u(m) = C A^j x` (rows weighted by `√w`), solved by nalgebra's SVD; and
/// the stacked system's residual at `start`, squared.
fn least_squares(ys: &[[f64; 2]], us: &[[f64; 1]], weights: [f64; 2], start: [f64; 2]) -> ([f64; 2], f64) {
    let (m, b, c) = (a(), Vector2::new(0.0, 0.1), nalgebra::Matrix2::new(1.0, 0.0, 1.0, 1.0));
    let mut o = SMatrix::<f64, 16, 2>::zeros();
    let mut rhs = SVector::<f64, 16>::zeros();
    let (mut power, mut forced) = (Matrix2::identity(), Vector2::zeros());
    for (j, y) in ys.iter().enumerate() {
        if j > 0 {
            forced = m * forced + b * us[j - 1][0];
            power = m * power;
        }
        let block = c * power;
        let free = c * forced;
        for i in 0..2 {
            let s = weights[i].sqrt();
            o[(2 * j + i, 0)] = s * block[(i, 0)];
            o[(2 * j + i, 1)] = s * block[(i, 1)];
            rhs[2 * j + i] = s * (y[i] - free[i]);
        }
    }
    let solution = o.svd(true, true).solve(&rhs, 1e-14).unwrap();
    let residual = rhs - o * Vector2::new(start[0], start[1]);
    ([solution[0], solution[1]], residual.norm_squared())
}

#[test]
fn one_step_on_a_linear_plant_is_the_weighted_least_squares_solution() {
    let (ys, us) = window();
    let weights = [2.0_f64, 0.5];
    let start = [3.0, -2.0];
    let (expected, cost) = least_squares(&ys, &us, weights, start);
    let normal = normal_equations(&Linear, &start, ys.iter().zip(&us), &weights);
    let step = solve_cholesky(&normal.matrix, &normal.gradient).unwrap();
    for i in 0..2 {
        assert!(
            (start[i] + step[i] - expected[i]).abs() < 1e-10,
            "{i}: {step:?} {expected:?}"
        );
    }
    // And the cost at the start is the stacked residual's squared norm.
    assert!((normal.cost - cost).abs() < 1e-9 * normal.cost);
    // The end is the start propagated N − 1 steps.
    let mut x = start;
    for u in &us[..us.len() - 1] {
        x = Linear.step(&x, u).0;
    }
    assert_eq!(normal.end, x);
    assert_eq!(propagate::<f64, Linear, 2, 2, 1>(&Linear, &start, us.iter()), x);
}

/// The chip observer over [`Linear`] with `SETTINGS` (its targets: the state); `WATCHED`: with a
/// watch over windows of 8 samples (`m N = 16`, `τ = 4`, `W = 8`).
struct OnLinear<const HEAVY: bool, const WATCHED: bool = false>;

impl<const HEAVY: bool, const WATCHED: bool> Horizon<f64, 2, 2, 1, 2> for OnLinear<HEAVY, WATCHED> {
    type Plant = Linear;
    fn plant() -> Linear {
        Linear
    }
    fn settings() -> Settings<f64, 2, 2> {
        if HEAVY {
            // A prior far heavier than the data.
            Settings {
                weights: [1.0, 1.0],
                prior: [1e12; 2],
                lower: [f64::NEG_INFINITY; 2],
                upper: [f64::INFINITY; 2],
                start: [0.0; 2],
                iterations: 2,
                damping: 0.0,
                watch: WATCHED.then_some(crate::watch::Watch {
                    start: 16.0,
                    gain: 0.125,
                    limit: 64.0,
                }),
            }
        } else {
            // One Gauss–Newton step, no damping, no prior: exact on a linear plant whatever the start.
            Settings {
                weights: [2.0, 0.5],
                prior: [0.0; 2],
                lower: [f64::NEG_INFINITY; 2],
                upper: [f64::INFINITY; 2],
                start: [0.0; 2],
                iterations: 1,
                damping: 0.0,
                watch: None,
            }
        }
    }
    fn targets(x: &[f64; 2], _: &[f64; 1]) -> [f64; 2] {
        *x
    }
}

fn values(estimate: Option<[crate::Estimate<f64>; 2]>) -> Option<[f64; 2]> {
    estimate.map(|e| e.map(|e| e.value))
}

#[test]
fn the_chip_estimator_on_a_linear_plant_gives_every_window_s_least_squares_end() {
    let mut estimator: Observer<f64, OnLinear<false>, 8, 2, 2, 1, 2> = Observer::new();
    let weights = OnLinear::<false>::settings().weights;
    let ys: Vec<[f64; 2]> = (0..30)
        .map(|k| [(k as f64 * 0.7).sin(), (k as f64 * 0.3).cos()])
        .collect();
    let us: Vec<[f64; 1]> = (0..30).map(|k| [(k as f64 * 0.5).cos()]).collect();
    for k in 0..30 {
        estimator.push(ys[k], us[k]).unwrap();
        let estimate = values(estimator.estimate());
        if k < 7 {
            assert_eq!(estimate, None);
            continue;
        }
        let (start, _) = least_squares(&ys[k - 7..=k], &us[k - 7..=k], weights, [0.0; 2]);
        let end = propagate::<f64, Linear, 2, 2, 1>(&Linear, &start, us[k - 7..=k].iter());
        let estimate = estimate.unwrap();
        for i in 0..2 {
            assert!((estimate[i] - end[i]).abs() < 1e-9, "{k}: {estimate:?} vs {end:?}");
        }
    }
    // A non-finite input or measurement is refused and not stored (the firmware contract: nothing
    // stored changes); a refused sample leaves the latest estimate.
    let latest = estimator.estimate();
    let solved = estimator.solution();
    assert_eq!(estimator.push([0.0, 0.0], [f64::NAN]), Err(RejectedSample));
    assert_eq!((estimator.estimate(), estimator.solution()), (latest, solved));
    assert_eq!(estimator.push([f64::NAN, 0.0], [0.0]), Err(RejectedSample));
    assert_eq!(estimator.push([0.0, f64::INFINITY], [0.0]), Err(RejectedSample));
    assert_eq!((estimator.estimate(), estimator.solution()), (latest, solved));
    assert!(estimator.push([0.1, 0.2], [0.0]).is_ok());
    assert_ne!(estimator.estimate(), latest);
    estimator.reset();
    assert!(!estimator.is_ready() && estimator.solution().is_none());
}

/// Issue 48: while the window fills, a non-finite measurement is refused and not stored, as after
/// (it was stored and taken, `Ok`, until the window was full): every later estimate is that of an
/// estimator that never saw it.
#[test]
fn a_non_finite_measurement_is_refused_while_the_window_fills() {
    let (ys, us) = window();
    let mut with: Observer<f64, OnLinear<false>, 8, 2, 2, 1, 2> = Observer::new();
    let mut without: Observer<f64, OnLinear<false>, 8, 2, 2, 1, 2> = Observer::new();
    for k in 0..8 {
        if k == 3 {
            assert_eq!(with.push([f64::NAN, 0.0], us[k]), Err(RejectedSample));
            assert_eq!(with.push([0.0, f64::NEG_INFINITY], us[k]), Err(RejectedSample));
        }
        with.push(ys[k], us[k]).unwrap();
        without.push(ys[k], us[k]).unwrap();
        assert_eq!(values(with.estimate()), values(without.estimate()), "sample {k}");
    }
    assert!(with.is_ready() && with.solution() == without.solution());
}

#[test]
fn a_heavy_prior_holds_the_chip_estimator_on_the_model_s_prediction() {
    // With a prior far heavier than the data, every window after the first starts where the model
    // carries the previous solution: the estimate is the first window's end, simulated on.
    let mut estimator: Observer<f64, OnLinear<true>, 8, 2, 2, 1, 2> = Observer::new();
    let (ys, us) = window();
    for k in 0..8 {
        estimator.push(ys[k], us[k]).unwrap();
    }
    let (mut simulated, mut held) = (values(estimator.estimate()).unwrap(), us[7]);
    for k in 0..10 {
        // Measurements far from the model's: the data pull, the prior holds.
        let u = [0.3 * k as f64];
        simulated = Linear.step(&simulated, &held).0;
        held = u;
        estimator.push([5.0, -5.0], u).unwrap();
        let estimate = values(estimator.estimate()).unwrap();
        for i in 0..2 {
            let scale = 1.0 + simulated[i].abs();
            assert!(
                (estimate[i] - simulated[i]).abs() < 1e-6 * scale,
                "{k}: {estimate:?} {simulated:?}"
            );
        }
    }
}

/// Issue 50: a heavy prior holds the estimator on the model's prediction when the plant jumps where
/// the model cannot go; the watch sees the windows' costs stay implausible and restarts it, and the
/// next window, solved from the start without the prior, is that window's least-squares end. Unwatched,
/// it never restarts.
#[test]
fn a_watched_estimator_held_where_the_samples_say_otherwise_restarts() {
    // Samples of the model itself from (0.3, −0.2): every window's cost is 0 at the moved solution.
    let us: Vec<[f64; 1]> = (0..30).map(|k| [(k as f64 * 0.5).cos()]).collect();
    let mut x = [0.3, -0.2];
    let mut ys = Vec::new();
    for u in &us {
        ys.push([x[0], x[0] + x[1]]);
        x = Linear.step(&x, u).0;
    }
    // From sample 12 on, outputs the model cannot follow with a prior that heavy.
    for y in &mut ys[12..] {
        *y = [5.0, -5.0];
    }
    let mut watched: Observer<f64, OnLinear<true, true>, 8, 2, 2, 1, 2> = Observer::new();
    let mut unwatched: Observer<f64, OnLinear<true, false>, 8, 2, 2, 1, 2> = Observer::new();
    let mut first_restart = None;
    for k in 0..30 {
        assert!(unwatched.push(ys[k], us[k]).is_ok(), "unwatched: {k}");
        let before = watched.estimate();
        match watched.push(ys[k], us[k]) {
            Ok(()) => {}
            Err(RejectedSample) => {
                // A restart keeps the latest estimate and counts.
                assert_eq!(watched.estimate(), before, "{k}");
                first_restart.get_or_insert(k);
                // The next window is solved from the start without the prior: its least-squares end
                // (one Gauss–Newton step is exact on a linear plant).
                watched.push(ys[k + 1], us[k + 1]).unwrap();
                let (start, _) = least_squares(&ys[k - 6..=k + 1], &us[k - 6..=k + 1], [1.0, 1.0], [0.0; 2]);
                let end = propagate::<f64, Linear, 2, 2, 1>(&Linear, &start, us[k - 6..=k + 1].iter());
                let estimate = values(watched.estimate()).unwrap();
                for i in 0..2 {
                    assert!((estimate[i] - end[i]).abs() < 1e-9, "{k}: {estimate:?} vs {end:?}");
                }
                break;
            }
        }
    }
    // No restart while the samples were the model's, nor at the first sample off (the watch needs a
    // run of implausible windows: from c ≈ 16 · (7/8)⁵ ≈ 8 and costs growing by about 50 per bad
    // sample, c passes 64 at the fifth); one within a few samples of the jump.
    let first = first_restart.expect("the watch restarts the held estimator");
    assert!((13..20).contains(&first), "first restart at {first}");
    assert_eq!((watched.restarts(), unwatched.restarts()), (1, 0));
}

#[test]
fn the_gradient_is_the_finite_difference_derivative_of_the_cost() {
    let ys: Vec<[f64; 1]> = (0..10).map(|k| [(k as f64 * 0.4).sin() * 2.0]).collect();
    let us = [[0.0_f64; 0]; 10];
    let weights = [1.0 / 0.2];
    let cost = |x: [f64; 2]| normal_equations(&VanDerPol, &x, ys.iter().zip(&us), &weights).cost;
    let x = [0.7, -1.3];
    let normal = normal_equations(&VanDerPol, &x, ys.iter().zip(&us), &weights);
    for i in 0..2 {
        let h = 1e-6;
        let (mut up, mut down) = (x, x);
        up[i] += h;
        down[i] -= h;
        // dC/dx = −2 Σ Jᵀ W r.
        let numeric = (cost(up) - cost(down)) / (2.0 * h);
        let analytic = -2.0 * normal.gradient[i];
        assert!(
            (numeric - analytic).abs() < 1e-6 * (1.0 + analytic.abs()),
            "{i}: {numeric} vs {analytic}"
        );
    }
}

#[test]
fn a_refused_measurement_adds_nothing() {
    let (mut ys, us) = window();
    let weights = [1.0, 1.0];
    let whole = normal_equations(&Linear, &[0.1, 0.2], ys.iter().zip(&us), &weights);
    let (first, _) = Linear.output(&[0.1, 0.2], &us[0]);
    ys[0][1] = f64::NAN;
    let refused = normal_equations(&Linear, &[0.1, 0.2], ys.iter().zip(&us), &weights);
    let r = window().0[0][1] - first[1];
    assert!((whole.cost - refused.cost - r * r).abs() < 1e-12);
    assert!(refused.cost.is_finite() && refused.gradient.iter().all(|v| v.is_finite()));
}

#[test]
fn cholesky_solves_as_an_lu_does_and_refuses_an_indefinite_matrix() {
    let m = Matrix3::new(4.0, 1.0, -0.5, 1.0, 3.0, 0.2, -0.5, 0.2, 2.0);
    let b = Vector3::new(1.0, -2.0, 0.5);
    let expected = m.lu().solve(&b).unwrap();
    let rows: [[f64; 3]; 3] = core::array::from_fn(|r| core::array::from_fn(|c| m[(r, c)]));
    let x = solve_cholesky(&rows, &[b[0], b[1], b[2]]).unwrap();
    for i in 0..3 {
        assert!((x[i] - expected[i]).abs() < 1e-14, "{x:?} {expected}");
    }
    let indefinite = [[1.0, 2.0], [2.0, 1.0]];
    assert_eq!(solve_cholesky(&indefinite, &[1.0, 1.0]), None);
    assert_eq!(solve_cholesky(&[[f64::NAN]], &[1.0]), None);
}
