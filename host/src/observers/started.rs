//! `firmware::Started`'s own rule ([`firmware::rules::StartedRule`]) on the host over a simulated run:
//! the shell that the model-corrected map ([`super::kind::corrected::run`]) and the map-started EKF
//! ([`super::ekf::estimate_started`]) plug their samples into.
//!
//! No estimate before the map's first (NaN rows: before sample `first`, or while the map's row is not
//! finite because refused samples left its window short); there the map's row, and `start` from the
//! map's states; then `follow` for every later sample with its count `j` (counted as the chip counts:
//! only samples taken). A sample with a non-finite output or input is refused as the chip refuses it:
//! its row is NaN (no estimate from that sample), and once started, when its input is finite, what
//! is carried takes one period of the model (`lost`, `Follower::predict`). A prediction that gives
//! `None` (not finite) is not taken; a start or follow-up that gives `None` (not finite, or an EKF's
//! χ² watch ended it) restarts the rule as the chip does (the last estimate stays, the rows until the
//! map's next estimate): the chip empties its window, so the map is read again only once `first + 1`
//! samples have been accepted since.

use firmware::rules::{Given, Refusals, Refused, StartedRule};
use firmware::Scalar;

/// One sample at a time: `firmware::Started`'s rule ([`StartedRule`]) and the rows the host
/// reads off it.
pub struct Shell<T, C> {
    first: usize,
    state_targets: Vec<usize>,
    start_up: usize,
    steady_reads_map: bool,
    /// A row of NaN: no estimate.
    nan: Vec<T>,
    rule: StartedRule<C>,
    refusals: Refusals,
    /// Samples seen.
    k: usize,
    /// Samples accepted since the start or the last restart: the chip's window fill.
    filled: usize,
    last: Vec<T>,
}

impl<T: Scalar, C> Shell<T, C> {
    /// Before the first sample of a run, for rows of `width` targets, the follower reading the map during `start_up` estimates and afterwards only if
    /// `steady_reads_map`.
    pub fn new(
        first: usize,
        state_targets: &[usize],
        width: usize,
        (start_up, steady_reads_map): (usize, bool),
    ) -> Self {
        let nan = vec![T::literal(f32::NAN, f64::NAN); width];
        Shell {
            first,
            state_targets: state_targets.to_vec(),
            start_up,
            steady_reads_map,
            last: nan.clone(),
            nan,
            rule: StartedRule::START,
            refusals: Refusals::NONE,
            k: 0,
            filled: 0,
        }
    }

    /// The targets at the next sample (outputs `y`, inputs `u`), given the map's estimate `row` there
    /// (zeros where not read): `start(x, u)` gives what to carry from the map's states,
    /// `follow(carried, j, map_states, y, u)` what to carry next and the targets, `lost(carried, u)`
    /// what to carry over a refused sample with a finite input. NaN where the sample is refused or there is no
    /// estimate yet; the latest estimate where a start or follow-up ends the follower and until the
    /// map starts it again (what the chip's `estimate` returns).
    pub fn step(
        &mut self,
        row: &[T],
        y: &[f64],
        u: &[f64],
        start: &mut impl FnMut(&[T], &[T]) -> Option<C>,
        follow: &mut impl FnMut(&C, usize, &[T], &[T], &[T]) -> Option<(C, Vec<T>)>,
        lost: &mut impl FnMut(&C, &[T]) -> Option<C>,
    ) -> Vec<T> {
        let k = self.k;
        self.k += 1;
        let (y, u) = (literals::<T>(y), literals::<T>(u));
        let inputs_finite = u.iter().all(|v| v.is_finite());
        if !(inputs_finite && y.iter().all(|v| v.is_finite())) {
            self.rule.lost(inputs_finite, |c| lost(c, &u));
            let _ = self.refusals.count::<()>(Err(Refused::Value));
            return self.nan.clone();
        }
        self.filled += 1;
        let targets = &self.state_targets;
        let states = |row: &[T]| targets.iter().map(|&t| row[t]).collect::<Vec<T>>();
        let first = self.first;
        let read = self.rule.reads_map(self.start_up, self.steady_reads_map);
        let result = self.rule.accepted(
            self.start_up,
            (read && k >= first && self.filled > first && row.iter().all(|v| v.is_finite())).then_some(row),
            |row| start(&states(row), &u),
            |c, j, _, row| {
                let map = row.map_or_else(|| vec![T::ZERO; targets.len()], |row| states(row));
                follow(c, j, &map, &y, &u)
            },
        );
        if result.is_err() {
            self.filled = 0; // restarted: the chip empties its window
        }
        match self.refusals.count(result) {
            // No estimate from this sample: none yet (NaN), or the latest while the map's window
            // refills after a restart, as the chip's `estimate` returns it.
            Ok(Given::Nothing) => self.last.clone(),
            // The targets' rows of the map (the helpers' follow them), as `firmware::Started`.
            Ok(Given::Map(row)) => {
                self.last = row[..self.nan.len()].to_vec();
                self.last.clone()
            }
            Ok(Given::Followed(targets)) => {
                self.last.clone_from(&targets);
                targets
            }
            Err(_) => self.last.clone(),
        }
    }

    /// Samples refused so far for a bad value, as the chip counts them ([`Refusals`]).
    pub fn refused(&self) -> u32 {
        self.refusals.get()
    }

    /// Restarts so far, as the chip counts them ([`Refusals`]).
    pub fn restarts(&self) -> u32 {
        self.refusals.restarts()
    }
}

/// `value` in `T`, as the chip receives it (the emitted `T::literal`).
pub fn literal<T: Scalar>(value: f64) -> T {
    T::literal(value as f32, value)
}

/// `values` in `T`, as the chip receives them.
pub fn literals<T: Scalar>(values: &[f64]) -> Vec<T> {
    values.iter().map(|&v| literal(v)).collect()
}
