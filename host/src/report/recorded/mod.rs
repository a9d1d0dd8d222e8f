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

mod columns;
mod decimate;
mod figure;
mod rows;
mod stream;

use std::path::{Path, PathBuf};

use super::draw::{with_suffix, write_figure, PlotError};
use crate::spec::Design;
use figure::figure;

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_prefix_keeps_dots_in_the_name() {
        assert_eq!(default_prefix(Path::new("out/est.v2.csv")), Path::new("out/est.v2"));
        assert_eq!(with_suffix(Path::new("out/est.v2"), "png"), Path::new("out/est.v2.png"));
    }
}
