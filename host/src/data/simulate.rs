//! Discretisation of `ẋ = f(x, u)` by classical RK4, the input held constant over each sample period.

use crate::data::Rows;
use crate::spec::model::Model;

/// The first non-finite state of a simulated run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("the state became non-finite at sample {sample} (t = {}), x = {state:?}", crate::output::number(*time))]
pub struct BlowUp {
    /// The sample index at which a state component is NaN or infinite.
    pub sample: usize,
    /// Its time.
    pub time: f64,
    /// The state there.
    pub state: Vec<f64>,
}

/// RK4 integrator for one model and sample period.
pub struct Integrator<'a> {
    model: &'a Model,
    step: f64,
    substeps: usize,
    environment: Vec<f64>,
    stages: [Vec<f64>; 4],
    scratch: Vec<f64>,
}

impl<'a> Integrator<'a> {
    /// An integrator advancing by `tau` in `substeps` RK4 steps.
    pub fn new(model: &'a Model, tau: f64, substeps: usize) -> Self {
        let n = model.states.len();
        Integrator {
            model,
            step: tau / substeps as f64,
            substeps,
            environment: Vec::new(),
            stages: std::array::from_fn(|_| vec![0.0; n]),
            scratch: vec![0.0; n],
        }
    }

    /// `x ← x(t + τ)` under the constant input `u`.
    pub fn advance(&mut self, x: &mut [f64], u: &[f64]) {
        let h = self.step;
        for _ in 0..self.substeps {
            let [k1, k2, k3, k4] = &mut self.stages;
            self.model.derivative(x, u, &mut self.environment, k1);
            for ((s, xi), ki) in self.scratch.iter_mut().zip(x.iter()).zip(k1.iter()) {
                *s = xi + 0.5 * h * ki;
            }
            self.model.derivative(&self.scratch, u, &mut self.environment, k2);
            for ((s, xi), ki) in self.scratch.iter_mut().zip(x.iter()).zip(k2.iter()) {
                *s = xi + 0.5 * h * ki;
            }
            self.model.derivative(&self.scratch, u, &mut self.environment, k3);
            for ((s, xi), ki) in self.scratch.iter_mut().zip(x.iter()).zip(k3.iter()) {
                *s = xi + h * ki;
            }
            self.model.derivative(&self.scratch, u, &mut self.environment, k4);
            for (i, xi) in x.iter_mut().enumerate() {
                *xi += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
        }
    }

    /// States `x(0) … x(n-1)` for `n = inputs.len()` samples from `x0`, `inputs[k]` held on
    /// `[kτ, (k+1)τ)`. Fails at the first non-finite state.
    pub fn run(&mut self, x0: &[f64], inputs: &Rows) -> Result<Rows, BlowUp> {
        let mut x = x0.to_vec();
        let mut states = Rows::new(x0.len());
        for (k, u) in inputs.iter().enumerate() {
            if x.iter().any(|v| !v.is_finite()) {
                return Err(BlowUp {
                    sample: k,
                    time: k as f64 * self.step * self.substeps as f64,
                    state: x,
                });
            }
            states.push(&x);
            if k + 1 < inputs.len() {
                self.advance(&mut x, u);
            }
        }
        Ok(states)
    }
}

/// Piecewise-constant inputs, one vector per sample.
pub(super) fn input_sequence(
    profiles: &[crate::spec::InputProfile],
    samples: usize,
    rng: &mut rand_chacha::ChaCha8Rng,
) -> super::Rows {
    let mut current = vec![0.0; profiles.len()];
    let mut inputs = super::Rows::new(profiles.len());
    for k in 0..samples {
        for (value, p) in current.iter_mut().zip(profiles) {
            if k % p.hold == 0 {
                *value = if p.min < p.max {
                    rand::RngExt::random_range(rng, p.min..=p.max)
                } else {
                    p.min
                };
            }
        }
        inputs.push(&current);
    }
    inputs
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::model::ModelText;

    fn model(derivatives: &[&str]) -> Model {
        let states: Vec<String> = (1..=derivatives.len()).map(|i| format!("x{i}")).collect();
        let derivatives: Vec<String> = derivatives.iter().map(|s| s.to_string()).collect();
        Model::compile(&ModelText {
            states: &states,
            inputs: &[],
            parameters: &[],
            definitions: &[],
            derivatives: &derivatives,
            outputs: &[("y".into(), "x1".into(), 0.0, String::new())],
        })
        .unwrap()
    }

    #[test]
    fn harmonic_oscillator_matches_the_closed_form() {
        // ẋ1 = x2, ẋ2 = -x1: x1 = cos t, x2 = -sin t from (1, 0). RK4's global error is O(h⁴).
        let m = model(&["x2", "-x1"]);
        let mut integrator = Integrator::new(&m, 0.1, 10);
        let states = integrator.run(&[1.0, 0.0], &Rows::from(vec![vec![]; 101])).unwrap();
        for (k, x) in states.iter().enumerate() {
            let t = k as f64 * 0.1;
            assert!(
                (x[0] - t.cos()).abs() < 1e-9 && (x[1] + t.sin()).abs() < 1e-9,
                "t={t}: {x:?}"
            );
        }
        // Halving the step divides the error at t = 10 by about 2⁴.
        let error = |substeps| {
            let mut i = Integrator::new(&m, 0.1, substeps);
            let x = i.run(&[1.0, 0.0], &Rows::from(vec![vec![]; 101])).unwrap();
            (x[100][0] - 10f64.cos()).abs()
        };
        let ratio = error(2) / error(4);
        assert!((12.0..20.0).contains(&ratio), "error ratio {ratio}");
    }

    #[test]
    fn nonlinear_decay_matches_the_closed_form() {
        // ẋ = -x², x(0) = 1  ⇒  x(t) = 1/(1 + t).
        let m = model(&["-(x1^2)"]);
        let states = Integrator::new(&m, 0.2, 20)
            .run(&[1.0], &Rows::from(vec![vec![]; 50]))
            .unwrap();
        for (k, x) in states.iter().enumerate() {
            let t = k as f64 * 0.2;
            assert!((x[0] - 1.0 / (1.0 + t)).abs() < 1e-9);
        }
    }

    #[test]
    fn finite_time_blow_up_is_reported_with_its_sample() {
        // ẋ = x², x(0) = 1 ⇒ x(t) = 1/(1 - t): infinite at t = 1.
        let m = model(&["x1^2"]);
        let err = Integrator::new(&m, 0.1, 10)
            .run(&[1.0], &Rows::from(vec![vec![]; 100]))
            .unwrap_err();
        assert!((9..=40).contains(&err.sample), "{err}");
    }
}
