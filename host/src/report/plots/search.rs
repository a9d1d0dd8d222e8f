//! The `search` figure: the design search's trade-off between the tuning score and the predicted
//! cost, with the Pareto front and the chosen candidate.

use std::path::{Path, PathBuf};

use super::PlotError;
use crate::report::draw::{with_unit, write_figure, Figure, Panel, Series, Style, ESTIMATE_COLOR, TRUE_COLOR};
use crate::spec::Design;
use plotters::style::RGBColor;

/// `search.png`/`.svg`: the design search's trade-off in two projections, the tuning score against
/// the predicted instructions per sample and against the delay to the first estimate. Every fitted
/// candidate is a grey dot, the Pareto front is drawn over them, the chosen candidate in red.
pub fn draw_search(
    design: &Design,
    outcome: &crate::search::Outcome,
    folder: &Path,
) -> Result<Vec<PathBuf>, PlotError> {
    let fitted: Vec<&crate::search::Candidate> = outcome.candidates.iter().filter(|c| c.score.is_some()).collect();
    let point = |c: &crate::search::Candidate, x: fn(&crate::search::Cost) -> f64| {
        (
            x(&c.cost.expect("a fitted candidate has a cost")),
            c.score.expect("fitted"),
        )
    };
    let panel = |x_label: String, x: fn(&crate::search::Cost) -> f64| {
        let mut front: Vec<(f64, f64)> = outcome.front().into_iter().map(|c| point(c, x)).collect();
        front.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.total_cmp(&a.1)));
        // The front in this projection: the best score reached at or below each x.
        let mut best = f64::INFINITY;
        let envelope: Vec<(f64, f64)> = front
            .iter()
            .filter(|p| {
                let better = p.1 < best;
                best = best.min(p.1);
                better
            })
            .copied()
            .collect();
        Panel::new(
            format!(
                "{}: design search ({} candidates)",
                design.name,
                outcome.candidates.len()
            ),
            x_label,
            "tuning score (mean RMSE / spread)",
        )
        .with(Series::new(
            "candidate",
            fitted.iter().map(|c| point(c, x)).collect(),
            RGBColor(170, 170, 170),
            Style::Dots,
        ))
        .with(Series::new("best at this cost", envelope, TRUE_COLOR, Style::Line))
        .with(Series::new(
            format!(
                "chosen: N = {}, n_m = {}, β = {}",
                outcome.chosen().horizon,
                outcome.chosen().nm,
                outcome.chosen().beta
            ),
            vec![point(outcome.chosen(), x)],
            ESTIMATE_COLOR,
            Style::Dots,
        ))
    };
    let panels = vec![
        panel("predicted instructions per sample (map)".to_owned(), |c| c.instructions),
        panel(with_unit("delay to the first estimate", &design.time_unit), |c| {
            c.first_estimate
        }),
    ];
    write_figure(&folder.join("search"), &Figure::grid(panels, 2))
}
