//! The generated observer (f32 tables, the firmware's ring buffer) against the host's library
//! estimate (f64, the same firmware code on the regressor), window by window, on every shipped design's
//! validation runs and on its scenario.
//!
//! The tolerance is derived in `integration_tests::tolerance`.

use host::data::{DataSet, Window};
use host::emit::precision::compare;
use host::fit::maps::FittedMap;
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
        let mut sets = vec![("validation", result.runs.validation.clone())];
        sets.push((
            "scenario",
            DataSet {
                runs: vec![result.runs.scenario.clone()],
                horizon: design.map.horizon,
            },
        ));
        let mut comparison = Comparison {
            estimates: 0,
            worst_ratio: 0.0,
            undecided_flags: 0,
        };
        let mut z = Vec::new();
        for (set, data) in &sets {
            for (r, run) in data.runs.iter().enumerate() {
                let mut observer = tables::map_observer();
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
                        let table = map.table.as_ref().expect("an emitted map has a table");
                        let agreement = compare(table, &z, *estimate, map.estimate(&z)).unwrap_or_else(|mismatch| {
                            panic!("{} {set} run {r} k = {k} target {t}: {mismatch}", tables::NAME)
                        });
                        comparison.undecided_flags += usize::from(!agreement.flag_decided);
                        comparison.worst_ratio = comparison.worst_ratio.max(agreement.ratio);
                        comparison.estimates += 1;
                    }
                }
            }
        }
        println!(
            "{}: {} estimates compared, largest |f32 - f64| / tolerance = {:.3}, {} flags within rounding of an edge",
            tables::NAME,
            comparison.estimates,
            comparison.worst_ratio,
            comparison.undecided_flags
        );
        assert!(comparison.estimates > 0);
    }};
}

#[test]
fn generated_observers_agree_with_the_library() {
    generated::for_each_design!(compare_design);
}

#[test]
fn searched_knot_tables_agree_with_the_library() {
    compare_design!(crate::vanderpol_beta7);
}

/// The comparison bites: on every validation window of Example 1, an f32 value just beyond the
/// tolerance (the next f32 past `f64 + tolerance`) is refused while the rounded f64 value passes; and
/// the tolerance is not loose: the generated observer's worst window uses a sizeable part of it.
#[test]
fn the_tolerance_is_tight_and_a_value_just_beyond_it_is_refused() {
    use host::emit::precision::tolerance;
    let design = integration_tests::load_relative(generated::vanderpol::SPEC);
    let result = build(&design);
    let mut z = Vec::new();
    let (mut windows, mut worst_ratio) = (0, 0.0f64);
    for window in result.runs.validation.windows() {
        result.runs.validation.regressor(window, &mut z);
        let z32: Vec<f32> = z.iter().map(|&v| v as f32).collect();
        for (t, map) in result.targets.iter().map(|t| &t.fit.map).enumerate() {
            let table = map.table.as_ref().unwrap();
            let library = map.estimate(&z);
            let (bound, _) = tolerance(table, &z);
            let beyond = next_f32_above(library.value + bound);
            let single = firmware::Estimate {
                value: beyond,
                saturation: library.saturation,
            };
            assert!(
                compare(table, &z, single, library).is_err(),
                "target {t}: {beyond} is {:e} from {} and passed a tolerance of {bound:e}",
                (f64::from(beyond) - library.value).abs(),
                library.value
            );
            let rounded = firmware::Estimate {
                value: library.value as f32,
                saturation: library.saturation,
            };
            assert!(
                compare(table, &z, rounded, library).is_ok(),
                "target {t}: the rounded value itself failed"
            );
            let on_chip = generated::vanderpol::MAPS[t].estimate(&z32);
            worst_ratio = worst_ratio.max(compare(table, &z, on_chip, library).unwrap().ratio);
        }
        windows += 1;
    }
    assert!(windows > 1000, "{windows}");
    // Measured 0.11: the derived bound is within a factor of 10 of the worst f32 error it covers.
    assert!(
        worst_ratio > 0.05,
        "the tolerance is loose: worst f32 error {worst_ratio} of it"
    );
}

/// The smallest f32 strictly above `value`.
fn next_f32_above(value: f64) -> f32 {
    let nearest = value as f32;
    if f64::from(nearest) > value {
        nearest
    } else {
        nearest.next_up()
    }
}
