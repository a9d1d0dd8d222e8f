//! The generated observer (f32 tables, the firmware's ring buffer) against the host's library
//! estimate (f64, the same firmware code on the regressor), window by window, on every shipped design's
//! validation runs and on its scenario.
//!
//! # Tolerance
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

use host::data::{self, DataSet, Window};
use host::maps::FittedMap;
use integration_tests::{build, load_relative};
use rand::SeedableRng;

const U: f64 = 1.0 / 16_777_216.0;

/// The bound above, and whether the flag is decidable, for one window.
fn tolerance(map: &FittedMap, z: &[f64]) -> (f64, bool) {
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

struct Comparison {
    estimates: usize,
    worst_ratio: f64,
    undecided_flags: usize,
}

macro_rules! compare_design {
    ($name:ident) => {{
        use generated::$name as tables;
        let design = load_relative(tables::SPEC);
        assert_eq!(design.name, tables::NAME);
        let result = build(&design);
        let maps: Vec<&FittedMap> = result.targets.iter().map(|t| &t.fit.map).collect();
        let mut sets = vec![("validation", result.validation.clone())];
        if let Some(s) = &design.scenario {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(s.seed);
            let run = data::simulate_run(&design, &s.x0, s.samples, &mut rng, "scenario").unwrap();
            sets.push(("scenario", DataSet { runs: vec![run], horizon: design.map.horizon }));
        }
        let mut comparison = Comparison { estimates: 0, worst_ratio: 0.0, undecided_flags: 0 };
        let mut z = Vec::new();
        for (set, data) in &sets {
            for (r, run) in data.runs.iter().enumerate() {
                let mut observer = tables::observer();
                for k in 0..run.states.len() {
                    let y: [f32; tables::OUTPUTS] = core::array::from_fn(|i| run.measurements[k][i] as f32);
                    let u: [f32; tables::INPUTS] = core::array::from_fn(|i| run.inputs[k][i] as f32);
                    observer.push(y, u).unwrap();
                    let Some(estimates) = observer.estimate() else {
                        assert!(k + 1 < design.map.horizon, "{set} run {r}: no estimate at k = {k}");
                        continue;
                    };
                    data.regressor(Window { run: r, end: k }, &mut z);
                    for (t, (estimate, map)) in estimates.iter().zip(&maps).enumerate() {
                        let library = map.estimate(&z);
                        let (tolerance, decidable) = tolerance(map, &z);
                        let difference = (f64::from(estimate.value) - library.value).abs();
                        assert!(
                            difference <= tolerance,
                            "{} {set} run {r} k = {k} target {t}: f32 {} vs f64 {} (|Δ| = {difference:e} > {tolerance:e})",
                            tables::NAME, estimate.value, library.value
                        );
                        if decidable {
                            assert_eq!(estimate.saturation, library.saturation, "{set} run {r} k = {k} target {t}");
                        } else {
                            comparison.undecided_flags += 1;
                        }
                        comparison.worst_ratio = comparison.worst_ratio.max(difference / tolerance);
                        comparison.estimates += 1;
                    }
                }
            }
        }
        println!(
            "{}: {} estimates compared, largest |f32 - f64| / tolerance = {:.3}, {} flags within rounding of an edge",
            tables::NAME, comparison.estimates, comparison.worst_ratio, comparison.undecided_flags
        );
        assert!(comparison.estimates > 0);
    }};
}

#[test]
fn generated_observers_agree_with_the_library() {
    generated::for_each_design!(compare_design);
}
