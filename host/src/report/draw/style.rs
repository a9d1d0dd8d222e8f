//! How a series looks: the colours shared by every figure and the styles a series is drawn in, each
//! with its legend swatch drawn by the same rule, so that a legend always matches its data.

use plotters::coord::Shift;
use plotters::prelude::*;

/// Colours shared by the figures, so that "true" and "estimate" look the same everywhere.
pub(crate) const TRUE_COLOR: RGBColor = RGBColor(31, 119, 180);
/// The map's colour in its registry entry ([`crate::observers::kind::Kind::colour`]).
pub(crate) const ESTIMATE_COLOR: RGBColor = {
    let (r, g, b) = crate::observers::kind::REGISTRY[0].colour;
    RGBColor(r, g, b)
};
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
    pub(super) fn swatch<DB: DrawingBackend>(
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

pub(super) const DOT_RADIUS: i32 = 2;
pub(super) const RING_RADIUS: i32 = 5;
pub(super) const LINE_WIDTH: u32 = 2;
/// Dashed vertical marks are thinner than data, as their swatch is.
pub(super) const MARK_WIDTH: u32 = 1;
/// Solid vertical marks ([`Style::Rule`]).
pub(super) const RULE_WIDTH: u32 = 2;
