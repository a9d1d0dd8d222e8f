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
//! accepted                       the kind's sample; its result kept if finite, else the filter
//!                                restarts (from its start, or from the map where it has one)
//! ```
//!
//! so that no NaN ever enters what a filter carries, a sample is refused only for a bad value, and
//! a filter whose step fails on finite data does not stay stuck: a sample with finite values either
//! gives an estimate or restarts the filter. Both are counted ([`Refusals`]).

use crate::RejectedSample;

/// Why a sample gave no estimate: a value that is not finite, or a filter step whose result is not
/// (the filter then restarted). The observers' `push` reports both as [`RejectedSample`]; their
/// counts ([`Refusals`]) tell them apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refused {
    /// A value of the sample is NaN or infinite.
    Value,
    /// The values were finite but the filter's step was not: the filter restarted.
    Restarted,
}

impl From<Refused> for RejectedSample {
    fn from(_: Refused) -> Self {
        RejectedSample
    }
}

/// How many samples an observer refused since its start for a bad value, and how many times its
/// filter restarted: health figures a firmware can read at any time. Each saturates at `u32::MAX`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Refusals {
    refused: u32,
    restarts: u32,
}

impl Refusals {
    /// No sample refused, no restart yet.
    pub const NONE: Self = Refusals {
        refused: 0,
        restarts: 0,
    };

    /// Counts `result` if it is a refusal or a restart, and passes it on as the observers report it.
    #[inline(always)]
    pub fn count<V>(&mut self, result: Result<V, Refused>) -> Result<V, RejectedSample> {
        match result {
            Ok(v) => Ok(v),
            // Branches the error paths alone take.
            Err(Refused::Value) => {
                self.refused = self.refused.saturating_add(1);
                Err(RejectedSample)
            }
            Err(Refused::Restarted) => {
                self.restarts = self.restarts.saturating_add(1);
                Err(RejectedSample)
            }
        }
    }

    /// Samples refused for a bad value.
    #[must_use]
    pub const fn get(self) -> u32 {
        self.refused
    }

    /// Restarts of the filter (a step that was not finite on finite values).
    #[must_use]
    pub const fn restarts(self) -> u32 {
        self.restarts
    }
}

/// One sample of a Kalman filter that carries `carried` from the start (the filters from the box
/// centre): with a finite output `measured` (the estimate given the sample and what to carry), with a
/// lost one `unmeasured` (the prediction alone); a result is kept only when `finite` holds. A measured
/// result that is not finite restarts the filter: what is carried becomes `fresh()`.
#[inline(always)]
pub fn filter_sample<C, E>(
    carried: &mut C,
    inputs_finite: bool,
    outputs_finite: bool,
    measured: impl FnOnce(&C) -> (E, C),
    unmeasured: impl FnOnce(&C) -> C,
    finite: impl Fn(&C) -> bool,
    fresh: impl FnOnce() -> C,
) -> Result<E, Refused> {
    // The lost output's path is `lost`'s, written out: through `lost` the compiler kept 48 more
    // stack bytes for E. coli's filters and 2 to 6 more Cortex-M0 instructions (measured).
    if !inputs_finite {
        return Err(Refused::Value);
    }
    if outputs_finite {
        let (estimate, next) = measured(carried);
        if finite(&next) {
            *carried = next;
            return Ok(estimate);
        }
        *carried = fresh();
        return Err(Refused::Restarted);
    }
    let next = unmeasured(carried);
    if finite(&next) {
        *carried = next;
    }
    Err(Refused::Value)
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
    /// follow-up that gives `None` restarts the rule ([`Refused::Restarted`]): back to
    /// [`START`](Self::START), to start again from the map's next estimate (the observer empties its
    /// window, whose samples it may not have kept).
    #[inline(always)]
    pub fn accepted<M, S>(
        &mut self,
        start_up: usize,
        map: Option<M>,
        start: impl FnOnce(&M) -> Option<C>,
        follow: impl FnOnce(&C, usize, bool, Option<&M>) -> Option<(C, S)>,
    ) -> Result<Given<M, S>, Refused> {
        let in_start_up = self.count <= start_up;
        let given = match (&self.carried, map) {
            (None, Some(first)) => match start(&first) {
                Some(carried) => {
                    self.carried = Some(carried);
                    Given::Map(first)
                }
                None => return Err(self.restart()),
            },
            (Some(carried), read) => match follow(carried, self.count, in_start_up, read.as_ref()) {
                Some((next, states)) => {
                    self.carried = Some(next);
                    Given::Followed(states)
                }
                None => return Err(self.restart()),
            },
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

    /// Back to the start after a step that was not finite.
    #[cold]
    fn restart(&mut self) -> Refused {
        *self = Self::START;
        Refused::Restarted
    }
}

/// The rule of a filter from the box centre that the map watches ([`crate::Restarted`]): at every
/// accepted sample where the map has an estimate, the filter restarts from it when the two disagree;
/// a step that is not finite restarts it too, from the map where it has an estimate, else from the
/// filter's start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RestartedRule<C> {
    /// What the filter carries.
    pub carried: C,
}

impl<C> RestartedRule<C> {
    /// At the filter's start.
    pub const fn new(fresh: C) -> Self {
        RestartedRule { carried: fresh }
    }

    /// An accepted sample. `map` is the map's estimate (`None`: fewer than `N` samples); where
    /// `disagrees(carried, map)`, the filter restarts from it by `start(map)` and the map's estimate
    /// is the sample's (a start that gives `None` is not taken). Otherwise `follow(carried)` gives
    /// what to carry next and the states; when it gives `None`, the filter restarts from
    /// `start(map)`, or `fresh()` without one, and the sample is [`Refused::Restarted`].
    #[inline(always)]
    pub fn accepted<M: Copy, S>(
        &mut self,
        map: Option<M>,
        disagrees: impl FnOnce(&C, &M) -> bool,
        start: impl Fn(&M) -> Option<C>,
        follow: impl FnOnce(&C) -> Option<(C, S)>,
        fresh: impl FnOnce() -> C,
    ) -> Result<Given<M, S>, Refused> {
        if let Some(m) = map {
            if disagrees(&self.carried, &m) {
                if let Some(carried) = start(&m) {
                    self.carried = carried;
                    return Ok(Given::Map(m));
                }
            }
        }
        match follow(&self.carried) {
            Some((next, states)) => {
                self.carried = next;
                Ok(Given::Followed(states))
            }
            None => {
                self.carried = map.as_ref().and_then(start).unwrap_or_else(fresh);
                Err(Refused::Restarted)
            }
        }
    }

    /// A refused sample (see [`lost`]).
    #[inline(always)]
    pub fn lost(&mut self, inputs_finite: bool, predict: impl FnOnce(&C) -> Option<C>) {
        lost(&mut self.carried, inputs_finite, predict);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A "filter" carrying one number from 0: measured adds the output, unmeasured adds one, a
    /// result above 100 is "not finite".
    fn sample(c: &mut f64, u: f64, y: f64) -> Result<f64, Refused> {
        filter_sample(
            c,
            u.is_finite(),
            y.is_finite(),
            |c| (c + y, c + y),
            |c| c + 1.0,
            |c| *c <= 100.0,
            || 0.0,
        )
    }

    #[test]
    fn a_filter_sample_keeps_only_finite_results_and_restarts_when_a_step_is_not() {
        let mut c = 0.0;
        assert_eq!(sample(&mut c, 0.0, 5.0), Ok(5.0));
        assert_eq!(sample(&mut c, 0.0, f64::NAN), Err(Refused::Value)); // lost: predicted
        assert_eq!(c, 6.0);
        assert_eq!(sample(&mut c, f64::NAN, 1.0), Err(Refused::Value)); // bad input: nothing
        assert_eq!(c, 6.0);
        assert_eq!(sample(&mut c, 0.0, 200.0), Err(Refused::Restarted)); // overflow: restarted
        assert_eq!(c, 0.0);
        assert_eq!(sample(&mut c, 0.0, 3.0), Ok(3.0)); // the fresh filter's first sample
        let mut refusals = Refusals::NONE;
        for y in [1.0, f64::NAN, 2.0, f64::INFINITY, 500.0] {
            let _ = refusals.count(sample(&mut c, 0.0, y));
        }
        assert_eq!((refusals.get(), refusals.restarts()), (2, 1));
        let mut full = Refusals {
            refused: u32::MAX,
            restarts: u32::MAX,
        };
        assert_eq!(full.count::<()>(Err(Refused::Value)), Err(RejectedSample));
        assert_eq!(full.count::<()>(Err(Refused::Restarted)), Err(RejectedSample));
        assert_eq!((full.get(), full.restarts()), (u32::MAX, u32::MAX));
    }

    #[test]
    fn a_started_rule_waits_for_the_map_then_reads_it_during_the_start_up_only() {
        let mut rule = StartedRule::<f64>::START;
        let reads = core::cell::Cell::new(0);
        let push = |rule: &mut StartedRule<f64>, map: Option<f64>| {
            let read = rule.reads_map(1, false);
            reads.set(reads.get() + usize::from(read));
            rule.accepted(
                1,
                map.filter(|_| read),
                |m| Some(*m),
                |c, j, start_up, m| (*c < 100.0).then_some((c + 1.0, (j, start_up, m.copied()))),
            )
        };
        assert_eq!(push(&mut rule, None), Ok(Given::Nothing));
        assert_eq!(push(&mut rule, Some(10.0)), Ok(Given::Map(10.0)));
        assert_eq!(push(&mut rule, Some(20.0)), Ok(Given::Followed((1, true, Some(20.0)))));
        assert_eq!(push(&mut rule, Some(30.0)), Ok(Given::Followed((2, false, None))));
        assert_eq!(push(&mut rule, Some(40.0)), Ok(Given::Followed((2, false, None))));
        assert_eq!(reads.get(), 3);
        assert_eq!(rule.carried, Some(13.0));
        rule.lost(true, |c| Some(c * 2.0));
        rule.lost(false, |c| Some(c * 2.0));
        assert_eq!(rule.carried, Some(26.0));
        // A follow-up that is not finite: back to the start, started again by the map's next estimate.
        rule.carried = Some(100.0);
        assert_eq!(push(&mut rule, Some(50.0)), Err(Refused::Restarted));
        assert_eq!(rule, StartedRule::START);
        assert_eq!(push(&mut rule, Some(60.0)), Ok(Given::Map(60.0)));
        assert_eq!(rule.carried, Some(60.0));
    }

    #[test]
    fn a_restarted_rule_watches_the_map_at_every_sample() {
        // The filter adds 1; it disagrees with the map beyond a distance of 1; a carried value above
        // 100 makes its step fail.
        let mut rule = RestartedRule::new(0.0_f64);
        let push = |rule: &mut RestartedRule<f64>, map: Option<f64>| {
            rule.accepted(
                map,
                |c, m| (c - m).abs() > 1.0,
                |m| Some(*m),
                |c| (*c < 100.0).then_some((c + 1.0, *c)),
                || -7.0,
            )
        };
        assert_eq!(push(&mut rule, None), Ok(Given::Followed(0.0))); // no map yet: the filter
        assert_eq!(push(&mut rule, Some(1.5)), Ok(Given::Followed(1.0))); // agrees
        assert_eq!(push(&mut rule, Some(9.0)), Ok(Given::Map(9.0))); // disagrees: restarted
        assert_eq!(rule.carried, 9.0);
        assert_eq!(push(&mut rule, Some(9.5)), Ok(Given::Followed(9.0))); // checked again, agrees
                                                                          // Later on, far from the map: restarted, however long the filter ran.
        rule.carried = 40.0;
        assert_eq!(push(&mut rule, Some(12.0)), Ok(Given::Map(12.0)));
        // A step that is not finite: restarted from the map, or from the start without one.
        rule.carried = 100.0;
        assert_eq!(push(&mut rule, Some(100.5)), Err(Refused::Restarted));
        assert_eq!(rule.carried, 100.5);
        rule.carried = 100.0;
        assert_eq!(push(&mut rule, None), Err(Refused::Restarted));
        assert_eq!(rule.carried, -7.0);
    }
}
