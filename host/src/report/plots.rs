//! The paper's figures for a design, as PNG and SVG, drawn by the report's drawing module (`draw`):
//!
//! * `measurements`: the scenario's measured outputs against their noise-free values, the noise
//!   (paper Fig. 1 and 5), and the inputs applied;
//! * `identification`: per target, identified against true values on the learning windows, and the
//!   gradient `dΓ/dr` of the identified `Γ` (Fig. 2 left, Fig. 3);
//! * `estimation`: per target, the observer's estimate against the truth along the scenario (Fig. 2
//!   right, Fig. 4);
//! * `validation`: per target, the map's error on every validation run against time and against the
//!   true value (what the report's validation RMSE and max error summarise).
//!
//! Saturated estimates (clamped by `Γ⁻¹` to the learning range) are ringed wherever the map's
//! estimates are drawn.

use std::path::{Path, PathBuf};

pub use super::draw::PlotError;
use super::draw::{
    thinning, tick, with_unit, write_figure, Figure, Panel, Series, Style, ESTIMATE_COLOR, MARK_COLOR, NOISE_COLOR,
    PALETTE, SATURATED_COLOR, TRUE_COLOR,
};
use crate::data::{DataSet, Run, Window};
use crate::fit::maps::FittedMap;
use crate::fit::DesignResult;
use crate::observers::Comparison;
use crate::spec::Design;
use plotters::style::RGBColor;

/// Most dots of one scatter panel.
const MAX_DOTS: usize = 4000;

/// Legend label of the rings around saturated estimates.
pub(crate) const SATURATED_LABEL: &str = "saturated (clamped to the learning range)";

/// Each observer kind's colour, style and legend label in the estimation figures.
fn kind_style(kind: &str) -> (RGBColor, Style, &'static str) {
    match kind {
        "map" => (ESTIMATE_COLOR, Style::Dots, "map F(Z)"),
        "ekf_box" => (RGBColor(255, 127, 14), Style::Line, "EKF from x̂(0)"),
        "corrected" => (RGBColor(44, 160, 44), Style::Line, "model-corrected map"),
        "ekf_restart" => (RGBColor(140, 86, 75), Style::Line, "EKF restarted by the map"),
        _ => (RGBColor(148, 103, 189), Style::Line, "EKF started by the map"),
    }
}

/// The stems of the figures [`draw`] and [`draw_search`] write for a design, in the order the report
/// shows them, each with what it shows.
pub fn figure_stems(mismatch: bool, search: bool) -> Vec<(&'static str, &'static str)> {
    let mut stems = vec![
        (
            "measurements",
            "The scenario's measured outputs against their noise-free values, the noise, and the inputs when the model has any (paper Fig. 1/5)",
        ),
        (
            "identification",
            "Identified against true on the learning windows, and dΓ/dr (paper Fig. 2 left/Fig. 3)",
        ),
        (
            "estimation",
            "Every observer along the scenario against the truth (paper Fig. 2 right/Fig. 4)",
        ),
    ];
    if mismatch {
        stems.push((
            "estimation_mismatch",
            "The same on the plant at the last corner of the uncertain parameters",
        ));
    }
    stems.push((
        "validation",
        "The map's error on every validation run, against time and against the true value",
    ));
    if search {
        stems.push(("search", "The design search's trade-off: the tuning score against the predicted instructions and the delay to the first estimate"));
    }
    stems
}

/// The map's estimate at every window end of `run` (NaN before the first), and whether it saturated.
fn map_along(map: &FittedMap, run: &Run, horizon: usize) -> Vec<(f64, bool)> {
    let set = DataSet {
        runs: vec![run.clone()],
        horizon,
    };
    let mut z = Vec::new();
    let mut out = vec![(f64::NAN, false); run.states.len()];
    for w in set.windows() {
        set.regressor(w, &mut z);
        let e = map.estimate(&z);
        out[w.end] = (e.value, e.saturation.is_saturated());
    }
    out
}

/// Rings at the saturated points of `estimates` (pairs of a point and whether it saturated).
fn saturated_rings(estimates: impl Iterator<Item = ((f64, f64), bool)>) -> Series {
    Series::new(
        SATURATED_LABEL,
        estimates.filter(|e| e.1).map(|e| e.0).collect(),
        SATURATED_COLOR,
        Style::Rings,
    )
}

/// Draws the figures of `design` into `folder` (every figure but `search`); returns the files written.
pub fn draw(
    design: &Design,
    result: &DesignResult,
    comparison: &Comparison,
    folder: &Path,
) -> Result<Vec<PathBuf>, PlotError> {
    std::fs::create_dir_all(folder).map_err(|source| PlotError::Io {
        path: folder.to_owned(),
        source,
    })?;
    let mut files = measurements(design, &result.scenario, folder)?;
    files.extend(identification(design, result, folder)?);
    // Estimation along the scenario, every observer, and on the mismatch plant.
    files.extend(estimation(design, result, comparison, &result.scenario, false, folder)?);
    if let Some(m) = &comparison.mismatch {
        files.extend(estimation(design, result, comparison, &m.scenario, true, folder)?);
    }
    files.extend(validation(design, result, folder)?);
    Ok(files)
}

/// `measurements`: per output, measured against noise-free and the noise; then the inputs, across.
fn measurements(design: &Design, run: &Run, folder: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let time_label = with_unit("time", &design.time_unit);
    let times: Vec<f64> = (0..run.states.len()).map(|k| k as f64 * design.tau).collect();
    let mut environment = Vec::new();
    let mut clean = vec![0.0; design.model.outputs.len()];
    let noise_free: Vec<Vec<f64>> = run
        .states
        .iter()
        .zip(&run.inputs)
        .map(|(x, u)| {
            design.model.outputs(x, u, &mut environment, &mut clean);
            clean.clone()
        })
        .collect();
    let mut rows = Vec::new();
    for (i, output) in design.model.outputs.iter().enumerate() {
        let label = with_unit(&output.name, &output.unit);
        let measured: Vec<(f64, f64)> = times.iter().zip(&run.measurements).map(|(&t, y)| (t, y[i])).collect();
        let exact: Vec<(f64, f64)> = times.iter().zip(&noise_free).map(|(&t, y)| (t, y[i])).collect();
        let noise: Vec<(f64, f64)> = measured.iter().zip(&exact).map(|(m, e)| (m.0, m.1 - e.1)).collect();
        rows.push(vec![
            Panel::new(
                format!(
                    "{}: measured {} (noise variance {})",
                    design.name, output.name, output.noise_variance
                ),
                time_label.clone(),
                label,
            )
            .with(Series::new("noise-free", exact, TRUE_COLOR, Style::Line))
            .with(Series::new("measured", measured, ESTIMATE_COLOR, Style::Dots)),
            Panel::new(
                format!("{}: noise on {}", design.name, output.name),
                time_label.clone(),
                with_unit(&format!("w ({})", output.name), &output.unit),
            )
            .with(Series::new("noise", noise, NOISE_COLOR, Style::Line)),
        ]);
    }
    if !design.model.inputs.is_empty() {
        let mut panel = Panel::new(
            format!("{}: inputs applied along the scenario", design.name),
            time_label,
            "input",
        );
        for (j, (name, unit)) in design.model.inputs.iter().zip(&design.input_units).enumerate() {
            let points = times.iter().zip(&run.inputs).map(|(&t, u)| (t, u[j])).collect();
            panel = panel.with(Series::new(
                with_unit(name, unit),
                points,
                PALETTE[j % PALETTE.len()],
                Style::Line,
            ));
        }
        rows.push(vec![panel]);
    }
    let figure = Figure {
        rows,
        panel_width: 560,
        row_height: 380,
    };
    write_figure(&folder.join("measurements"), &figure)
}

/// `identification`: identified against true on the learning windows (saturated ringed), then each
/// target's `dΓ/dr`, on an axis from 0 so that a straight `Γ` looks straight and says it is linear.
fn identification(design: &Design, result: &DesignResult, folder: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let learning: &DataSet = &result.learning;
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

/// The `estimation` figure (or `estimation_mismatch`, on the plant at the last corner of the uncertain
/// parameters): per target, every observer's estimate against the truth along `run` (the map's
/// saturated estimates ringed), with the first estimate and the end of the start-up
/// (`START_UP_HORIZONS · N` estimates later) marked.
fn estimation(
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
    let start_up = first + (crate::observers::corrected::START_UP_HORIZONS * horizon) as f64 * design.tau;
    let plant = match (&comparison.mismatch, on_mismatch) {
        (Some(m), true) => format!(
            " on the plant at {}",
            m.names
                .iter()
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

/// Bins of the validation figure's RMSE curve against the true value.
const BINS: usize = 40;

/// `validation`: per target, the map's error (estimate − true) on every validation window against
/// the time in its run, with the RMSE over the runs at each time, and against the true value, with
/// the RMSE per bin of it; saturated estimates ringed.
fn validation(design: &Design, result: &DesignResult, folder: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let set = &result.validation;
    let count = set.window_count();
    let stride = thinning(count, MAX_DOTS);
    let shown = if stride == 1 {
        format!("{} runs, {count} windows", set.runs.len())
    } else {
        format!("{} runs, 1 in {stride} of {count} windows", set.runs.len())
    };
    let samples = set.runs.iter().map(|r| r.states.len()).max().unwrap_or(0);
    let mut z = Vec::new();
    let mut rows = Vec::new();
    for t in &result.targets {
        let target = &design.targets[t.index];
        // Every window counts in the RMSE curves; every `stride`-th is drawn.
        let (mut by_time, mut by_time_count) = (vec![0.0; samples], vec![0usize; samples]);
        let mut errors = Vec::with_capacity(count);
        for w in set.windows() {
            set.regressor(w, &mut z);
            let e = t.fit.map.estimate(&z);
            let truth = set.target(w, t.index);
            let error = e.value - truth;
            by_time[w.end] += error * error;
            by_time_count[w.end] += 1;
            errors.push((w.end, truth, error, e.saturation.is_saturated()));
        }
        let time = |k: usize| k as f64 * design.tau;
        let rmse_by_time: Vec<(f64, f64)> = by_time
            .iter()
            .zip(&by_time_count)
            .enumerate()
            .filter(|(_, (_, &n))| n > 0)
            .map(|(k, (&sum, &n))| (time(k), (sum / n as f64).sqrt()))
            .collect();
        let (lo, hi) = (t.fit.map.r_min, t.fit.map.r_max);
        let width = (hi - lo) / BINS as f64;
        let (mut by_value, mut by_value_count) = (vec![0.0; BINS], vec![0usize; BINS]);
        for &(_, truth, error, _) in &errors {
            let bin = (((truth - lo) / width).floor().max(0.0) as usize).min(BINS - 1);
            by_value[bin] += error * error;
            by_value_count[bin] += 1;
        }
        let rmse_by_value: Vec<(f64, f64)> = (0..BINS)
            .filter(|&b| by_value_count[b] > 0)
            .map(|b| {
                (
                    lo + (b as f64 + 0.5) * width,
                    (by_value[b] / by_value_count[b] as f64).sqrt(),
                )
            })
            .collect();
        let drawn: Vec<_> = errors.iter().step_by(stride).collect();
        let error_label = with_unit(&format!("error of {} (estimate − true)", target.name), &target.unit);
        rows.push(vec![
            Panel::new(
                format!("{}: map error on {} ({shown})", design.name, target.name),
                with_unit("time in the run", &design.time_unit),
                error_label.clone(),
            )
            .with(Series::new(
                "error",
                drawn.iter().map(|e| (time(e.0), e.2)).collect(),
                ESTIMATE_COLOR,
                Style::Dots,
            ))
            .with(saturated_rings(drawn.iter().map(|e| ((time(e.0), e.2), e.3))))
            .with(Series::new(
                "RMSE over the runs at this time",
                rmse_by_time,
                TRUE_COLOR,
                Style::Line,
            )),
            Panel::new(
                format!("{}: map error on {} against the true value", design.name, target.name),
                format!("true {}", with_unit(&target.name, &target.unit)),
                error_label,
            )
            .with(Series::new(
                "error",
                drawn.iter().map(|e| (e.1, e.2)).collect(),
                ESTIMATE_COLOR,
                Style::Dots,
            ))
            .with(saturated_rings(drawn.iter().map(|e| ((e.1, e.2), e.3))))
            .with(Series::new(
                format!("RMSE per 1/{BINS} of the learning range"),
                rmse_by_value,
                TRUE_COLOR,
                Style::Line,
            )),
        ]);
    }
    let figure = Figure {
        rows,
        panel_width: 560,
        row_height: 380,
    };
    write_figure(&folder.join("validation"), &figure)
}

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

    #[test]
    fn every_figure_is_listed_once_in_the_report_order() {
        let all = figure_stems(true, true);
        let stems: Vec<&str> = all.iter().map(|s| s.0).collect();
        assert_eq!(
            stems,
            [
                "measurements",
                "identification",
                "estimation",
                "estimation_mismatch",
                "validation",
                "search"
            ]
        );
        assert_eq!(figure_stems(false, false).len(), 4);
    }
}
