//! One sampling period of the model for every particle at once, in the chip's RK4 substeps.

use super::Floor;

/// RK4's stages for every particle.
pub(super) struct Stages {
    k: [Vec<Vec<f64>>; 4],
    probe: Vec<Vec<f64>>,
}

impl Stages {
    pub(super) fn new(states: usize, count: usize) -> Self {
        let zeros = || vec![vec![0.0; count]; states];
        Stages {
            k: std::array::from_fn(|_| zeros()),
            probe: zeros(),
        }
    }

    /// One sampling period of the model for every particle, in the chip's RK4 substeps (the model
    /// every observer carries: the floor is that of an observer of this model).
    pub(super) fn advance(
        &mut self,
        floor: &Floor<'_>,
        x: &mut [Vec<f64>],
        varying: &[(usize, &[f64])],
        u: &[f64],
        values: &mut Vec<f64>,
    ) {
        let h = floor.h;
        let parameters = &floor.code.parameters;
        for _ in 0..floor.substeps {
            let [k1, k2, k3, k4] = &mut self.k;
            floor.field.eval_many(parameters, varying, x, u, values, k1);
            for ((probe, x), k) in self.probe.iter_mut().zip(x.iter()).zip(k1.iter()) {
                for ((p, &x), &k) in probe.iter_mut().zip(x).zip(k) {
                    *p = x + 0.5 * h * k;
                }
            }
            floor.field.eval_many(parameters, varying, &self.probe, u, values, k2);
            for ((probe, x), k) in self.probe.iter_mut().zip(x.iter()).zip(k2.iter()) {
                for ((p, &x), &k) in probe.iter_mut().zip(x).zip(k) {
                    *p = x + 0.5 * h * k;
                }
            }
            floor.field.eval_many(parameters, varying, &self.probe, u, values, k3);
            for ((probe, x), k) in self.probe.iter_mut().zip(x.iter()).zip(k3.iter()) {
                for ((p, &x), &k) in probe.iter_mut().zip(x).zip(k) {
                    *p = x + h * k;
                }
            }
            floor.field.eval_many(parameters, varying, &self.probe, u, values, k4);
            for (i, x) in x.iter_mut().enumerate() {
                for (p, x) in x.iter_mut().enumerate() {
                    *x += h / 6.0 * (k1[i][p] + 2.0 * k2[i][p] + 2.0 * k3[i][p] + k4[i][p]);
                }
            }
        }
        // A particle the model sent to a non-finite state is kept at the bound it crossed, or dropped
        // to weight zero by its output at the next sample.
        for (state, bounds) in x.iter_mut().zip(&floor.code.bounds) {
            for v in state.iter_mut() {
                *v = v.clamp(bounds.lower(), bounds.upper());
            }
        }
    }
}
