//! The rows of a recorded CSV file: the columns a design reads, checked and parsed.

use std::path::Path;

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
    /// A time is not a number, or not the design's sample period after the previous one.
    #[error("{file}: line {line}, column `{column}`: {source}")]
    Time {
        /// The file.
        file: String,
        /// Line number (1 is the header).
        line: u64,
        /// The time column's name (`time` or `t`).
        column: String,
        /// What is wrong.
        source: Box<super::spacing::SpacingError>,
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
    /// The `time` (else `t`) cell as written, `None` without such a column.
    pub time: Option<String>,
    /// Value of the `run` column ("" when there is none).
    pub run: String,
    /// Outputs, in the design's order.
    pub y: Vec<f64>,
    /// Inputs, in the design's order.
    pub u: Vec<f64>,
}

/// `false` when `path` exists but is not a regular file: a folder, a device such as `/dev/zero` or
/// a pipe, which may never end (a reader would run until memory is gone) and cannot be read twice. A
/// missing path passes, so that opening it names the real error.
pub fn regular_or_missing(path: &Path) -> bool {
    !path.exists() || std::fs::metadata(path).is_ok_and(|m| m.is_file())
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
/// of `f64` (`1e400`), and a time that is not the design's sample period after the previous one of
/// its run ([`super::spacing`]); `nan` and `inf` written as such are kept, and the observer refuses
/// them.
pub struct RowReader {
    reader: csv::Reader<std::fs::File>,
    file: String,
    header: Vec<String>,
    output_columns: Vec<usize>,
    input_columns: Vec<usize>,
    run_column: Option<usize>,
    time_column: Option<usize>,
    spacing: super::spacing::Spacing,
    record: csv::ByteRecord,
    line: u64,
}

impl RowReader {
    /// `true` when the file has a `run` column (the estimates then repeat it).
    pub fn has_runs(&self) -> bool {
        self.run_column.is_some()
    }

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
        let time_column = match column("time")? {
            Some(c) => Some(c),
            None => column("t")?,
        };
        Ok(RowReader {
            reader,
            file,
            header,
            output_columns,
            input_columns,
            run_column,
            time_column,
            spacing: super::spacing::Spacing::new(design.tau, &design.time_unit),
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
        let run = self.run_column.map(text).unwrap_or_default();
        let time = self.time_column.map(text);
        if let (Some(cell), Some(c)) = (&time, self.time_column) {
            self.spacing.check(&run, cell).map_err(|source| RecordingError::Time {
                file: self.file.clone(),
                line: self.line,
                column: self.header[c].clone(),
                source: Box::new(source),
            })?;
        }
        Ok(Some(Row {
            time,
            run,
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
