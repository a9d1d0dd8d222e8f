//! A Kalman filter that `gen` wrote out for a design (one of its Kalman filters, from the centre of the state
//! box or the start the spec fixes) with the interface every observer has: [`FilterObserver`].

use crate::rules::{Refusals, Refused};
use crate::{Estimate, RejectedSample, Saturation, Scalar};

/// A filter written out by `gen` (a generated design's `Ekf`, say): its state and covariance,
/// one sample as straight-line code, and the design's targets. Implemented by generated code only.
pub trait Filter<T, const NX: usize, const NY: usize, const NU: usize, const NT: usize>: Copy {
    /// The filter at its start: a constant, so that an observer can be a `static`'s initial value.
    const FRESH: Self;

    /// Takes the sample `(y, u)`: the estimate given it, `x̂(k|k)`, or the refusal of a sample that
    /// is not finite (the filter then predicts, or keeps, its state), or the restart of a filter
    /// whose result is not ([`crate::rules::filter_sample`]).
    fn push(&mut self, y: &[T; NY], u: &[T; NU]) -> Result<[T; NX], Refused>;

    /// The targets at state `x` and input `u`.
    fn targets(x: &[T; NX], u: &[T; NU]) -> [T; NT];
}

/// The filter `F` of a design with the observers' interface: `push` takes a sample, `estimate` gives
/// the targets of the latest accepted one (each `Inside`: the filter does not saturate), `reset`
/// starts again. It has an estimate from the first accepted sample on; a refused sample keeps the
/// previous one, and so does a sample on which the filter restarted ([`restarts`](Self::restarts)). `NT` targets from `NY` outputs and `NU` inputs, `NX` states.
///
/// Generated designs name it per filter, after the filter's kind (`generated::for_each_observer!`
/// lists each design's kinds and types).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterObserver<T, F, const NX: usize, const NY: usize, const NU: usize, const NT: usize> {
    filter: F,
    latest: Option<[Estimate<T>; NT]>,
    refusals: Refusals,
}

impl<T, F, const NX: usize, const NY: usize, const NU: usize, const NT: usize> FilterObserver<T, F, NX, NY, NU, NT>
where
    T: Scalar,
    F: Filter<T, NX, NY, NU, NT>,
{
    /// A fresh observer (the filter at its start), holding no sample yet.
    #[must_use]
    pub const fn new() -> Self {
        FilterObserver {
            filter: F::FRESH,
            latest: None,
            refusals: Refusals::NONE,
        }
    }

    /// Takes the sample `(y, u)`: the filter's sample, then the targets of its estimate `x̂(k|k)`.
    pub fn push(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), RejectedSample> {
        let result = self.filter.push(&y, &u);
        let x = self.refusals.count(result)?;
        let values = F::targets(&x, &u);
        let mut latest = [Estimate {
            value: T::ZERO,
            saturation: Saturation::Inside,
        }; NT];
        for (e, value) in latest.iter_mut().zip(values) {
            e.value = value;
        }
        self.latest = Some(latest);
        Ok(())
    }

    /// The targets of the latest accepted sample; `None` before the first.
    #[must_use]
    pub fn estimate(&self) -> Option<[Estimate<T>; NT]> {
        self.latest
    }

    /// Back to the start: the filter at its start, no estimate.
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// Whether it has an estimate.
    #[must_use]
    pub fn is_ready(&self) -> bool {
        self.latest.is_some()
    }

    /// Samples refused for a bad value since the start (see [`crate::rules::Refusals`]).
    #[must_use]
    pub fn refused(&self) -> u32 {
        self.refusals.get()
    }

    /// Restarts of the filter since the start: samples with finite values whose step was not finite
    /// (see [`crate::rules::Refusals`]).
    #[must_use]
    pub fn restarts(&self) -> u32 {
        self.refusals.restarts()
    }

    /// The filter as it is now (its state and covariance).
    #[must_use]
    pub fn filter(&self) -> &F {
        &self.filter
    }
}

impl<T, F, const NX: usize, const NY: usize, const NU: usize, const NT: usize> Default
    for FilterObserver<T, F, NX, NY, NU, NT>
where
    T: Scalar,
    F: Filter<T, NX, NY, NU, NT>,
{
    fn default() -> Self {
        Self::new()
    }
}
