//! Accuracy of a fitted map and of its linear floor on a data set.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x < y)` is deliberate: a NaN RMSE counts as weak.

use serde::Serialize;

use crate::data::{Column, DataSet};
use crate::fit::identify::Fit;

/// Errors of one estimator over every window of a data set.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Accuracy {
    /// Root-mean-square error.
    pub rmse: f64,
    /// Largest absolute error: the empirical `ε_x` of the paper's Proposition.
    pub max_error: f64,
}

/// The map and its linear floor, judged on the same windows.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Evaluation {
    /// The fitted map `Γ⁻¹(Lᵀ Z)` (evaluated by the firmware code in `f64`).
    pub map: Accuracy,
    /// The linear least-squares map `Lᵀ Z + c`.
    pub linear: Accuracy,
    /// Fraction of windows where `Γ⁻¹` saturated at `r_min` or `r_max`.
    pub saturated_fraction: f64,
    /// Standard deviation of the target over the windows: the RMSE of the best constant estimate.
    pub target_spread: f64,
    /// Windows evaluated.
    pub windows: usize,
}

/// A map whose RMSE is at least this fraction of the target's spread explains less than half of its
/// variance (`1 - 0.7² ≈ 0.51`): it barely beats a constant.
pub const WEAK_FRACTION: f64 = 0.7;

impl Evaluation {
    /// Whether the map barely beats the constant estimate (see [`WEAK_FRACTION`]): the target may not be
    /// observable from these measurements over this horizon.
    pub fn is_weak(&self) -> bool {
        !(self.map.rmse < WEAK_FRACTION * self.target_spread)
    }
}

/// Evaluates `fit` for target `target` on every window of `data`.
pub fn evaluate(data: &DataSet, target: impl Into<Column>, fit: &Fit) -> Evaluation {
    let target = target.into();
    let mut z = Vec::new();
    let (mut map, mut linear) = (Sums::default(), Sums::default());
    let mut saturated = 0usize;
    // Welford's running mean and sum of squared deviations of the target.
    let (mut mean, mut deviations) = (0.0f64, 0.0f64);
    for window in data.windows() {
        data.regressor(window, &mut z);
        let truth = data.value(window, target);
        let delta = truth - mean;
        mean += delta / (map.count + 1) as f64;
        deviations += delta * (truth - mean);
        let estimate = fit.map.estimate(&z);
        map.add(estimate.value - truth);
        linear.add(fit.linear.estimate(&z) - truth);
        saturated += usize::from(estimate.saturation.is_saturated());
    }
    let windows = map.count;
    Evaluation {
        map: map.accuracy(),
        linear: linear.accuracy(),
        saturated_fraction: saturated as f64 / windows.max(1) as f64,
        target_spread: (deviations / windows.max(1) as f64).sqrt(),
        windows,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn evaluation(rmse: f64, target_spread: f64) -> Evaluation {
        let accuracy = Accuracy { rmse, max_error: rmse };
        Evaluation {
            map: accuracy,
            linear: accuracy,
            saturated_fraction: 0.0,
            target_spread,
            windows: 10,
        }
    }

    #[test]
    fn a_map_is_weak_when_it_explains_less_than_half_the_variance() {
        assert!(!evaluation(0.69, 1.0).is_weak());
        assert!(evaluation(0.71, 1.0).is_weak());
        assert!(evaluation(0.0, 0.0).is_weak()); // a constant target: nothing to explain
        assert!(evaluation(f64::NAN, 1.0).is_weak());
    }
}

#[derive(Default)]
struct Sums {
    squares: f64,
    max: f64,
    count: usize,
}

impl Sums {
    fn add(&mut self, error: f64) {
        self.squares += error * error;
        self.max = self.max.max(error.abs());
        self.count += 1;
    }

    fn accuracy(&self) -> Accuracy {
        Accuracy {
            rmse: (self.squares / self.count.max(1) as f64).sqrt(),
            max_error: self.max,
        }
    }
}
