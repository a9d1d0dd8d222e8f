//! The recorded sequence every emitted design carries (`RECORDED_Y`, `RECORDED_U`): the scenario's
//! samples in `f32`, two of them made NaN and +∞ so that whoever runs it checks that they are refused.

use crate::emit::{f32_literal, EmitError};

/// Samples of the recorded sequence where a value is replaced by NaN, then by +∞, so that every
/// consumer of it (the on-target program, tests) checks that such samples are refused harmlessly.
pub fn refused_samples(len: usize) -> Vec<usize> {
    if len >= 3 {
        vec![len / 3, 2 * len / 3]
    } else {
        vec![]
    }
}

/// The recorded sequence an emitted design carries (`RECORDED_Y`, `RECORDED_U`), as rows of a
/// recording: `scenario`'s measurements and inputs rounded to `f32` as emitted, the
/// [`refused_samples`]' first output NaN, then +∞. What the chip runs, for the host to run too.
pub fn recorded_sequence(scenario: &crate::data::Run) -> Vec<crate::recording::Row> {
    let len = scenario.measurements.len();
    let exact = |row: &[f64]| -> Vec<f64> { row.iter().map(|&v| f64::from(v as f32)).collect() };
    scenario
        .measurements
        .iter()
        .zip(scenario.inputs.iter())
        .enumerate()
        .map(|(k, (y, u))| {
            let mut y = exact(y);
            if let (Some(value), Some(first)) = (refused_value(k, len), y.first_mut()) {
                *first = value;
            }
            crate::recording::Row {
                time: None,
                run: String::new(),
                y,
                u: exact(u),
            }
        })
        .collect()
}

/// The value that replaces the first output of sample `k` of a recorded sequence of `len` samples:
/// NaN at the first of the [`refused_samples`], +∞ at the second, `None` elsewhere.
fn refused_value(k: usize, len: usize) -> Option<f64> {
    match refused_samples(len).iter().position(|&r| r == k)? {
        0 => Some(f64::NAN),
        _ => Some(f64::INFINITY),
    }
}

/// Rows `[v, …],` of a recorded sequence, one sample per line, with the refused samples' first value
/// replaced by `f32::NAN` or `f32::INFINITY`.
pub(super) fn recorded_rows(what: &str, rows: &crate::data::Rows, corrupt: bool) -> Result<String, EmitError> {
    let mut text = Vec::new();
    for (k, row) in rows.iter().enumerate() {
        let mut cells = row
            .iter()
            .enumerate()
            .map(|(i, &v)| f32_literal(&format!("{what}[{k}][{i}]"), v))
            .collect::<Result<Vec<_>, _>>()?;
        if let (true, Some(value), Some(first)) = (corrupt, refused_value(k, rows.len()), cells.first_mut()) {
            *first = if value.is_nan() {
                "f32::NAN".into()
            } else {
                "f32::INFINITY".into()
            };
        }
        text.push(format!("    [{}],", cells.join(", ")));
    }
    Ok(text.join("\n"))
}
