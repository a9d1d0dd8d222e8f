//! How far an f32 evaluation of a map (generated tables, firmware code) may be from its f64 library
//! evaluation on the same regressor.
//!
//! With `u = 2⁻²⁴` (f32 unit roundoff) and, per window, the library's `v = Lᵀ Z`, `η`, `Γ'(η)`:
//! * `Lᵀ Z` in f32 from rounded gains and rounded samples: `δv ≤ (n_z + 3) u Σ|L_i z_i|`;
//! * `Γ(η) = offset + Σ μ_j B(η; b_j)` in f32 from rounded `w_j`, `b_j` (each term is at most `|μ_j|`,
//!   a rounded `b_j` moves it by at most `u κ_j |μ_j|`, `κ_j = max(1, |b_j|/(1+b_j))`):
//!   `δΓ ≤ (m + 6) u (|offset| + Σ κ_j |μ_j|)`;
//! * the f32 root then moves by at most `(δv + δΓ) / Γ'(η)` (doubled, for the variation of `Γ'` over
//!   that interval), and bisection stops within `2⁻²⁴`;
//! * `r = r_min + r_span η` in f32 adds `4 u (|r_min| + r_span)`.
//!
//! So `|r_f32 - r_f64| ≤ r_span (2⁻²⁴ + 2 (δv + δΓ)/Γ'(η)) + 4 u (|r_min| + r_span)`. Saturation flags
//! must agree except where `v` lies within `δv + δΓ` of `Γ(0)` or `Γ(1)`, where either answer is right.

use host::maps::FittedMap;

/// The f32 unit roundoff `2⁻²⁴`.
pub const U: f64 = 1.0 / 16_777_216.0;

/// The bound above, and whether the saturation flag is decidable, for one window `z`.
pub fn tolerance(map: &FittedMap, z: &[f64]) -> (f64, bool) {
    let firmware_map = map.as_firmware();
    let v = firmware_map.project(z);
    let eta = firmware_map.gamma.inverse(v).eta;
    let sum_abs: f64 = map.gains.iter().zip(z).map(|(g, z)| (g * z).abs()).sum();
    let dv = (z.len() as f64 + 3.0) * U * sum_abs;
    let terms: f64 = map
        .mu
        .iter()
        .zip(&map.curvatures)
        .map(|(mu, b)| mu.abs() * 1f64.max(b.abs() / (1.0 + b)))
        .sum();
    let dgamma = (map.mu.len() as f64 + 6.0) * U * (map.offset.abs() + terms);
    let span = map.r_max - map.r_min;
    let slope = map.gamma().slope(eta);
    let tolerance = span * (U + 2.0 * (dv + dgamma) / slope) + 4.0 * U * (map.r_min.abs() + span);
    let gamma = map.gamma();
    let margin = dv + dgamma;
    let decidable = (v - gamma.value(0.0)).abs() > margin && (v - gamma.upper()).abs() > margin;
    (tolerance, decidable)
}
