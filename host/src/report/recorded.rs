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

/// A CSV file as text cells (trimmed), with each row's line number.
struct Table {
    file: PathBuf,
    header: Vec<String>,
    rows: Vec<(u64, Vec<String>)>,
}

impl Table {
    fn read(file: &Path) -> Result<Self, RecordedPlotError> {
        let csv_error = |e: csv::Error| RecordedPlotError::Csv {
            file: file.to_owned(),
            message: e.to_string(),
        };
        let mut reader = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .from_path(file)
            .map_err(csv_error)?;
        let header = reader.headers().map_err(csv_error)?.iter().map(str::to_owned).collect();
        let mut rows = Vec::new();
        let mut record = csv::StringRecord::new();
        while reader.read_record(&mut record).map_err(csv_error)? {
            let line = record.position().map_or(0, |p| p.line());
            rows.push((line, record.iter().map(str::to_owned).collect()));
        }
        Ok(Table {
            file: file.to_owned(),
            header,
            rows,
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

    fn cells(&self, column: usize) -> impl Iterator<Item = (u64, &str)> {
        self.rows
            .iter()
            .map(move |(line, cells)| (*line, cells.get(column).map_or("", String::as_str)))
    }

    /// The column as numbers, an empty cell as NaN (a gap); a cell that is not a number is an error.
    fn numbers(&self, column: usize) -> Result<Vec<f64>, RecordedPlotError> {
        self.cells(column)
            .map(|(line, cell)| {
                if cell.is_empty() {
                    return Ok(f64::NAN);
                }
                cell.parse().map_err(|_| RecordedPlotError::NotANumber {
                    file: self.file.clone(),
                    line,
                    column: self.header[column].clone(),
                    cell: cell.to_owned(),
                })
            })
            .collect()
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
pub fn plot(
    input: &Path,
    estimates: &Path,
    design: Option<&Design>,
    out: Option<&Path>,
) -> Result<Vec<PathBuf>, RecordedPlotError> {
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
    let figure = figure(&Table::read(input)?, &Table::read(estimates)?, design)?;
    Ok(write_figure(&prefix, &figure)?)
}

const ESTIMATES_FIX: &str =
    "plot the estimates file `estimate` wrote (time, [run,] status, targets, saturated_<target>)";

/// The figure of a recorded run and its estimates.
fn figure(input: &Table, estimates: &Table, design: Option<&Design>) -> Result<Figure, RecordedPlotError> {
    if input.rows.len() != estimates.rows.len() {
        return Err(RecordedPlotError::RowCount {
            input: input.file.clone(),
            input_rows: input.rows.len(),
            estimates: estimates.file.clone(),
            estimate_rows: estimates.rows.len(),
        });
    }
    let time_column = estimates.require("time", ESTIMATES_FIX)?;
    let times = estimates.numbers(time_column)?;
    if let Some(column) = input.column("time").or_else(|| input.column("t")) {
        // With a design, its times as `estimate` checks them.
        if let Some(design) = design {
            let mut spacing = crate::recording::spacing::Spacing::new(design.tau, &design.time_unit);
            let runs: Vec<&str> = match input.column("run") {
                Some(run) => input.cells(run).map(|(_, cell)| cell).collect(),
                None => vec![""; input.rows.len()],
            };
            for ((line, cell), run) in input.cells(column).zip(runs) {
                spacing.check(run, cell).map_err(|source| RecordedPlotError::Time {
                    file: input.file.clone(),
                    line,
                    column: input.header[column].clone(),
                    source: Box::new(source),
                })?;
            }
        }
        for ((line, given), (_, written)) in input.cells(column).zip(estimates.cells(time_column)) {
            if given != written {
                return Err(RecordedPlotError::OtherTimes {
                    input: input.file.clone(),
                    estimates: estimates.file.clone(),
                    line,
                    input_time: given.to_owned(),
                    estimate_time: written.to_owned(),
                });
            }
        }
    }
    let status_column = estimates.require("status", ESTIMATES_FIX)?;
    let statuses: Vec<Status> = estimates
        .cells(status_column)
        .map(|(line, cell)| match cell {
            "ok" => Ok(Status::Ok),
            "refused" => Ok(Status::Refused),
            "no_estimate_yet" => Ok(Status::NoEstimateYet),
            _ => Err(RecordedPlotError::BadCell {
                file: estimates.file.clone(),
                line,
                column: "status".into(),
                cell: cell.to_owned(),
                allowed: "ok, refused, no_estimate_yet",
            }),
        })
        .collect::<Result<_, _>>()?;
    // A restart: the row where `run` changes (in the estimates, else the input).
    let run_column = estimates
        .column("run")
        .map(|c| (estimates, c))
        .or_else(|| input.column("run").map(|c| (input, c)));
    let restarts: Vec<usize> = match run_column {
        Some((table, column)) => {
            let runs: Vec<&str> = table.cells(column).map(|c| c.1).collect();
            (1..runs.len()).filter(|&k| runs[k] != runs[k - 1]).collect()
        }
        None => Vec::new(),
    };
    let targets: Vec<(usize, &str)> = estimates
        .header
        .iter()
        .enumerate()
        .filter(|(_, h)| !matches!(h.as_str(), "time" | "run" | "status") && !h.starts_with("saturated_"))
        .map(|(i, h)| (i, h.as_str()))
        .collect();
    if targets.is_empty() {
        return Err(RecordedPlotError::NoTargets {
            file: estimates.file.clone(),
        });
    }
    if let Some(design) = design {
        let mut found: Vec<&str> = targets.iter().map(|t| t.1).collect();
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
    let title = input
        .file
        .file_stem()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    let time_label = design.map_or("time".to_owned(), |d| with_unit("time", &d.time_unit));
    let at = |k: usize| times[k];
    let refused: Vec<f64> = (0..statuses.len())
        .filter(|&k| statuses[k] == Status::Refused)
        .map(at)
        .collect();
    let restarted: Vec<f64> = restarts.iter().map(|&k| at(k)).collect();
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
    // Lines break at a restart: a run's last point is never joined to the next run's first.
    let series = |values: &[f64]| -> Vec<(f64, f64)> {
        let mut points = Vec::with_capacity(values.len() + restarts.len());
        for (k, &v) in values.iter().enumerate() {
            if restarts.contains(&k) {
                points.push((f64::NAN, f64::NAN));
            }
            points.push((at(k), v));
        }
        points
    };

    let mut panels = Vec::new();
    let mut used: Vec<&str> = vec!["time", "t", "run"];
    for &(column, name) in &targets {
        let values = estimates.numbers(column)?;
        let estimate: Vec<f64> = values
            .iter()
            .zip(&statuses)
            .map(|(&v, &s)| if s == Status::Ok { v } else { f64::NAN })
            .collect();
        let unit = design
            .and_then(|d| d.targets.iter().find(|t| t.name == name))
            .map_or("", |t| t.unit.as_str());
        let mut panel = Panel::new(
            format!("{title}: estimating {name}"),
            time_label.clone(),
            with_unit(name, unit),
        );
        if let Some(truth_column) = input.column(&format!("truth_{name}")).or_else(|| input.column(name)) {
            let label = input.header[truth_column].as_str();
            used.push(label);
            let truth = input.numbers(truth_column)?;
            panel = panel.with(Series::new(
                format!("true ({label})"),
                series(&truth),
                TRUE_COLOR,
                Style::Line,
            ));
        }
        panel = panel.with(Series::new("estimate", series(&estimate), ESTIMATE_COLOR, Style::Dots));
        if let Some(saturation_column) = estimates.column(&format!("saturated_{name}")) {
            let mut rings = Vec::new();
            for ((k, (line, cell)), &s) in estimates.cells(saturation_column).enumerate().zip(&statuses) {
                match (cell, s) {
                    ("1" | "-1", Status::Ok) => rings.push((at(k), estimate[k])),
                    ("0", Status::Ok) | ("", _) => {}
                    _ => {
                        return Err(RecordedPlotError::BadCell {
                            file: estimates.file.clone(),
                            line,
                            column: estimates.header[saturation_column].clone(),
                            cell: cell.to_owned(),
                            allowed: "-1, 0, 1 (empty unless the status is ok)",
                        })
                    }
                }
            }
            panel = panel.with(Series::new(
                super::plots::SATURATED_LABEL,
                rings,
                SATURATED_COLOR,
                Style::Rings,
            ));
        }
        panels.push(marked(panel));
    }

    match design {
        Some(design) => {
            let fix = format!(
                "the design `{}` reads the outputs {} and the inputs {}: name the input's columns so, or plot without --design/--spec",
                design.name,
                design.model.outputs.iter().map(|o| o.name.as_str()).collect::<Vec<_>>().join(", "),
                if design.model.inputs.is_empty() { "(none)".to_owned() } else { design.model.inputs.join(", ") }
            );
            for output in &design.model.outputs {
                let values = input.numbers(input.require(&output.name, &fix)?)?;
                panels.push(marked(
                    Panel::new(
                        format!("{title}: measured {}", output.name),
                        time_label.clone(),
                        with_unit(&output.name, &output.unit),
                    )
                    .with(Series::new("measured", series(&values), ESTIMATE_COLOR, Style::Dots)),
                ));
            }
            for (name, unit) in design.model.inputs.iter().zip(&design.input_units) {
                let values = input.numbers(input.require(name, &fix)?)?;
                panels.push(marked(
                    Panel::new(
                        format!("{title}: input {name}"),
                        time_label.clone(),
                        with_unit(name, unit),
                    )
                    .with(Series::new(name.as_str(), series(&values), PALETTE[1], Style::Line)),
                ));
            }
        }
        None => {
            // The input's other columns that hold numbers only (a column of text is left out).
            let names: Vec<&str> = targets.iter().map(|t| t.1).collect();
            let mut panel = Panel::new(format!("{title}: recorded signals"), time_label, "value");
            let mut colors = PALETTE.iter().cycle();
            for (column, name) in input.header.iter().enumerate() {
                let truth_of_a_target = name.strip_prefix("truth_").is_some_and(|t| names.contains(&t));
                if used.contains(&name.as_str()) || names.contains(&name.as_str()) || truth_of_a_target {
                    continue;
                }
                if let Ok(values) = input.numbers(column) {
                    let color = *colors.next().unwrap_or(&PALETTE[0]);
                    panel = panel.with(Series::new(name.as_str(), series(&values), color, Style::Line));
                }
            }
            if !panel.series.is_empty() {
                panels.push(marked(panel));
            }
        }
    }
    Ok(Figure {
        rows: panels.into_iter().map(|p| vec![p]).collect(),
        panel_width: 900,
        row_height: 320,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(file: &str, text: &str) -> Table {
        let mut lines = text.lines();
        let header = lines.next().unwrap().split(',').map(str::to_owned).collect();
        let rows = lines
            .enumerate()
            .map(|(i, l)| (i as u64 + 2, l.split(',').map(str::to_owned).collect()))
            .collect();
        Table {
            file: file.into(),
            header,
            rows,
        }
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
        let figure = figure(&table("run.csv", INPUT), &table("est.csv", ESTIMATES), None).unwrap();
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
        let figure = figure(&table("in.csv", input), &table("est.csv", estimates), None).unwrap();
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
        let error = figure(&table("run.csv", INPUT), &table("est.csv", &shifted), None)
            .err()
            .unwrap();
        assert!(
            matches!(error, RecordedPlotError::OtherTimes { line: 5, .. }),
            "{error}"
        );
        let short: String = ESTIMATES.lines().take(3).map(|l| format!("{l}\n")).collect();
        let error = figure(&table("run.csv", INPUT), &table("est.csv", &short), None)
            .err()
            .unwrap();
        assert!(matches!(
            error,
            RecordedPlotError::RowCount {
                input_rows: 4,
                estimate_rows: 2,
                ..
            }
        ));
        let bad = ESTIMATES.replace("refused", "maybe");
        let error = figure(&table("run.csv", INPUT), &table("est.csv", &bad), None)
            .err()
            .unwrap();
        assert!(
            error.to_string().contains("line 4, column `status`: `maybe`"),
            "{error}"
        );
    }

    #[test]
    fn the_prefix_keeps_dots_in_the_name() {
        assert_eq!(default_prefix(Path::new("out/est.v2.csv")), Path::new("out/est.v2"));
        assert_eq!(with_suffix(Path::new("out/est.v2"), "png"), Path::new("out/est.v2.png"));
    }
}
