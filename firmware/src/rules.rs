//! The rules every filter kind follows over a sample, written once over any storage: the chip runs
//! them over its fixed-size arrays ([`crate::FilterObserver`], [`crate::Started`],
//! [`crate::Restarted`]) and the host runs the very same functions over its interpreted programs in
//! `f64` and `f32` (the host's filter steps and started shell), so that the two cannot drift apart.
//!
//! A kind plugs in its written-out samples as closures; the rules decide which one runs and what is
//! kept:
//!
//! ```text
//! input not finite               refused; nothing changes
//! output not finite (lost)       refused; once started, what is carried takes the model's period
//!                                (the prediction alone), kept only if finite
//! accepted                       the kind's sample; its result kept only if finite, else refused
//!                                and nothing changes
//! ```
//!
//! so that no NaN ever enters what a filter carries, and every refusal is counted ([`Refusals`]).

use crate::RejectedSample;

/// How many samples an observer refused since its start (a bad input, a lost output or a result
/// that was not finite): a health figure a firmware can read at any time. Saturates at `u32::MAX`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Refusals(u32);

impl Refusals {
    /// No sample refused yet.
    pub const NONE: Self = Refusals(0);

    /// Counts `result` if it is a refusal, and passes it on.
    #[inline(always)]
    pub fn count<V>(&mut self, result: Result<V, RejectedSample>) -> Result<V, RejectedSample> {
        if result.is_err() {
            self.0 = self.0.saturating_add(1); // a branch the error paths alone take
        }
        result
    }

    /// The number counted.
    #[must_use]
    pub const fn get(self) -> u32 {
        self.0
    }
}

/// One sample of a Kalman filter that carries `carried` from the start (the filters from the box
/// centre): with a finite output `measured` (the estimate given the sample and what to carry), with a
/// lost one `unmeasured` (the prediction alone); a result is kept only when `finite` holds.
#[inline(always)]
pub fn filter_sample<C, E>(
    carried: &mut C,
    inputs_finite: bool,
    outputs_finite: bool,
    measured: impl FnOnce(&C) -> (E, C),
    unmeasured: impl FnOnce(&C) -> C,
    finite: impl Fn(&C) -> bool,
) -> Result<E, RejectedSample> {
    // The lost output's path is `lost`'s, written out: through `lost` the compiler kept 48 more
    // stack bytes for E. coli's filters and 2 to 6 more Cortex-M0 instructions (measured).
    if !inputs_finite {
        return Err(RejectedSample);
    }
    if outputs_finite {
        let (estimate, next) = measured(carried);
        if finite(&next) {
            *carried = next;
            return Ok(estimate);
        }
    } else {
        let next = unmeasured(carried);
        if finite(&next) {
            *carried = next;
        }
    }
    Err(RejectedSample)
}

/// Over a refused sample of a filter that carries `carried`: the output is lost, not the time, so
/// when the input is finite what is carried takes the model's period (`predict`, kept when `Some`).
#[inline(always)]
pub fn lost<C>(carried: &mut C, inputs_finite: bool, predict: impl FnOnce(&C) -> Option<C>) {
    if inputs_finite {
        if let Some(next) = predict(carried) {
            *carried = next;
        }
    }
}

/// What an accepted sample gave an observer that the map starts or checks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Given<M, S> {
    /// No estimate yet (fewer than `N` samples in the map's window).
    Nothing,
    /// The map's own estimate (the observer started or restarted from it).
    Map(M),
    /// The follower's states.
    Followed(S),
}

/// The rule of an observer that the map starts ([`crate::Started`]): nothing before the map's
/// first estimate, then the follower from what the map started, reading the map during a start-up
/// of `start_up` estimates and afterwards only if `steady_reads_map`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StartedRule<C> {
    /// What the follower carries, once started.
    pub carried: Option<C>,
    /// Estimates so far, counted up to `start_up + 1`.
    pub count: usize,
}

impl<C> StartedRule<C> {
    /// Before the first sample.
    pub const START: Self = StartedRule {
        carried: None,
        count: 0,
    };

    /// Whether the next accepted sample reads the map: during the start-up of `start_up` estimates,
    /// and afterwards only if `steady_reads_map`.
    #[inline(always)]
    #[must_use]
    pub fn reads_map(&self, start_up: usize, steady_reads_map: bool) -> bool {
        self.count <= start_up || steady_reads_map
    }

    /// An accepted sample. `map` is the map's estimate where [`reads_map`](Self::reads_map) holds
    /// (`None`: not read, or fewer than `N` samples); `start(map)` what to carry from the map's first
    /// estimate; `follow(carried, j, start_up, map)` what to carry next and the states. A start or
    /// follow-up that gives `None` is refused and changes nothing.
    #[inline(always)]
    pub fn accepted<M, S>(
        &mut self,
        start_up: usize,
        map: Option<M>,
        start: impl FnOnce(&M) -> Option<C>,
        follow: impl FnOnce(&C, usize, bool, Option<&M>) -> Option<(C, S)>,
    ) -> Result<Given<M, S>, RejectedSample> {
        let in_start_up = self.count <= start_up;
        let given = match (&self.carried, map) {
            (None, Some(first)) => {
                self.carried = Some(start(&first).ok_or(RejectedSample)?);
                Given::Map(first)
            }
            (Some(carried), read) => {
                let (next, states) = follow(carried, self.count, in_start_up, read.as_ref()).ok_or(RejectedSample)?;
                self.carried = Some(next);
                Given::Followed(states)
            }
            (None, None) => return Ok(Given::Nothing), // fewer than N samples: no estimate yet
        };
        self.count = if in_start_up { self.count + 1 } else { self.count };
        Ok(given)
    }

    /// A refused sample (see [`lost`]): nothing before the start.
    #[inline(always)]
    pub fn lost(&mut self, inputs_finite: bool, predict: impl FnOnce(&C) -> Option<C>) {
        if let Some(carried) = &mut self.carried {
            lost(carried, inputs_finite, predict);
        }
    }
}

/// The rule of a filter from the box centre that checks the map once, at its first estimate, and
/// restarts from it when the two disagree ([`crate::Restarted`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RestartedRule<C> {
    /// What the filter carries.
    pub carried: C,
    /// Whether the map has been read (once).
    pub checked: bool,
}

impl<C> RestartedRule<C> {
    /// At the filter's start.
    pub const fn new(fresh: C) -> Self {
        RestartedRule {
            carried: fresh,
            checked: false,
        }
    }

    /// The check, before the sample's follow-up while not yet checked: `map()` is the map's estimate
    /// (`None`: fewer than `N` samples, not checked yet). Once it has one, checked; when
    /// `disagrees(carried, map)`, restarted from it by `start(map)` (unless that gives `None`), and
    /// the map's estimate is the sample's.
    #[inline(always)]
    pub fn check<M>(
        &mut self,
        map: impl FnOnce() -> Option<M>,
        disagrees: impl FnOnce(&C, &M) -> bool,
        start: impl FnOnce(&M) -> Option<C>,
    ) -> Option<M> {
        let first = map()?;
        self.checked = true;
        if !disagrees(&self.carried, &first) {
            return None;
        }
        self.carried = start(&first)?;
        Some(first)
    }

    /// A refused sample (see [`lost`]).
    #[inline(always)]
    pub fn lost(&mut self, inputs_finite: bool, predict: impl FnOnce(&C) -> Option<C>) {
        lost(&mut self.carried, inputs_finite, predict);
    }

    /// The filter's own sample: `follow(carried)` gives what to carry next and the states, or `None`
    /// (refused, nothing changes).
    #[inline(always)]
    pub fn follow<S>(&mut self, follow: impl FnOnce(&C) -> Option<(C, S)>) -> Result<S, RejectedSample> {
        let (next, states) = follow(&self.carried).ok_or(RejectedSample)?;
        self.carried = next;
        Ok(states)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A "filter" carrying one number: measured adds the output, unmeasured adds one, a result above
    /// 100 is "not finite".
    fn sample(c: &mut f64, u: f64, y: f64) -> Result<f64, RejectedSample> {
        filter_sample(
            c,
            u.is_finite(),
            y.is_finite(),
            |c| (c + y, c + y),
            |c| c + 1.0,
            |c| *c <= 100.0,
        )
    }

    #[test]
    fn a_filter_sample_keeps_only_finite_results_and_predicts_over_a_lost_output() {
        let mut c = 0.0;
        assert_eq!(sample(&mut c, 0.0, 5.0), Ok(5.0));
        assert_eq!(sample(&mut c, 0.0, f64::NAN), Err(RejectedSample)); // lost: predicted
        assert_eq!(c, 6.0);
        assert_eq!(sample(&mut c, f64::NAN, 1.0), Err(RejectedSample)); // bad input: nothing
        assert_eq!(c, 6.0);
        assert_eq!(sample(&mut c, 0.0, 200.0), Err(RejectedSample)); // overflow: not taken
        assert_eq!(c, 6.0);
        let mut refusals = Refusals::NONE;
        for y in [1.0, f64::NAN, 2.0, f64::INFINITY] {
            let _ = refusals.count(sample(&mut c, 0.0, y));
        }
        assert_eq!(refusals.get(), 2);
        let mut full = Refusals(u32::MAX);
        let _ = full.count::<()>(Err(RejectedSample));
        assert_eq!(full.get(), u32::MAX);
    }

    #[test]
    fn a_started_rule_waits_for_the_map_then_reads_it_during_the_start_up_only() {
        let mut rule = StartedRule::<f64>::START;
        let mut reads = 0;
        let mut push = |rule: &mut StartedRule<f64>, map: Option<f64>| {
            let read = rule.reads_map(1, false);
            reads += usize::from(read);
            rule.accepted(
                1,
                map.filter(|_| read),
                |m| Some(*m),
                |c, j, start_up, m| Some((c + 1.0, (j, start_up, m.copied()))),
            )
        };
        assert_eq!(push(&mut rule, None), Ok(Given::Nothing));
        assert_eq!(push(&mut rule, Some(10.0)), Ok(Given::Map(10.0)));
        assert_eq!(push(&mut rule, Some(20.0)), Ok(Given::Followed((1, true, Some(20.0)))));
        assert_eq!(push(&mut rule, Some(30.0)), Ok(Given::Followed((2, false, None))));
        assert_eq!(push(&mut rule, Some(40.0)), Ok(Given::Followed((2, false, None))));
        assert_eq!(reads, 3);
        assert_eq!(rule.carried, Some(13.0));
        rule.lost(true, |c| Some(c * 2.0));
        rule.lost(false, |c| Some(c * 2.0));
        assert_eq!(rule.carried, Some(26.0));
    }

    #[test]
    fn a_restarted_rule_checks_once_and_restarts_only_on_disagreement() {
        let mut rule = RestartedRule::new(0.0_f64);
        assert_eq!(rule.check(|| None::<f64>, |_, _| true, |m| Some(*m)), None);
        assert!(!rule.checked);
        assert_eq!(
            rule.check(|| Some(5.0), |c, m| (c - m).abs() > 1.0, |m| Some(*m)),
            Some(5.0)
        );
        assert!(rule.checked);
        assert_eq!(rule.carried, 5.0);
        let mut agreeing = RestartedRule::new(0.0_f64);
        assert_eq!(
            agreeing.check(|| Some(0.5), |c, m| (c - m).abs() > 1.0, |m| Some(*m)),
            None
        );
        assert_eq!((agreeing.checked, agreeing.carried), (true, 0.0));
        assert_eq!(agreeing.follow(|c| Some((c + 1.0, 7))), Ok(7));
        assert_eq!(agreeing.follow(|_| None::<(f64, i32)>), Err(RejectedSample));
        assert_eq!(agreeing.carried, 1.0);
    }
}
