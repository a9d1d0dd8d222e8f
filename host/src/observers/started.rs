//! `firmware::Started` on the host, step for step, over a simulated run: the one mirror of the
//! chip's shell that the model-corrected map ([`super::corrected`]) and the map-started EKF
//! ([`super::ekf::estimate_started`]) plug their samples into.
//!
//! No estimate before the map's first (NaN rows: before sample `first`, or while the map's row is not
//! finite because refused samples left its window short); there the map's row, and `start` from the
//! map's states; then `follow` for every later sample with its count `j` (counted as the chip counts:
//! only samples taken). A sample with a non-finite output or input is refused as the chip refuses it:
//! its row is NaN (no estimate from that sample), and once started, when its input is finite, what
//! is carried takes one period of the model (`lost`, `Follower::predict`). A start, follow-up or
//! prediction that gives `None` (not finite) is refused too: nothing carried changes and the last
//! estimate stays.

use firmware::Scalar;

use crate::data::Run;

/// The targets at every sample of `run` (rows of `map`'s width), in `T`. `map` is the map's
/// estimate at every sample, `state_targets` the map target of each state. `start(x, u)` gives what
/// to carry from the map's states; `follow(carried, j, map_states, y, u)` what to carry next and the
/// targets; `lost(carried, u)` what to carry over a refused sample with a finite input.
pub fn run<T: Scalar, C>(
    first: usize,
    state_targets: &[usize],
    map: &[Vec<T>],
    run: &Run,
    mut start: impl FnMut(&[T], &[T]) -> Option<C>,
    mut follow: impl FnMut(&C, usize, &[T], &[T], &[T]) -> Option<(C, Vec<T>)>,
    mut lost: impl FnMut(&C, &[T]) -> Option<C>,
) -> Vec<Vec<T>> {
    let literal = |v: f64| T::literal(v as f32, v);
    let width = map.first().map_or(0, Vec::len);
    let nan = vec![literal(f64::NAN); width];
    let mut out: Vec<Vec<T>> = Vec::with_capacity(map.len());
    let mut carried: Option<C> = None;
    let mut j = 0;
    let mut last = nan.clone();
    for (k, row) in map.iter().enumerate().take(run.measurements.len()) {
        let refused = run.measurements[k]
            .iter()
            .chain(run.inputs[k].iter())
            .any(|v| !v.is_finite());
        let u: Vec<T> = run.inputs[k].iter().map(|&v| literal(v)).collect();
        if refused {
            if let Some(c) = carried.as_ref().filter(|_| u.iter().all(|v| v.is_finite())) {
                if let Some(next) = lost(c, &u) {
                    carried = Some(next);
                }
            }
            out.push(nan.clone());
            continue;
        }
        if carried.is_none() && (k < first || row.iter().any(|v| !v.is_finite())) {
            out.push(nan.clone());
            continue;
        }
        let y: Vec<T> = run.measurements[k].iter().map(|&v| literal(v)).collect();
        let states: Vec<T> = state_targets.iter().map(|&t| row[t]).collect();
        match &carried {
            None => match start(&states, &u) {
                Some(c) => {
                    carried = Some(c);
                    j = 1;
                    last = row.clone();
                    out.push(row.clone());
                }
                None => out.push(last.clone()),
            },
            Some(c) => match follow(c, j, &states, &y, &u) {
                Some((next, targets)) => {
                    carried = Some(next);
                    j += 1;
                    last = targets.clone();
                    out.push(targets);
                }
                None => out.push(last.clone()),
            },
        }
    }
    out
}
