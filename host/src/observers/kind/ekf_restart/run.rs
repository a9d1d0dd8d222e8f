//! The EKF from the box centre, checked against the map at every sample and restarted from it when
//! the two disagree (kind `ekf_restart`; on the chip `firmware::Restarted` over the design's
//! `StartedEkf`).
//!
//! The box-started EKF converges fast from starts near the box centre and slowly from its corners
//! (Example 1's scenario, `x(0) = (2, 0.5)`: 0.27 / 0.40 against the map-started EKF's 0.04 / 0.05);
//! the map-started one has no estimate for `N − 1` samples and starts from the map's error; and a
//! filter may lose track later (a wrong branch, a bound). Checked at every sample from the map's
//! first estimate on with
//!
//! ```text
//! d = Σ_i (x̂_i(k|k−1) − F_i)² / (P_ii(k|k−1) + e_i²),     restart from F (as `ekf_map` starts) when d > τ,
//! ```
//!
//! `e_i²` the map's mean squared error of state `i` on the tuning runs, the filter keeps its own
//! estimate when it is consistent with the map's and takes the map's when it is not. `τ` is chosen on
//! the tuning runs ([`tune`]) from [`THRESHOLDS`].

use std::cell::RefCell;

use firmware::emitted::Maths;
use firmware::rules::{Given, Refusals, Refused, RestartedRule};
use firmware::Scalar;

use crate::data::Run;
use crate::observers::ekf::steps::{kept, Watcher};
use crate::observers::lost::Track;
use crate::observers::started::{literal, literals};
use crate::plant::kalman::{self, EkfConstants, FilterCode};
use crate::plant::ModelCode;

/// The check's constants, chosen on the tuning runs.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RestartConstants {
    /// `τ`: the filter restarts when the distance exceeds it.
    pub threshold: f64,
    /// `e_i²`: the map's mean squared error of each state on the tuning runs.
    pub variances: Vec<f64>,
}

/// The thresholds [`tune`] tries: powers of two from 0.5 to 1024 (for two states the χ² quantiles of
/// 0.22 … 1 − 10⁻¹⁴ up to 64; beyond, for maps whose errors have heavier tails than a Gaussian's,
/// now that the check runs at every sample).
pub const THRESHOLDS: [f64; 12] = [0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0, 512.0, 1024.0];

/// Whether the prediction `x` with covariance `p` (upper triangle) and the map's states `map` disagree:
/// `!(d ≤ τ)`, so that a NaN distance restarts. Summed in state order in `T`, as the emitted
/// `restart_disagrees` sums it.
pub fn disagrees<T: Scalar>(x: &[T], p: &[T], map: &[T], constants: &RestartConstants) -> bool {
    let n = x.len();
    let mut d = T::ZERO;
    for i in 0..n {
        let e = x[i] - map[i];
        d += e * e / (p[kalman::upper(n, i, i)] + literal(constants.variances[i]));
    }
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    let out = !(d <= literal(constants.threshold));
    out
}

/// The observer over `run` in `T`, step for step `firmware::Restarted` with the generated
/// `StartedEkf`: per sample the targets, NaN where there is none (a refused sample's row). The filter
/// `filter` starts at `constants.x0` with `P(0)` = `constants.p0`; at every accepted sample whose
/// map row `map[k]` is finite it is checked ([`disagrees`]) and, if so, restarted from the map's states
/// with `P` = `started_p0` on the diagonal, that sample's estimate the map's row. A step whose result is
/// not finite, or whose innovations leave the filter's watch (`constants.watch`) implausible, restarts
/// it, from the map's row where it is finite, else from `constants.x0` (the last estimate stays). With
/// the restarts on the run.
#[allow(clippy::too_many_arguments)]
pub fn estimate<T: Scalar + Maths>(
    filter: &FilterCode,
    constants: &EkfConstants,
    started_p0: &[f64],
    restart: &RestartConstants,
    state_targets: &[usize],
    map: &[Vec<T>],
    run: &Run,
    code: &ModelCode,
) -> Track<Vec<Vec<T>>> {
    let mut observer = RestartStep::new(filter, constants, started_p0, restart, state_targets, code);
    let none = vec![T::literal(f32::NAN, f64::NAN); code.dimensions.targets];
    let rows = run
        .measurements
        .iter()
        .zip(run.inputs.iter())
        .enumerate()
        .map(|(k, (y, u))| observer.step(map.get(k).unwrap_or(&none), y, u))
        .collect();
    Track {
        rows,
        restarts: observer.restarts(),
    }
}

/// [`estimate`] one sample at a time: `firmware::Restarted`'s rule ([`RestartedRule`]) over the
/// written-out programs.
pub struct RestartStep<'a, T> {
    filter: &'a FilterCode,
    code: &'a ModelCode,
    restart: &'a RestartConstants,
    state_targets: &'a [usize],
    /// `P` of a restart, its upper triangle.
    started: Vec<T>,
    /// `x`, the upper triangle of `P` and the watched mean at the start.
    fresh: (Vec<T>, Vec<T>, T),
    watch: Watcher<T>,
    /// `x`, the upper triangle of `P` and the watched mean (`m` where not watched: never read).
    rule: RestartedRule<(Vec<T>, Vec<T>, T)>,
    refusals: Refusals,
    last: Vec<T>,
    nan: Vec<T>,
    scratch: RefCell<Vec<T>>,
}

impl<'a, T: Scalar + Maths> RestartStep<'a, T> {
    /// At the box centre, before the first sample of a run.
    pub fn new(
        filter: &'a FilterCode,
        constants: &EkfConstants,
        started_p0: &[f64],
        restart: &'a RestartConstants,
        state_targets: &'a [usize],
        code: &'a ModelCode,
    ) -> Self {
        let nan = vec![T::literal(f32::NAN, f64::NAN); code.dimensions.targets];
        let watch = Watcher::new(&constants.watch, code.dimensions.outputs);
        let fresh = (literals(&constants.x0), literals(&constants.p0.upper()), watch.start());
        RestartStep {
            filter,
            code,
            restart,
            state_targets,
            started: literals(&kalman::diagonal_upper(started_p0)),
            watch,
            rule: RestartedRule::new(fresh.clone()),
            fresh,
            refusals: Refusals::NONE,
            last: nan.clone(),
            nan,
            scratch: RefCell::new(Vec::new()),
        }
    }

    /// The targets at the sample with outputs `y` and inputs `u`, the map's estimate there `row`
    /// (NaN where it has none): NaN where the sample is refused, the latest estimate where the
    /// filter restarted on a step that was not finite.
    pub fn step(&mut self, row: &[T], y: &[f64], u: &[f64]) -> Vec<T> {
        let (y, u) = (literals::<T>(y), literals::<T>(u));
        let RestartStep {
            filter,
            code,
            restart,
            state_targets,
            started,
            fresh,
            watch,
            rule,
            scratch,
            ..
        } = self;
        let watch = *watch;
        let inputs_finite = u.iter().all(|v| v.is_finite());
        if !(inputs_finite && y.iter().all(|v| v.is_finite())) {
            rule.lost(inputs_finite, |(x, p, chi)| {
                kept(filter.run(x, p, None, &u, &mut scratch.borrow_mut())).map(|(x, p)| (x, p, *chi))
            });
            let _ = self.refusals.count::<()>(Err(Refused::Value));
            return self.nan.clone();
        }
        let states = |row: &[T]| state_targets.iter().map(|&t| row[t]).collect::<Vec<T>>();
        let result = rule.accepted(
            row.iter().all(|v| v.is_finite()).then_some(row),
            |(x, p, _), row| disagrees(x, p, &states(row), restart),
            |row| {
                kept(filter.run(&states(row), started, None, &u, &mut scratch.borrow_mut()))
                    .map(|(x, p)| (x, p, watch.start()))
            },
            |(x, p, chi)| {
                let ((estimate, x, p), nis) = filter.run_watched(x, p, Some(&y), &u, &mut scratch.borrow_mut());
                let estimate = estimate.expect("a measured sample has an estimate");
                let nis = nis.expect("a measured sample has one");
                let chi = watch.watched(*chi, nis);
                let (x, p) = kept((None, x, p))?;
                if !watch.plausible(chi) {
                    return None; // the watch: the innovations stay implausible
                }
                Some(((x, p, chi), code.targets(&estimate, &u, &mut scratch.borrow_mut())))
            },
            || fresh.clone(),
        );
        match self.refusals.count(result) {
            // The targets' rows of the map (the helpers' follow them), as `firmware::Restarted`.
            Ok(Given::Map(row)) => self.last = row[..self.nan.len()].to_vec(),
            Ok(Given::Followed(targets)) => self.last = targets,
            Ok(Given::Nothing) | Err(_) => {}
        }
        self.last.clone()
    }

    /// Samples refused so far for a bad value, as the chip counts them.
    pub fn refused(&self) -> u32 {
        self.refusals.get()
    }

    /// Restarts on a step that was not finite so far, as the chip counts them.
    pub fn restarts(&self) -> u32 {
        self.refusals.restarts()
    }
}

/// Chooses `τ` from [`THRESHOLDS`]: the lowest `score(τ)`, the first of equals. Returns `(τ, score)`.
pub fn tune(score: impl Fn(f64) -> f64 + Sync) -> (f64, f64) {
    crate::observers::score::lowest(&THRESHOLDS, score)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_distance_is_the_sum_of_scaled_squares_and_nan_restarts() {
        // Two states, P = [[1, 0.5], [0.5, 3]] (upper triangle 1, 0.5, 3), e² = (1, 1):
        // d = (2 − 0)² / 2 + (1 − 2)² / 4 = 2.25.
        let constants = |threshold| RestartConstants {
            threshold,
            variances: vec![1.0, 1.0],
        };
        let (x, p, map) = ([2.0, 1.0], [1.0, 0.5, 3.0], [0.0, 2.0]);
        assert!(disagrees(&x, &p, &map, &constants(2.24)));
        assert!(!disagrees(&x, &p, &map, &constants(2.25)));
        assert!(disagrees(&[f64::NAN, 1.0], &p, &map, &constants(1e9)));
    }
}
