//! The bank against a second method: on a linear model, the Gaussian sum of Kalman filters (the
//! EKF's programs, exact there) with each member's innovation likelihood computed here from its
//! predicted state and covariance; with one member, the box UKF's own run, bit for bit, through
//! refusals, the watch and restarts.

use std::path::Path;

use super::*;
use crate::observers::kind::ukf_box::program::{member_code, unscented_code};
use crate::plant::kalman::{diagonal_upper, filter_code, Watch};
use crate::plant::Covariance;

/// Example 1 with a linear `x2'` (its output `y = x1 + x2` is linear already).
fn linear() -> ModelCode {
    let text = std::fs::read_to_string("specs/vanderpol.toml").unwrap();
    let linear = text.replace("x2 = \"4*x1 + (1 - x1^2)*x2\"", "x2 = \"4*x1 - 0.5*x2\"");
    assert_ne!(linear, text, "the derivative to replace");
    ModelCode::new(&crate::spec::parse(Path::new("linear.toml"), &linear).unwrap()).unwrap()
}

fn constants(watch: Watch) -> EkfConstants {
    EkfConstants {
        x0: vec![0.0; 2],
        p0: Covariance::Diagonal(vec![1.0; 2]),
        q: Covariance::Diagonal(vec![1e-3, 2e-3]),
        r: vec![0.2],
        substeps: 2,
        h: 0.05,
        watch,
    }
}

fn layout(members: usize) -> Layout {
    Layout {
        axis: 0,
        members,
        spacing: Spacing::Plant,
        scale: 1.0,
    }
}

#[test]
fn on_a_linear_model_the_bank_is_the_gaussian_sum_of_kalman_filters() {
    let code = linear();
    let constants = constants(Watch::OFF);
    let bank = BankConstants {
        layout: layout(2),
        x0: vec![vec![1.0, -1.0], vec![-0.5, 0.5]],
        p0: vec![vec![0.5, 1.0], vec![2.0, 0.3]],
        prior: vec![0.3f64.ln(), 0.7f64.ln()],
    };
    let member = member_code(&code, &constants);
    let kalman = filter_code(&code, &constants);
    let mut step = BankStep::<f64>::new(&member, &constants, &bank, &code);
    // Each member: its state, covariance and log-weight ln πₘ + Σ ln N(ν; 0, s).
    let mut filters: Vec<(Vec<f64>, Vec<f64>, f64)> = (0..2)
        .map(|m| (bank.x0[m].clone(), diagonal_upper(&bank.p0[m]), bank.prior[m]))
        .collect();
    let (mut worst, mut apart) = (0.0f64, 0.0f64);
    for k in 0..40 {
        let y = [(0.3 * k as f64).sin() + 0.2];
        let mut estimates = Vec::new();
        for (x, p, log) in &mut filters {
            let innovation = y[0] - (x[0] + x[1]);
            let s = p[0] + 2.0 * p[1] + p[2] + 0.2;
            *log += -0.5 * innovation * innovation / s - 0.5 * s.ln();
            let (estimate, next, covariance) = kalman.run(x, p, Some(&y), &[], &mut Vec::new());
            estimates.push(estimate.unwrap());
            (*x, *p) = (next, covariance);
        }
        let top = filters[0].2.max(filters[1].2);
        let w: Vec<f64> = filters.iter().map(|f| (f.2 - top).exp()).collect();
        let expected: Vec<f64> = (0..2)
            .map(|i| (w[0] * estimates[0][i] + w[1] * estimates[1][i]) / (w[0] + w[1]))
            .collect();
        let got = step.step(&y, &[]).expect("finite");
        for (m, f) in filters.iter().enumerate() {
            worst = worst.max((step.log_weights()[m] - (f.2 - top)).abs());
        }
        worst = worst
            .max((got[0] - expected[0]).abs())
            .max((got[1] - expected[1]).abs());
        apart = apart.max((estimates[0][0] - estimates[1][0]).abs().min(w[0].min(w[1])));
    }
    assert!(worst < 1e-9, "the bank and the Gaussian sum differ by {worst:e}");
    // The test bites: both members weighed and apart at some sample.
    assert!(apart > 1e-3, "{apart}");
}

#[test]
fn with_one_member_it_is_the_box_ukf_bit_for_bit() {
    // Example 1 (nonlinear), watched tightly so that it restarts, with lost outputs and inputs:
    // the bank's rules and the box UKF's are the same.
    let code = ModelCode::new(&crate::spec::load(Path::new("specs/vanderpol.toml")).unwrap()).unwrap();
    let constants = EkfConstants {
        x0: vec![0.5, -0.5],
        ..constants(Watch {
            window: 2,
            threshold: 2.0,
        })
    };
    let bank = BankConstants {
        layout: layout(1),
        x0: vec![constants.x0.clone()],
        p0: vec![constants.p0.diagonal()],
        prior: vec![0.0],
    };
    let (ukf, member) = (unscented_code(&code, &constants), member_code(&code, &constants));
    let mut one = crate::observers::ekf::BoxStep::<f32>::new(&ukf, &constants.x0, &constants, &code);
    let mut step = BankStep::<f32>::new(&member, &constants, &bank, &code);
    let mut compared = 0;
    for k in 0..80 {
        let y = match k % 17 {
            5 => [f64::NAN],
            9 => [40.0], // an impossible output: the watch restarts
            _ => [(0.4 * k as f64).cos() * 2.0],
        };
        let expected = one.step(&y, &[]);
        let got = step.step(&y, &[]);
        assert_eq!(
            got.as_ref().map(|v| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>()),
            expected
                .as_ref()
                .map(|v| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>()),
            "sample {k}"
        );
        compared += usize::from(got.is_some());
    }
    assert_eq!((step.refused(), step.restarts()), (one.refused(), one.restarts()));
    assert!(step.refused() > 0 && step.restarts() > 0 && compared > 60);
}
