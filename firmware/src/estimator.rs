//! [`Estimator`]: the interface every observer has, whatever its kind, so that firmware is written
//! once against it and the kind is chosen by a type.

use crate::emitted::{fixed::FixedDesign, mhe::Horizon, Filter, Follower, Restart};
use crate::fixed::{self, OutOfRange};
use crate::{Design, Estimate, FamilyObserver, FilterObserver, Observer, RejectedSample, Restarted, Scalar, Started};

/// What every observer a design carries offers, whatever its kind: the map ([`crate::Observer`]),
/// the observers the map starts ([`crate::Started`]: the model-corrected map, the map-started EKF),
/// the box-started EKF checked by the map ([`crate::Restarted`]), the Kalman filters from the box
/// centre ([`crate::FilterObserver`]), the moving-horizon estimate
/// ([`crate::mhe::Observer`]), the map in integers ([`crate::fixed::Observer`]) and the family of
/// maps ([`crate::FamilyObserver`]).
///
/// Every sample, [`push`](Estimator::push) the outputs and inputs of the current instant, then read
/// [`estimate`](Estimator::estimate). A refused sample (NaN or infinite; for the integer map, outside
/// its declared range) is an error and leaves the latest estimate as it was. Each observer's own
/// methods of the same names are what the trait calls (inlined): written against the trait, a
/// firmware runs the same instructions as written against the type.
///
/// ```
/// use firmware::{Estimate, Estimator};
///
/// /// One sample period of any observer of a design with one output and no input.
/// fn every_sample<O>(observer: &mut O, y: f32) -> Option<f32>
/// where
///     O: Estimator<Scalar = f32, Outputs = [f32; 1], Inputs = [f32; 0]>,
/// {
///     observer.push([y], []).ok()?; // a refused sample gives no new estimate
///     let estimates = observer.estimate()?; // `None` until the observer has one
///     estimates.as_ref().first().map(|e: &Estimate<f32>| e.value)
/// }
/// ```
pub trait Estimator {
    /// What a value is: `f32` for the float observers, `i32` (raw counts in, LSBs out) for the map
    /// in integers.
    type Scalar: Copy;
    /// One instant's outputs `y(k)`, `[Scalar; NY]`.
    type Outputs: Copy;
    /// One instant's inputs `u(k)`, `[Scalar; NU]`.
    type Inputs: Copy;
    /// One estimate per target, `[Estimate<Scalar>; NT]`.
    type Estimates: Copy + AsRef<[Estimate<Self::Scalar>]>;
    /// Why a sample was refused: [`crate::RejectedSample`], or [`crate::fixed::OutOfRange`] for the
    /// map in integers.
    type Error: Copy + Eq + core::error::Error;

    /// Takes the sample of the current instant; a refused one changes no estimate.
    fn push(&mut self, y: Self::Outputs, u: Self::Inputs) -> Result<(), Self::Error>;

    /// The latest estimate, one per target, or `None` while the observer has none.
    fn estimate(&self) -> Option<Self::Estimates>;

    /// Back to the observer as it was made: every sample forgotten (a new batch or run starts).
    fn reset(&mut self);

    /// `true` once [`estimate`](Estimator::estimate) gives an estimate.
    fn is_ready(&self) -> bool;

    /// How many times the observer restarted since it was made or reset: a sample with finite values
    /// whose step was not finite restarts a filter (from its start, or from the map), and `push`
    /// reports that sample as refused. Always 0 for the maps, which carry nothing from one sample to
    /// the next. Read it after a refused `push` to tell a restart from a bad value.
    fn restarts(&self) -> u32 {
        0
    }
}

// Each observer by its own methods (which take precedence over the trait's in method resolution).

/// The trait's four methods, each the observer type `$ty`'s own method of the same name.
macro_rules! by_own_methods {
    ($ty:ty) => {
        #[inline(always)]
        fn push(&mut self, y: Self::Outputs, u: Self::Inputs) -> Result<(), Self::Error> {
            <$ty>::push(self, y, u)
        }

        #[inline(always)]
        fn estimate(&self) -> Option<Self::Estimates> {
            <$ty>::estimate(self)
        }

        #[inline(always)]
        fn reset(&mut self) {
            <$ty>::reset(self)
        }

        #[inline(always)]
        fn is_ready(&self) -> bool {
            <$ty>::is_ready(self)
        }
    };
}

impl<T: Scalar, D, const N: usize, const NY: usize, const NU: usize, const NT: usize> Estimator
    for Observer<T, D, N, NY, NU, NT>
where
    D: Design<T, N, NY, NU, NT>,
{
    type Scalar = T;
    type Outputs = [T; NY];
    type Inputs = [T; NU];
    type Estimates = [Estimate<T>; NT];
    type Error = RejectedSample;

    by_own_methods!(Observer<T, D, N, NY, NU, NT>);
}

impl<
        T: Scalar,
        D,
        F,
        const N: usize,
        const NX: usize,
        const NY: usize,
        const NU: usize,
        const NM: usize,
        const NT: usize,
    > Estimator for Started<T, D, F, N, NX, NY, NU, NM, NT>
where
    D: Design<T, N, NY, NU, NM>,
    F: Follower<T, NX, NY, NU, NT>,
{
    type Scalar = T;
    type Outputs = [T; NY];
    type Inputs = [T; NU];
    type Estimates = [Estimate<T>; NT];
    type Error = RejectedSample;

    by_own_methods!(Started<T, D, F, N, NX, NY, NU, NM, NT>);

    #[inline(always)]
    fn restarts(&self) -> u32 {
        <Started<T, D, F, N, NX, NY, NU, NM, NT>>::restarts(self)
    }
}

impl<
        T: Scalar,
        D,
        F,
        const N: usize,
        const NX: usize,
        const NY: usize,
        const NU: usize,
        const NM: usize,
        const NT: usize,
    > Estimator for Restarted<T, D, F, N, NX, NY, NU, NM, NT>
where
    D: Design<T, N, NY, NU, NM>,
    F: Restart<T, NX, NY, NU, NT>,
{
    type Scalar = T;
    type Outputs = [T; NY];
    type Inputs = [T; NU];
    type Estimates = [Estimate<T>; NT];
    type Error = RejectedSample;

    by_own_methods!(Restarted<T, D, F, N, NX, NY, NU, NM, NT>);

    #[inline(always)]
    fn restarts(&self) -> u32 {
        <Restarted<T, D, F, N, NX, NY, NU, NM, NT>>::restarts(self)
    }
}

impl<T: Scalar, F, const NX: usize, const NY: usize, const NU: usize, const NT: usize> Estimator
    for FilterObserver<T, F, NX, NY, NU, NT>
where
    F: Filter<T, NX, NY, NU, NT>,
{
    type Scalar = T;
    type Outputs = [T; NY];
    type Inputs = [T; NU];
    type Estimates = [Estimate<T>; NT];
    type Error = RejectedSample;

    by_own_methods!(FilterObserver<T, F, NX, NY, NU, NT>);

    #[inline(always)]
    fn restarts(&self) -> u32 {
        <FilterObserver<T, F, NX, NY, NU, NT>>::restarts(self)
    }
}

impl<T: Scalar, H, const N: usize, const NX: usize, const NY: usize, const NU: usize, const NT: usize> Estimator
    for crate::mhe::Observer<T, H, N, NX, NY, NU, NT>
where
    H: Horizon<T, NX, NY, NU, NT>,
{
    type Scalar = T;
    type Outputs = [T; NY];
    type Inputs = [T; NU];
    type Estimates = [Estimate<T>; NT];
    type Error = RejectedSample;

    by_own_methods!(crate::mhe::Observer<T, H, N, NX, NY, NU, NT>);

    #[inline(always)]
    fn restarts(&self) -> u32 {
        <crate::mhe::Observer<T, H, N, NX, NY, NU, NT>>::restarts(self)
    }
}

impl<D, const N: usize, const NY: usize, const NU: usize, const NT: usize> Estimator
    for fixed::Observer<D, N, NY, NU, NT>
where
    D: FixedDesign<N, NY, NU, NT>,
{
    type Scalar = i32;
    type Outputs = [i32; NY];
    type Inputs = [i32; NU];
    type Estimates = [Estimate<i32>; NT];
    type Error = OutOfRange;

    by_own_methods!(fixed::Observer<D, N, NY, NU, NT>);
}

impl<'a, T, const N: usize, const NY: usize, const NU: usize, const NT: usize, const K: usize> Estimator
    for FamilyObserver<'a, T, N, NY, NU, NT, K>
where
    T: Scalar,
{
    type Scalar = T;
    type Outputs = [T; NY];
    type Inputs = [T; NU];
    type Estimates = [Estimate<T>; NT];
    type Error = RejectedSample;

    by_own_methods!(FamilyObserver<'a, T, N, NY, NU, NT, K>);
}
