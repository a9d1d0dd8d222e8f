//! How far an f32 evaluation of a map (generated tables, firmware code) may be from its f64 library
//! evaluation on the same regressor.
//!
//! With `u = 2⁻²⁴` (f32 unit roundoff) and, per window, the library's `v = Lᵀ Z`, `η`, `Γ'(η)`:
//! * `Lᵀ Z` in f32 from rounded gains and rounded samples: `δv ≤ (n_z + 3) u Σ|L_i z_i|`;
//! * `Γ(η) = offset + Σ μ_j B(η; c_j)` in f32 from rounded `w_j`, `c_j`: each term is at most `|μ_j|`,
//!   and a relative change `u` of `c_j` changes it by at most `u B |μ_j| ≤ u |μ_j|` (the odds-ratio form
//!   of the basis keeps this bounded for every `c_j`), so `δΓ ≤ (m + 6) u (|offset| + Σ |μ_j|)`;
//! * the f32 root then moves by at most `(δv + δΓ) / Γ'(η)` (doubled, for the variation of `Γ'` over
//!   that interval), and bisection stops within `2⁻²⁴`;
//! * `r = r_min + r_span η` in f32 adds `4 u (|r_min| + r_span)`.
//!
//! So `|r_f32 - r_f64| ≤ r_span (2⁻²⁴ + 2 (δv + δΓ)/Γ'(η)) + 4 u (|r_min| + r_span)`. Saturation flags
//! must agree except where `v` lies within `δv + δΓ` of `Γ(0)` or `Γ(1)`, where either answer is right.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x <= y)` is deliberate: a NaN must fail the check.

use crate::data::DataSet;
use crate::maps::FittedMap;

/// The f32 unit roundoff `2⁻²⁴`.
pub const U: f64 = 1.0 / 16_777_216.0;

/// The bound above, and whether the saturation flag is decidable, for one window `z`.
pub fn tolerance(map: &FittedMap, z: &[f64]) -> (f64, bool) {
    let firmware_map = map.as_firmware();
    let v = firmware_map.project(z);
    let eta = firmware_map.gamma.inverse(v).eta;
    let sum_abs: f64 = map.gains.iter().zip(z).map(|(g, z)| (g * z).abs()).sum();
    let dv = (z.len() as f64 + 3.0) * U * sum_abs;
    let terms: f64 = map.mu.iter().map(|mu| mu.abs()).sum();
    let dgamma = (map.mu.len() as f64 + 6.0) * U * (map.offset.abs() + terms);
    let span = map.r_max - map.r_min;
    let slope = map.gamma().slope(eta);
    let tolerance = span * (U + 2.0 * (dv + dgamma) / slope) + 4.0 * U * (map.r_min.abs() + span);
    let gamma = map.gamma();
    let margin = dv + dgamma;
    let decidable = (v - gamma.value(0.0)).abs() > margin && (v - gamma.upper()).abs() > margin;
    (tolerance, decidable)
}

/// The f32 tables of a map, exactly as `emit` prints them (every literal round-trips to these bits).
pub struct F32Tables {
    gains: Vec<f32>,
    weights: Vec<f32>,
    odds_ratios: Vec<f32>,
    offset: f32,
    r_min: f32,
    r_span: f32,
}

impl F32Tables {
    /// Rounds a fitted map to f32.
    pub fn new(map: &FittedMap) -> Self {
        let round = |v: &[f64]| v.iter().map(|&x| x as f32).collect();
        F32Tables {
            gains: round(&map.gains),
            weights: round(&map.weights),
            odds_ratios: round(&map.odds_ratios),
            offset: map.offset as f32,
            r_min: map.r_min as f32,
            r_span: (map.r_max - map.r_min) as f32,
        }
    }

    /// The firmware's view of the tables.
    pub fn as_firmware(&self) -> firmware::TargetMap<'_, f32> {
        firmware::TargetMap {
            gains: &self.gains,
            gamma: firmware::Gamma {
                offset: self.offset,
                weights: &self.weights,
                odds_ratios: &self.odds_ratios,
            },
            r_min: self.r_min,
            r_span: self.r_span,
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

/// Evaluates `map` in f32 (rounded tables, firmware code) and in f64 on every window of `data`;
/// returns the largest `|difference| / tolerance`, or the first window beyond the bound, or whose
/// decidable saturation flag differs.
pub fn check_f32(map: &FittedMap, data: &DataSet) -> Result<f64, F32Mismatch> {
    let tables = F32Tables::new(map);
    let single = tables.as_firmware();
    let (mut z, mut z32) = (Vec::new(), Vec::new());
    let mut worst: f64 = 0.0;
    for window in data.windows() {
        data.regressor(window, &mut z);
        z32.clear();
        z32.extend(z.iter().map(|&v| v as f32));
        let (exact, rounded) = (map.estimate(&z), single.estimate(&z32));
        let (tolerance, decidable) = tolerance(map, &z);
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
