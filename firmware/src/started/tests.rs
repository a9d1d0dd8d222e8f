use super::*;
use crate::{InverseTable, Knots, TargetMap};

// The map: r = 10 (0.5 y(k) + 0.5 y(k−1)) on [0, 10] (one segment, r = 10 t).
struct Mean;
impl Design<f64, 2, 1, 0, 1> for Mean {
    const MAPS: [TargetMap<'static, f64>; 1] = [TargetMap {
        gains: &[0.5, 0.5],
        offset: 0.0,
        inverse: InverseTable {
            knots: Knots::Uniform,
            segments: &[[0.0, 10.0]],
            t_max: 1.0,
            r_min: 0.0,
            r_max: 10.0,
        },
    }];
}

// The follower: x⁺ = 0.5 x, h = x, x̂ = clamp(x̄ + g (F − x̄) + 0.25 (y − x̄)) to [0, 10], start-up
// blend 1 − 0.25 j for j = 1, 2, then G (0.5 when `READS`, else 0).
struct Halving<const READS: bool>;
impl<const READS: bool> Follower<f64, 1, 1, 0, 1> for Halving<READS> {
    type Carried = [f64; 1];
    const START_UP: usize = 2;
    const STEADY_READS_MAP: bool = READS;
    const STATE_TARGETS: [usize; 1] = [0];

    fn start(first: &[f64; 1], _: &[f64; 0]) -> Option<[f64; 1]> {
        Some([0.5 * first[0]])
    }

    fn follow(
        carried: &[f64; 1],
        j: usize,
        start_up: bool,
        map: &[f64; 1],
        y: &[f64; 1],
        _: &[f64; 0],
    ) -> Option<([f64; 1], [Estimate<f64>; 1])> {
        let g = if start_up {
            1.0 - 0.25 * j as f64
        } else if READS {
            0.5
        } else {
            0.0
        };
        let x = carried[0];
        let raw = x + g * (map[0] - x) + 0.25 * (y[0] - x);
        let state = clamp(&[raw], &[0.0], &[10.0]);
        let next = 0.5 * state[0].value;
        next.is_finite().then_some(([next], state))
    }

    fn predict(carried: &[f64; 1], _: &[f64; 0]) -> Option<[f64; 1]> {
        let next = 0.5 * carried[0];
        next.is_finite().then_some([next])
    }

    fn targets(x: &[f64; 1], _: &[f64; 0]) -> [f64; 1] {
        *x
    }
}

/// The same observer written as a plain recursion, sample by sample: `(estimate, map read)`.
fn by_hand(ys: &[f64], g_steady: f64) -> Vec<Option<f64>> {
    let mut out = Vec::new();
    let mut predicted = 0.0;
    for k in 0..ys.len() {
        if k == 0 {
            out.push(None);
            continue;
        }
        let map = 10.0 * (0.5 * ys[k] + 0.5 * ys[k - 1]);
        let j = (k - 1) as f64;
        let x = if k == 1 {
            map
        } else {
            let g = if j <= 2.0 { 1.0 - 0.25 * j } else { g_steady };
            (predicted + g * (map - predicted) + 0.25 * (ys[k] - predicted)).clamp(0.0, 10.0)
        };
        predicted = 0.5 * x;
        out.push(Some(x));
    }
    out
}

fn ys() -> Vec<f64> {
    (0..12).map(|k| 0.3 + 0.05 * (k as f64)).collect()
}

#[test]
fn follows_the_recursion_through_start_up_and_steady_state() {
    for (reads, g) in [(true, 0.5), (false, 0.0)] {
        let expected = by_hand(&ys(), g);
        let mut with_map: Started<f64, Mean, Halving<true>, 2, 1, 1, 0, 1, 1> = Started::new();
        let mut without: Started<f64, Mean, Halving<false>, 2, 1, 1, 0, 1, 1> = Started::new();
        for (k, y) in ys().into_iter().enumerate() {
            let got = if reads {
                with_map.push([y], []).unwrap();
                with_map.estimate()
            } else {
                without.push([y], []).unwrap();
                without.estimate()
            };
            let got = got.map(|[e]| e.value);
            match (got, expected[k]) {
                (Some(a), Some(b)) => assert!((a - b).abs() < 1e-12, "reads {reads}, k = {k}: {a} vs {b}"),
                (a, b) => assert_eq!(a, b, "reads {reads}, k = {k}"),
            }
        }
    }
}

#[test]
fn the_map_is_not_read_after_the_start_up_unless_the_steady_blend_needs_it() {
    // After the start-up, the map of a follower whose G is 0 would see a sample that changes it, but
    // the estimate does not move with it; one whose G is not 0 does.
    let run = |reads_map: bool, last: f64| {
        let mut ys = ys();
        *ys.last_mut().unwrap() = last;
        if reads_map {
            let mut o: Started<f64, Mean, Halving<true>, 2, 1, 1, 0, 1, 1> = Started::new();
            ys.iter().for_each(|&y| o.push([y], []).unwrap());
            o.estimate().unwrap()[0].value
        } else {
            let mut o: Started<f64, Mean, Halving<false>, 2, 1, 1, 0, 1, 1> = Started::new();
            ys.iter().for_each(|&y| o.push([y], []).unwrap());
            o.estimate().unwrap()[0].value
        }
    };
    // y enters through the innovation (0.25 y) in both; through the map (0.5 · 10 · 0.5 y) only in one.
    let without = run(false, 1.0) - run(false, 0.0);
    let with = run(true, 1.0) - run(true, 0.0);
    assert!((without - 0.25).abs() < 1e-12, "{without}");
    assert!((with - (0.25 + 0.5 * 5.0)).abs() < 1e-12, "{with}");
}

#[test]
fn refused_samples_give_no_estimate_but_the_model_keeps_time_and_clamps_are_flagged() {
    let mut o: Started<f64, Mean, Halving<true>, 2, 1, 1, 0, 1, 1> = Started::new();
    // Before the start, a refused sample changes nothing: the first estimate below is the map's.
    assert_eq!(o.push([f64::NAN], []), Err(RejectedSample));
    o.push([0.4], []).unwrap();
    assert!(o.estimate().is_none() && !o.is_ready());
    o.push([0.6], []).unwrap();
    let first = o.estimate().unwrap();
    assert_eq!(first[0].value, 5.0);
    let before = o.clone();
    assert_eq!(o.push([f64::NAN], []), Err(RejectedSample));
    assert_eq!(o.push([f64::INFINITY], []), Err(RejectedSample));
    assert_eq!(o.estimate(), before.estimate(), "no estimate from a refused sample");
    // By hand: x̄ = 0.5 · 5 = 2.5 carried from the first estimate; each lost sample halves it (the model's
    // period, no correction), so the next sample meets x̄ = 0.625. Its map reads the window [0.6, 0.5]
    // (the lost samples never entered it): F = 10 (0.3 + 0.25) = 5.5; j = 1, g = 0.75:
    // x̂ = 0.625 + 0.75 (5.5 − 0.625) + 0.25 (0.5 − 0.625).
    o.push([0.5], []).unwrap();
    let expected = 0.625 + 0.75 * (5.5 - 0.625) + 0.25 * (0.5 - 0.625);
    assert!((o.estimate().unwrap()[0].value - expected).abs() < 1e-12);
    // Without the lost samples, the same sample meets x̄ = 2.5: another estimate.
    let mut twin = before.clone();
    twin.push([0.5], []).unwrap();
    let skipped = 2.5 + 0.75 * (5.5 - 2.5) + 0.25 * (0.5 - 2.5);
    assert!((twin.estimate().unwrap()[0].value - skipped).abs() < 1e-12);
    // A large measurement drives the corrected state past the range: clamped and flagged.
    o.push([1e6], []).unwrap();
    let [e] = o.estimate().unwrap();
    assert_eq!((e.value, e.saturation), (10.0, Saturation::High));
    o.push([-1e6], []).unwrap();
    o.push([-1e6], []).unwrap();
    let [e] = o.estimate().unwrap();
    assert_eq!((e.value, e.saturation), (0.0, Saturation::Low));
    o.reset();
    assert!(o.estimate().is_none());
}

#[test]
fn clamp_sends_nan_to_the_lower_end() {
    let [a, b, c] = clamp(&[f64::NAN, 0.5, 3.0], &[0.0; 3], &[1.0; 3]);
    assert_eq!((a.value, a.saturation), (0.0, Saturation::Low));
    assert_eq!((b.value, b.saturation), (0.5, Saturation::Inside));
    assert_eq!((c.value, c.saturation), (1.0, Saturation::High));
}

// A map of two rows over the same window: the target's (r = 10 mean, as `Mean`) and a helper
// state's (x₂ = 4 mean on [0, 4]); the follower's target is x₁ + x₂.
struct WithHelper;
impl Design<f64, 2, 1, 0, 2> for WithHelper {
    const MAPS: [TargetMap<'static, f64>; 2] = [
        Mean::MAPS[0],
        TargetMap {
            gains: &[0.5, 0.5],
            offset: 0.0,
            inverse: InverseTable {
                knots: Knots::Uniform,
                segments: &[[0.0, 4.0]],
                t_max: 1.0,
                r_min: 0.0,
                r_max: 4.0,
            },
        },
    ];
}

// Carries the map's states as they are (a follower that always takes the map), target x₁ + x₂.
struct Sum;
impl Follower<f64, 2, 1, 0, 1> for Sum {
    type Carried = [f64; 2];
    const START_UP: usize = 0;
    const STEADY_READS_MAP: bool = true;
    const STATE_TARGETS: [usize; 2] = [0, 1];

    fn start(first: &[f64; 2], _: &[f64; 0]) -> Option<[f64; 2]> {
        Some(*first)
    }

    fn follow(
        _: &[f64; 2],
        _: usize,
        _: bool,
        map: &[f64; 2],
        _: &[f64; 1],
        _: &[f64; 0],
    ) -> Option<([f64; 2], [Estimate<f64>; 2])> {
        Some((*map, clamp(map, &[0.0, 0.0], &[10.0, 4.0])))
    }

    fn predict(carried: &[f64; 2], _: &[f64; 0]) -> Option<[f64; 2]> {
        Some(*carried)
    }

    fn targets(x: &[f64; 2], _: &[f64; 0]) -> [f64; 1] {
        [x[0] + x[1]]
    }
}

#[test]
fn a_helper_row_starts_a_state_that_is_no_target_and_is_not_returned() {
    let mut o: Started<f64, WithHelper, Sum, 2, 2, 1, 0, 2, 1> = Started::new();
    let ys = [0.2, 0.4, 0.6];
    o.push([ys[0]], []).unwrap();
    assert!(o.estimate().is_none());
    // The first estimate is the target's own map row (10 · 0.3), not x₁ + x₂ of both rows.
    o.push([ys[1]], []).unwrap();
    assert!((o.estimate().unwrap()[0].value - 3.0).abs() < 1e-12);
    // Then the follower's target from both rows' states: 10 · 0.5 + 4 · 0.5.
    o.push([ys[2]], []).unwrap();
    assert!((o.estimate().unwrap()[0].value - 7.0).abs() < 1e-12);
}
