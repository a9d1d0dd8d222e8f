{# The box-started EKF checked by the map: the check's constants, `firmware::Restart` in f32 and f64. #}
/// The check of [`EkfRestartObserver`] as `gen` chose it on the tuning runs (f64): the threshold `τ`
/// (no unit).
pub const RESTART_THRESHOLD: f64 = {{ threshold_f64 }};
/// See [`RESTART_THRESHOLD`]: each state's `e_i²`, the map's mean squared error on the tuning runs,
/// in its unit squared ([`STATE_UNITS`]).
pub const RESTART_VARIANCES: [f64; STATES] = {{ variances_f64 }};

/// Whether the filter's prediction `x` with covariance `p` and the map's states `f` disagree:
/// `d = Σ_i (x_i − f_i)² / (P_ii + e_i²) > τ`, or `d` is NaN. Runs once, at the map's first estimate.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
#[inline(always)]
fn restart_disagrees<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], f: &[T; STATES]) -> bool {
    const DIAGONAL: [usize; STATES] = {{ diagonal }};
    let variances: [T; STATES] = {{ variances }};
    let mut d = T::ZERO;
    for i in 0..STATES {
        let e = x[i] - f[i];
        d += e * e / (p[DIAGONAL[i]] + variances[i]);
    }
    !(d <= {{ threshold }})
}

impl firmware::emitted::Restart<f32, STATES, OUTPUTS, INPUTS, TARGETS> for StartedEkf {
    const FRESH: ([f32; STATES], [f32; COVARIANCE]) = ({{ x0_f32 }}, {{ p0_f32 }});

    #[inline(always)]
    fn disagrees(carried: &([f32; STATES], [f32; COVARIANCE]), map: &[f32; STATES]) -> bool {
        restart_disagrees(&carried.0, &carried.1, map)
    }
}

impl firmware::emitted::Restart<f64, STATES, OUTPUTS, INPUTS, TARGETS> for StartedEkf {
    const FRESH: ([f64; STATES], [f64; COVARIANCE]) = ({{ x0_f64 }}, {{ p0_f64 }});

    #[inline(always)]
    fn disagrees(carried: &([f64; STATES], [f64; COVARIANCE]), map: &[f64; STATES]) -> bool {
        restart_disagrees(&carried.0, &carried.1, map)
    }
}

/// The EKF from the centre of the state box ([`Ekf`]'s start and samples) that checks the map once,
/// at its first estimate, and restarts from it as [`EkfMapObserver`] starts when the two disagree
/// (`d > τ`, [`RESTART_THRESHOLD`]): an estimate from the first sample, the map's guess-free start where the
/// box centre is far from the plant.
pub type EkfRestartObserver = firmware::Restarted<f32, Design, StartedEkf, HORIZON, STATES, OUTPUTS, INPUTS, TARGETS>;

