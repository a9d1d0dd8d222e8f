//! The generated observers' contract on arbitrary input, and their straight-line code against the
//! firmware's loops.

use firmware::emitted::estimate_by_loops;
use firmware::{Design as _, Sample};
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

contract!(vanderpol_beta7, crate::vanderpol_beta7);

/// Every observer kind of every design driven through the one trait, [`firmware::Estimator`], by a
/// generic function (as a firmware written against the trait drives it): the same acceptance,
/// estimates (bits) and flags as the type's own calls, sample by sample over the recorded sequence
/// (refused samples included); and `reset` returns an observer to its fresh state: after `reset`,
/// mid-sequence or at its end, it runs the sequence as a new one does.
mod every_kind_through_the_trait {
    use firmware::{Estimate, Estimator, Saturation};

    /// A value as bits: an `f32`'s, or the integer map's `i32` as `u32`.
    trait Bits: Copy {
        fn bits(self) -> u32;
    }

    impl Bits for f32 {
        fn bits(self) -> u32 {
            self.to_bits()
        }
    }

    impl Bits for i32 {
        fn bits(self) -> u32 {
            self as u32
        }
    }

    /// Per sample: whether it was accepted, and the estimate's bits and flags if there is one.
    type Trace = Vec<(bool, Option<Vec<(u32, Saturation)>>)>;

    fn flat<T: Bits>(estimates: &[Estimate<T>]) -> Vec<(u32, Saturation)> {
        estimates.iter().map(|e| (e.value.bits(), e.saturation)).collect()
    }

    /// What a firmware written against the trait does every sample period.
    fn run<O: Estimator>(observer: &mut O, samples: &[(O::Outputs, O::Inputs)]) -> Trace
    where
        O::Scalar: Bits,
    {
        samples
            .iter()
            .map(|&(y, u)| {
                let accepted = observer.push(y, u).is_ok();
                let estimate = observer.estimate();
                assert_eq!(observer.is_ready(), estimate.is_some());
                (accepted, estimate.map(|e| flat(e.as_ref())))
            })
            .collect()
    }

    /// `fresh` (a new observer) through [`run`] against `concrete` (the type's own `push` and
    /// `estimate`), then `reset` against a new observer.
    fn check<O: Estimator>(
        what: &str,
        fresh: fn() -> O,
        samples: &[(O::Outputs, O::Inputs)],
        concrete: impl Fn(&mut O, O::Outputs, O::Inputs) -> (bool, Option<Vec<(u32, Saturation)>>),
    ) where
        O::Scalar: Bits,
    {
        let mut by_type = fresh();
        let expected: Trace = samples.iter().map(|&(y, u)| concrete(&mut by_type, y, u)).collect();
        let mut observer = fresh();
        assert!(!observer.is_ready(), "{what}: ready before any sample");
        let through_trait = run(&mut observer, samples);
        assert_eq!(through_trait, expected, "{what}: the trait's calls against the type's");
        assert!(
            expected.iter().any(|(accepted, _)| !accepted),
            "{what}: no refused sample"
        );
        assert!(expected.iter().any(|(_, e)| e.is_some()), "{what}: no estimate");
        // `reset` at the end of the sequence and in its middle: then as a new observer.
        for cut in [samples.len(), samples.len() / 2] {
            let mut observer = fresh();
            run(&mut observer, &samples[..cut]);
            observer.reset();
            assert!(
                !observer.is_ready() && observer.estimate().is_none(),
                "{what}: ready after reset"
            );
            assert_eq!(
                run(&mut observer, samples),
                expected,
                "{what}: after reset at sample {cut}"
            );
        }
    }

    /// The type's own calls (inherent methods: they take precedence over the trait's).
    macro_rules! concrete {
        ($ty:ty) => {
            |o: &mut $ty, y, u| {
                let accepted = o.push(y, u).is_ok();
                (accepted, o.estimate().map(|e| flat(&e)))
            }
        };
    }

    /// Every float kind of every design (each design's kinds as `gen` listed them,
    /// `generated::for_each_observer!`) over the design's recorded sequence.
    #[test]
    fn every_kind_of_every_design() {
        let mut checked = 0;
        macro_rules! one {
            ($design:ident, $kind:ident, $ty:ident) => {{
                use generated::$design as d;
                let samples: Vec<_> = d::RECORDED_Y
                    .iter()
                    .copied()
                    .zip(d::RECORDED_U.iter().copied())
                    .collect();
                check(
                    concat!(stringify!($design), "::", stringify!($ty)),
                    d::$ty::new,
                    &samples,
                    concrete!(d::$ty),
                );
                checked += 1;
            }};
        }
        generated::for_each_observer!(one);
        // Seven kinds on each of the five Van der Pol and tank designs, four on each E. coli one.
        assert!(checked >= 43, "{checked} observers checked");
    }

    /// Every design's `observer()` over its recorded sequence, and its integer map over the raw one.
    #[test]
    fn every_designs_chosen_observer_and_integer_map() {
        macro_rules! one {
            ($design:ident) => {{
                use generated::$design as d;
                let samples: Vec<_> = d::RECORDED_Y
                    .iter()
                    .copied()
                    .zip(d::RECORDED_U.iter().copied())
                    .collect();
                check(
                    concat!(stringify!($design), "::observer()"),
                    d::observer,
                    &samples,
                    concrete!(d::Observer),
                );
                let raw: Vec<_> = d::RECORDED_RAW_Y
                    .iter()
                    .copied()
                    .zip(d::RECORDED_RAW_U.iter().copied())
                    .collect();
                check(
                    concat!(stringify!($design), "::FixedObserver"),
                    d::fixed_observer,
                    &raw,
                    concrete!(d::FixedObserver),
                );
            }};
        }
        generated::for_each_design!(one);
    }

    #[test]
    fn the_family() {
        use generated::ecoli_x0_0p5 as member;
        let samples: Vec<_> = member::RECORDED_Y
            .iter()
            .copied()
            .zip(member::RECORDED_U.iter().copied())
            .collect();
        check(
            "ecoli::observer()",
            generated::ecoli::observer,
            &samples,
            concrete!(generated::ecoli::Observer),
        );
    }
}
