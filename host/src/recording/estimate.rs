//! The map over a recording as the chip runs it: a window of the last `N` accepted samples, restarted
//! at each new `run`, evaluated in the library's `f64` or in the firmware's `f32` (the emitted
//! tables, so bit for bit what the generated observer computes).

use std::collections::VecDeque;

use firmware::Saturation;

use crate::emit::precision::F32Tables;
use crate::fit::maps::FittedMap;

use super::read::{RecordingError, Row, RowReader};
use super::row::{EstimateRow, Status};
use super::write::EstimatesCsv;

/// The arithmetic `estimate` runs in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Precision {
    /// The host library in `f64`: the reference the emitted tables are certified against.
    #[default]
    F64,
    /// The firmware's code on the emitted `f32` tables: what the chip computes, bit for bit.
    F32,
}

/// The maps of a design as `estimate` evaluates them in a [`Precision`].
pub struct MapEvaluator<'a> {
    library: &'a [FittedMap],
    firmware: Option<Vec<F32Tables>>,
}

/// `--precision f32` on a map without an emitted table.
#[derive(Debug, thiserror::Error)]
#[error(
    "target `{target}` has no certified table, so there is no f32 observer to mirror; use the default precision (f64)"
)]
pub struct NoTable {
    /// The target.
    pub target: String,
}

impl<'a> MapEvaluator<'a> {
    /// The maps in `precision`: `f32` needs each map's certified table (what `gen` emits).
    pub fn new(maps: &'a [FittedMap], precision: Precision) -> Result<Self, NoTable> {
        let firmware = match precision {
            Precision::F64 => None,
            Precision::F32 => Some(
                maps.iter()
                    .map(|m| {
                        m.table.as_ref().map(F32Tables::new).ok_or_else(|| NoTable {
                            target: m.target.clone(),
                        })
                    })
                    .collect::<Result<_, _>>()?,
            ),
        };
        Ok(MapEvaluator {
            library: maps,
            firmware,
        })
    }

    /// The targets' names, in order.
    pub fn targets(&self) -> Vec<&str> {
        self.library.iter().map(|m| m.target.as_str()).collect()
    }

    /// Every target from the regressor `z` (each value rounded to `f32` first in that precision, as
    /// the chip receives it).
    pub fn estimate(&self, z: &[f64]) -> Vec<(f64, Saturation)> {
        match &self.firmware {
            None => self
                .library
                .iter()
                .map(|m| {
                    let e = m.estimate(z);
                    (e.value, e.saturation)
                })
                .collect(),
            Some(tables) => {
                let z: Vec<f32> = z.iter().map(|&v| v as f32).collect();
                tables
                    .iter()
                    .map(|t| {
                        let e = t.as_firmware().estimate(&z);
                        (f64::from(e.value), e.saturation)
                    })
                    .collect()
            }
        }
    }
}

/// The observer's window over a recording: the last `N` accepted samples of the current run.
pub struct Window {
    horizon: usize,
    samples: VecDeque<Row>,
    run: Option<String>,
    z: Vec<f64>,
}

/// What one row did to the [`Window`].
pub enum Step<'w> {
    /// Refused (a NaN or infinite value): the window is unchanged.
    Refused,
    /// Accepted, but fewer than `N` samples of this run so far.
    Filling,
    /// The regressor `Z`: all outputs newest first, then all inputs newest first.
    Full(&'w [f64]),
}

impl Window {
    /// An empty window of `horizon` samples.
    pub fn new(horizon: usize) -> Self {
        Window {
            horizon,
            samples: VecDeque::with_capacity(horizon + 1),
            run: None,
            z: Vec::new(),
        }
    }

    /// Takes the next row (a new `run` value restarts the window first).
    pub fn push(&mut self, row: &Row) -> Step<'_> {
        if self.run.as_deref() != Some(row.run.as_str()) {
            self.samples.clear();
            self.run = Some(row.run.clone());
        }
        if row.y.iter().chain(&row.u).any(|v| !v.is_finite()) {
            return Step::Refused;
        }
        if self.samples.len() == self.horizon {
            self.samples.pop_back();
        }
        self.samples.push_front(row.clone());
        if self.samples.len() < self.horizon {
            return Step::Filling;
        }
        self.z.clear();
        self.z.extend(self.samples.iter().flat_map(|r| r.y.iter().copied()));
        self.z.extend(self.samples.iter().flat_map(|r| r.u.iter().copied()));
        Step::Full(&self.z)
    }
}

/// The regressor `Z` for every row, with the observer's semantics ([`Window`]): `None` while fewer
/// than `N` samples of the run were accepted, and on a refused row.
pub fn regressors(horizon: usize, rows: &[Row]) -> Vec<Option<Vec<f64>>> {
    let mut window = Window::new(horizon);
    rows.iter()
        .map(|row| match window.push(row) {
            Step::Full(z) => Some(z.to_vec()),
            Step::Refused | Step::Filling => None,
        })
        .collect()
}

/// The map's output for one row.
pub fn map_row(maps: &MapEvaluator<'_>, step: Step<'_>) -> EstimateRow {
    match step {
        Step::Refused => EstimateRow::without(Status::Refused),
        Step::Filling => EstimateRow::without(Status::NoEstimateYet),
        Step::Full(z) => EstimateRow {
            status: Status::Ok,
            targets: maps.estimate(z),
        },
    }
}

/// The maps over `rows`: one [`EstimateRow`] per row.
pub fn estimate(maps: &MapEvaluator<'_>, horizon: usize, rows: &[Row]) -> Vec<EstimateRow> {
    let mut window = Window::new(horizon);
    rows.iter().map(|row| map_row(maps, window.push(row))).collect()
}

/// [`estimate`] over `rows` as they are read, each line written to `out` as it is known: the same
/// text as [`super::write::estimates_csv`], in memory of `N` rows.
pub fn estimate_streaming(
    maps: &MapEvaluator<'_>,
    horizon: usize,
    csv: &EstimatesCsv,
    rows: &mut RowReader,
    out: &mut impl std::io::Write,
) -> Result<(), StreamError> {
    out.write_all(csv.header().as_bytes())?;
    let mut window = Window::new(horizon);
    let mut k = 0;
    while let Some(row) = rows.next_row()? {
        let estimates = map_row(maps, window.push(&row));
        out.write_all(csv.line(k, &row, &estimates).as_bytes())?;
        k += 1;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::{DataSet, Run};

    /// Rows of two runs with two outputs and one input, every value distinct.
    fn rows() -> Vec<Row> {
        (0..14)
            .map(|k| Row {
                time: None,
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
            data.regressor(crate::data::Window { run, end }, &mut z);
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
