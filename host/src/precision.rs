//! How far an f32 evaluation of a map (generated tables, firmware code) may be from its f64 library
//! evaluation (the same table, the same code) on the same regressor.
//!
//! With `u = 2⁻²⁴` (f32 unit roundoff), `n_z` regressor entries and, per window, the library's
//! `t = offset + Σ g_i z_i` and segment `k = ⌊t⌋`:
//! * `t` in f32 from rounded gains, offset and samples: each product is off by at most `3u` of itself
//!   (three roundings) and the `n_z` additions add `n_z u` of the running sums, so
//!   `δt ≤ (n_z + 4) u (|offset| + Σ |g_i z_i|)`;
//! * `r = a_k + b_k t`: `t` off by `δt` moves `r` by `|b| δt`, and where `t` is within `δt` of a knot the
//!   f32 side may take the neighbouring segment, which the continuity of the table keeps within another
//!   `|b| δt`; with `b` the largest slope of segments `k - 1 … k + 1`, `2 |b| δt`;
//! * rounding `a_k`, `b_k`, the product and the sum adds at most `4 u (|a| + |b| (|t| + 1))`, and the
//!   saturated values `r_min`, `r_max` are off by at most `u` of themselves.
//!
//! So `|r_f32 - r_f64| ≤ 2 |b| δt + 4 u (|a| + |b| (|t| + 1) + |r_min| + |r_max|)`. Saturation flags
//! must agree except where `t` lies within `δt` of `0` or `K`, where either answer is right.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x <= y)` is deliberate: a NaN must fail the check.

use crate::data::DataSet;
use crate::maps::FittedMap;

/// The f32 unit roundoff `2⁻²⁴`.
pub const U: f64 = 1.0 / 16_777_216.0;

/// The bound above, and whether the saturation flag is decidable, for one window `z`; `None` for a
/// map without a table (which is never emitted).
pub fn tolerance(map: &FittedMap, z: &[f64]) -> Option<(f64, bool)> {
    let table = map.table.as_ref()?;
    let t = map.as_firmware()?.project(z);
    let terms: f64 = table.offset.abs() + table.gains.iter().zip(z).map(|(g, z)| (g * z).abs()).sum::<f64>();
    let dt = (z.len() as f64 + 4.0) * U * terms;
    let last = table.segments.len() - 1;
    let k = (t.max(0.0) as usize).min(last);
    let (mut a, mut b) = (0.0f64, 0.0f64);
    for segment in &table.segments[k.saturating_sub(1)..=(k + 1).min(last)] {
        a = a.max(segment[0].abs());
        b = b.max(segment[1].abs());
    }
    let t_inside = t.clamp(0.0, table.segments.len() as f64);
    let tolerance = 2.0 * b * dt + 4.0 * U * (a + b * (t_inside + 1.0) + table.r_min.abs() + table.r_max.abs());
    let decidable = t.abs() > dt && (t - table.segments.len() as f64).abs() > dt;
    Some((tolerance, decidable))
}

/// The f32 tables of a map, exactly as `emit` prints them (every literal round-trips to these bits).
pub struct F32Tables {
    gains: Vec<f32>,
    offset: f32,
    segments: Vec<[f32; 2]>,
    t_max: f32,
    r_min: f32,
    r_max: f32,
}

impl F32Tables {
    /// Rounds a fitted map's table to f32 (`None` for a map without a table).
    pub fn new(map: &FittedMap) -> Option<Self> {
        let table = map.table.as_ref()?;
        Some(F32Tables {
            gains: table.gains.iter().map(|&g| g as f32).collect(),
            offset: table.offset as f32,
            segments: table.segments.iter().map(|[a, b]| [*a as f32, *b as f32]).collect(),
            t_max: table.segments.len() as f32,
            r_min: table.r_min as f32,
            r_max: table.r_max as f32,
        })
    }

    /// The firmware's view of the tables.
    pub fn as_firmware(&self) -> firmware::TargetMap<'_, f32> {
        firmware::TargetMap {
            gains: &self.gains,
            offset: self.offset,
            inverse: firmware::InverseTable {
                segments: &self.segments,
                t_max: self.t_max,
                r_min: self.r_min,
                r_max: self.r_max,
            },
        }
    }
}

/// An f32 evaluation that left the bound.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("in f32 the map gives {f32_value} where f64 gives {f64_value} (allowed difference {tolerance:e})")]
pub struct F32Mismatch {
    /// The f32 estimate.
    pub f32_value: f64,
    /// The f64 estimate.
    pub f64_value: f64,
    /// The bound.
    pub tolerance: f64,
}

/// Evaluates `map` in f32 (its rounded `tables`, firmware code) and in f64 on every window of `data`;
/// returns the largest `|difference| / tolerance`, or the first window beyond the bound, or whose
/// decidable saturation flag differs.
pub fn check_f32(map: &FittedMap, tables: &F32Tables, data: &DataSet) -> Result<f64, F32Mismatch> {
    let single = tables.as_firmware();
    let (mut z, mut z32) = (Vec::new(), Vec::new());
    let mut worst: f64 = 0.0;
    for window in data.windows() {
        data.regressor(window, &mut z);
        z32.clear();
        z32.extend(z.iter().map(|&v| v as f32));
        let (exact, rounded) = (map.estimate(&z), single.estimate(&z32));
        let (tolerance, decidable) = tolerance(map, &z).unwrap_or((0.0, true));
        let difference = (f64::from(rounded.value) - exact.value).abs();
        let flags_differ = decidable && exact.saturation != rounded.saturation;
        if !(difference <= tolerance) || flags_differ {
            return Err(F32Mismatch {
                f32_value: f64::from(rounded.value),
                f64_value: exact.value,
                tolerance,
            });
        }
        worst = worst.max(difference / tolerance);
    }
    Ok(worst)
}
