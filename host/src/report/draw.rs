//! The one drawing stack of every figure (the design's report and `plot` of recorded data): panels
//! of series laid out in rows, one series style ([`Style`]: how a series is drawn and its legend
//! swatch, from the same code) and one legend placement ([`legend`]: beside the plotting area, so it
//! never covers data), written as PNG and SVG (plotters; the bundled DejaVu Sans font is rasterised by
//! ab_glyph, so no system font library is involved).

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Once;

use plotters::coord::Shift;
use plotters::prelude::*;

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

/// Colours shared by the figures, so that "true" and "estimate" look the same everywhere.
pub(crate) const TRUE_COLOR: RGBColor = RGBColor(31, 119, 180);
pub(crate) const ESTIMATE_COLOR: RGBColor = RGBColor(214, 39, 40);
pub(crate) const NOISE_COLOR: RGBColor = RGBColor(90, 90, 90);
pub(crate) const MARK_COLOR: RGBColor = RGBColor(60, 60, 60);
/// Saturated estimates: a black ring around the estimate's own marker.
pub(crate) const SATURATED_COLOR: RGBColor = RGBColor(0, 0, 0);
/// Refused samples (NaN or infinite): a light red line across the panel.
pub(crate) const REFUSED_COLOR: RGBColor = RGBColor(240, 150, 150);
/// Further signals (outputs, inputs) in one panel, in this order.
pub(crate) const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(23, 190, 207),
];

/// How a series is drawn; its legend swatch is drawn by the same rule, so they always match.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Style {
    /// A line through the points, broken where a point is not finite (no estimate, a refused sample).
    Line,
    /// A filled dot per point.
    Dots,
    /// A hollow ring per point, drawn over another series' dots to mark them (saturated estimates).
    Rings,
    /// A dashed line (vertical marks only).
    Dashes,
    /// A thin solid line (vertical marks only).
    Rule,
}

impl Style {
    /// The legend swatch of a series of this style, centred vertically on `y` from `left`.
    fn swatch<DB: DrawingBackend>(
        self,
        area: &DrawingArea<DB, Shift>,
        (left, y): (i32, i32),
        color: RGBColor,
    ) -> Result<(), String> {
        match self {
            Style::Dots => area.draw(&Circle::new((left + 11, y), DOT_RADIUS + 1, color.filled())),
            Style::Rings => area.draw(&Circle::new((left + 11, y), RING_RADIUS, color.stroke_width(1))),
            Style::Line => area.draw(&PathElement::new(
                vec![(left, y), (left + 22, y)],
                color.stroke_width(LINE_WIDTH + 1),
            )),
            Style::Rule => area.draw(&PathElement::new(
                vec![(left, y), (left + 22, y)],
                color.stroke_width(RULE_WIDTH),
            )),
            Style::Dashes => (0..3).try_for_each(|d| {
                area.draw(&PathElement::new(
                    vec![(left + 9 * d, y), (left + 9 * d + 5, y)],
                    color.stroke_width(1),
                ))
            }),
        }
        .map_err(|e| e.to_string())
    }
}

const DOT_RADIUS: i32 = 2;
const RING_RADIUS: i32 = 5;
const LINE_WIDTH: u32 = 2;
/// Dashed vertical marks are thinner than data, as their swatch is.
const MARK_WIDTH: u32 = 1;
/// Solid vertical marks ([`Style::Rule`]).
const RULE_WIDTH: u32 = 2;

/// One series of a panel.
pub(crate) struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub color: RGBColor,
    pub style: Style,
    /// Dots only: vertical bands `(x, low, high)` as wide as a dot, standing for a column of dots
    /// that touch one another (one element instead of hundreds; their end dots are in `points`).
    pub bands: Vec<(f64, f64, f64)>,
}

impl Series {
    pub(crate) fn new(label: impl Into<String>, points: Vec<(f64, f64)>, color: RGBColor, style: Style) -> Self {
        Series {
            label: label.into(),
            points,
            color,
            style,
            bands: Vec::new(),
        }
    }

    /// With `bands` (see [`Series::bands`]).
    pub(crate) fn with_bands(mut self, bands: Vec<(f64, f64, f64)>) -> Self {
        self.bands = bands;
        self
    }
}

/// Vertical lines across a panel at the given abscissae, one legend entry for all of them.
pub(crate) struct Marks {
    pub label: String,
    pub at: Vec<f64>,
    pub color: RGBColor,
    pub style: Style,
}

/// One panel: a title, axis descriptions, its series and marks.
pub(crate) struct Panel {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    pub marks: Vec<Marks>,
    /// The value axis reaches 0 (a positive quantity whose size matters, such as `dΓ/dr`).
    pub y_from_zero: bool,
}

impl Panel {
    pub(crate) fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
        Panel {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            marks: Vec::new(),
            y_from_zero: false,
        }
    }

    /// Adds a series.
    pub(crate) fn with(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// Adds marks (none when `at` is empty, and then no legend entry either).
    pub(crate) fn marked(mut self, label: impl Into<String>, at: Vec<f64>, color: RGBColor, style: Style) -> Self {
        if !at.is_empty() {
            self.marks.push(Marks {
                label: label.into(),
                at,
                color,
                style,
            });
        }
        self
    }

    /// Legend entries: every series with a point, then every mark.
    fn entries(&self) -> impl Iterator<Item = (&str, RGBColor, Style)> {
        self.series
            .iter()
            .filter(|s| s.points.iter().any(|p| p.0.is_finite() && p.1.is_finite()))
            .map(|s| (s.label.as_str(), s.color, s.style))
            .chain(self.marks.iter().map(|m| (m.label.as_str(), m.color, m.style)))
    }
}

/// `name [unit]`, or `name` without a unit.
pub(crate) fn with_unit(name: &str, unit: &str) -> String {
    if unit.is_empty() {
        name.to_owned()
    } else {
        format!("{name} [{unit}]")
    }
}

/// The axis range of `values` (finite ones), padded.
fn range(values: impl Iterator<Item = f64>, from_zero: bool) -> Range<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .chain(from_zero.then_some(0.0))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    if !(lo.is_finite() && hi.is_finite()) {
        return 0.0..1.0;
    }
    // Pad by 5 % of the spread, and by at least 2 % of the magnitude so that a flat curve looks flat.
    let pad = (0.05 * (hi - lo)).max(0.02 * lo.abs().max(hi.abs())).max(1e-12);
    let lo = if from_zero && lo >= 0.0 { 0.0 } else { lo - pad };
    lo..(hi + pad)
}

/// Tick labels: fixed-point for ordinary magnitudes, scientific for tiny or huge ones, without
/// trailing zeros.
pub(crate) fn tick(value: &f64) -> String {
    let magnitude = value.abs();
    let trim = |text: &str| text.trim_end_matches('0').trim_end_matches('.').to_owned();
    if magnitude < 1e-12 {
        "0".to_owned() // a tick at zero computed with rounding noise
    } else if !(1e-2..1e4).contains(&magnitude) {
        let text = format!("{value:.3e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        format!("{}e{exponent}", trim(mantissa))
    } else {
        trim(&format!("{value:.4}"))
    }
}

/// Draws `points` as `style`, `color`. Lines break at non-finite points; a point with a non-finite
/// coordinate is never drawn.
fn draw_series<DB: DrawingBackend>(
    chart: &mut ChartContext<
        '_,
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    points: &[(f64, f64)],
    color: RGBColor,
    style: Style,
    width: u32,
) -> Result<(), String> {
    let finite = |p: &&(f64, f64)| p.0.is_finite() && p.1.is_finite();
    match style {
        Style::Dots => chart
            .draw_series(
                points
                    .iter()
                    .filter(finite)
                    .map(|&p| Circle::new(p, DOT_RADIUS, color.filled())),
            )
            .map(drop),
        Style::Rings => chart
            .draw_series(
                points
                    .iter()
                    .filter(finite)
                    .map(|&p| Circle::new(p, RING_RADIUS, color.stroke_width(1))),
            )
            .map(drop),
        Style::Line | Style::Dashes | Style::Rule => points
            .split(|p| !(p.0.is_finite() && p.1.is_finite()))
            .filter(|piece| !piece.is_empty())
            .try_for_each(|piece| {
                let pixels: Vec<(i32, i32)> = piece.iter().map(|p| chart.backend_coord(p)).collect();
                let mut start = 0;
                for end in sharp_turns(&pixels).chain([piece.len() - 1]) {
                    let part = &piece[start..=end];
                    chart
                        .draw_series(LineSeries::new(part.iter().copied(), color.stroke_width(width)))
                        .map(drop)?;
                    start = end;
                }
                Ok(())
            }),
    }
    .map_err(|e| e.to_string())
}

/// The vertices of a path (in pixels) where it turns by more than a right angle. plotters fills a
/// wide line as one polygon, and at such a turn its inner corner lies far from the vertex (at a
/// hairpin, as a decimated signal goes down and up within a pixel column, across the figure), so
/// the path is drawn in parts that meet there.
fn sharp_turns(pixels: &[(i32, i32)]) -> impl Iterator<Item = usize> + '_ {
    // Each vertex against the next pixel the path moves to (repeated pixels are no move).
    (1..pixels.len()).filter(move |&i| {
        let step = |a: (i32, i32), b: (i32, i32)| (i64::from(b.0 - a.0), i64::from(b.1 - a.1));
        let here = step(pixels[i - 1], pixels[i]);
        if here == (0, 0) {
            return false;
        }
        let Some(next) = pixels[i + 1..]
            .iter()
            .map(|&p| step(pixels[i], p))
            .find(|s| *s != (0, 0))
        else {
            return false;
        };
        here.0 * next.0 + here.1 * next.1 < 0
    })
}

/// The legend of a panel: one entry per line from `(left, top)`, each swatch drawn by its series'
/// [`Style`]. Every figure places it in the margin right of the plotting area ([`legend_width`]
/// wide), so it never covers data, whatever the data.
fn legend<'a, DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (left, top): (i32, i32),
    entries: impl Iterator<Item = (&'a str, RGBColor, Style)>,
) -> Result<(), String> {
    for (i, (label, color, style)) in entries.enumerate() {
        let y = top + 10 + LEGEND_LINE * i as i32;
        style.swatch(area, (left, y), color)?;
        area.draw(&Text::new(
            label.to_owned(),
            (left + 30, y - 7),
            (FONT, 13).into_font().color(&BLACK),
        ))
        .map_err(|e| e.to_string())?;
    }
    Ok(())
}

const LEGEND_LINE: i32 = 20;
/// Width of a character of the legend's 13 px font, generously (DejaVu Sans averages about 7 px).
const LEGEND_CHAR: f64 = 7.2;

/// Pixels right of each plotting area kept for the legends of `figure`: its longest label fits.
fn legend_width(figure: &Figure) -> u32 {
    let longest = figure
        .rows
        .iter()
        .flatten()
        .flat_map(|p| p.entries().map(|(label, _, _)| label.chars().count()))
        .max()
        .unwrap_or(0);
    (48.0 + LEGEND_CHAR * longest as f64).ceil().max(120.0) as u32
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    legend_width: u32,
) -> Result<(), String> {
    let all = || panel.series.iter().flat_map(|s| s.points.iter());
    let x = range(
        all()
            .map(|p| p.0)
            .chain(panel.marks.iter().flat_map(|m| m.at.iter().copied())),
        false,
    );
    let y = range(all().map(|p| p.1), panel.y_from_zero);
    let mut chart = ChartBuilder::on(area)
        .caption(&panel.title, (FONT, 18))
        .margin(12)
        .margin_right(12 + legend_width)
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
    for mark in &panel.marks {
        for &at in &mark.at {
            let line = match mark.style {
                Style::Dashes => {
                    // Vertical dashes: pieces separated by non-finite points break the line.
                    let dashes = 24;
                    let step = (y.end - y.start) / (2 * dashes) as f64;
                    (0..dashes)
                        .flat_map(|i| {
                            let from = y.start + 2.0 * i as f64 * step;
                            [(at, from), (at, from + step), (f64::NAN, f64::NAN)]
                        })
                        .collect()
                }
                _ => vec![(at, y.start), (at, y.end)],
            };
            let width = if mark.style == Style::Dashes {
                MARK_WIDTH
            } else {
                RULE_WIDTH
            };
            draw_series(&mut chart, &line, mark.color, Style::Line, width)?;
        }
    }
    for series in &panel.series {
        for &(x, low, high) in &series.bands {
            let band = [(x, low), (x, high)];
            draw_series(&mut chart, &band, series.color, Style::Line, 2 * DOT_RADIUS as u32)?;
        }
        draw_series(&mut chart, &series.points, series.color, series.style, LINE_WIDTH)?;
    }
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let (base_x, base_y) = area.get_base_pixel();
    legend(area, (xs.end - base_x + 12, ys.start - base_y), panel.entries())
}

/// A figure: rows of panels, each row split evenly among its panels (a row of one spans the width).
pub(crate) struct Figure {
    pub rows: Vec<Vec<Panel>>,
    /// Width of a panel's plotting part in a row of one (legend excluded), in pixels.
    pub panel_width: u32,
    /// Height of a row, in pixels.
    pub row_height: u32,
}

impl Figure {
    /// Rows of `per_row` panels (the last may hold fewer), each panel 560 × 380 px before its legend.
    pub(crate) fn grid(panels: Vec<Panel>, per_row: usize) -> Self {
        let mut rows: Vec<Vec<Panel>> = Vec::new();
        for panel in panels {
            match rows.last_mut() {
                Some(row) if row.len() < per_row.max(1) => row.push(panel),
                _ => rows.push(vec![panel]),
            }
        }
        Figure {
            rows,
            panel_width: 560,
            row_height: 380,
        }
    }

    fn size(&self, legend_width: u32) -> (u32, u32) {
        let columns = self.rows.iter().map(Vec::len).max().unwrap_or(1).max(1) as u32;
        (
            (self.panel_width + legend_width) * columns,
            self.row_height * self.rows.len().max(1) as u32,
        )
    }

    fn draw<DB: DrawingBackend>(&self, root: DrawingArea<DB, Shift>, legend_width: u32) -> Result<(), String> {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        for (row_area, row) in root.split_evenly((self.rows.len().max(1), 1)).iter().zip(&self.rows) {
            for (area, panel) in row_area.split_evenly((1, row.len().max(1))).iter().zip(row) {
                draw_panel(area, panel, legend_width)?;
            }
        }
        root.present().map_err(|e| e.to_string())
    }
}

/// Writes `figure` as `<prefix>.png` and `<prefix>.svg`. Both are drawn before either replaces a file
/// (the PNG through a temporary file beside it, the SVG in memory), so a failure to draw writes
/// nothing.
pub(crate) fn write_figure(prefix: &Path, figure: &Figure) -> Result<Vec<PathBuf>, PlotError> {
    register_font();
    let legend_width = legend_width(figure);
    let size = figure.size(legend_width);
    let stem = prefix
        .file_name()
        .map_or(String::new(), |n| n.to_string_lossy().into_owned());
    let folder = match prefix.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_owned(),
        _ => PathBuf::from("."),
    };
    let (png, svg) = (with_suffix(prefix, "png"), with_suffix(prefix, "svg"));
    let mut svg_text = String::new();
    figure
        .draw(
            SVGBackend::with_string(&mut svg_text, size).into_drawing_area(),
            legend_width,
        )
        .map_err(|message| PlotError::Draw {
            file: svg.clone(),
            message,
        })?;
    crate::output::remove_stale_temporaries(&folder, &format!(".{stem}.tmp"), ".png");
    let temporary = folder.join(format!(".{stem}.tmp{}.png", std::process::id()));
    let drawn = figure
        .draw(BitMapBackend::new(&temporary, size).into_drawing_area(), legend_width)
        .map_err(|message| PlotError::Draw {
            file: png.clone(),
            message,
        });
    let written = drawn.and_then(|()| {
        crate::output::write_atomically(&svg, svg_text.as_bytes()).map_err(|source| PlotError::Io {
            path: svg.clone(),
            source,
        })?;
        std::fs::rename(&temporary, &png).map_err(|source| PlotError::Io {
            path: png.clone(),
            source,
        })
    });
    if written.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    written?;
    Ok(vec![png, svg])
}

/// `<prefix>.<extension>` (`with_extension` would replace a dot already in the prefix's name).
pub(crate) fn with_suffix(prefix: &Path, extension: &str) -> PathBuf {
    let mut name = prefix.as_os_str().to_owned();
    name.push(format!(".{extension}"));
    PathBuf::from(name)
}

/// Every `stride`-th of `count` items so that at most `most` are drawn (a dot per window would make
/// an SVG grow with the data: 184 MB at 10⁶ windows), and how to say so.
pub(crate) fn thinning(count: usize, most: usize) -> usize {
    count.div_ceil(most.max(1)).max(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_short_and_exact() {
        assert_eq!(tick(&0.5), "0.5");
        assert_eq!(tick(&2.0), "2");
        assert_eq!(tick(&9.0e-3), "9e-3");
        assert_eq!(tick(&1.085e-3), "1.085e-3");
        assert_eq!(tick(&-2.5e5), "-2.5e5");
        assert_eq!(tick(&1e-15), "0");
    }

    #[test]
    fn a_positive_axis_from_zero_starts_at_zero() {
        // A constant slope of 1.07e-3 must not fill a ±2 % axis when the panel asks for zero.
        let r = range([1.07e-3, 1.07e-3].into_iter(), true);
        assert_eq!(r.start, 0.0);
        assert!(r.end > 1.07e-3 && r.end < 1.2e-3);
        let flat = range([1.07e-3, 1.07e-3].into_iter(), false);
        assert!(flat.start > 1.0e-3);
    }

    #[test]
    fn a_path_is_split_where_it_turns_back_and_nowhere_else() {
        // Down a pixel column, up again, then on to the next column (a decimated signal).
        let hairpin = [(10, 50), (10, 200), (10, 200), (10, 80), (11, 70), (12, 60)];
        assert_eq!(sharp_turns(&hairpin).collect::<Vec<_>>(), [1]);
        // A smooth curve and a right angle are drawn whole.
        let smooth = [(0, 0), (10, 5), (20, 8), (30, 8), (40, 5), (50, 0)];
        assert_eq!(sharp_turns(&smooth).count(), 0);
        assert_eq!(sharp_turns(&[(0, 0), (10, 0), (10, 10)]).count(), 0);
    }

    #[test]
    fn legends_are_wide_enough_for_their_longest_label() {
        let label = "a label of exactly thirty-two ch";
        let figure = Figure::grid(
            vec![Panel::new("t", "x", "y").with(Series::new(label, vec![(0.0, 1.0)], TRUE_COLOR, Style::Line))],
            1,
        );
        assert!(legend_width(&figure) as f64 >= 30.0 + 32.0 * 7.0);
        // A series with no finite point has no entry (nothing of it is drawn).
        let empty = Figure::grid(
            vec![Panel::new("t", "x", "y").with(Series::new(label, vec![(0.0, f64::NAN)], TRUE_COLOR, Style::Line))],
            1,
        );
        assert_eq!(legend_width(&empty), 120);
    }
}
