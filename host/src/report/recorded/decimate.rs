//! Decimation as the rows are read: each series keeps only what the figure can show (per column of
//! the time axis, a line's first, lowest, highest and last point; dots one per 2 × 2 px cell; marks
//! one per column), so memory and the SVG's size are bounded by the figure, not by the rows.

/// Width of a panel in pixels, and the number of columns the time axis is cut into for drawing:
/// the plotting area is narrower (axis labels and margins, and the axis pads the data by 5 %), so a
/// column is never wider than a pixel and what is left out of it cannot be seen.
pub(super) const PANEL_WIDTH: u32 = 900;
/// Height of a row of the figure in pixels (its plotting area is smaller).
pub(super) const ROW_HEIGHT: u32 = 320;
/// Columns of the time axis: one per pixel of a panel's width, at least one per pixel drawn.
pub(super) const COLUMNS: usize = PANEL_WIDTH as usize;
/// Dots are kept one per cell of this many columns by this many pixel rows: a dot is 5 px wide, so
/// every dot left out lies within 2 px of one drawn, and a dense cloud looks the same.
const DOT_CELL: usize = 2;
const DOT_CELLS_X: usize = COLUMNS / DOT_CELL + 1;
const DOT_CELLS_Y: usize = ROW_HEIGHT as usize / DOT_CELL + 1;
/// Above this many pieces a line is folded to one piece per column: with restarts or gaps by the
/// thousand a piece per stretch would grow with the rows, and memory and the SVG must not.
const MAX_PIECES: usize = 16 * COLUMNS;

pub(super) type Point = (f64, f64);

/// The time axis cut into [`COLUMNS`] equal columns, from the earliest time to the latest.
#[derive(Clone, Copy, Debug)]
pub(super) struct Grid {
    start: f64,
    per_unit: f64,
}

impl Grid {
    pub(super) fn new(times: Extent) -> Self {
        let span = times.high - times.low;
        Grid {
            start: times.low,
            per_unit: if span > 0.0 && span.is_finite() {
                COLUMNS as f64 / span
            } else {
                0.0
            },
        }
    }

    /// The column of time `t`, `None` for a time that is not a number (never drawn).
    pub(super) fn column(&self, t: f64) -> Option<usize> {
        t.is_finite()
            .then(|| (((t - self.start) * self.per_unit).max(0.0) as usize).min(COLUMNS - 1))
    }
}

/// The lowest and highest finite value seen.
#[derive(Clone, Copy, Debug)]
pub(super) struct Extent {
    low: f64,
    high: f64,
}

impl Default for Extent {
    fn default() -> Self {
        Extent {
            low: f64::INFINITY,
            high: f64::NEG_INFINITY,
        }
    }
}

impl Extent {
    pub(super) fn add(&mut self, v: f64) {
        if v.is_finite() {
            self.low = self.low.min(v);
            self.high = self.high.max(v);
        }
    }
}

/// The rows of one unbroken stretch of a line that fall in one column. A polyline through them
/// covers the same pixels as first → lowest and highest (in their order) → last, so these four
/// points draw the column as every row would.
#[derive(Clone, Copy, Debug)]
struct Piece {
    column: usize,
    first: Point,
    low: Point,
    high: Point,
    last: Point,
    /// The lowest point came before the highest.
    low_first: bool,
    /// The line continues from the previous piece (same run, no gap between).
    joined: bool,
}

impl Piece {
    fn new(column: usize, p: Point, joined: bool) -> Self {
        Piece {
            column,
            first: p,
            low: p,
            high: p,
            last: p,
            low_first: true,
            joined,
        }
    }

    fn add(&mut self, p: Point) {
        if p.1 < self.low.1 {
            self.low = p;
            self.low_first = false;
        }
        if p.1 > self.high.1 {
            self.high = p;
            self.low_first = true;
        }
        self.last = p;
    }

    /// Takes in a later piece of the same column.
    fn merge(&mut self, later: &Piece) {
        self.add(later.low);
        self.add(later.high);
        self.last = later.last;
    }

    fn points(&self, out: &mut Vec<Point>) {
        let (a, b) = if self.low_first {
            (self.low, self.high)
        } else {
            (self.high, self.low)
        };
        for p in [self.first, a, b, self.last] {
            if out.last() != Some(&p) {
                out.push(p);
            }
        }
    }
}

/// A line decimated as it is read: [`Piece`]s in row order, at most four points per column of each
/// unbroken stretch, however many rows; folded to one piece per column past [`MAX_PIECES`].
#[derive(Debug, Default)]
pub(super) struct Line {
    pieces: Vec<Piece>,
    /// Once folded: one piece per column, none joined to another.
    folded: Vec<Option<Piece>>,
    /// The next point starts a new stretch (after a missing value or a row without a time).
    gap: bool,
}

impl Line {
    /// The value `v` at time `t`; `restart`: this row starts a new run (the line breaks before it).
    pub(super) fn push(&mut self, grid: &Grid, t: f64, v: f64, restart: bool) {
        let joined = !(self.gap || restart);
        let Some(column) = grid.column(t).filter(|_| v.is_finite()) else {
            self.gap = true;
            return;
        };
        self.gap = false;
        let p = (t, v);
        if !self.folded.is_empty() {
            match &mut self.folded[column] {
                Some(piece) => piece.add(p),
                slot => *slot = Some(Piece::new(column, p, false)),
            }
            return;
        }
        match self.pieces.last_mut() {
            Some(last) if joined && last.column == column => last.add(p),
            _ => self.pieces.push(Piece::new(column, p, joined)),
        }
        if self.pieces.len() > MAX_PIECES {
            self.folded = vec![None; COLUMNS];
            for piece in std::mem::take(&mut self.pieces) {
                match &mut self.folded[piece.column] {
                    Some(folded) => folded.merge(&piece),
                    slot => *slot = Some(Piece { joined: false, ..piece }),
                }
            }
        }
    }

    /// The points to draw, a NaN point where the line breaks.
    pub(super) fn points(&self) -> Vec<Point> {
        let mut out = Vec::new();
        for piece in self.pieces.iter().chain(self.folded.iter().flatten()) {
            if !piece.joined && !out.is_empty() {
                out.push((f64::NAN, f64::NAN));
            }
            piece.points(&mut out);
        }
        out
    }
}

/// Dots thinned as they are read: the first of each cell of [`DOT_CELL`] columns by [`DOT_CELL`]
/// pixel rows, the rows over the series' own values (the panel's axis holds them, so its cells are
/// no larger). Dots of neighbouring cells of a column touch; a run of them is drawn as a band as
/// wide as a dot between its end dots ([`Dots::finish`]): a signal that sweeps its range in every
/// column would otherwise still draw a dot per cell (218,000 dots, 19 MB of SVG at 10⁶ rows).
#[derive(Debug)]
pub(super) struct Dots {
    /// Per cell, the index of its dot in `points`, or `u32::MAX`.
    cells: Vec<u32>,
    low: f64,
    per_unit: f64,
    points: Vec<Point>,
}

impl Dots {
    pub(super) fn new(values: Extent) -> Self {
        let span = values.high - values.low;
        Dots {
            cells: vec![u32::MAX; DOT_CELLS_X * DOT_CELLS_Y],
            low: values.low,
            per_unit: if span > 0.0 && span.is_finite() {
                (DOT_CELLS_Y - 1) as f64 / span
            } else {
                0.0
            },
            points: Vec::new(),
        }
    }

    pub(super) fn push(&mut self, grid: &Grid, t: f64, v: f64) {
        let Some(column) = grid.column(t).filter(|_| v.is_finite()) else {
            return;
        };
        let row = (((v - self.low) * self.per_unit).max(0.0) as usize).min(DOT_CELLS_Y - 1);
        let cell = column / DOT_CELL * DOT_CELLS_Y + row;
        if self.cells[cell] == u32::MAX {
            // At most DOT_CELLS_X × DOT_CELLS_Y (72,611) points: an index fits.
            self.cells[cell] = self.points.len() as u32;
            self.points.push((t, v));
        }
    }

    /// The dots to draw and the bands `(x, low, high)`: per column of cells, a lone dot as itself,
    /// a run of neighbouring ones as a band at its lowest dot's time between its end dots.
    pub(super) fn finish(&self) -> (Vec<Point>, Vec<(f64, f64, f64)>) {
        let (mut dots, mut bands) = (Vec::new(), Vec::new());
        for column in self.cells.chunks(DOT_CELLS_Y) {
            let mut run: Option<(Point, Point)> = None;
            for cell in column.iter().chain([&u32::MAX]) {
                match (self.points.get(*cell as usize), &mut run) {
                    (Some(&p), Some((_, last))) => *last = p,
                    (Some(&p), None) => run = Some((p, p)),
                    (None, _) => {
                        if let Some((first, last)) = run.take() {
                            dots.push(first);
                            if last != first {
                                dots.push(last);
                                bands.push((first.0, first.1, last.1));
                            }
                        }
                    }
                }
            }
        }
        (dots, bands)
    }
}

/// The first of a kind of mark in each column: a second one in a column would cover the same pixels.
#[derive(Debug)]
pub(super) struct PerColumn<T>(Vec<Option<T>>);

impl<T: Copy> PerColumn<T> {
    pub(super) fn new() -> Self {
        PerColumn(vec![None; COLUMNS])
    }

    pub(super) fn put(&mut self, column: Option<usize>, value: T) {
        if let Some(c) = column {
            self.0[c].get_or_insert(value);
        }
    }

    pub(super) fn values(&self) -> Vec<T> {
        self.0.iter().flatten().copied().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic noise in [0, 1) for row `k` (a multiplicative hash; the test's own truth).
    fn noise(k: usize) -> f64 {
        ((k as u64).wrapping_mul(6_364_136_223_846_793_005) >> 40) as f64 / (1u64 << 24) as f64
    }
    #[test]
    fn a_line_of_thousands_of_runs_is_folded_and_still_covers_every_row() {
        const ROWS: usize = 60_000;
        let grid = Grid::new(Extent {
            low: 0.0,
            high: (ROWS - 1) as f64,
        });
        let value = |k: usize| noise(k);
        let mut line = Line::default();
        for k in 0..ROWS {
            // A run of three rows, then a restart: 20,000 stretches, more than 16 per column.
            line.push(&grid, k as f64, value(k), k % 3 == 0);
        }
        assert!(!line.folded.is_empty(), "folded");
        let points = line.points();
        // A column's piece is at most four points and a break.
        assert!(points.len() <= 5 * COLUMNS, "{} points", points.len());
        // Seen at the width of a column (66.7 rows), the drawn values span every row's value.
        let mut drawn: Vec<(f64, f64)> = points.iter().copied().filter(|p| p.0.is_finite()).collect();
        drawn.sort_by(|a, b| a.0.total_cmp(&b.0));
        let width = (ROWS - 1) as f64 / COLUMNS as f64;
        for k in 0..ROWS {
            let (t, v) = (k as f64, value(k));
            let from = drawn.partition_point(|p| p.0 < t - width);
            let near = drawn[from..].iter().take_while(|p| p.0 <= t + width);
            let (below, above) = near.fold((false, false), |(b, a), p| (b || p.1 <= v, a || p.1 >= v));
            assert!(below && above, "row {k}");
        }
    }
}
