//! The generated observers' contract on arbitrary input, and their straight-line code against the
//! firmware's loops.

use firmware::{estimate_by_loops, Design as _, Sample};
use proptest::prelude::*;

/// Any f32, with the awkward ones (NaN, ±∞, ±0, subnormals, ±f32::MAX, huge) drawn often.
fn hostile_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        any::<u32>().prop_map(f32::from_bits),
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(f32::MAX),
        Just(f32::MIN),
        Just(f32::MIN_POSITIVE / 4.0),
        Just(-0.0f32),
        -1e30f32..1e30,
        -10.0f32..10.0,
    ]
}

macro_rules! contract {
    ($name:ident) => {
        contract!($name, generated::$name);
    };
    ($name:ident, $path:path) => {
        mod $name {
            use super::*;
            use $path as d;

            proptest! {
                #![proptest_config(ProptestConfig::with_cases(256))]
                #[test]
                fn never_panics_and_estimates_stay_finite_and_in_range(
                    samples in proptest::collection::vec(
                        (proptest::array::uniform::<_, { d::OUTPUTS }>(hostile_f32()), proptest::array::uniform::<_, { d::INPUTS }>(hostile_f32())),
                        1..3 * d::HORIZON,
                    )
                ) {
                    let mut observer = d::map_observer();
                    let mut accepted = 0usize;
                    for (y, u) in samples {
                        let finite = y.iter().chain(&u).all(|v| v.is_finite());
                        prop_assert_eq!(observer.push(y, u).is_ok(), finite);
                        accepted += usize::from(finite);
                        match observer.estimate() {
                            None => prop_assert!(accepted < d::HORIZON),
                            Some(estimates) => {
                                prop_assert!(accepted >= d::HORIZON);
                                for (e, map) in estimates.iter().zip(&d::MAPS) {
                                    let (lo, hi) = (map.inverse.r_min, map.inverse.r_max);
                                    prop_assert!(e.value.is_finite() && e.value >= lo && e.value <= hi, "{:?} outside [{lo}, {hi}]", e);
                                }
                            }
                        }
                    }
                }

                #[test]
                fn straight_line_code_equals_the_loops_bit_for_bit(
                    window in proptest::array::uniform::<_, { d::HORIZON }>(
                        (proptest::array::uniform::<_, { d::OUTPUTS }>(hostile_f32()), proptest::array::uniform::<_, { d::INPUTS }>(hostile_f32()))
                    )
                ) {
                    let window: [Sample<f32, { d::OUTPUTS }, { d::INPUTS }>; d::HORIZON] = window.map(|(y, u)| Sample { y, u });
                    let emitted = d::Design::estimate(&window);
                    let looped = estimate_by_loops(&d::MAPS, &window);
                    for (a, b) in emitted.iter().zip(&looped) {
                        prop_assert_eq!(a.value.to_bits(), b.value.to_bits());
                        prop_assert_eq!(a.saturation, b.saturation);
                    }
                    for s in &window {
                        let finite = s.y.iter().chain(&s.u).all(|v| v.is_finite());
                        prop_assert_eq!(d::Design::accepts(&s.y, &s.u), finite);
                    }
                }
            }

            #[test]
            fn straight_line_code_equals_the_loops_on_the_recorded_sequence() {
                let mut observer = d::map_observer();
                let mut window: Vec<Sample<f32, { d::OUTPUTS }, { d::INPUTS }>> = Vec::new();
                let mut compared = 0;
                for (y, u) in d::RECORDED_Y.iter().zip(&d::RECORDED_U) {
                    if observer.push(*y, *u).is_err() {
                        continue;
                    }
                    window.push(Sample { y: *y, u: *u });
                    if window.len() > d::HORIZON {
                        window.remove(0);
                    }
                    if let Some(estimates) = observer.estimate() {
                        let full: [_; d::HORIZON] = window.clone().try_into().unwrap();
                        assert_eq!(estimates, estimate_by_loops(&d::MAPS, &full));
                        compared += 1;
                    }
                }
                assert!(compared > 0);
            }
        }
    };
}

generated::for_each_design!(contract);

/// The fixture whose tables have searched knots (see `integration_tests::SEARCHED_FIXTURE_SPEC`).
#[rustfmt::skip]
#[path = "../fixtures/vanderpol_beta7.rs"]
#[allow(dead_code)]
mod vanderpol_beta7_tables;
contract!(vanderpol_beta7, crate::vanderpol_beta7_tables);
