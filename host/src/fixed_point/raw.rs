//! Raw samples: each signal's scaling (declared, or the default Q format) and the counts a converter
//! gives for a value, as the integer map reads them.

use crate::data::DataSet;
use crate::spec::{FixedSpec, RawScale};

use super::{DEFAULT_HEADROOM, DEFAULT_RAW};

/// The scaling of every output and input: as declared, or the default Q format from `learning`.
pub fn scalings(spec: &FixedSpec, learning: &DataSet) -> (Vec<RawScale>, Vec<RawScale>) {
    let largest = |column: usize, inputs: bool| {
        learning
            .runs
            .iter()
            .flat_map(|run| {
                if inputs {
                    run.inputs.iter()
                } else {
                    run.measurements.iter()
                }
            })
            .map(|row| row[column].abs())
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max)
    };
    let resolve = |declared: &Option<RawScale>, column: usize, inputs: bool| {
        declared.unwrap_or_else(|| default_scale(largest(column, inputs)))
    };
    (
        spec.outputs
            .iter()
            .enumerate()
            .map(|(i, d)| resolve(d, i, false))
            .collect(),
        spec.inputs
            .iter()
            .enumerate()
            .map(|(i, d)| resolve(d, i, true))
            .collect(),
    )
}

/// The default Q format for a signal whose largest learning magnitude is `largest`.
pub fn default_scale(largest: f64) -> RawScale {
    let cover = if largest > 0.0 { DEFAULT_HEADROOM * largest } else { 1.0 };
    // The largest q with 32767 · 2^−q ≥ cover.
    let q = (f64::from(DEFAULT_RAW) / cover).log2().floor() as i32;
    RawScale {
        scale: 2f64.powi(-q),
        offset: 0.0,
        min: -DEFAULT_RAW,
        max: DEFAULT_RAW,
    }
}

/// The raw count a converter with `scale` gives for `value`: rounded, clamped to its range (a
/// converter saturates); `None` for a non-finite value.
pub fn to_raw(value: f64, scale: &RawScale) -> Option<i32> {
    let raw = ((value - scale.offset) / scale.scale).round();
    if raw.is_nan() {
        return None;
    }
    Some(raw.clamp(f64::from(scale.min), f64::from(scale.max)) as i32)
}

/// The raw counts of a recorded sequence (rows of values, [`crate::emit::recorded_sequence`]'s): each
/// value converted by its signal's scaling ([`to_raw`]); a non-finite value (the sequence's refused
/// samples) becomes `max + 1`, out of range, so that the integer observer refuses it as the float
/// one refuses the NaN.
pub fn raw_rows(rows: &[Vec<f64>], scales: &[RawScale]) -> Vec<Vec<i32>> {
    rows.iter()
        .map(|row| {
            row.iter()
                .zip(scales)
                .map(|(&v, s)| match v.is_finite() {
                    true => to_raw(v, s).unwrap_or(s.max),
                    false => s.max + 1,
                })
                .collect()
        })
        .collect()
}
