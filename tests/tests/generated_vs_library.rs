//! The generated observer (f32 tables, the firmware's ring buffer) against the host's library
//! estimate (f64, the same firmware code on the regressor), window by window, on every shipped design's
//! validation runs and on its scenario.
//!
//! The tolerance is derived in `integration_tests::tolerance`.

use host::data::{DataSet, Window};
use host::fit::maps::FittedMap;
use integration_tests::tolerance::tolerance;
use integration_tests::{build, load_relative};

struct Comparison {
    estimates: usize,
    worst_ratio: f64,
    undecided_flags: usize,
}

macro_rules! compare_design {
    ($name:ident) => {
        compare_design!(generated::$name)
    };
    ($path:path) => {{
        use $path as tables;
        let design = load_relative(tables::SPEC);
        assert_eq!(design.name, tables::NAME);
        let result = build(&design);
        let maps: Vec<&FittedMap> = result.targets.iter().map(|t| &t.fit.map).collect();
        let mut sets = vec![("validation", result.validation.clone())];
        sets.push(("scenario", DataSet { runs: vec![result.scenario.clone()], horizon: design.map.horizon }));
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
                        let (tolerance, decidable) = tolerance(map.table.as_ref().expect("an emitted map has a table"), &z);
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

/// The fixture whose tables have searched knots (see `integration_tests::SEARCHED_FIXTURE_SPEC`).
#[rustfmt::skip]
#[path = "../fixtures/vanderpol_beta7.rs"]
#[allow(dead_code)]
mod vanderpol_beta7;

#[test]
fn searched_knot_tables_agree_with_the_library() {
    compare_design!(crate::vanderpol_beta7);
}
