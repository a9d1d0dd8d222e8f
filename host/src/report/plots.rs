//! The paper's figures for a design, as PNG and SVG (plotters; the bundled DejaVu Sans font is
//! rasterised by ab_glyph, so no system font library is involved):
//!
//! * `measurements`: the scenario's measured outputs against their noise-free values, and the noise
//!   (paper Fig. 1 and 5);
//! * `identification`: per target, identified against true values on the learning windows, and the
//!   gradient `dΓ/dr` of the identified `Γ` (Fig. 2 left, Fig. 3);
//! * `estimation`: per target, the observer's estimate against the truth along the scenario (Fig. 2
//!   right, Fig. 4).

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Once;

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::data::{DataSet, Window};
use crate::fit::DesignResult;
use crate::recording;
use crate::spec::Design;

/// Why a figure could not be written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// plotters failed to draw (its errors are generic over the backend; their text is kept).
    #[error("{}: cannot draw: {message}", file.display())]
    Draw {
        /// The figure.
        file: PathBuf,
        /// plotters' message.
        message: String,
    },
    /// The file or its folder could not be written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
}

const FONT: &str = "sans-serif";
static REGISTER_FONT: Once = Once::new();

fn register_font() {
    REGISTER_FONT.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../../assets/DejaVuSans.ttf");
        // The font is bundled and valid; a failure here would only lose the text of the plots.
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, bytes);
    });
}

/// One curve of a panel.
struct Curve {
    label: String,
    points: Vec<(f64, f64)>,
    color: RGBColor,
    dots: bool,
}

/// One panel: a title, axis descriptions and its curves.
struct Panel {
    title: String,
    x_label: String,
    y_label: String,
    curves: Vec<Curve>,
}

fn with_unit(name: &str, unit: &str) -> String {
    if unit.is_empty() {
        name.to_owned()
    } else {
        format!("{name} [{unit}]")
    }
}

fn range(values: impl Iterator<Item = f64>) -> Range<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    if !(lo.is_finite() && hi.is_finite()) {
        return 0.0..1.0;
    }
    // Pad by 5 % of the spread, and by at least 2 % of the magnitude so that a flat curve looks flat.
    let pad = (0.05 * (hi - lo)).max(0.02 * lo.abs().max(hi.abs())).max(1e-12);
    (lo - pad)..(hi + pad)
}

/// Tick labels: fixed-point for ordinary magnitudes, scientific for tiny or huge ones.
fn tick(value: &f64) -> String {
    let magnitude = value.abs();
    if magnitude < 1e-12 {
        "0".to_owned() // a tick at zero computed with rounding noise
    } else if !(1e-2..1e4).contains(&magnitude) {
        format!("{value:.3e}")
    } else {
        let text = format!("{value:.4}");
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    }
}

fn draw_panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, panel: &Panel) -> Result<(), String> {
    let all = || panel.curves.iter().flat_map(|c| c.points.iter());
    let x = range(all().map(|p| p.0));
    let y = range(all().map(|p| p.1));
    let mut chart = ChartBuilder::on(area)
        .caption(&panel.title, (FONT, 18))
        .margin(12)
        .x_label_area_size(42)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .label_style((FONT, 13))
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .axis_desc_style((FONT, 15))
        .draw()
        .map_err(|e| e.to_string())?;
    for curve in &panel.curves {
        let color = curve.color;
        let series = if curve.dots {
            chart.draw_series(curve.points.iter().map(move |&p| Circle::new(p, 2, color.filled())))
        } else {
            chart.draw_series(LineSeries::new(curve.points.iter().copied(), color.stroke_width(2)))
        };
        series
            .map_err(|e| e.to_string())?
            .label(curve.label.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(3)));
    }
    chart
        .configure_series_labels()
        .label_font((FONT, 13))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(|e| e.to_string())
}

fn draw_grid<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    rows: usize,
    columns: usize,
    panels: &[Panel],
) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    for (area, panel) in root.split_evenly((rows, columns)).iter().zip(panels) {
        draw_panel(area, panel)?;
    }
    root.present().map_err(|e| e.to_string())
}

/// Writes `<stem>.png` and `<stem>.svg` in `folder`, each through a temporary file.
fn write_figure(
    folder: &Path,
    stem: &str,
    rows: usize,
    columns: usize,
    panels: &[Panel],
) -> Result<Vec<PathBuf>, PlotError> {
    let size = (560 * columns as u32, 380 * rows as u32);
    let png = folder.join(format!("{stem}.png"));
    crate::output::remove_stale_temporaries(folder, &format!(".{stem}.tmp"), ".png");
    let temporary = folder.join(format!(".{stem}.tmp{}.png", std::process::id()));
    let drawn = draw_grid(
        BitMapBackend::new(&temporary, size).into_drawing_area(),
        rows,
        columns,
        panels,
    );
    let written = match drawn {
        Ok(()) => std::fs::rename(&temporary, &png).map_err(|source| PlotError::Io {
            path: png.clone(),
            source,
        }),
        Err(message) => Err(PlotError::Draw {
            file: png.clone(),
            message,
        }),
    };
    if written.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    written?;
    let svg = folder.join(format!("{stem}.svg"));
    let mut svg_text = String::new();
    draw_grid(
        SVGBackend::with_string(&mut svg_text, size).into_drawing_area(),
        rows,
        columns,
        panels,
    )
    .map_err(|message| PlotError::Draw {
        file: svg.clone(),
        message,
    })?;
    crate::output::write_atomically(&svg, svg_text.as_bytes()).map_err(|source| PlotError::Io {
        path: svg.clone(),
        source,
    })?;
    Ok(vec![png, svg])
}

/// Most dots of one scatter panel.
const MAX_DOTS: usize = 4000;

const TRUE_COLOR: RGBColor = RGBColor(31, 119, 180);
const ESTIMATE_COLOR: RGBColor = RGBColor(214, 39, 40);
const NOISE_COLOR: RGBColor = RGBColor(90, 90, 90);

/// Draws the three figures of `design` into `folder`; returns the files written.
pub fn draw(design: &Design, result: &DesignResult, folder: &Path) -> Result<Vec<PathBuf>, PlotError> {
    register_font();
    std::fs::create_dir_all(folder).map_err(|source| PlotError::Io {
        path: folder.to_owned(),
        source,
    })?;
    let run = &result.scenario;
    let time_label = with_unit("time", &design.time_unit);
    let times: Vec<f64> = (0..run.states.len()).map(|k| k as f64 * design.tau).collect();
    let mut files = Vec::new();

    // Measurements and noise.
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
    let mut panels = Vec::new();
    for (i, output) in design.model.outputs.iter().enumerate() {
        let label = with_unit(&output.name, &output.unit);
        let measured: Vec<(f64, f64)> = times.iter().zip(&run.measurements).map(|(&t, y)| (t, y[i])).collect();
        let exact: Vec<(f64, f64)> = times.iter().zip(&noise_free).map(|(&t, y)| (t, y[i])).collect();
        let noise: Vec<(f64, f64)> = measured.iter().zip(&exact).map(|(m, e)| (m.0, m.1 - e.1)).collect();
        panels.push(Panel {
            title: format!(
                "{}: measured {} (noise variance {})",
                design.name, output.name, output.noise_variance
            ),
            x_label: time_label.clone(),
            y_label: label.clone(),
            curves: vec![
                Curve {
                    label: "noise-free".into(),
                    points: exact,
                    color: TRUE_COLOR,
                    dots: false,
                },
                Curve {
                    label: "measured".into(),
                    points: measured,
                    color: ESTIMATE_COLOR,
                    dots: true,
                },
            ],
        });
        panels.push(Panel {
            title: format!("{}: noise on {}", design.name, output.name),
            x_label: time_label.clone(),
            y_label: with_unit(&format!("w ({})", output.name), &output.unit),
            curves: vec![Curve {
                label: "noise".into(),
                points: noise,
                color: NOISE_COLOR,
                dots: false,
            }],
        });
    }
    files.extend(write_figure(
        folder,
        "measurements",
        design.model.outputs.len(),
        2,
        &panels,
    )?);

    // Identification on the learning windows, and dΓ/dr.
    let learning: &DataSet = &result.learning;
    // A dot per window would make the SVG grow with n_E (184 MB at 10⁶ windows): every `stride`-th.
    let count = learning.windows().count();
    let stride = count.div_ceil(MAX_DOTS).max(1);
    let windows: Vec<Window> = learning.windows().step_by(stride).collect();
    let shown = if stride == 1 {
        format!("the n_E = {count} learning windows")
    } else {
        format!("every {stride}th of the n_E = {count} learning windows")
    };
    let mut z = Vec::new();
    let mut panels = Vec::new();
    let mut gradients = Vec::new();
    for t in &result.targets {
        let target = &design.targets[t.index];
        let map = &t.fit.map;
        let mut pairs = Vec::new();
        for &w in &windows {
            learning.regressor(w, &mut z);
            pairs.push((learning.target(w, t.index), map.estimate(&z).value));
        }
        let label = with_unit(&target.name, &target.unit);
        let diagonal = vec![(map.r_min, map.r_min), (map.r_max, map.r_max)];
        panels.push(Panel {
            title: format!("{}: {} on {shown}", design.name, target.name),
            x_label: format!("true {label}"),
            y_label: format!("identified {label}"),
            curves: vec![
                Curve {
                    label: "identified".into(),
                    points: pairs,
                    color: ESTIMATE_COLOR,
                    dots: true,
                },
                Curve {
                    label: "identified = true".into(),
                    points: diagonal,
                    color: TRUE_COLOR,
                    dots: false,
                },
            ],
        });
        let span = map.r_max - map.r_min;
        let gamma = map.gamma();
        let gradient: Vec<(f64, f64)> = (0..=400)
            .map(|i| i as f64 / 400.0)
            .map(|eta| (map.r_min + span * eta, gamma.slope(eta) / span))
            .collect();
        gradients.push(Panel {
            title: format!("{}: gradient of Γ for {}", design.name, target.name),
            x_label: label,
            y_label: "dΓ/dr".into(),
            curves: vec![Curve {
                label: "dΓ/dr".into(),
                points: gradient,
                color: TRUE_COLOR,
                dots: false,
            }],
        });
    }
    let columns = panels.len();
    panels.extend(gradients);
    files.extend(write_figure(folder, "identification", 2, columns, &panels)?);

    // Estimation along the scenario.
    let maps: Vec<_> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
    let rows: Vec<recording::Row> = run
        .measurements
        .iter()
        .zip(&run.inputs)
        .map(|(y, u)| recording::Row {
            run: String::new(),
            y: y.to_vec(),
            u: u.to_vec(),
        })
        .collect();
    let estimates = recording::estimate(&maps, design.map.horizon, &rows);
    let mut panels = Vec::new();
    for (i, t) in result.targets.iter().enumerate() {
        let target = &design.targets[t.index];
        let truth: Vec<(f64, f64)> = times
            .iter()
            .zip(&run.targets)
            .map(|(&time, r)| (time, r[t.index]))
            .collect();
        let estimate: Vec<(f64, f64)> = times
            .iter()
            .zip(&estimates)
            .filter_map(|(&time, e)| e[i].map(|(value, _)| (time, value)))
            .collect();
        panels.push(Panel {
            title: format!(
                "{}: estimating {} (first estimate at t = {})",
                design.name,
                target.name,
                (design.map.horizon - 1) as f64 * design.tau
            ),
            x_label: time_label.clone(),
            y_label: with_unit(&target.name, &target.unit),
            curves: vec![
                Curve {
                    label: "true".into(),
                    points: truth,
                    color: TRUE_COLOR,
                    dots: false,
                },
                Curve {
                    label: "estimate".into(),
                    points: estimate,
                    color: ESTIMATE_COLOR,
                    dots: true,
                },
            ],
        });
    }
    files.extend(write_figure(folder, "estimation", panels.len(), 1, &panels)?);
    Ok(files)
}
