//! The `validation` figure: per target, the map's error on every validation run against time and
//! against the true value (what the report's validation RMSE and max error summarise).

use std::path::{Path, PathBuf};

use super::{saturated_rings, PlotError, MAX_DOTS};
use crate::fit::DesignResult;
use crate::report::draw::{
    thinning, with_unit, write_figure, Figure, Panel, Series, Style, ESTIMATE_COLOR, TRUE_COLOR,
};
use crate::spec::Design;

/// Bins of the validation figure's RMSE curve against the true value.
const BINS: usize = 40;

/// `validation`: per target, the map's error (estimate − true) on every validation window against
/// the time in its run, with the RMSE over the runs at each time, and against the true value, with
/// the RMSE per bin of it; saturated estimates ringed.
pub(super) fn validation(design: &Design, result: &DesignResult, folder: &Path) -> Result<Vec<PathBuf>, PlotError> {
    let set = &result.runs.validation;
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
