//! Recorded measurements as CSV: reading a recording, running the map over it as the chip does, and
//! writing simulated runs and estimates.
//!
//! A recording has a header; the columns named after the design's outputs and inputs are read, any
//! other column is ignored, one row per sample in time order. An optional column `time` (else `t`) is
//! checked against the design's sample period ([`spacing`]: within a run, each time `τ` after the
//! previous, within 5 %) and copied to the estimates as written; without it the time of row `k` is
//! `k τ`. An optional column `run` splits the file into independent runs: the observer restarts
//! whenever its value changes.
//!
//! The estimates file has one row per recorded row ([`EstimatesCsv`]): `time`, `run` (when the
//! recording has one), `status` (`ok`, `refused` for a sample with a NaN or infinite value,
//! `no_estimate_yet` while fewer than `N` samples of the run were accepted), one column per target
//! (empty unless `ok`), and `saturated_<target>` per target: `-1` or `1` when the estimate was held at
//! the low or high end of its range, `0` otherwise.

mod estimate;
mod read;
mod row;
pub mod spacing;
mod write;

pub use estimate::{
    estimate, estimate_streaming, map_row, regressors, MapEvaluator, NoTable, Precision, Step, StreamError, Window,
};
pub use read::{read, regular_or_missing, RecordingError, Row, RowReader};
pub use row::{EstimateRow, Status};
pub use write::{estimates_csv, run_csv, time_text, write_run_csv, EstimatesCsv};
