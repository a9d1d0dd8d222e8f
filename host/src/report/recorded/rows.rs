//! Both files read row by row and checked as `estimate` would have written them (same rows, same
//! times, the design's sample period, known status and saturation cells), each row handed on as
//! numbers.

use std::path::Path;

use super::columns::{Layout, Role, Side};
use super::stream::Csv;
use super::RecordedPlotError;
use crate::spec::Design;

/// `status` of an estimates row.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Status {
    Ok,
    Refused,
    NoEstimateYet,
    /// The observer restarted at this sample (a step that was not finite).
    Restarted,
}

/// One target on one row: the estimate (NaN unless `ok`), the truth (NaN without), the saturation.
#[derive(Clone, Copy, Debug)]
pub(super) struct TargetRow {
    pub(super) estimate: f64,
    pub(super) truth: f64,
    pub(super) saturation: i8,
}

/// One row of both files, checked.
#[derive(Debug)]
pub(super) struct Row {
    pub(super) time: f64,
    pub(super) status: Status,
    /// A new run starts here (the observer restarted).
    pub(super) restart: bool,
    pub(super) targets: Vec<TargetRow>,
    /// In the order of [`Layout::signals`]; NaN for an empty cell or a column that is not numeric.
    pub(super) signals: Vec<f64>,
}

/// Opens both files and reads their headers.
pub(super) fn open(
    input: &Path,
    estimates: &Path,
    design: Option<&Design>,
) -> Result<(Csv, Csv, Layout), RecordedPlotError> {
    let (input, estimates) = (Csv::open(input)?, Csv::open(estimates)?);
    let layout = Layout::new(&input, &estimates, design)?;
    Ok((input, estimates, layout))
}

/// Reads both files row by row, checks each row as `estimate` would have written it, and gives it
/// to `each`; returns which signals hold numbers only.
pub(super) fn scan(
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
            "restarted" => Status::Restarted,
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
