//! Observers that the map starts and the model carries on: the model-corrected map and the EKF
//! started at the map's first estimate.
//!
//! The map `F(Z)` needs no initial guess and has no transient, but it only sees `N` samples; a model
//! carries information across all of them. [`Started`] joins the two: no estimate before `N` samples,
//! then `x̂(N−1) = F(Z(N−1))`, then for every later sample a [`Follower`] updates `x̂` from what it
//! carried and the new sample (reading the map during a start-up of [`Follower::START_UP`]
//! estimates, and afterwards only if [`Follower::STEADY_READS_MAP`]). The model-corrected map is
//!
//! ```text
//! x̂(k) = clamp(x̄ + g_j ⊙ (F(Z(k)) − x̄) + K (y(k) − h(x̄, u(k)))),    x̄ = f(x̂(k−1), u(k−1)),
//! g_j = a table of the host's (start-up, j = 1 … START_UP),   g_j = G  (after),
//! ```
//!
//! clamped to each state's learning range ([`clamp`]), so its estimate is bounded as the map's is.
//! Generated designs implement [`Follower`] with their model written out as straight-line code.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x >= lower)` is deliberate: a NaN must count as low.

use core::marker::PhantomData;

use crate::rules::{Given, Refusals, Refused, StartedRule};
use crate::window::{Sample, Window};
use crate::{Design, Estimate, RejectedSample, Saturation, Scalar};

/// What carries the estimate from one sample to the next once the map has started it.
pub trait Follower<T: Scalar, const NX: usize, const NY: usize, const NU: usize, const NT: usize> {
    /// What is kept between samples (the predicted state; with its covariance for an EKF).
    type Carried: Copy;
    /// Estimates after the first (`j = 1 … START_UP`) that read the map and take the start-up path.
    const START_UP: usize;
    /// Whether the estimates after the start-up read the map.
    const STEADY_READS_MAP: bool;
    /// The map row of each state: row `STATE_TARGETS[i]` of the design's map estimates state `i`
    /// (a target's row below `NT`, else a helper map's: a state that no target is).
    const STATE_TARGETS: [usize; NX];

    /// From the first estimate `x̂(N−1)` (the map's) and `u(N−1)`: what to carry, or `None` when it is
    /// not finite.
    fn start(first: &[T; NX], u: &[T; NU]) -> Option<Self::Carried>;

    /// Estimate `j ≥ 1` (`start_up` is `j ≤ START_UP`; `j` is not counted beyond `START_UP + 1`)
    /// from what was carried, the map's states (zeros when not read), `y(k)` and `u(k)`: what to
    /// carry next and the states, or `None` when a result is not finite or the follower gives up
    /// (an EKF whose χ² watch finds its innovations implausible: [`crate::watch`]).
    fn follow(
        carried: &Self::Carried,
        j: usize,
        start_up: bool,
        map: &[T; NX],
        y: &[T; NY],
        u: &[T; NU],
    ) -> Option<(Self::Carried, [Estimate<T>; NX])>;

    /// Over a sample whose output was lost (refused: not finite) but whose input `u` is known: what
    /// to carry to the next sample with no measurement (the model's prediction from what was
    /// carried), or `None` when it is not finite. Without it the carried state would fall one period
    /// behind the plant for every lost sample.
    fn predict(carried: &Self::Carried, u: &[T; NU]) -> Option<Self::Carried>;

    /// The targets at state `x` and input `u`.
    fn targets(x: &[T; NX], u: &[T; NU]) -> [T; NT];
}

/// `x` clamped to `[lower, upper]` per entry, with the end it was clamped to (NaN goes to `lower`),
/// by selects: the same instructions whatever the values.
#[inline(always)]
#[must_use]
pub fn clamp<T: Scalar, const NX: usize>(x: &[T; NX], lower: &[T; NX], upper: &[T; NX]) -> [Estimate<T>; NX] {
    let mut out = [Estimate {
        value: T::ZERO,
        saturation: Saturation::Inside,
    }; NX];
    for i in 0..NX {
        let (low, high) = (!(x[i] >= lower[i]), x[i] > upper[i]);
        let edge = select(low, lower[i], upper[i]);
        let flag = select(low, Saturation::Low, Saturation::High);
        out[i] = Estimate {
            value: select(low | high, edge, x[i]),
            saturation: select(low | high, flag, Saturation::Inside),
        };
    }
    out
}

/// The targets at the follower's `states` and `u`, each state's saturation flag on its target.
#[inline(always)]
pub(crate) fn targets_of<T, F, const NX: usize, const NY: usize, const NU: usize, const NT: usize>(
    states: &[Estimate<T>; NX],
    u: &[T; NU],
) -> [Estimate<T>; NT]
where
    T: Scalar,
    F: Follower<T, NX, NY, NU, NT>,
{
    let mut x = [T::ZERO; NX];
    for (x, state) in x.iter_mut().zip(states) {
        *x = state.value;
    }
    let values = F::targets(&x, u);
    let mut targets = [Estimate {
        value: T::ZERO,
        saturation: Saturation::Inside,
    }; NT];
    for (target, &value) in targets.iter_mut().zip(&values) {
        target.value = value;
    }
    for (state, &t) in states.iter().zip(&F::STATE_TARGETS) {
        if let Some(target) = targets.get_mut(t) {
            target.saturation = state.saturation;
        }
    }
    targets
}

/// The map's estimate of each state of the follower (row `STATE_TARGETS[i]` for state `i`).
#[inline(always)]
pub(crate) fn states_of<T, F, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize>(
    all: &[Estimate<T>; NM],
) -> [T; NX]
where
    T: Scalar,
    F: Follower<T, NX, NY, NU, NT>,
{
    let mut map = [T::ZERO; NX];
    for (m, &t) in map.iter_mut().zip(&F::STATE_TARGETS) {
        *m = all.get(t).map_or(T::ZERO, |e| e.value);
    }
    map
}

/// The targets' rows of the map's `NM` (its first `NT`: the helper maps' rows follow them).
#[inline(always)]
pub(crate) fn map_targets<T: Scalar, const NM: usize, const NT: usize>(all: &[Estimate<T>; NM]) -> [Estimate<T>; NT] {
    let mut targets = [Estimate {
        value: T::ZERO,
        saturation: Saturation::Inside,
    }; NT];
    for (target, row) in targets.iter_mut().zip(all) {
        *target = *row;
    }
    targets
}

fn select<V>(condition: bool, a: V, b: V) -> V {
    core::hint::select_unpredictable(condition, a, b)
}

/// The observer of map design `D` followed by `F`: `NT` targets from `NY` outputs and `NU` inputs,
/// `NX` states, the map's `NM` rows over the last `N` samples (the targets', then a helper map per
/// state that no target is: [`Follower::STATE_TARGETS`]).
///
/// `push` takes every sample and does the work; `estimate` returns the latest estimate. Memory is
/// fixed (the window, what `F` carries, the latest estimate). After the start-up every accepted
/// sample runs the same instructions. A sample with a NaN or infinite value is refused: it gives no
/// estimate and the map's window does not take it, but once started, a refused sample whose input
/// is finite still takes one period of the model ([`Follower::predict`]), so that what is carried
/// stays in step with the plant. A sample with finite values whose start or follow-up gives `None`
/// (not finite: the model overflowed; or an EKF's χ² watch, [`crate::watch`], found its innovations
/// implausible) restarts the observer: no estimate from it, the window emptied, and the map's next
/// estimate starts the follower again ([`restarts`](Self::restarts) counts them; the latest estimate
/// stays until then).
pub struct Started<
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
    F: Follower<T, NX, NY, NU, NT>,
{
    window: Window<T, N, NY, NU>,
    /// What the follower carries and the estimates so far ([`crate::rules::StartedRule`]).
    rule: StartedRule<F::Carried>,
    latest: Option<[Estimate<T>; NT]>,
    refusals: Refusals,
    design: PhantomData<fn() -> D>,
}

impl<T, D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize>
    Started<T, D, F, N, NX, NY, NU, NM, NT>
where
    T: Scalar,
    D: Design<T, N, NY, NU, NM>,
    F: Follower<T, NX, NY, NU, NT>,
{
    /// An observer holding no sample.
    #[must_use]
    pub const fn new() -> Self {
        Started {
            window: Window::new(),
            rule: StartedRule::START,
            latest: None,
            refusals: Refusals::NONE,
            design: PhantomData,
        }
    }

    /// Takes the sample of the current instant (see the type's docs).
    #[inline]
    pub fn push(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), RejectedSample> {
        let result = self.sample(y, u);
        self.refusals.count(result)
    }

    /// [`push`](Self::push) but for the count of refusals: the shared rule over this design's map
    /// and follower.
    #[inline(always)]
    fn sample(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), Refused> {
        if !D::accepts(&y, &u) {
            self.lost(&u);
            return Err(Refused::Value);
        }
        let mut all = None;
        if self.rule.reads_map(F::START_UP, F::STEADY_READS_MAP) {
            self.window.push(Sample { y, u });
            let Some(window) = self.window.samples() else {
                return Ok(()); // fewer than N samples: no estimate yet
            };
            all = Some(D::estimate(window));
        }
        let given = self.rule.accepted(
            F::START_UP,
            all,
            |all| F::start(&states_of::<T, F, NX, NY, NU, NM, NT>(all), &u),
            |carried, j, start_up, all| {
                let map = all.map_or([T::ZERO; NX], states_of::<T, F, NX, NY, NU, NM, NT>);
                F::follow(carried, j, start_up, &map, &y, &u)
            },
        );
        let given = match given {
            Ok(given) => given,
            Err(refused) => {
                // Restarted: the map's next estimate starts the follower again, from a window it
                // fills afresh (in steady state it may not have been fed).
                self.window = Window::new();
                return Err(refused);
            }
        };
        match given {
            Given::Nothing => {}
            Given::Map(all) => self.latest = Some(map_targets(&all)),
            Given::Followed(states) => self.latest = Some(targets_of::<T, F, NX, NY, NU, NT>(&states, &u)),
        }
        Ok(())
    }

    /// Over a refused sample: the output is lost, not the time, so once started what is carried
    /// takes the model's period when the input is known. Out of line and cold, so that the accepted
    /// samples' code is laid out as without it.
    #[cold]
    #[inline(never)]
    fn lost(&mut self, u: &[T; NU]) {
        self.rule
            .lost(u.iter().all(|v| v.is_finite()), |carried| F::predict(carried, u));
    }

    /// Samples refused since the start (see [`crate::rules::Refusals`]).
    #[must_use]
    pub fn refused(&self) -> u32 {
        self.refusals.get()
    }

    /// Restarts of the follower since the start: samples with finite values whose start or
    /// follow-up was not finite; each waits for the map's next estimate (see
    /// [`crate::rules::StartedRule::accepted`]).
    #[must_use]
    pub fn restarts(&self) -> u32 {
        self.refusals.restarts()
    }

    /// The latest estimate, one per target, or `None` before `N` samples have arrived.
    #[inline]
    #[must_use]
    pub fn estimate(&self) -> Option<[Estimate<T>; NT]> {
        self.latest
    }

    /// Forgets every sample (a new batch or run starts).
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
    Default for Started<T, D, F, N, NX, NY, NU, NM, NT>
where
    T: Scalar,
    D: Design<T, N, NY, NU, NM>,
    F: Follower<T, NX, NY, NU, NT>,
{
    fn default() -> Self {
        Self::new()
    }
}

impl<T, D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize> Clone
    for Started<T, D, F, N, NX, NY, NU, NM, NT>
where
    T: Scalar,
    F: Follower<T, NX, NY, NU, NT>,
{
    fn clone(&self) -> Self {
        Started {
            window: self.window.clone(),
            rule: self.rule,
            latest: self.latest,
            refusals: self.refusals,
            design: PhantomData,
        }
    }
}

impl<T, D, F, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NM: usize, const NT: usize>
    core::fmt::Debug for Started<T, D, F, N, NX, NY, NU, NM, NT>
where
    T: Scalar,
    F: Follower<T, NX, NY, NU, NT>,
{
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Started")
            .field("design", &core::any::type_name::<D>())
            .field("follower", &core::any::type_name::<F>())
            .field("estimates", &self.rule.count)
            .field("refused", &self.refusals)
            .field("latest", &self.latest)
            .finish()
    }
}

#[cfg(test)]
mod tests;
