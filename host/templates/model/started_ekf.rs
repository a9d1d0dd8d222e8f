{# The EKF started by the map (`StartedEkf`, `EkfMapObserver`): `p0`, its `P(N-1)` in `T` literals. #}
/// `P(N−1)` diagonal of [`StartedEkf`] (f64), as `gen` chose it, in each state's unit squared
/// ([`STATE_UNITS`]).
pub const STARTED_P0: [f64; STATES] = {{ p0_f64 }};

/// The EKF started at the map's first estimate `x̂(N−1) = F(Z)` with `P(N−1)` diagonal, each variance
/// the map's mean squared error on the tuning runs, then [`Ekf`]'s samples (same `Q` and `R`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StartedEkf;

impl<T: Scalar + Maths> firmware::emitted::Follower<T, STATES, OUTPUTS, INPUTS, TARGETS> for StartedEkf {
    type Carried = ([T; STATES], [T; COVARIANCE]);
    const START_UP: usize = 0;
    const STEADY_READS_MAP: bool = false;
    const STATE_TARGETS: [usize; STATES] = {{ state_targets }};

    #[inline(always)]
    fn start(first: &[T; STATES], u: &[T; INPUTS]) -> Option<([T; STATES], [T; COVARIANCE])> {
        let (x, p) = ekf_unmeasured(first, &{{ p0 }}, u);
        finite(&x, &p).then_some((x, p))
    }

    #[inline(always)]
    fn follow(
        carried: &([T; STATES], [T; COVARIANCE]),
        _: usize,
        _: bool,
        _: &[T; STATES],
        y: &[T; OUTPUTS],
        u: &[T; INPUTS],
    ) -> Option<(([T; STATES], [T; COVARIANCE]), [Estimate<T>; STATES])> {
        let (estimate, x, p) = ekf_measured(&carried.0, &carried.1, y, u);
        let mut inside = [Estimate { value: T::ZERO, saturation: firmware::Saturation::Inside }; STATES];
        for (e, &value) in inside.iter_mut().zip(&estimate) {
            e.value = value;
        }
        finite(&x, &p).then_some(((x, p), inside))
    }

    /// A lost output: the filter's prediction alone, as [`Ekf::push`] runs it.
    #[inline(always)]
    fn predict(carried: &([T; STATES], [T; COVARIANCE]), u: &[T; INPUTS]) -> Option<([T; STATES], [T; COVARIANCE])> {
        let (x, p) = ekf_unmeasured(&carried.0, &carried.1, u);
        finite(&x, &p).then_some((x, p))
    }

    #[inline(always)]
    fn targets(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {
        targets(x, u)
    }
}

/// The EKF started by this design's map.
pub type EkfMapObserver = firmware::Started<f32, Design, StartedEkf, HORIZON, STATES, OUTPUTS, INPUTS, TARGETS>;

