use super::*;
use crate::{InverseTable, Knots, Saturation, TargetMap};

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

// The filter: carried (x, p), a constant model, the estimate x̂ = x + (y − x) / 2; it starts at
// (0, 1), restarts at (F, 0.5) unless F > 9 (a start that is "not finite"), and disagrees with the
// map when (x − F)² / (p + 1) > 4.
struct Toy;
impl Follower<f64, 1, 1, 0, 1> for Toy {
    type Carried = (f64, f64);
    const START_UP: usize = 0;
    const STEADY_READS_MAP: bool = false;
    const STATE_TARGETS: [usize; 1] = [0];

    fn start(first: &[f64; 1], _: &[f64; 0]) -> Option<(f64, f64)> {
        (first[0] <= 9.0).then_some((first[0], 0.5))
    }

    fn follow(
        carried: &(f64, f64),
        _: usize,
        _: bool,
        _: &[f64; 1],
        y: &[f64; 1],
        _: &[f64; 0],
    ) -> Option<((f64, f64), [Estimate<f64>; 1])> {
        let x = carried.0 + 0.5 * (y[0] - carried.0);
        let state = Estimate {
            value: x,
            saturation: Saturation::Inside,
        };
        x.is_finite().then_some(((x, carried.1), [state]))
    }

    fn predict(carried: &(f64, f64), _: &[f64; 0]) -> Option<(f64, f64)> {
        Some(*carried)
    }

    fn targets(x: &[f64; 1], _: &[f64; 0]) -> [f64; 1] {
        *x
    }
}

impl Restart<f64, 1, 1, 0, 1> for Toy {
    const FRESH: (f64, f64) = (0.0, 1.0);

    fn disagrees(carried: &(f64, f64), map: &[f64; 1]) -> bool {
        let d = (carried.0 - map[0]).powi(2) / (carried.1 + 1.0);
        !(d <= 4.0)
    }
}

type Observer = Restarted<f64, Mean, Toy, 2, 1, 1, 0, 1, 1>;

/// The estimates (value, saturation) after pushing `ys` (NaN refused).
fn run(ys: &[f64]) -> Vec<Option<(f64, Saturation)>> {
    let mut observer = Observer::new();
    ys.iter()
        .map(|&y| {
            let _ = observer.push([y], []);
            observer.estimate().map(|[e]| (e.value, e.saturation))
        })
        .collect()
}

fn values(estimates: &[Option<(f64, Saturation)>]) -> Vec<f64> {
    estimates.iter().map(|e| e.map_or(f64::NAN, |e| e.0)).collect()
}

fn close(got: &[f64], expected: &[f64]) {
    assert_eq!(got.len(), expected.len());
    for (k, (a, b)) in got.iter().zip(expected).enumerate() {
        assert!((a - b).abs() < 1e-12, "sample {k}: {a} against {b} ({got:?})");
    }
}

#[test]
fn estimates_from_the_first_sample_and_keeps_the_filter_when_the_map_agrees() {
    // y = 0.2, 0.2, 0.2: x̂ = 0.1; at the check F = 2, d = 1.9² / 2 = 1.805 ≤ 4, so x̂ = 0.15; then
    // d = 1.85² / 2 = 1.71 ≤ 4 again: 0.175.
    close(&values(&run(&[0.2, 0.2, 0.2])), &[0.1, 0.15, 0.175]);
}

#[test]
fn restarts_from_the_map_whenever_they_disagree() {
    // y = 0.6, 0.6: x̂ = 0.3; at the map's first estimate F = 6, d = 5.7² / 2 = 16.245 > 4: the
    // estimate is the map's (with its flag) and the filter goes on from (6, 0.5): 6 + (0.6 − 6) / 2 =
    // 3.3 (d = 0); then d = 2.7² / 1.5 = 4.86 > 4: the map's again, and so on: checked every sample.
    let got = run(&[0.6, 0.6, 0.6, 0.6, 0.6]);
    close(&values(&got), &[0.3, 6.0, 3.3, 6.0, 3.3]);
    assert_eq!(got[1].unwrap().1, Saturation::Inside);
    // y = 0.2, 0.2, 0.8, 0.8: the filter agrees with the map's F = 2 (d = 1.9² / 2 = 1.805), so 0.15;
    // after the step F = 5 (d = 4.85² / 2 > 4): the map's; then F = 8 (d = 3² / 1.5 = 6 > 4): again.
    close(&values(&run(&[0.2, 0.2, 0.8, 0.8])), &[0.1, 0.15, 5.0, 8.0]);
}

#[test]
fn a_restart_that_is_not_finite_is_not_taken() {
    // y = 0.95, 0.95: x̂ = 0.475; F = 9.5 disagrees but its start is refused, so the filter goes on.
    close(&values(&run(&[0.95, 0.95])), &[0.475, 0.7125]);
}

#[test]
fn a_refused_sample_is_not_in_the_window_and_the_check_waits_for_n_accepted_samples() {
    // y = 0.6, NaN, 0.6: the second is refused (the estimate stays 0.3) and the window holds one
    // sample, so the third is the check (F = 6, restart); a NaN input to the map never happens.
    let mut observer = Observer::new();
    observer.push([0.6], []).unwrap();
    assert!(observer.push([f64::NAN], []).is_err());
    assert_eq!(observer.estimate().map(|[e]| e.value), Some(0.3));
    observer.push([0.6], []).unwrap();
    close(&[observer.estimate().map_or(f64::NAN, |[e]| e.value)], &[6.0]);
}

#[test]
fn reset_starts_again() {
    let mut observer = Observer::new();
    for y in [0.6, 0.6, 0.6] {
        observer.push([y], []).unwrap();
    }
    observer.reset();
    assert!(!observer.is_ready());
    observer.push([0.2], []).unwrap();
    assert_eq!(observer.estimate().map(|[e]| e.value), Some(0.1));
}
