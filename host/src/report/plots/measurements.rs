//! The `measurements` figure: the scenario's measured outputs against their noise-free values, the
//! noise (paper Fig. 1 and 5), and the inputs applied.

use std::path::{Path, PathBuf};

use super::PlotError;
use crate::data::Run;
use crate::report::draw::{
    with_unit, write_figure, Figure, Panel, Series, Style, ESTIMATE_COLOR, NOISE_COLOR, PALETTE, TRUE_COLOR,
};
use crate::spec::Design;

/// `measurements`: per output, measured against noise-free and the noise; then the inputs, across.
pub(super) fn measurements(design: &Design, run: &Run, folder: &Path) -> Result<Vec<PathBuf>, PlotError> {
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
