//! How far an f32 evaluation of a map (generated tables, firmware code) may be from its f64 library
//! evaluation (the same table, the same code) on the same regressor.
//!
//! With `u = 2⁻²⁴` (f32 unit roundoff), `n_z` regressor entries and, per window, the library's
//! `t = offset + Σ g_i z_i`, its segment `k` and the segment's origin `s` (`0` for uniform knots, the
//! left knot `t_k` for searched ones, see [`firmware::Knots`]):
//! * `t` in f32 from rounded gains, offset and samples: each product is off by at most `3u` of itself
//!   (three roundings) and the `n_z` additions add `n_z u` of the running sums, so
//!   `δt ≤ (n_z + 4) u (|offset| + Σ |g_i z_i|)`; a searched knot is rounded by at most `u |t_k|`, so
//!   `t - s` is off by at most `δt + u |s|` before its own rounding;
//! * `r = a_k + b_k (t - s)`: that moves `r` by `|b| (δt + u |s|)`, and where `t` is that close to a
//!   knot the f32 side may take the neighbouring segment, which the continuity of the table keeps
//!   within as much again; with `b` the largest slope of segments `k - 1 … k + 1`, `2 |b| (δt + u |s|)`;
//! * rounding `a_k`, `b_k`, the difference, the product and the sum adds at most
//!   `4 u (|a| + |b| (|t - s| + 1))`, and the saturated values `r_min`, `r_max` are off by at most `u`
//!   of themselves.
//!
//! So `|r_f32 - r_f64| ≤ 2 |b| (δt + u |s|) + 4 u (|a| + |b| (|t - s| + 1) + |r_min| + |r_max|)`.
//! Saturation flags must agree except where `t` lies within `δt` of `0` or `t_max`, where either answer
//! is right.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x <= y)` is deliberate: a NaN must fail the check.

use firmware::{Estimate, Knots, Saturation, TargetMap};

use crate::data::DataSet;
use crate::fit::inverse_table::InverseTable;

/// The f32 unit roundoff `2⁻²⁴`.
pub const U: f64 = 1.0 / 16_777_216.0;

/// The bound above, and whether the saturation flag is decidable, for one window `z`.
pub fn tolerance(table: &InverseTable, z: &[f64]) -> (f64, bool) {
    let t = f64_map(table).project(z);
    let terms: f64 = table.offset.abs() + table.gains.iter().zip(z).map(|(g, z)| (g * z).abs()).sum::<f64>();
    let dt = (z.len() as f64 + 4.0) * U * terms;
    let last = table.segments.len() - 1;
    let k = match &table.starts {
        None => (t.max(0.0) as usize).min(last),
        Some(starts) => starts.partition_point(|&s| s <= t).saturating_sub(1),
    };
    let origin = match table.starts {
        None => 0.0,
        Some(_) => table.start(k),
    };
    let (mut a, mut b) = (0.0f64, 0.0f64);
    for segment in &table.segments[k.saturating_sub(1)..=(k + 1).min(last)] {
        a = a.max(segment[0].abs());
        b = b.max(segment[1].abs());
    }
    let t_inside = t.clamp(0.0, table.t_max());
    let tolerance = 2.0 * b * (dt + U * origin.abs())
        + 4.0 * U * (a + b * ((t_inside - origin).abs() + 1.0) + table.r_min.abs() + table.r_max.abs());
    let decidable = t.abs() > dt && (t - table.t_max()).abs() > dt;
    (tolerance, decidable)
}

/// The table's map in f64: what the library estimate runs.
fn f64_map(table: &InverseTable) -> TargetMap<'_, f64> {
    TargetMap {
        gains: &table.gains,
        offset: table.offset,
        inverse: table.as_firmware(),
    }
}

/// The f32 tables of a map, exactly as `emit` prints them (every literal round-trips to these bits).
pub struct F32Tables {
    /// The scaled gains.
    pub gains: Vec<f32>,
    /// Where the dot product starts.
    pub offset: f32,
    /// The left knots of a searched table.
    pub starts: Option<Vec<f32>>,
    /// `(a_k, b_k)`.
    pub segments: Vec<[f32; 2]>,
    /// The end of the table.
    pub t_max: f32,
    /// The estimate below the table.
    pub r_min: f32,
    /// The estimate above it.
    pub r_max: f32,
}

impl F32Tables {
    /// Rounds a table to f32.
    pub fn new(table: &InverseTable) -> Self {
        let round = |values: &[f64]| values.iter().map(|&v| v as f32).collect::<Vec<f32>>();
        F32Tables {
            gains: round(&table.gains),
            offset: table.offset as f32,
            starts: table.starts.as_deref().map(round),
            segments: table.segments.iter().map(|[a, b]| [*a as f32, *b as f32]).collect(),
            t_max: table.t_max() as f32,
            r_min: table.r_min as f32,
            r_max: table.r_max as f32,
        }
    }

    /// The firmware's view of the tables.
    pub fn as_firmware(&self) -> TargetMap<'_, f32> {
        TargetMap {
            gains: &self.gains,
            offset: self.offset,
            inverse: firmware::InverseTable {
                knots: match &self.starts {
                    None => Knots::Uniform,
                    Some(starts) => Knots::Searched(starts),
                },
                segments: &self.segments,
                t_max: self.t_max,
                r_min: self.r_min,
                r_max: self.r_max,
            },
        }
    }
}

/// An f32 evaluation that left the bound, or whose decidable saturation flag differs.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("in f32 the map gives {f32_value} ({f32_saturation:?}) where f64 gives {f64_value} ({f64_saturation:?}) (allowed difference {tolerance:e})")]
pub struct F32Mismatch {
    /// The f32 estimate.
    pub f32_value: f64,
    /// Its saturation flag.
    pub f32_saturation: Saturation,
    /// The f64 estimate.
    pub f64_value: f64,
    /// Its saturation flag.
    pub f64_saturation: Saturation,
    /// The bound.
    pub tolerance: f64,
}

/// How an f32 estimate agreed with the f64 one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Agreement {
    /// `|f32 - f64|`.
    pub difference: f64,
    /// `|f32 - f64| / tolerance` (at most 1).
    pub ratio: f64,
    /// Whether the saturation flags were compared (`false` within rounding of an edge of the table).
    pub flag_decided: bool,
}

/// The one comparison of an f32 estimate (`single`: generated tables, the chip, the host's f32 run)
/// with the f64 library estimate (`double`) of `table`'s map on the regressor `z`: within
/// [`tolerance`], and the same saturation flag unless `t` is within rounding of an edge.
pub fn compare(
    table: &InverseTable,
    z: &[f64],
    single: Estimate<f32>,
    double: Estimate<f64>,
) -> Result<Agreement, F32Mismatch> {
    let (tolerance, decidable) = tolerance(table, z);
    let difference = (f64::from(single.value) - double.value).abs();
    if !(difference <= tolerance) || (decidable && single.saturation != double.saturation) {
        return Err(F32Mismatch {
            f32_value: f64::from(single.value),
            f32_saturation: single.saturation,
            f64_value: double.value,
            f64_saturation: double.saturation,
            tolerance,
        });
    }
    Ok(Agreement {
        difference,
        ratio: difference / tolerance,
        flag_decided: decidable,
    })
}

/// Evaluates `table` in f32 (`rounded`, firmware code) and in f64 on every window of `data`; returns
/// the largest `|difference| / tolerance`, or the first window that fails [`compare`].
pub fn check_f32(table: &InverseTable, rounded: &F32Tables, data: &DataSet) -> Result<f64, F32Mismatch> {
    let (single, double) = (rounded.as_firmware(), f64_map(table));
    let (mut z, mut z32) = (Vec::new(), Vec::new());
    let mut worst: f64 = 0.0;
    for window in data.windows() {
        data.regressor(window, &mut z);
        z32.clear();
        z32.extend(z.iter().map(|&v| v as f32));
        let agreement = compare(table, &z, single.estimate(&z32), double.estimate(&z))?;
        worst = worst.max(agreement.ratio);
    }
    Ok(worst)
}
