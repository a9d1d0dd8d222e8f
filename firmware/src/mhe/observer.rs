//! The moving-horizon estimate as an observer kind: the last `N` samples, the previous solution, and
//! at every sample `solve_window` from that solution moved one sample on, with the interface every
//! observer has (`push`, `estimate`, `reset`). A design provides the model, the constants and its
//! targets through `Horizon`, so that `new` is `const` and the constants are folded into the code.

use core::marker::PhantomData;

use super::solver::{solve_window, Settings};
use crate::bounds::project;
use crate::watch::Watch;
use crate::window::{Sample, Window};
use crate::{Estimate, Plant, RejectedSample, Saturation, Scalar};

/// What a design gives its moving-horizon observer.
pub trait Horizon<T: Scalar, const NX: usize, const NY: usize, const NU: usize, const NT: usize> {
    /// The model the windows are solved with (the design's RK4 step and its Jacobian).
    type Plant: Plant<T, NX, NY, NU>;
    /// That model.
    fn plant() -> Self::Plant;
    /// The constants `gen` chose: weights, prior, box, first start, iterations, damping.
    fn settings() -> Settings<T, NX, NY>;
    /// The targets at state `x` and input `u`.
    fn targets(x: &[T; NX], u: &[T; NU]) -> [T; NT];
}

/// The moving-horizon observer of design `H`: `NT` targets from `NY` outputs and `NU` inputs, `NX`
/// states, windows of `N` samples (see the [module's](super) documentation for the maths).
///
/// Every accepted sample runs `solve_window`: `settings().iterations` Gauss–Newton steps from the
/// previous solution moved one sample on (the prior's centre too), then the solution carried to the
/// newest sample. Memory is fixed (the window, the previous solution, the latest estimate); once the
/// window is full every sample runs the same instructions. A sample with a non-finite measurement or
/// input is refused and not stored, before the window is full as after (the firmware contract: nothing
/// stored changes); a solution the model carries to a non-finite value is not kept, and the next window is
/// solved from the start (a restart) instead of from it. With a watch (`settings().watch`), the
/// windows' output costs are watched as a filter's normalised innovations are ([`crate::watch`]:
/// their mean is `N m` when the model and the noise are right): a run of implausible windows, a
/// solution stuck where the samples say otherwise, restarts the observer the same way. A refused
/// sample, or a restart, leaves the latest estimate as it was. The estimate is a state inside the box, so its targets
/// carry no saturation flag (each is `Inside`).
pub struct Observer<T, H, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize> {
    window: Window<T, N, NY, NU>,
    /// The latest window's solution (its start), once there is one.
    solved: Option<[T; NX]>,
    latest: Option<[Estimate<T>; NT]>,
    /// The watched mean of the windows' costs since the last (re)start, once a window was solved.
    chi: Option<T>,
    /// Restarts since the start (saturating).
    restarts: u32,
    design: PhantomData<fn() -> H>,
}

impl<T, H, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize>
    Observer<T, H, N, NX, NY, NU, NT>
where
    T: Scalar,
    H: Horizon<T, NX, NY, NU, NT>,
{
    /// An observer holding no sample.
    #[must_use]
    pub const fn new() -> Self {
        Observer {
            window: Window::new(),
            solved: None,
            latest: None,
            chi: None,
            restarts: 0,
            design: PhantomData,
        }
    }

    /// Takes the sample of the current instant (see the type's documentation).
    #[inline]
    pub fn push(&mut self, y: [T; NY], u: [T; NU]) -> Result<(), RejectedSample> {
        if !y.iter().chain(&u).all(|v| v.is_finite()) {
            return Err(RejectedSample);
        }
        let (plant, s) = (H::plant(), H::settings());
        // The previous solution moved one sample on, under the input of the window's oldest sample
        // (which this push drops): the warm start, and the prior's centre.
        let moved = match (self.solved, self.window.samples()) {
            (Some(x), Some(window)) => Some(project(&plant.step(&x, &window[0].u).0, &s.lower, &s.upper)),
            _ => None,
        };
        self.window.push(Sample { y, u });
        let Some(samples) = self.window.samples() else {
            return Ok(()); // fewer than N samples: no estimate yet
        };
        let solved = solve_window(&plant, &s, samples, &moved.unwrap_or(s.start), moved.is_some());
        let (x, end) = (solved.start, solved.end);
        let values = H::targets(&end, &u);
        let (chi, watch_passes) = Watch::after(s.watch, self.chi, solved.cost);
        if !(x.iter().chain(&end).chain(&values).all(|v| v.is_finite()) && watch_passes) {
            // Restarted: the next window is solved from the start, not from this solution.
            self.solved = None;
            self.chi = None;
            self.restarts = self.restarts.saturating_add(1);
            return Err(RejectedSample);
        }
        self.solved = Some(x);
        self.chi = chi;
        let mut latest = [Estimate {
            value: T::ZERO,
            saturation: Saturation::Inside,
        }; NT];
        for (estimate, value) in latest.iter_mut().zip(values) {
            estimate.value = value;
        }
        self.latest = Some(latest);
        Ok(())
    }

    /// The latest estimate, one per target, or `None` before the first.
    #[inline]
    #[must_use]
    pub fn estimate(&self) -> Option<[Estimate<T>; NT]> {
        self.latest
    }

    /// The state at the latest window's start, once a window was solved.
    #[must_use]
    pub fn solution(&self) -> Option<[T; NX]> {
        self.solved
    }

    /// Forgets every sample and solution (a new batch or run starts).
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// `true` once an estimate is available.
    #[must_use]
    pub fn is_ready(&self) -> bool {
        self.latest.is_some()
    }

    /// Restarts since the start: samples with finite values whose solution was not finite, or whose
    /// watch found the windows implausible, after which the next window is solved from the start.
    #[must_use]
    pub fn restarts(&self) -> u32 {
        self.restarts
    }
}

impl<T, H, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize> Default
    for Observer<T, H, N, NX, NY, NU, NT>
where
    T: Scalar,
    H: Horizon<T, NX, NY, NU, NT>,
{
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Scalar, H, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize> Clone
    for Observer<T, H, N, NX, NY, NU, NT>
{
    fn clone(&self) -> Self {
        Observer {
            window: self.window.clone(),
            solved: self.solved,
            latest: self.latest,
            chi: self.chi,
            restarts: self.restarts,
            design: PhantomData,
        }
    }
}

impl<T: Scalar, H, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize> core::fmt::Debug
    for Observer<T, H, N, NX, NY, NU, NT>
{
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("mhe::Observer")
            .field("solved", &self.solved)
            .field("latest", &self.latest)
            .finish_non_exhaustive()
    }
}
