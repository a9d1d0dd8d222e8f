//! A panel drawn with plotters: its axes (padded ranges, short tick labels), its series (lines split
//! at sharp turns, dots, rings, bands, vertical marks) and its legend in the margin beside it.

use std::ops::Range;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::panel::Panel;
use super::style::{Style, DOT_RADIUS, LINE_WIDTH, MARK_WIDTH, RING_RADIUS, RULE_WIDTH};
use super::{Figure, FONT};

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
pub(super) fn legend_width(figure: &Figure) -> u32 {
    let longest = figure
        .rows
        .iter()
        .flatten()
        .flat_map(|p| p.entries().map(|(label, _, _)| label.chars().count()))
        .max()
        .unwrap_or(0);
    (48.0 + LEGEND_CHAR * longest as f64).ceil().max(120.0) as u32
}

pub(super) fn draw_panel<DB: DrawingBackend>(
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

#[cfg(test)]
mod tests {
    use super::super::{Series, TRUE_COLOR};
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
