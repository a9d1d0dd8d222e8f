//! Recorded measurements as CSV: writing simulated runs, and estimating over a recorded file with
//! the library maps (the firmware's code in `f64`).
//!
//! An input file has a header; the columns named after the design's outputs and inputs are read, any
//! other column is ignored, one row per sample in time order. An optional column `run` splits the file
//! into independent runs: the observer restarts whenever its value changes. The output has one row per
//! input row and one column per target, empty while no estimate exists (fewer than N samples in the
//! run, or a sample with a NaN/infinite value was refused), plus `saturated` (1 when any target was
//! clamped to its learning range, 0 otherwise).

use std::collections::VecDeque;
use std::path::Path;

use crate::data::Run;
use crate::fit::maps::FittedMap;
use crate::spec::Design;

/// Why a recorded file could not be processed. Nothing is written when this happens.
#[derive(Debug, thiserror::Error)]
pub enum RecordingError {
    /// The file cannot be read or parsed as CSV.
    #[error("{file}: {message}")]
    Csv {
        /// The file.
        file: String,
        /// What went wrong.
        message: String,
    },
    /// A column the design needs is missing from the header.
    #[error("{file}: no column `{column}` in the header (found: {found}); the design `{design}` reads {needed}")]
    MissingColumn {
        /// The file.
        file: String,
        /// The missing column.
        column: String,
        /// The header.
        found: String,
        /// The design.
        design: String,
        /// The columns it needs.
        needed: String,
    },
    /// A column the design reads is named twice in the header.
    #[error("{file}: the header names column `{column}` twice: keep one")]
    DuplicateColumn {
        /// The file.
        file: String,
        /// The column.
        column: String,
    },
    /// A cell is not a number, or beyond the range of `f64`.
    #[error("{file}: line {line}, column `{column}`: `{cell}` is not a number within the range of f64")]
    NotANumber {
        /// The file.
        file: String,
        /// Line number (1 is the header).
        line: u64,
        /// Column name.
        column: String,
        /// The cell.
        cell: String,
    },
}

/// One sample of a recorded file.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Value of the `run` column ("" when there is none).
    pub run: String,
    /// Outputs, in the design's order.
    pub y: Vec<f64>,
    /// Inputs, in the design's order.
    pub u: Vec<f64>,
}

/// Reads the columns `design` needs from `path` (all rows; see [`RowReader`] for the rules).
pub fn read(design: &Design, path: &Path) -> Result<Vec<Row>, RecordingError> {
    let mut reader = RowReader::open(design, path)?;
    let mut rows = Vec::new();
    while let Some(row) = reader.next_row()? {
        rows.push(row);
    }
    Ok(rows)
}

/// The rows of a recorded file, one at a time (memory independent of the file's length).
///
/// Lines are counted by record (the header is line 1): exact for any line ending (`\n`, `\r\n`, `\r`)
/// as long as no quoted field spans lines. Columns the design does not read may hold anything, even
/// bytes that are not UTF-8. A needed column named twice is refused, as is a number beyond the range
/// of `f64` (`1e400`); `nan` and `inf` written as such are kept, and the observer refuses them.
pub struct RowReader {
    reader: csv::Reader<std::fs::File>,
    file: String,
    header: Vec<String>,
    output_columns: Vec<usize>,
    input_columns: Vec<usize>,
    run_column: Option<usize>,
    record: csv::ByteRecord,
    line: u64,
}

impl RowReader {
    /// Opens `path` and checks its header against the columns `design` reads.
    pub fn open(design: &Design, path: &Path) -> Result<Self, RecordingError> {
        let file = path.display().to_string();
        let csv_error = |e: csv::Error| RecordingError::Csv {
            file: file.clone(),
            message: e.to_string(),
        };
        let mut reader = csv::ReaderBuilder::new()
            .trim(csv::Trim::All)
            .from_path(path)
            .map_err(csv_error)?;
        let header: Vec<String> = reader
            .byte_headers()
            .map_err(csv_error)?
            .iter()
            .map(|h| String::from_utf8_lossy(h).into_owned())
            .collect();
        let outputs: Vec<&str> = design.model.outputs.iter().map(|o| o.name.as_str()).collect();
        let inputs: Vec<&str> = design.model.inputs.iter().map(String::as_str).collect();
        let column = |name: &str| {
            let mut positions = header.iter().enumerate().filter(|(_, h)| *h == name).map(|(i, _)| i);
            match (positions.next(), positions.next()) {
                (Some(i), None) => Ok(Some(i)),
                (None, _) => Ok(None),
                (Some(_), Some(_)) => Err(RecordingError::DuplicateColumn {
                    file: file.clone(),
                    column: name.to_owned(),
                }),
            }
        };
        let needed = |name: &str| {
            column(name)?.ok_or_else(|| RecordingError::MissingColumn {
                file: file.clone(),
                column: name.to_owned(),
                found: header.join(", "),
                design: design.name.clone(),
                needed: outputs.iter().chain(&inputs).copied().collect::<Vec<_>>().join(", "),
            })
        };
        let output_columns = outputs.iter().map(|n| needed(n)).collect::<Result<Vec<_>, _>>()?;
        let input_columns = inputs.iter().map(|n| needed(n)).collect::<Result<Vec<_>, _>>()?;
        let run_column = column("run")?;
        Ok(RowReader {
            reader,
            file,
            header,
            output_columns,
            input_columns,
            run_column,
            record: csv::ByteRecord::new(),
            line: 1,
        })
    }

    /// The next row, `None` at the end of the file.
    pub fn next_row(&mut self) -> Result<Option<Row>, RecordingError> {
        let more = self
            .reader
            .read_byte_record(&mut self.record)
            .map_err(|e| RecordingError::Csv {
                file: self.file.clone(),
                message: e.to_string(),
            })?;
        if !more {
            return Ok(None);
        }
        self.line += 1;
        let text = |c: usize| String::from_utf8_lossy(self.record.get(c).unwrap_or(b"")).into_owned();
        let number = |c: usize| -> Result<f64, RecordingError> {
            let cell = text(c);
            let not_a_number = || RecordingError::NotANumber {
                file: self.file.clone(),
                line: self.line,
                column: self.header[c].clone(),
                cell: cell.clone(),
            };
            let value = cell.parse::<f64>().map_err(|_| not_a_number())?;
            // `1e400` parses as infinity: out of range, not an infinity the user wrote.
            let written_infinite = cell
                .trim_start_matches(['+', '-'])
                .to_ascii_lowercase()
                .starts_with("inf");
            if value.is_infinite() && !written_infinite {
                return Err(not_a_number());
            }
            Ok(value)
        };
        Ok(Some(Row {
            run: self.run_column.map(text).unwrap_or_default(),
            y: self
                .output_columns
                .iter()
                .map(|&c| number(c))
                .collect::<Result<_, _>>()?,
            u: self
                .input_columns
                .iter()
                .map(|&c| number(c))
                .collect::<Result<_, _>>()?,
        }))
    }
}

/// Estimates over `rows` as they are read and writes each estimate row to `out` as it is known (the
/// same text as [`estimates_csv`] of [`estimate`] on all rows, in memory of `N` rows).
pub fn estimate_streaming(
    maps: &[FittedMap],
    horizon: usize,
    rows: &mut RowReader,
    out: &mut impl std::io::Write,
) -> Result<(), StreamError> {
    let names: Vec<&str> = maps.iter().map(|m| m.target.as_str()).collect();
    out.write_all((names.join(",") + ",saturated\n").as_bytes())?;
    let mut window: VecDeque<Row> = VecDeque::with_capacity(horizon + 1);
    let mut previous_run: Option<String> = None;
    let mut z = Vec::new();
    while let Some(row) = rows.next_row()? {
        if previous_run.as_deref() != Some(row.run.as_str()) {
            window.clear();
            previous_run = Some(row.run.clone());
        }
        let estimates: EstimateRow = if row.y.iter().chain(&row.u).any(|v| !v.is_finite()) {
            vec![None; maps.len()]
        } else {
            if window.len() == horizon {
                window.pop_back();
            }
            window.push_front(row);
            if window.len() == horizon {
                // Newest first, all outputs of one instant together, then all inputs.
                z.clear();
                z.extend(window.iter().flat_map(|r| r.y.iter().copied()));
                z.extend(window.iter().flat_map(|r| r.u.iter().copied()));
                maps.iter()
                    .map(|m| {
                        let e = m.estimate(&z);
                        Some((e.value, e.saturation.is_saturated()))
                    })
                    .collect()
            } else {
                vec![None; maps.len()]
            }
        };
        out.write_all(estimate_line(&estimates).as_bytes())?;
    }
    Ok(())
}

/// Why streaming estimates stopped.
#[derive(Debug, thiserror::Error)]
pub enum StreamError {
    /// The recorded file.
    #[error(transparent)]
    Recording(#[from] RecordingError),
    /// Writing the estimates.
    #[error("writing the estimates: {0}")]
    Io(#[from] std::io::Error),
}

/// One estimate row: per target `Some((value, saturated))`, or `None` where there is no estimate.
pub type EstimateRow = Vec<Option<(f64, bool)>>;

/// The regressor `Z` for every row, with the observer's semantics: a window of the last N accepted
/// samples, restarted at each new `run`; `None` while fewer than N samples of the run were accepted,
/// and on a row whose NaN/infinite sample was refused.
pub fn regressors(horizon: usize, rows: &[Row]) -> Vec<Option<Vec<f64>>> {
    let mut window: VecDeque<&Row> = VecDeque::with_capacity(horizon);
    let mut previous_run: Option<&str> = None;
    rows.iter()
        .map(|row| {
            if previous_run != Some(row.run.as_str()) {
                window.clear();
                previous_run = Some(&row.run);
            }
            if row.y.iter().chain(&row.u).any(|v| !v.is_finite()) {
                return None;
            }
            if window.len() == horizon {
                window.pop_back();
            }
            window.push_front(row);
            (window.len() == horizon).then(|| {
                // Newest first, all outputs of one instant together, then all inputs.
                let mut z: Vec<f64> = window.iter().flat_map(|r| r.y.iter().copied()).collect();
                z.extend(window.iter().flat_map(|r| r.u.iter().copied()));
                z
            })
        })
        .collect()
}

/// Runs the library maps over `rows` ([`regressors`]): per row, per target, the estimate and whether
/// it saturated.
pub fn estimate(maps: &[FittedMap], horizon: usize, rows: &[Row]) -> Vec<EstimateRow> {
    regressors(horizon, rows)
        .into_iter()
        .map(|z| match z {
            Some(z) => maps
                .iter()
                .map(|m| {
                    let e = m.estimate(&z);
                    Some((e.value, e.saturation.is_saturated()))
                })
                .collect(),
            None => vec![None; maps.len()],
        })
        .collect()
}

/// CSV text of the estimates: one column per target, then `saturated`.
pub fn estimates_csv(target_names: &[&str], estimates: &[EstimateRow]) -> String {
    let mut text = target_names.join(",") + ",saturated\n";
    for row in estimates {
        text += &estimate_line(row);
    }
    text
}

/// One line of the estimates file: a value per target (empty without an estimate), then `saturated`.
fn estimate_line(row: &[Option<(f64, bool)>]) -> String {
    let cells: Vec<String> = row
        .iter()
        .map(|e| e.map(|(v, _)| format!("{v}")).unwrap_or_default())
        .collect();
    let saturated = if row.iter().all(Option::is_none) {
        String::new()
    } else {
        u8::from(row.iter().any(|e| e.is_some_and(|(_, s)| s))).to_string()
    };
    format!("{},{saturated}\n", cells.join(","))
}

/// CSV text of a simulated run: `time`, the states (true values), the outputs (with noise) and inputs.
pub fn run_csv(design: &Design, run: &Run) -> String {
    let mut text = Vec::new();
    write_run_csv(design, run, &mut text).expect("writing into memory cannot fail");
    String::from_utf8(text).expect("the CSV is ASCII")
}

/// [`run_csv`], written line by line into `out`.
pub fn write_run_csv(design: &Design, run: &Run, out: &mut impl std::io::Write) -> std::io::Result<()> {
    let names: Vec<&str> = std::iter::once("time")
        .chain(design.model.states.iter().map(String::as_str))
        .chain(design.model.outputs.iter().map(|o| o.name.as_str()))
        .chain(design.model.inputs.iter().map(String::as_str))
        .collect();
    writeln!(out, "{}", names.join(","))?;
    for (k, ((x, y), u)) in run.states.iter().zip(&run.measurements).zip(&run.inputs).enumerate() {
        let values: Vec<String> = std::iter::once(k as f64 * design.tau)
            .chain(x.iter().copied())
            .chain(y.iter().copied())
            .chain(u.iter().copied())
            .map(|v| format!("{v}"))
            .collect();
        writeln!(out, "{}", values.join(","))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::{DataSet, Run, Window};

    /// Rows of two runs with two outputs and one input, every value distinct.
    fn rows() -> Vec<Row> {
        (0..14)
            .map(|k| Row {
                run: if k < 6 { "a".into() } else { "b".into() },
                y: vec![k as f64, 100.0 + k as f64],
                u: vec![1000.0 + k as f64],
            })
            .collect()
    }

    #[test]
    fn regressors_match_the_learning_data_construction() {
        // The same samples as runs of a DataSet, whose regressor code is independent of this one.
        let rows = rows();
        let as_run = |rows: &[Row]| Run {
            states: vec![vec![]; rows.len()].into(),
            inputs: rows.iter().map(|r| r.u.clone()).collect(),
            measurements: rows.iter().map(|r| r.y.clone()).collect(),
            targets: vec![vec![]; rows.len()].into(),
            parameters: Vec::new(),
        };
        let data = DataSet {
            runs: vec![as_run(&rows[..6]), as_run(&rows[6..])],
            horizon: 3,
        };
        let computed = regressors(3, &rows);
        let mut z = Vec::new();
        for (k, got) in computed.iter().enumerate() {
            let (run, end) = if k < 6 { (0, k) } else { (1, k - 6) };
            if end + 1 < 3 {
                assert!(got.is_none(), "row {k}");
                continue;
            }
            data.regressor(Window { run, end }, &mut z);
            assert_eq!(got.as_deref(), Some(&z[..]), "row {k}");
        }
    }

    #[test]
    fn a_refused_row_is_skipped_not_counted() {
        let mut rows = rows();
        rows[9].u[0] = f64::NAN;
        let computed = regressors(3, &rows);
        assert!(computed[9].is_none());
        // Row 10's window is rows 10, 8, 7 (row 9 refused, run b starts at row 6).
        let expected: Vec<f64> = vec![10.0, 110.0, 8.0, 108.0, 7.0, 107.0, 1010.0, 1008.0, 1007.0];
        assert_eq!(computed[10].as_deref(), Some(&expected[..]));
    }
}
