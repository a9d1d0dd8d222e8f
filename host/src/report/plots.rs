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
use crate::observers::Comparison;
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

/// One panel: a title, axis descriptions, its curves and vertical marks (a time and what happens
/// there, drawn as a dashed line across the panel).
struct Panel {
    title: String,
    x_label: String,
    y_label: String,
    curves: Vec<Curve>,
    marks: Vec<(f64, String)>,
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
    let x = range(all().map(|p| p.0).chain(panel.marks.iter().map(|m| m.0)));
    let y = range(all().map(|p| p.1));
    let mut chart = ChartBuilder::on(area)
        .caption(&panel.title, (FONT, 18))
        .margin(12)
        .margin_right(12 + LEGEND_WIDTH as u32)
        .x_label_area_size(42)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y.clone())
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
        // A NaN (no estimate yet) would break a line: draw only the finite points.
        let points = curve
            .points
            .iter()
            .copied()
            .filter(|p| p.0.is_finite() && p.1.is_finite());
        if curve.dots {
            chart.draw_series(points.map(move |p| Circle::new(p, 2, color.filled())))
        } else {
            chart.draw_series(LineSeries::new(points, color.stroke_width(2)))
        }
        .map_err(|e| e.to_string())?;
    }
    for (at, _) in &panel.marks {
        let (bottom, top) = (y.start, y.end);
        let dashes = 24;
        let step = (top - bottom) / (2 * dashes) as f64;
        chart
            .draw_series((0..dashes).map(|i| {
                let from = bottom + 2.0 * i as f64 * step;
                PathElement::new(vec![(*at, from), (*at, from + step)], MARK_COLOR.stroke_width(1))
            }))
            .map_err(|e| e.to_string())?;
    }
    // The legend goes in the right margin, beside the plotting area, so that it never covers data;
    // each swatch is drawn as its series is (dots, line, dashes).
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let (base_x, base_y) = area.get_base_pixel();
    let (left, top) = (xs.end - base_x + 12, ys.start - base_y);
    let entries = panel
        .curves
        .iter()
        .map(|c| {
            (
                c.label.as_str(),
                c.color,
                if c.dots { Swatch::Dots } else { Swatch::Line },
            )
        })
        .chain(
            panel
                .marks
                .iter()
                .map(|(_, label)| (label.as_str(), MARK_COLOR, Swatch::Dashes)),
        );
    for (i, (label, color, swatch)) in entries.enumerate() {
        let y = top + 10 + 20 * i as i32;
        let drawn = match swatch {
            Swatch::Dots => area.draw(&Circle::new((left + 11, y), 3, color.filled())),
            Swatch::Line => area.draw(&PathElement::new(
                vec![(left, y), (left + 22, y)],
                color.stroke_width(3),
            )),
            Swatch::Dashes => (0..3).try_for_each(|d| {
                area.draw(&PathElement::new(
                    vec![(left + 9 * d, y), (left + 9 * d + 5, y)],
                    color.stroke_width(1),
                ))
            }),
        };
        drawn.map_err(|e| e.to_string())?;
        area.draw(&Text::new(
            label.to_owned(),
            (left + 30, y - 7),
            (FONT, 13).into_font().color(&BLACK),
        ))
        .map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// How a legend entry shows its series.
#[derive(Clone, Copy)]
enum Swatch {
    Dots,
    Line,
    Dashes,
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

/// Pixels right of each panel's plotting area kept for its legend.
const LEGEND_WIDTH: i32 = 230;

/// Writes `<stem>.png` and `<stem>.svg` in `folder`, each through a temporary file.
fn write_figure(
    folder: &Path,
    stem: &str,
    rows: usize,
    columns: usize,
    panels: &[Panel],
) -> Result<Vec<PathBuf>, PlotError> {
    let size = ((560 + LEGEND_WIDTH as u32) * columns as u32, 380 * rows as u32);
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
const MARK_COLOR: RGBColor = RGBColor(60, 60, 60);

/// Each observer kind's colour and whether it is drawn as dots, in the estimation figures.
fn kind_style(kind: &str) -> (RGBColor, bool, &'static str) {
    match kind {
        "map" => (ESTIMATE_COLOR, true, "map F(Z)"),
        "ekf" => (RGBColor(255, 127, 14), false, "EKF from x̂(0)"),
        "corrected" => (RGBColor(44, 160, 44), false, "model-corrected map"),
        _ => (RGBColor(148, 103, 189), false, "EKF started by the map"),
    }
}

/// Draws the figures of `design` into `folder`; returns the files written.
pub fn draw(
    design: &Design,
    result: &DesignResult,
    comparison: &Comparison,
    folder: &Path,
) -> Result<Vec<PathBuf>, PlotError> {
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
            marks: Vec::new(),
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
            marks: Vec::new(),
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
            marks: Vec::new(),
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
            marks: Vec::new(),
        });
    }
    let columns = panels.len();
    panels.extend(gradients);
    files.extend(write_figure(folder, "identification", 2, columns, &panels)?);

    // Estimation along the scenario, every observer, and on the mismatch plant.
    files.extend(estimation(design, comparison, run, false, folder)?);
    if let Some(m) = &comparison.mismatch {
        files.extend(estimation(design, comparison, &m.scenario, true, folder)?);
    }
    Ok(files)
}

/// The `estimation` figure (or `estimation_mismatch`, on the plant at the last corner of the uncertain
/// parameters): per target, every observer's estimate against the truth along `run`, with the first
/// estimate and the end of the start-up (`START_UP_HORIZONS · N` estimates later) marked.
fn estimation(
    design: &Design,
    comparison: &Comparison,
    run: &crate::data::Run,
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
        let mut curves = vec![Curve {
            label: "true".into(),
            points: times.iter().zip(&run.targets).map(|(&t, r)| (t, r[index])).collect(),
            color: TRUE_COLOR,
            dots: false,
        }];
        for o in &comparison.observers {
            let rows = if on_mismatch {
                o.mismatch_scenario.as_ref()
            } else {
                Some(&o.scenario)
            };
            let Some(rows) = rows else { continue };
            let (color, dots, label) = kind_style(o.kind);
            curves.push(Curve {
                label: label.into(),
                points: times.iter().zip(rows.iter()).map(|(&t, e)| (t, e[index])).collect(),
                color,
                dots,
            });
        }
        panels.push(Panel {
            title: format!("{}: estimating {}{plant}", design.name, target.name),
            x_label: with_unit("time", &design.time_unit),
            y_label: with_unit(&target.name, &target.unit),
            curves,
            marks: vec![
                (first, format!("first estimate (t = {})", tick(&first))),
                (start_up, format!("end of start-up (t = {})", tick(&start_up))),
            ],
        });
    }
    let stem = if on_mismatch {
        "estimation_mismatch"
    } else {
        "estimation"
    };
    write_figure(folder, stem, panels.len(), 1, &panels)
}

/// `search.png`/`.svg`: the design search's trade-off in two projections, the tuning score against
/// the predicted instructions per sample and against the delay to the first estimate. Every fitted
/// candidate is a grey dot, the Pareto front is drawn over them, the chosen candidate in red.
pub fn draw_search(
    design: &Design,
    outcome: &crate::search::Outcome,
    folder: &Path,
) -> Result<Vec<PathBuf>, PlotError> {
    register_font();
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
        Panel {
            title: format!(
                "{}: design search ({} candidates)",
                design.name,
                outcome.candidates.len()
            ),
            x_label,
            y_label: "tuning score (mean RMSE / spread)".to_owned(),
            curves: vec![
                Curve {
                    label: "candidate".to_owned(),
                    points: fitted.iter().map(|c| point(c, x)).collect(),
                    color: RGBColor(170, 170, 170),
                    dots: true,
                },
                Curve {
                    label: "best at this cost".to_owned(),
                    points: envelope,
                    color: RGBColor(31, 119, 180),
                    dots: false,
                },
                Curve {
                    label: format!(
                        "chosen: N = {}, n_m = {}, β = {}",
                        outcome.chosen().horizon,
                        outcome.chosen().nm,
                        outcome.chosen().beta
                    ),
                    points: vec![point(outcome.chosen(), x)],
                    color: RGBColor(214, 39, 40),
                    dots: true,
                },
            ],
            marks: Vec::new(),
        }
    };
    let panels = [
        panel("predicted instructions per sample (map)".to_owned(), |c| c.instructions),
        panel(with_unit("delay to the first estimate", &design.time_unit), |c| {
            c.first_estimate
        }),
    ];
    write_figure(folder, "search", 1, 2, &panels)
}
