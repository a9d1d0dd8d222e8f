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
    let width = map.first().map_or(0, Vec::len);
    let mut shell = Shell::new(first, state_targets, width);
    map.iter()
        .zip(run.measurements.iter().zip(run.inputs.iter()))
        .map(|(row, (y, u))| shell.step(row, y, u, &mut start, &mut follow, &mut lost))
        .collect()
}

/// [`run`] one sample at a time: what `firmware::Started` carries between samples.
pub struct Shell<T, C> {
    first: usize,
    state_targets: Vec<usize>,
    /// A row of NaN: no estimate.
    nan: Vec<T>,
    carried: Option<C>,
    /// Samples taken since the start.
    j: usize,
    /// Samples seen.
    k: usize,
    last: Vec<T>,
}

impl<T: Scalar, C> Shell<T, C> {
    /// Before the first sample of a run, for rows of `width` targets.
    pub fn new(first: usize, state_targets: &[usize], width: usize) -> Self {
        let nan = vec![T::literal(f32::NAN, f64::NAN); width];
        Shell {
            first,
            state_targets: state_targets.to_vec(),
            last: nan.clone(),
            nan,
            carried: None,
            j: 0,
            k: 0,
        }
    }

    /// The targets at the next sample (outputs `y`, inputs `u`), given the map's estimate `row` there
    /// (see [`run`] for `start`, `follow` and `lost`).
    pub fn step(
        &mut self,
        row: &[T],
        y: &[f64],
        u: &[f64],
        start: &mut impl FnMut(&[T], &[T]) -> Option<C>,
        follow: &mut impl FnMut(&C, usize, &[T], &[T], &[T]) -> Option<(C, Vec<T>)>,
        lost: &mut impl FnMut(&C, &[T]) -> Option<C>,
    ) -> Vec<T> {
        let literal = |v: f64| T::literal(v as f32, v);
        let k = self.k;
        self.k += 1;
        let refused = y.iter().chain(u).any(|v| !v.is_finite());
        let u: Vec<T> = u.iter().map(|&v| literal(v)).collect();
        if refused {
            if let Some(c) = self.carried.as_ref().filter(|_| u.iter().all(|v| v.is_finite())) {
                if let Some(next) = lost(c, &u) {
                    self.carried = Some(next);
                }
            }
            return self.nan.clone();
        }
        if self.carried.is_none() && (k < self.first || row.iter().any(|v| !v.is_finite())) {
            return self.nan.clone();
        }
        let y: Vec<T> = y.iter().map(|&v| literal(v)).collect();
        let states: Vec<T> = self.state_targets.iter().map(|&t| row[t]).collect();
        match &self.carried {
            None => match start(&states, &u) {
                Some(c) => {
                    self.carried = Some(c);
                    self.j = 1;
                    self.last = row.to_vec();
                    row.to_vec()
                }
                None => self.last.clone(),
            },
            Some(c) => match follow(c, self.j, &states, &y, &u) {
                Some((next, targets)) => {
                    self.carried = Some(next);
                    self.j += 1;
                    self.last.clone_from(&targets);
                    targets
                }
                None => self.last.clone(),
            },
        }
    }
}
