//! A filter from the centre of the state box that the map watches and restarts: the EKF's
//! convergence from a good start, the map's guess-free estimate whenever the filter loses track.
//!
//! An EKF started at the box centre converges fast and far when the plant starts near it, and slowly
//! (or to a wrong branch) from a corner, and a filter may lose track later on (a wrong branch, a
//! bound); the map `F(Z)` needs no initial guess but forgets everything older than `N` samples.
//! [`Restarted`] runs the filter from the first sample (estimates from the first accepted sample on)
//! and, at every accepted sample from the map's first estimate (the `N`-th) on, compares the
//! filter's prediction `x̂(k|k−1)`, with its covariance `P(k|k−1)`, to the map's states:
//!
//! ```text
//! d = Σ_i (x̂_i − F_i)² / (P_ii + e_i²)        e_i²: the map's mean squared error of state i
//! d > τ  →  restart: x̂(k) = F(Z), carried on as the map-started filter (Follower::start)
//! d ≤ τ  →  the filter's usual sample
//! ```
//!
//! `d` is the χ²-like distance of two independent estimates of one state; the threshold `τ` is the
//! host's, chosen on the tuning runs. The check runs at every sample, so every accepted sample from
//! the `N`-th on runs the same instructions: the window, the map, the distance, the filter. A step
//! whose result is not finite restarts the filter too, from the map where it has an estimate.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(d <= τ)` is deliberate: a NaN distance restarts.

use core::marker::PhantomData;

use crate::rules::{Given, Refusals, Refused, RestartedRule};
use crate::started::{map_targets, states_of, targets_of};
use crate::window::{Sample, Window};
use crate::{Design, Estimate, Follower, RejectedSample, Scalar};

/// A [`Follower`] that can also start without the map and be checked against it.
///
/// Its `follow` is called with `j = 1`, `start_up = false` and zeros for the map (it reads none of
/// them: `START_UP` is 0 and `STEADY_READS_MAP` false); `start` is its restart from the map.
pub trait Restart<T: Scalar, const NX: usize, const NY: usize, const NU: usize, const NT: usize>:
    Follower<T, NX, NY, NU, NT>
{
    /// What is carried before the first sample (the filter at the box centre with its `P(0)`); a
    /// constant, so that an observer can be a `static`'s initial value.
    const FRESH: Self::Carried;

    /// Whether `carried` (the prediction to the sample) and the map's states `map` disagree so much
    /// that the filter restarts from the map; a NaN distance must say yes.
    fn disagrees(carried: &Self::Carried, map: &[T; NX]) -> bool;
}

/// The filter `F` from the box centre, watched by the map of design `D` (see the module's docs):
/// `NT` targets from `NY` outputs and `NU` inputs, `NX` states, the map's `NM` rows over `N` samples
/// (the targets', then a helper map per state that no target is: [`Follower::STATE_TARGETS`]).
///
/// A sample with a NaN or infinite value is refused: no estimate from it, the window does not take
/// it, and the filter takes one period of its model when the input is finite ([`Follower::predict`]).
/// A sample whose result is not finite (the model overflowed), or that the filter's χ² watch
/// ([`crate::watch`]) finds implausible, restarts the filter, from the map's estimate where it has
/// one, else from the box centre ([`restarts`](Self::restarts) counts them); a restart whose start is
/// not finite is not taken.
pub struct Restarted<
    T: Scalar,
    D,
    F,
    const N: usize,
    const NX: usize,
    const NY: usize,
    const NU: usize,
    const NM: usize,
    const NT: usize,
> where
    F: Restart<T, NX, NY, NU, NT>,
{
    window: Window<T, N, NY, NU>,
    /// What the filter carries: [`crate::rules::RestartedRule`].
    rule: RestartedRule<F::Carried>,
    latest: Option<[Estimate<T>; NT]>,
    refusals: Refusals,
    design: PhantomData<fn() -> D>,
}

impl<T, D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize>
    Restarted<T, D, F, N, NX, NY, NU, NM, NT>
where
    T: Scalar,
    D: Design<T, N, NY, NU, NM>,
    F: Restart<T, NX, NY, NU, NT>,
{
    /// The filter at its start, holding no sample.
    #[must_use]
    pub const fn new() -> Self {
        Restarted {
            window: Window::new(),
            rule: RestartedRule::new(F::FRESH),
            latest: None,
            refusals: Refusals::NONE,
            design: PhantomData,
        }
    }

    /// Takes the sample of the current instant: refused if it is not finite (see the module docs);
    /// else fed to the map's window, checked against the map once the window is full, and the
    /// filter's sample unless the check restarted it.
    #[inline]
    pub fn push(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), RejectedSample> {
        let result = self.sample(y, u);
        self.refusals.count(result)
    }

    /// [`push`](Self::push) but for the count of refusals: the shared rule over this design's map
    /// and filter.
    #[inline(always)]
    fn sample(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), Refused> {
        if !D::accepts(&y, &u) {
            self.lost(&u);
            return Err(Refused::Value);
        }
        self.window.push(Sample { y, u });
        let map = self.window.samples().map(D::estimate);
        let given = self.rule.accepted(
            map,
            |carried, all| F::disagrees(carried, &states_of::<T, F, NX, NY, NU, NM, NT>(all)),
            |all| F::start(&states_of::<T, F, NX, NY, NU, NM, NT>(all), &u),
            |carried| F::follow(carried, 1, false, &[T::ZERO; NX], &y, &u),
            || F::FRESH,
        )?;
        self.latest = Some(match given {
            Given::Map(all) => map_targets(&all),
            Given::Followed(states) => targets_of::<T, F, NX, NY, NU, NT>(&states, &u),
            Given::Nothing => return Ok(()), // not given by this rule
        });
        Ok(())
    }

    /// Over a refused sample: the output is lost, not the time (see [`crate::Started`]). Out of line
    /// and cold.
    #[cold]
    #[inline(never)]
    fn lost(&mut self, u: &[T; NU]) {
        self.rule
            .lost(u.iter().all(|v| v.is_finite()), |carried| F::predict(carried, u));
    }

    /// Samples refused for a bad value since the start (see [`crate::rules::Refusals`]).
    #[must_use]
    pub fn refused(&self) -> u32 {
        self.refusals.get()
    }

    /// Restarts of the filter since the start whose step was not finite (see
    /// [`crate::rules::Refusals`]); restarts on the map's check are its usual work, not counted.
    #[must_use]
    pub fn restarts(&self) -> u32 {
        self.refusals.restarts()
    }

    /// The latest estimate, one per target, or `None` before the first accepted sample.
    #[inline]
    #[must_use]
    pub fn estimate(&self) -> Option<[Estimate<T>; NT]> {
        self.latest
    }

    /// Forgets every sample: the filter back at its start (a new batch or run starts).
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// `true` once an estimate is available.
    #[must_use]
    pub fn is_ready(&self) -> bool {
        self.latest.is_some()
    }
}

impl<T, D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize>
    Default for Restarted<T, D, F, N, NX, NY, NU, NM, NT>
where
    T: Scalar,
    D: Design<T, N, NY, NU, NM>,
    F: Restart<T, NX, NY, NU, NT>,
{
    fn default() -> Self {
        Self::new()
    }
}

impl<T, D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize> Clone
    for Restarted<T, D, F, N, NX, NY, NU, NM, NT>
where
    T: Scalar,
    F: Restart<T, NX, NY, NU, NT>,
{
    fn clone(&self) -> Self {
        Restarted {
            window: self.window.clone(),
            rule: self.rule,
            latest: self.latest,
            refusals: self.refusals,
            design: PhantomData,
        }
    }
}

impl<T, D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize>
    core::fmt::Debug for Restarted<T, D, F, N, NX, NY, NU, NM, NT>
where
    T: Scalar,
    F: Restart<T, NX, NY, NU, NT>,
{
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Restarted")
            .field("design", &core::any::type_name::<D>())
            .field("filter", &core::any::type_name::<F>())
            .field("refused", &self.refusals)
            .field("latest", &self.latest)
            .finish()
    }
}

#[cfg(test)]
mod tests;
