//! The `identification` figure: per target, identified against true values on the learning windows,
//! and the gradient `dΓ/dr` of the identified `Γ` (paper Fig. 2 left, Fig. 3).

use std::path::{Path, PathBuf};

use super::{saturated_rings, PlotError, MAX_DOTS};
use crate::data::{DataSet, Window};
use crate::fit::DesignResult;
use crate::report::draw::{
    thinning, tick, with_unit, write_figure, Figure, Panel, Series, Style, ESTIMATE_COLOR, TRUE_COLOR,
};
use crate::spec::Design;

/// `identification`: identified against true on the learning windows (saturated ringed), then each
/// target's `dΓ/dr`, on an axis from 0 so that a straight `Γ` looks straight and says it is linear.
pub(super) fn identification(design: &Design, result: &DesignResult, folder: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let learning: &DataSet = &result.runs.learning;
    let count = learning.windows().count();
    let stride = thinning(count, MAX_DOTS);
    let windows: Vec<Window> = learning.windows().step_by(stride).collect();
    let shown = if stride == 1 {
        format!("the n_E = {count} learning windows")
    } else {
        format!("1 in {stride} of the n_E = {count} learning windows")
    };
    let mut z = Vec::new();
    let mut scatter = Vec::new();
    let mut gradients = Vec::new();
    for t in &result.targets {
        let target = &design.targets[t.index];
        let map = &t.fit.map;
        let mut pairs = Vec::new();
        for &w in &windows {
            learning.regressor(w, &mut z);
            let e = map.estimate(&z);
            pairs.push(((learning.target(w, t.index), e.value), e.saturation.is_saturated()));
        }
        let label = with_unit(&target.name, &target.unit);
        let diagonal = vec![(map.r_min, map.r_min), (map.r_max, map.r_max)];
        scatter.push(
            Panel::new(
                format!("{}: {} on {shown}", design.name, target.name),
                format!("true {label}"),
                format!("identified {label}"),
            )
            .with(Series::new(
                "identified",
                pairs.iter().map(|p| p.0).collect(),
                ESTIMATE_COLOR,
                Style::Dots,
            ))
            .with(saturated_rings(pairs.into_iter()))
            .with(Series::new("identified = true", diagonal, TRUE_COLOR, Style::Line)),
        );
        let span = map.r_max - map.r_min;
        let gamma = map.gamma();
        let gradient: Vec<(f64, f64)> = (0..=400)
            .map(|i| i as f64 / 400.0)
            .map(|eta| (map.r_min + span * eta, gamma.slope(eta) / span))
            .collect();
        let (title, legend) = if linear(&gradient) || t.fit.diagnostics.collapsed {
            (
                format!(
                    "{}: Γ for {} is linear (collapsed), dΓ/dr = {}",
                    design.name,
                    target.name,
                    tick(&gradient[0].1)
                ),
                "dΓ/dr (constant: Γ is a straight line)",
            )
        } else {
            (format!("{}: gradient of Γ for {}", design.name, target.name), "dΓ/dr")
        };
        let mut panel = Panel::new(title, label, "dΓ/dr").with(Series::new(legend, gradient, TRUE_COLOR, Style::Line));
        panel.y_from_zero = true;
        gradients.push(panel);
    }
    let figure = Figure {
        rows: vec![scatter, gradients],
        panel_width: 560,
        row_height: 380,
    };
    write_figure(&folder.join("identification"), &figure)
}

/// Whether a gradient is constant to within 10⁻⁶ of its size (a collapsed `Γ` whatever the QP's
/// active-constraint count says).
fn linear(gradient: &[(f64, f64)]) -> bool {
    let (lo, hi) = gradient
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
    hi - lo <= 1e-6 * hi.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_constant_gradient_is_linear_and_a_curved_one_is_not() {
        let flat: Vec<(f64, f64)> = (0..10).map(|i| (i as f64, 1.069e-3)).collect();
        assert!(linear(&flat));
        let curved: Vec<(f64, f64)> = (0..10).map(|i| (i as f64, 2e-3 + 1e-4 * (i * i) as f64)).collect();
        assert!(!linear(&curved));
    }
}
