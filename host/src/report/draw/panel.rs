//! What a figure holds before it is drawn: panels of series and marks with their titles and axis
//! descriptions, built by the report's figures and by `plot`.

use plotters::style::RGBColor;

use super::style::Style;

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
    pub(super) fn entries(&self) -> impl Iterator<Item = (&str, RGBColor, Style)> {
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
