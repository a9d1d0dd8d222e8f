//! The two files read one record at a time: a CSV reader that holds one row, so that `plot` reads a
//! recording of any length in the same memory.

use std::path::{Path, PathBuf};

use super::RecordedPlotError;

/// A CSV file read one record at a time (cells trimmed): memory independent of its length.
pub(super) struct Csv {
    pub(super) file: PathBuf,
    pub(super) header: Vec<String>,
    pub(super) reader: csv::Reader<std::fs::File>,
    pub(super) record: csv::StringRecord,
    /// The line of the current record (1 is the header).
    pub(super) line: u64,
}

impl Csv {
    pub(super) fn open(file: &Path) -> Result<Self, RecordedPlotError> {
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

    pub(super) fn column(&self, name: &str) -> Option<usize> {
        self.header.iter().position(|h| h == name)
    }

    pub(super) fn require(&self, name: &str, fix: &str) -> Result<usize, RecordedPlotError> {
        self.column(name).ok_or_else(|| RecordedPlotError::MissingColumn {
            file: self.file.clone(),
            column: name.to_owned(),
            found: self.header.join(", "),
            fix: fix.to_owned(),
        })
    }

    /// Reads the next record; `false` at the end of the file.
    pub(super) fn advance(&mut self) -> Result<bool, RecordedPlotError> {
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

    pub(super) fn cell(&self, column: usize) -> &str {
        self.record.get(column).unwrap_or("")
    }

    /// The cell as a number, an empty cell as NaN (a gap); a cell that is not a number is an error.
    pub(super) fn number(&self, column: usize) -> Result<f64, RecordedPlotError> {
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
