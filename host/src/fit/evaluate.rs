//! Accuracy of a fitted map and of its linear floor on a data set.

use serde::Serialize;

use crate::data::DataSet;
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
    /// Windows evaluated.
    pub windows: usize,
}

/// Evaluates `fit` for target `target` on every window of `data`.
pub fn evaluate(data: &DataSet, target: usize, fit: &Fit) -> Evaluation {
    let mut z = Vec::new();
    let (mut map, mut linear) = (Sums::default(), Sums::default());
    let mut saturated = 0usize;
    for window in data.windows() {
        data.regressor(window, &mut z);
        let truth = data.target(window, target);
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
        windows,
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
