//! The `estimation` figures: per target, every observer's estimate against the truth along the
//! scenario (paper Fig. 2 right, Fig. 4), and the same on the mismatch plant.

use std::path::{Path, PathBuf};

use super::{map_along, saturated_rings, PlotError};
use crate::data::Run;
use crate::fit::DesignResult;
use crate::observers::Comparison;
use crate::report::draw::{tick, with_unit, write_figure, Figure, Panel, Series, Style, MARK_COLOR, TRUE_COLOR};
use crate::spec::Design;
use plotters::style::RGBColor;

/// Each observer kind's colour, style and legend label in the estimation figures (its registry
/// entry's: [`crate::observers::kind::Kind`]).
fn kind_style(kind: &str) -> (RGBColor, Style, &'static str) {
    let entry = crate::observers::kind::named(kind).unwrap_or(&crate::observers::kind::REGISTRY[0]);
    let (r, g, b) = entry.colour;
    let style = if entry.dots { Style::Dots } else { Style::Line };
    (RGBColor(r, g, b), style, entry.legend)
}

/// The `estimation` figure (or `estimation_mismatch`, on the plant at the last corner of the uncertain
/// parameters): per target, every observer's estimate against the truth along `run` (the map's
/// saturated estimates ringed), with the first estimate and the end of the start-up
/// (`START_UP_HORIZONS · N` estimates later) marked.
pub(super) fn estimation(
    design: &Design,
    result: &DesignResult,
    comparison: &Comparison,
    run: &Run,
    on_mismatch: bool,
    folder: &Path,
) -> Result<Vec<PathBuf>, PlotError> {
    let times: Vec<f64> = (0..run.states.len()).map(|k| k as f64 * design.tau).collect();
    let horizon = design.map.horizon;
    let first = (horizon - 1) as f64 * design.tau;
    let start_up = first + (crate::observers::kind::corrected::run::START_UP_HORIZONS * horizon) as f64 * design.tau;
    let plant = match (&result.runs.mismatch, on_mismatch) {
        (Some(m), true) => format!(
            " on the plant at {}",
            design
                .model
                .uncertain
                .iter()
                .map(|u| &u.name)
                .zip(m.corners.last().into_iter().flatten())
                .map(|(n, v)| format!("{n} = {v}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        _ => String::new(),
    };
    let mut panels = Vec::new();
    for (index, target) in design.targets.iter().enumerate() {
        let mut panel = Panel::new(
            format!("{}: estimating {}{plant}", design.name, target.name),
            with_unit("time", &design.time_unit),
            with_unit(&target.name, &target.unit),
        )
        .with(Series::new(
            "true",
            times.iter().zip(&run.targets).map(|(&t, r)| (t, r[index])).collect(),
            TRUE_COLOR,
            Style::Line,
        ));
        for o in &comparison.observers {
            let rows = if on_mismatch {
                o.mismatch_scenario.as_ref()
            } else {
                Some(&o.scenario)
            };
            let Some(rows) = rows else { continue };
            let (color, style, label) = kind_style(o.kind);
            panel = panel.with(Series::new(
                label,
                times.iter().zip(rows.iter()).map(|(&t, e)| (t, e[index])).collect(),
                color,
                style,
            ));
        }
        if let Some(t) = result.targets.iter().find(|t| t.index == index) {
            let along = map_along(&t.fit.map, run, horizon);
            panel = panel.with(saturated_rings(
                times
                    .iter()
                    .zip(along)
                    .map(|(&time, (value, saturated))| ((time, value), saturated)),
            ));
        }
        panels.push(
            panel
                .marked(
                    format!("first estimate (t = {})", tick(&first)),
                    vec![first],
                    MARK_COLOR,
                    Style::Dashes,
                )
                .marked(
                    format!("end of start-up (t = {})", tick(&start_up)),
                    vec![start_up],
                    MARK_COLOR,
                    Style::Dashes,
                ),
        );
    }
    let stem = if on_mismatch {
        "estimation_mismatch"
    } else {
        "estimation"
    };
    write_figure(&folder.join(stem), &Figure::grid(panels, 1))
}
