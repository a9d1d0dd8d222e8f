//! `plot`: a recorded run and its estimates (what `estimate` writes) in one figure, the paper's
//! Fig. 2 (right) for recorded data, drawn by the report's drawing module (`draw`) as PNG and SVG.
//!
//! Per target, a panel of the estimates against the truth when the input holds it (a column
//! `truth_<target>`, else one named after the target, as `simulate` writes the states); then, with
//! the design, a panel per output and per input by the design's names; without it, one panel of the
//! input's other numeric columns ("recorded signals"). Every panel marks the refused samples
//! (`status` = `refused`) and the restarts (a change of `run`); saturated estimates are ringed.
//!
//! The estimates file: a header `time`, `run` (only if the input had one), `status` (`ok`,
//! `refused`, `no_estimate_yet`), one column per target, one `saturated_<target>` per target (`-1`,
//! `0`, `1`); target and saturation cells are empty unless the status is `ok`. It has one row per
//! row of the input, and its `time` is the input's `time` (or `t`) cell when there is one, which is
//! checked cell by cell, so that estimates of another recording are refused.
//!
//! Neither file is held: both are read row by row, twice (first to check every row and find the
//! time axis, then to keep what is drawn), and each series keeps only what the figure can show. The
//! time axis is cut into one column per pixel of the panel's width; a line keeps, per column of each
//! unbroken stretch, its first, lowest, highest and last point (through which a polyline covers the
//! same pixels as through every point); dots keep one per 2 × 2 px cell, a column of touching ones
//! drawn as one band; refusal and restart marks
//! and saturation rings of each kind one per column. So memory and the SVG's size are bounded by the
//! figure's size, not the rows (10⁶ rows drew a 291 MB SVG and held 956 MB). Lines still break
//! between runs and at missing values; past 16 pieces per column (restarts or gaps by the thousand)
//! a line is folded to one piece per column, each drawn on its own.

use std::path::{Path, PathBuf};

use super::draw::{
    with_suffix, with_unit, write_figure, Figure, Panel, PlotError, Series, Style, ESTIMATE_COLOR, MARK_COLOR, PALETTE,
    REFUSED_COLOR, SATURATED_COLOR, TRUE_COLOR,
};
use crate::spec::Design;

/// Why `plot` could not draw. Nothing is written when this happens.
#[derive(Debug, thiserror::Error)]
pub enum RecordedPlotError {
    /// The file cannot be read or parsed as CSV.
    #[error("{}: {message}", file.display())]
    Csv {
        /// The file.
        file: PathBuf,
        /// What went wrong.
        message: String,
    },
    /// A column the figure needs is not in the header.
    #[error("{}: no column `{column}` in the header (found: {found})\n  fix: {fix}", file.display())]
    MissingColumn {
        /// The file.
        file: PathBuf,
        /// The column.
        column: String,
        /// The header.
        found: String,
        /// What to do.
        fix: String,
    },
    /// A cell that is drawn is not a number.
    #[error("{}: line {line}, column `{column}`: `{cell}` is not a number", file.display())]
    NotANumber {
        /// The file.
        file: PathBuf,
        /// Line (1 is the header).
        line: u64,
        /// Column.
        column: String,
        /// The cell.
        cell: String,
    },
    /// A `status` or `saturated_<target>` cell outside its values.
    #[error("{}: line {line}, column `{column}`: `{cell}` is not one of {allowed}\n  fix: plot the estimates file `estimate` wrote", file.display())]
    BadCell {
        /// The file.
        file: PathBuf,
        /// Line (1 is the header).
        line: u64,
        /// Column.
        column: String,
        /// The cell.
        cell: String,
        /// Its values.
        allowed: &'static str,
    },
    /// The estimates file has no target column.
    #[error("{}: no target column (only time, run, status and saturated_<target>)\n  fix: plot the estimates file `estimate` wrote", file.display())]
    NoTargets {
        /// The file.
        file: PathBuf,
    },
    /// The estimates' targets are not the design's.
    #[error("{}: targets {found}, the design `{design}` has {expected}\n  fix: pass the design (--design/--spec) that made these estimates, or none", file.display())]
    OtherTargets {
        /// The estimates file.
        file: PathBuf,
        /// The design.
        design: String,
        /// The file's targets.
        found: String,
        /// The design's.
        expected: String,
    },
    /// The two files have different numbers of rows.
    #[error("{} has {input_rows} rows and {} {estimate_rows}: the estimates are not of this input\n  fix: run `estimate` on this input again", input.display(), estimates.display())]
    RowCount {
        /// The input.
        input: PathBuf,
        /// Its rows.
        input_rows: usize,
        /// The estimates.
        estimates: PathBuf,
        /// Theirs.
        estimate_rows: usize,
    },
    /// A time of the estimates is not the input's on the same row.
    #[error("{}: line {line}: time `{estimate_time}`, but {} has `{input_time}` there: the estimates are not of this input\n  fix: run `estimate` on this input again", estimates.display(), input.display())]
    OtherTimes {
        /// The input.
        input: PathBuf,
        /// The estimates.
        estimates: PathBuf,
        /// Line (1 is the header).
        line: u64,
        /// The input's time.
        input_time: String,
        /// The estimates'.
        estimate_time: String,
    },
    /// The input or the estimates is not a regular file: a folder, a device such as `/dev/zero` or
    /// a pipe may never end, and `plot` reads each file twice (to check it and find the axes, then
    /// to draw it).
    #[error("{}: --{option} is not a regular file (a folder, a device or a pipe)\n  fix: give --{option} the CSV file itself (save a pipe's output to a file first)", file.display())]
    NotAFile {
        /// The file.
        file: PathBuf,
        /// The command line option that named it.
        option: &'static str,
    },
    /// A figure would replace one of the files it is drawn from.
    #[error("{}: is one of the files plotted; plot refuses to overwrite it\n  fix: pass --out with another prefix", path.display())]
    WouldOverwrite {
        /// The figure's file.
        path: PathBuf,
    },
    /// The figure could not be drawn or written.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A time of the input is not the design's sample period after the previous one (as `estimate`
    /// refuses it).
    #[error("{}: line {line}, column `{column}`: {source}", file.display())]
    Time {
        /// The input.
        file: PathBuf,
        /// Line (1 is the header).
        line: u64,
        /// The time column.
        column: String,
        /// What is wrong.
        source: Box<crate::recording::spacing::SpacingError>,
    },
}

/// Width of a panel in pixels, and the number of columns the time axis is cut into for drawing:
/// the plotting area is narrower (axis labels and margins, and the axis pads the data by 5 %), so a
/// column is never wider than a pixel and what is left out of it cannot be seen.
const PANEL_WIDTH: u32 = 900;
/// Height of a row of the figure in pixels (its plotting area is smaller).
const ROW_HEIGHT: u32 = 320;
/// Columns of the time axis: one per pixel of a panel's width, at least one per pixel drawn.
const COLUMNS: usize = PANEL_WIDTH as usize;
/// Dots are kept one per cell of this many columns by this many pixel rows: a dot is 5 px wide, so
/// every dot left out lies within 2 px of one drawn, and a dense cloud looks the same.
const DOT_CELL: usize = 2;
const DOT_CELLS_X: usize = COLUMNS / DOT_CELL + 1;
const DOT_CELLS_Y: usize = ROW_HEIGHT as usize / DOT_CELL + 1;
/// Above this many pieces a line is folded to one piece per column: with restarts or gaps by the
/// thousand a piece per stretch would grow with the rows, and memory and the SVG must not.
const MAX_PIECES: usize = 16 * COLUMNS;

type Point = (f64, f64);

/// The time axis cut into [`COLUMNS`] equal columns, from the earliest time to the latest.
#[derive(Clone, Copy, Debug)]
struct Grid {
    start: f64,
    per_unit: f64,
}

impl Grid {
    fn new(times: Extent) -> Self {
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
    fn column(&self, t: f64) -> Option<usize> {
        t.is_finite()
            .then(|| (((t - self.start) * self.per_unit).max(0.0) as usize).min(COLUMNS - 1))
    }
}

/// The lowest and highest finite value seen.
#[derive(Clone, Copy, Debug)]
struct Extent {
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
    fn add(&mut self, v: f64) {
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
struct Line {
    pieces: Vec<Piece>,
    /// Once folded: one piece per column, none joined to another.
    folded: Vec<Option<Piece>>,
    /// The next point starts a new stretch (after a missing value or a row without a time).
    gap: bool,
}

impl Line {
    /// The value `v` at time `t`; `restart`: this row starts a new run (the line breaks before it).
    fn push(&mut self, grid: &Grid, t: f64, v: f64, restart: bool) {
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
    fn points(&self) -> Vec<Point> {
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
struct Dots {
    /// Per cell, the index of its dot in `points`, or `u32::MAX`.
    cells: Vec<u32>,
    low: f64,
    per_unit: f64,
    points: Vec<Point>,
}

impl Dots {
    fn new(values: Extent) -> Self {
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

    fn push(&mut self, grid: &Grid, t: f64, v: f64) {
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
    fn finish(&self) -> (Vec<Point>, Vec<(f64, f64, f64)>) {
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
struct PerColumn<T>(Vec<Option<T>>);

impl<T: Copy> PerColumn<T> {
    fn new() -> Self {
        PerColumn(vec![None; COLUMNS])
    }

    fn put(&mut self, column: Option<usize>, value: T) {
        if let Some(c) = column {
            self.0[c].get_or_insert(value);
        }
    }

    fn values(&self) -> Vec<T> {
        self.0.iter().flatten().copied().collect()
    }
}

/// A CSV file read one record at a time (cells trimmed): memory independent of its length.
struct Csv {
    file: PathBuf,
    header: Vec<String>,
    reader: csv::Reader<std::fs::File>,
    record: csv::StringRecord,
    /// The line of the current record (1 is the header).
    line: u64,
}

impl Csv {
    fn open(file: &Path) -> Result<Self, RecordedPlotError> {
        let csv_error = |e: csv::Error| RecordedPlotError::Csv {
            file: file.to_owned(),
            message: e.to_string(),
        };
        let mut reader = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .from_path(file)
            .map_err(csv_error)?;
        let header = reader.headers().map_err(csv_error)?.iter().map(str::to_owned).collect();
        Ok(Csv {
            file: file.to_owned(),
            header,
            reader,
            record: csv::StringRecord::new(),
            line: 1,
        })
    }

    fn column(&self, name: &str) -> Option<usize> {
        self.header.iter().position(|h| h == name)
    }

    fn require(&self, name: &str, fix: &str) -> Result<usize, RecordedPlotError> {
        self.column(name).ok_or_else(|| RecordedPlotError::MissingColumn {
            file: self.file.clone(),
            column: name.to_owned(),
            found: self.header.join(", "),
            fix: fix.to_owned(),
        })
    }

    /// Reads the next record; `false` at the end of the file.
    fn advance(&mut self) -> Result<bool, RecordedPlotError> {
        let more = self
            .reader
            .read_record(&mut self.record)
            .map_err(|e| RecordedPlotError::Csv {
                file: self.file.clone(),
                message: e.to_string(),
            })?;
        if more {
            self.line = self.record.position().map_or(self.line + 1, |p| p.line());
        }
        Ok(more)
    }

    fn cell(&self, column: usize) -> &str {
        self.record.get(column).unwrap_or("")
    }

    /// The cell as a number, an empty cell as NaN (a gap); a cell that is not a number is an error.
    fn number(&self, column: usize) -> Result<f64, RecordedPlotError> {
        let cell = self.cell(column);
        if cell.is_empty() {
            return Ok(f64::NAN);
        }
        cell.parse().map_err(|_| RecordedPlotError::NotANumber {
            file: self.file.clone(),
            line: self.line,
            column: self.header[column].clone(),
            cell: cell.to_owned(),
        })
    }
}

/// `status` of an estimates row.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Status {
    Ok,
    Refused,
    NoEstimateYet,
}

/// The default prefix of the figure: the estimates' path without its extension.
pub fn default_prefix(estimates: &Path) -> PathBuf {
    estimates.with_extension("")
}

/// Draws `input` (the recorded run) and `estimates` (what `estimate` wrote for it) as `<out>.png` and
/// `<out>.svg` (default prefix: [`default_prefix`]); `design`, when given, names the outputs and inputs
/// and gives the units. Everything is read and checked before anything is written; returns the files.
///
/// Both files are streamed, twice (to check them and find the axes, then to draw), and each series
/// is kept only as the figure can show it (see the module's documentation): memory and the SVG's
/// size do not grow with the rows.
pub fn plot(
    input: &Path,
    estimates: &Path,
    design: Option<&Design>,
    out: Option<&Path>,
) -> Result<Vec<PathBuf>, RecordedPlotError> {
    for (file, option) in [(input, "input"), (estimates, "estimates")] {
        if !crate::recording::regular_or_missing(file) {
            return Err(RecordedPlotError::NotAFile {
                file: file.to_owned(),
                option,
            });
        }
    }
    let prefix = out.map_or_else(|| default_prefix(estimates), Path::to_owned);
    let files = [with_suffix(&prefix, "png"), with_suffix(&prefix, "svg")];
    for figure in &files {
        let same = |other: &Path| {
            std::fs::canonicalize(figure)
                .ok()
                .is_some_and(|f| std::fs::canonicalize(other).is_ok_and(|o| o == f))
        };
        if same(input) || same(estimates) {
            return Err(RecordedPlotError::WouldOverwrite { path: figure.clone() });
        }
    }
    let figure = figure(input, estimates, design)?;
    Ok(write_figure(&prefix, &figure)?)
}

const ESTIMATES_FIX: &str =
    "plot the estimates file `estimate` wrote (time, [run,] status, targets, saturated_<target>)";

/// Which file a column is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    Input,
    Estimates,
}

/// A target's columns: its estimate, its truth in the input (if any), its saturation (if any).
#[derive(Debug, PartialEq)]
struct TargetColumns {
    name: String,
    estimate: usize,
    truth: Option<usize>,
    saturation: Option<usize>,
}

/// What an input column other than the truth is drawn as.
#[derive(Debug, PartialEq)]
enum Role {
    /// A design's output: a panel of its own, dots; every cell must be a number.
    Output { unit: String },
    /// A design's input: a panel of its own, a line; every cell must be a number.
    Input { unit: String },
    /// Without a design: a line in the shared panel, left out if a cell is not a number.
    Other,
}

#[derive(Debug, PartialEq)]
struct Signal {
    column: usize,
    name: String,
    role: Role,
}

/// What the figure reads, found in the two headers before any row.
#[derive(Debug, PartialEq)]
struct Layout {
    headers: [Vec<String>; 2],
    /// The estimates' `time`; the input's `time` (else `t`), when it has one.
    time: usize,
    input_time: Option<usize>,
    status: usize,
    /// The input's `run` (the time spacing restarts at a change).
    input_run: Option<usize>,
    /// Where a restart is read: the estimates' `run`, else the input's.
    run: Option<(Side, usize)>,
    targets: Vec<TargetColumns>,
    signals: Vec<Signal>,
}

impl Layout {
    fn new(input: &Csv, estimates: &Csv, design: Option<&Design>) -> Result<Self, RecordedPlotError> {
        let time = estimates.require("time", ESTIMATES_FIX)?;
        let status = estimates.require("status", ESTIMATES_FIX)?;
        let run = estimates
            .column("run")
            .map(|c| (Side::Estimates, c))
            .or_else(|| input.column("run").map(|c| (Side::Input, c)));
        let names: Vec<&str> = estimates
            .header
            .iter()
            .map(String::as_str)
            .filter(|h| !matches!(*h, "time" | "run" | "status") && !h.starts_with("saturated_"))
            .collect();
        if names.is_empty() {
            return Err(RecordedPlotError::NoTargets {
                file: estimates.file.clone(),
            });
        }
        if let Some(design) = design {
            let mut found = names.clone();
            let mut expected: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
            found.sort_unstable();
            expected.sort_unstable();
            if found != expected {
                return Err(RecordedPlotError::OtherTargets {
                    file: estimates.file.clone(),
                    design: design.name.clone(),
                    found: found.join(", "),
                    expected: expected.join(", "),
                });
            }
        }
        let mut used: Vec<&str> = vec!["time", "t", "run"];
        let mut targets = Vec::new();
        for (estimate, name) in estimates.header.iter().enumerate() {
            if !names.contains(&name.as_str()) {
                continue;
            }
            let truth = input.column(&format!("truth_{name}")).or_else(|| input.column(name));
            if let Some(t) = truth {
                used.push(input.header[t].as_str());
            }
            targets.push(TargetColumns {
                name: name.clone(),
                estimate,
                truth,
                saturation: estimates.column(&format!("saturated_{name}")),
            });
        }
        let mut signals = Vec::new();
        match design {
            Some(design) => {
                let fix = format!(
                    "the design `{}` reads the outputs {} and the inputs {}: name the input's columns so, or plot without --design/--spec",
                    design.name,
                    design.model.outputs.iter().map(|o| o.name.as_str()).collect::<Vec<_>>().join(", "),
                    if design.model.inputs.is_empty() { "(none)".to_owned() } else { design.model.inputs.join(", ") }
                );
                for output in &design.model.outputs {
                    signals.push(Signal {
                        column: input.require(&output.name, &fix)?,
                        name: output.name.clone(),
                        role: Role::Output {
                            unit: output.unit.clone(),
                        },
                    });
                }
                for (name, unit) in design.model.inputs.iter().zip(&design.input_units) {
                    signals.push(Signal {
                        column: input.require(name, &fix)?,
                        name: name.clone(),
                        role: Role::Input { unit: unit.clone() },
                    });
                }
            }
            None => {
                for (column, name) in input.header.iter().enumerate() {
                    let truth_of_a_target = name.strip_prefix("truth_").is_some_and(|t| names.contains(&t));
                    if used.contains(&name.as_str()) || names.contains(&name.as_str()) || truth_of_a_target {
                        continue;
                    }
                    signals.push(Signal {
                        column,
                        name: name.clone(),
                        role: Role::Other,
                    });
                }
            }
        }
        Ok(Layout {
            headers: [input.header.clone(), estimates.header.clone()],
            time,
            input_time: input.column("time").or_else(|| input.column("t")),
            status,
            input_run: input.column("run"),
            run,
            targets,
            signals,
        })
    }
}

/// One target on one row: the estimate (NaN unless `ok`), the truth (NaN without), the saturation.
#[derive(Clone, Copy, Debug)]
struct TargetRow {
    estimate: f64,
    truth: f64,
    saturation: i8,
}

/// One row of both files, checked.
#[derive(Debug)]
struct Row {
    time: f64,
    status: Status,
    /// A new run starts here (the observer restarted).
    restart: bool,
    targets: Vec<TargetRow>,
    /// In the order of [`Layout::signals`]; NaN for an empty cell or a column that is not numeric.
    signals: Vec<f64>,
}

/// Opens both files and reads their headers.
fn open(input: &Path, estimates: &Path, design: Option<&Design>) -> Result<(Csv, Csv, Layout), RecordedPlotError> {
    let (input, estimates) = (Csv::open(input)?, Csv::open(estimates)?);
    let layout = Layout::new(&input, &estimates, design)?;
    Ok((input, estimates, layout))
}

/// Reads both files row by row, checks each row as `estimate` would have written it, and gives it
/// to `each`; returns which signals hold numbers only.
fn scan(
    mut input: Csv,
    mut estimates: Csv,
    layout: &Layout,
    design: Option<&Design>,
    mut each: impl FnMut(&Row),
) -> Result<Vec<bool>, RecordedPlotError> {
    // With a design, its times as `estimate` checks them.
    let mut spacing = design.map(|d| crate::recording::spacing::Spacing::new(d.tau, &d.time_unit));
    let mut numeric = vec![true; layout.signals.len()];
    let mut previous_run: Option<String> = None;
    let mut row = Row {
        time: f64::NAN,
        status: Status::NoEstimateYet,
        restart: false,
        targets: vec![
            TargetRow {
                estimate: f64::NAN,
                truth: f64::NAN,
                saturation: 0,
            };
            layout.targets.len()
        ],
        signals: vec![f64::NAN; layout.signals.len()],
    };
    let mut rows = 0usize;
    loop {
        let (more_input, more_estimates) = (input.advance()?, estimates.advance()?);
        if more_input != more_estimates {
            // Count the rest of the longer file, to say both lengths.
            let longer = if more_input { &mut input } else { &mut estimates };
            let mut longer_rows = rows + 1;
            while longer.advance()? {
                longer_rows += 1;
            }
            let (input_rows, estimate_rows) = if more_input {
                (longer_rows, rows)
            } else {
                (rows, longer_rows)
            };
            return Err(RecordedPlotError::RowCount {
                input: input.file,
                input_rows,
                estimates: estimates.file,
                estimate_rows,
            });
        }
        if !more_input {
            return Ok(numeric);
        }
        rows += 1;
        if let Some(column) = layout.input_time {
            let given = input.cell(column);
            if let Some(spacing) = &mut spacing {
                let run = layout.input_run.map_or("", |c| input.cell(c));
                spacing.check(run, given).map_err(|source| RecordedPlotError::Time {
                    file: input.file.clone(),
                    line: input.line,
                    column: input.header[column].clone(),
                    source: Box::new(source),
                })?;
            }
            let written = estimates.cell(layout.time);
            if given != written {
                return Err(RecordedPlotError::OtherTimes {
                    input: input.file.clone(),
                    estimates: estimates.file.clone(),
                    line: input.line,
                    input_time: given.to_owned(),
                    estimate_time: written.to_owned(),
                });
            }
        }
        row.time = estimates.number(layout.time)?;
        row.status = match estimates.cell(layout.status) {
            "ok" => Status::Ok,
            "refused" => Status::Refused,
            "no_estimate_yet" => Status::NoEstimateYet,
            cell => {
                return Err(RecordedPlotError::BadCell {
                    file: estimates.file.clone(),
                    line: estimates.line,
                    column: "status".into(),
                    cell: cell.to_owned(),
                    allowed: "ok, refused, no_estimate_yet",
                })
            }
        };
        row.restart = match layout.run {
            Some((side, column)) => {
                let run = match side {
                    Side::Input => input.cell(column),
                    Side::Estimates => estimates.cell(column),
                };
                let changed = previous_run.as_deref().is_some_and(|p| p != run);
                if previous_run.as_deref() != Some(run) {
                    previous_run = Some(run.to_owned());
                }
                changed
            }
            None => false,
        };
        for (target, value) in layout.targets.iter().zip(&mut row.targets) {
            let estimate = estimates.number(target.estimate)?;
            value.estimate = if row.status == Status::Ok { estimate } else { f64::NAN };
            value.truth = match target.truth {
                Some(column) => input.number(column)?,
                None => f64::NAN,
            };
            value.saturation = match target.saturation {
                None => 0,
                Some(column) => match (estimates.cell(column), row.status) {
                    ("1", Status::Ok) => 1,
                    ("-1", Status::Ok) => -1,
                    ("0", Status::Ok) | ("", _) => 0,
                    (cell, _) => {
                        return Err(RecordedPlotError::BadCell {
                            file: estimates.file.clone(),
                            line: estimates.line,
                            column: estimates.header[column].clone(),
                            cell: cell.to_owned(),
                            allowed: "-1, 0, 1 (empty unless the status is ok)",
                        })
                    }
                },
            };
        }
        for ((signal, value), numeric) in layout.signals.iter().zip(&mut row.signals).zip(&mut numeric) {
            *value = match signal.role {
                Role::Other if !*numeric => f64::NAN,
                Role::Other => input.number(signal.column).unwrap_or_else(|_| {
                    *numeric = false;
                    f64::NAN
                }),
                Role::Output { .. } | Role::Input { .. } => input.number(signal.column)?,
            };
        }
        each(&row);
    }
}

/// How a signal's values are kept.
enum Drawn {
    Dots(Dots),
    Line(Line),
}

impl Drawn {
    /// The points, and the bands of dots.
    fn points(&self) -> (Vec<Point>, Vec<(f64, f64, f64)>) {
        match self {
            Drawn::Dots(dots) => dots.finish(),
            Drawn::Line(line) => (line.points(), Vec::new()),
        }
    }
}

/// The figure of a recorded run and its estimates: both files are read twice, first to check every
/// row and find the time axis and each dotted series' values, then to keep what is drawn.
fn figure(input: &Path, estimates: &Path, design: Option<&Design>) -> Result<Figure, RecordedPlotError> {
    let (input_csv, estimates_csv, layout) = open(input, estimates, design)?;
    let mut times = Extent::default();
    let mut estimate_values = vec![Extent::default(); layout.targets.len()];
    let mut signal_values = vec![Extent::default(); layout.signals.len()];
    let numeric = scan(input_csv, estimates_csv, &layout, design, |row| {
        times.add(row.time);
        for (extent, target) in estimate_values.iter_mut().zip(&row.targets) {
            extent.add(target.estimate);
        }
        for (extent, &value) in signal_values.iter_mut().zip(&row.signals) {
            extent.add(value);
        }
    })?;
    let grid = Grid::new(times);

    let (input_csv, estimates_csv, again) = open(input, estimates, design)?;
    if again != layout {
        return Err(RecordedPlotError::Csv {
            file: input.to_owned(),
            message: format!(
                "{} or this file changed while plot read them; plot again",
                estimates.display()
            ),
        });
    }
    let mut truths: Vec<Line> = layout.targets.iter().map(|_| Line::default()).collect();
    let mut estimate_dots: Vec<Dots> = estimate_values.iter().map(|&e| Dots::new(e)).collect();
    let mut rings: Vec<[PerColumn<Point>; 2]> = layout
        .targets
        .iter()
        .map(|_| [PerColumn::new(), PerColumn::new()])
        .collect();
    let mut signals: Vec<Drawn> = layout
        .signals
        .iter()
        .zip(&signal_values)
        .map(|(signal, &values)| match signal.role {
            Role::Output { .. } => Drawn::Dots(Dots::new(values)),
            Role::Input { .. } | Role::Other => Drawn::Line(Line::default()),
        })
        .collect();
    let mut refused = PerColumn::new();
    let mut restarted = PerColumn::new();
    scan(input_csv, estimates_csv, &layout, design, |row| {
        let (t, column) = (row.time, grid.column(row.time));
        if row.status == Status::Refused {
            refused.put(column, t);
        }
        if row.restart {
            restarted.put(column, t);
        }
        for (i, target) in row.targets.iter().enumerate() {
            truths[i].push(&grid, t, target.truth, row.restart);
            estimate_dots[i].push(&grid, t, target.estimate);
            if target.saturation != 0 && target.estimate.is_finite() {
                rings[i][usize::from(target.saturation > 0)].put(column, (t, target.estimate));
            }
        }
        for (drawn, &value) in signals.iter_mut().zip(&row.signals) {
            match drawn {
                Drawn::Dots(dots) => dots.push(&grid, t, value),
                Drawn::Line(line) => line.push(&grid, t, value, row.restart),
            }
        }
    })?;

    let title = input
        .file_stem()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    let time_label = design.map_or("time".to_owned(), |d| with_unit("time", &d.time_unit));
    let (refused, restarted) = (refused.values(), restarted.values());
    let marked = |panel: Panel| {
        panel
            .marked(
                "refused sample (NaN or infinite)",
                refused.clone(),
                REFUSED_COLOR,
                Style::Rule,
            )
            .marked(
                "observer restarted (new run)",
                restarted.clone(),
                MARK_COLOR,
                Style::Dashes,
            )
    };
    let mut panels = Vec::new();
    for (i, target) in layout.targets.iter().enumerate() {
        let name = target.name.as_str();
        let unit = design
            .and_then(|d| d.targets.iter().find(|t| t.name == name))
            .map_or("", |t| t.unit.as_str());
        let mut panel = Panel::new(
            format!("{title}: estimating {name}"),
            time_label.clone(),
            with_unit(name, unit),
        );
        if let Some(truth) = target.truth {
            let label = &layout.headers[0][truth];
            panel = panel.with(Series::new(
                format!("true ({label})"),
                truths[i].points(),
                TRUE_COLOR,
                Style::Line,
            ));
        }
        let (dots, bands) = estimate_dots[i].finish();
        panel = panel.with(Series::new("estimate", dots, ESTIMATE_COLOR, Style::Dots).with_bands(bands));
        if target.saturation.is_some() {
            let [low, high] = &rings[i];
            let mut points = low.values();
            points.extend(high.values());
            panel = panel.with(Series::new(
                super::plots::SATURATED_LABEL,
                points,
                SATURATED_COLOR,
                Style::Rings,
            ));
        }
        panels.push(marked(panel));
    }
    let mut others = Panel::new(format!("{title}: recorded signals"), time_label.clone(), "value");
    let mut colors = PALETTE.iter().cycle();
    for ((signal, drawn), numeric) in layout.signals.iter().zip(&signals).zip(numeric) {
        let name = signal.name.as_str();
        match &signal.role {
            Role::Output { unit } => panels.push(marked(
                Panel::new(
                    format!("{title}: measured {name}"),
                    time_label.clone(),
                    with_unit(name, unit),
                )
                .with({
                    let (dots, bands) = drawn.points();
                    Series::new("measured", dots, ESTIMATE_COLOR, Style::Dots).with_bands(bands)
                }),
            )),
            Role::Input { unit } => panels.push(marked(
                Panel::new(
                    format!("{title}: input {name}"),
                    time_label.clone(),
                    with_unit(name, unit),
                )
                .with(Series::new(name, drawn.points().0, PALETTE[1], Style::Line)),
            )),
            // A column of text is left out.
            Role::Other if numeric => {
                let color = *colors.next().unwrap_or(&PALETTE[0]);
                others = others.with(Series::new(name, drawn.points().0, color, Style::Line));
            }
            Role::Other => {}
        }
    }
    if !others.series.is_empty() {
        panels.push(marked(others));
    }
    Ok(Figure {
        rows: panels.into_iter().map(|p| vec![p]).collect(),
        panel_width: PANEL_WIDTH,
        row_height: ROW_HEIGHT,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `input` and `estimates` written as `<name>-<pid>/run.csv` and `est.csv` in the temporary folder.
    fn files(name: &str, input: &str, estimates: &str) -> (PathBuf, PathBuf) {
        let dir = std::env::temp_dir().join(format!("recorded-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (run, est) = (dir.join("run.csv"), dir.join("est.csv"));
        std::fs::write(&run, input).unwrap();
        std::fs::write(&est, estimates).unwrap();
        (run, est)
    }

    fn figure_of(name: &str, input: &str, estimates: &str) -> Result<Figure, RecordedPlotError> {
        let (run, est) = files(name, input, estimates);
        let figure = figure(&run, &est, None);
        std::fs::remove_dir_all(run.parent().unwrap()).unwrap();
        figure
    }

    const INPUT: &str = "time,x1,y,u\n0,1,1.1,0\n0.1,2,2.1,0\n0.2,3,nan,1\n0.3,4,4.1,1\n";
    const ESTIMATES: &str =
        "time,status,x1,saturated_x1\n0,no_estimate_yet,,\n0.1,ok,2.5,1\n0.2,refused,,\n0.3,ok,3.9,0\n";

    fn panel<'f>(figure: &'f Figure, title_end: &str) -> &'f Panel {
        figure
            .rows
            .iter()
            .flatten()
            .find(|p| p.title.ends_with(title_end))
            .unwrap_or_else(|| panic!("no panel `{title_end}`"))
    }

    #[test]
    fn the_estimates_are_drawn_against_the_truth_with_refusals_and_saturation_marked() {
        let figure = figure_of("drawn", INPUT, ESTIMATES).unwrap();
        let x1 = panel(&figure, "estimating x1");
        let truth = x1.series.iter().find(|s| s.label == "true (x1)").unwrap();
        assert_eq!(truth.points, [(0.0, 1.0), (0.1, 2.0), (0.2, 3.0), (0.3, 4.0)]);
        let estimate = x1.series.iter().find(|s| s.label == "estimate").unwrap();
        let finite: Vec<_> = estimate.points.iter().filter(|p| p.1.is_finite()).copied().collect();
        assert_eq!(finite, [(0.1, 2.5), (0.3, 3.9)]);
        let rings = x1.series.iter().find(|s| s.style == Style::Rings).unwrap();
        assert_eq!(rings.points, [(0.1, 2.5)]);
        assert_eq!(x1.marks[0].at, [0.2]);
        // Without the design the other numeric columns share one panel; the truth is not repeated.
        let signals = panel(&figure, "recorded signals");
        let names: Vec<&str> = signals.series.iter().map(|s| s.label.as_str()).collect();
        assert_eq!(names, ["y", "u"]);
    }

    #[test]
    fn a_truth_column_is_preferred_and_runs_break_lines_and_are_marked() {
        let input = "run,truth_x1,x1,y\na,10,1,0\na,11,2,0\nb,12,3,0\nb,13,4,0\n";
        let estimates = "time,run,status,x1,saturated_x1\n0,a,ok,1,0\n0.1,a,ok,2,0\n0.2,b,ok,3,-1\n0.3,b,ok,4,0\n";
        let figure = figure_of("runs", input, estimates).unwrap();
        let x1 = panel(&figure, "estimating x1");
        let truth = &x1.series[0];
        assert_eq!(truth.label, "true (truth_x1)");
        assert_eq!(truth.points.len(), 5);
        assert!(truth.points[2].0.is_nan(), "a restart breaks the line");
        assert_eq!(x1.marks[0].label, "observer restarted (new run)");
        assert_eq!(x1.marks[0].at, [0.2]);
        let rings = x1.series.iter().find(|s| s.style == Style::Rings).unwrap();
        assert_eq!(rings.points, [(0.2, 3.0)]);
        // A column named after a target is never a recorded signal, even when truth_x1 is the truth.
        let signals = panel(&figure, "recorded signals");
        assert_eq!(
            signals.series.iter().map(|s| s.label.as_str()).collect::<Vec<_>>(),
            ["y"]
        );
    }

    #[test]
    fn estimates_of_another_input_are_refused() {
        let shifted = ESTIMATES.replace("0.3,ok", "0.4,ok");
        let error = figure_of("shifted", INPUT, &shifted).err().unwrap();
        assert!(
            matches!(error, RecordedPlotError::OtherTimes { line: 5, .. }),
            "{error}"
        );
        let short: String = ESTIMATES.lines().take(3).map(|l| format!("{l}\n")).collect();
        let error = figure_of("short", INPUT, &short).err().unwrap();
        assert!(matches!(
            error,
            RecordedPlotError::RowCount {
                input_rows: 4,
                estimate_rows: 2,
                ..
            }
        ));
        let bad = ESTIMATES.replace("refused", "maybe");
        let error = figure_of("bad", INPUT, &bad).err().unwrap();
        assert!(
            error.to_string().contains("line 4, column `status`: `maybe`"),
            "{error}"
        );
    }

    /// Deterministic noise in [0, 1) for row `k` (a multiplicative hash; the test's own truth).
    fn noise(k: usize) -> f64 {
        ((k as u64).wrapping_mul(6_364_136_223_846_793_005) >> 40) as f64 / (1u64 << 24) as f64
    }

    #[test]
    fn a_long_line_keeps_each_columns_first_last_lowest_and_highest_row_and_dots_stay_within_2_px() {
        // Times 0, 1, …, ROWS − 1 over 900 columns of 222.5 each: no time lies on a border, so the
        // column of row k is ⌊k / 222.5⌋ by plain arithmetic.
        const ROWS: usize = 200_251;
        let width = (ROWS - 1) as f64 / 900.0;
        assert_eq!(width, 222.5);
        let column = |t: f64| ((t / width).floor() as usize).min(899);
        let value = |k: usize| (k as f64 / 3000.0).sin() + 0.3 * noise(k);
        let (mut input, mut estimates) = (String::from("x1\n"), String::from("time,status,x1\n"));
        for k in 0..ROWS {
            input.push_str(&format!("{}\n", value(k)));
            estimates.push_str(&format!("{k},ok,{}\n", value(k)));
        }
        let figure = figure_of("long", &input, &estimates).unwrap();
        let x1 = panel(&figure, "estimating x1");

        // The line: per column, brute force over every row.
        let truth = &x1.series.iter().find(|s| s.label == "true (x1)").unwrap().points;
        assert!(truth.len() <= 4 * 900, "{} points for 900 columns", truth.len());
        let mut expected: Vec<Option<[(f64, f64); 4]>> = vec![None; 900]; // first, last, lowest, highest
        for k in 0..ROWS {
            let p = (k as f64, value(k));
            let e = expected[column(p.0)].get_or_insert([p; 4]);
            e[1] = p;
            if p.1 < e[2].1 {
                e[2] = p;
            }
            if p.1 > e[3].1 {
                e[3] = p;
            }
        }
        for (c, e) in expected.iter().enumerate() {
            let [first, last, low, high] = e.unwrap();
            let drawn: Vec<(f64, f64)> = truth.iter().copied().filter(|p| column(p.0) == c).collect();
            assert_eq!(drawn.first(), Some(&first), "column {c}");
            assert_eq!(drawn.last(), Some(&last), "column {c}");
            assert!(drawn.contains(&low) && drawn.contains(&high), "column {c}");
            // Every point drawn is a row of the file, in the file's order (one unbroken line).
            assert!(drawn.iter().all(|p| p.1 == value(p.0 as usize)));
        }
        assert!(truth.windows(2).all(|w| w[0].0 <= w[1].0), "in row order, never broken");

        // The dots: far fewer than the rows, and every row's dot within one 2-column by
        // (range / 160) cell of a drawn dot or band: under 2 px, as the plotting area is under
        // 900 × 320 px.
        let estimate = x1.series.iter().find(|s| s.label == "estimate").unwrap();
        let (dots, bands) = (&estimate.points, &estimate.bands);
        assert!(
            dots.len() + bands.len() < ROWS / 10,
            "{} dots, {} bands",
            dots.len(),
            bands.len()
        );
        let (low, high) = (0..ROWS)
            .map(value)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
        let cell_height = (high - low) / 160.0;
        let mut by_column: Vec<Vec<(f64, f64)>> = vec![Vec::new(); 900];
        for &(t, v) in dots {
            by_column[column(t)].push((v, v));
        }
        for &(t, from, to) in bands {
            assert!(from < to, "a band runs up");
            by_column[column(t)].push((from, to));
        }
        for k in 0..ROWS {
            let (c, v) = (column(k as f64), value(k));
            let near = (c.saturating_sub(2)..=(c + 2).min(899))
                .flat_map(|c| &by_column[c])
                .any(|&(from, to)| from - cell_height <= v && v <= to + cell_height);
            assert!(near, "row {k}: nothing drawn within 2 px");
        }
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

    #[test]
    fn the_prefix_keeps_dots_in_the_name() {
        assert_eq!(default_prefix(Path::new("out/est.v2.csv")), Path::new("out/est.v2"));
        assert_eq!(with_suffix(Path::new("out/est.v2"), "png"), Path::new("out/est.v2.png"));
    }
}
