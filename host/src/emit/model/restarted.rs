//! The box-started EKF checked by the map (`RestartedEkfObserver`, kind `ekf_restart`): the check's
//! constants and `firmware::Restart` for the map-started EKF.

use super::rust_text::{f32_list, list, literal};
use crate::emit::EmitError;
use crate::observers::restart::RestartConstants;
use crate::plant::kalman::{self, EkfConstants};

/// The box-started EKF checked by the map: `StartedEkf`'s `firmware::Restart` in `f32` and `f64`,
/// the check, and `RestartedEkfObserver`.
pub(super) fn restarted(ekf: &EkfConstants, restart: &RestartConstants) -> Result<String, EmitError> {
    let nx = ekf.x0.len();
    let upper = ekf.p0.upper();
    let f64_list = |values: &[f64]| format!("{values:?}");
    let variances = restart
        .variances
        .iter()
        .enumerate()
        .map(|(i, v)| literal(&format!("restart variance {i}"), *v))
        .collect::<Result<Vec<_>, _>>()?;
    let diagonal: Vec<usize> = (0..nx).map(|i| kalman::upper(nx, i, i)).collect();
    Ok(RESTARTED_TEMPLATE
        .replace("{THRESHOLD_F64}", &format!("{:?}", restart.threshold))
        .replace("{THRESHOLD}", &literal("restart threshold", restart.threshold)?)
        .replace("{VARIANCES_F64}", &f64_list(&restart.variances))
        .replace("{VARIANCES}", &list(&variances))
        .replace("{DIAGONAL}", &format!("{diagonal:?}"))
        .replace("{X0_F32}", &f32_list("EKF x0", &ekf.x0)?)
        .replace("{P0_F32}", &f32_list("EKF P0", &upper)?)
        .replace("{X0_F64}", &f64_list(&ekf.x0))
        .replace("{P0_F64}", &f64_list(&upper)))
}

/// The restarted EKF (`{…}` filled in by [`restarted`]).
const RESTARTED_TEMPLATE: &str = r#"
/// The check of [`RestartedEkfObserver`] as `gen` chose it on the tuning runs (f64): the threshold `τ`
/// (no unit).
pub const RESTART_THRESHOLD: f64 = {THRESHOLD_F64};
/// See [`RESTART_THRESHOLD`]: each state's `e_i²`, the map's mean squared error on the tuning runs,
/// in its unit squared ([`STATE_UNITS`]).
pub const RESTART_VARIANCES: [f64; STATES] = {VARIANCES_F64};

/// Whether the filter's prediction `x` with covariance `p` and the map's states `f` disagree:
/// `d = Σ_i (x_i − f_i)² / (P_ii + e_i²) > τ`, or `d` is NaN. Runs once, at the map's first estimate.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
#[inline(always)]
fn restart_disagrees<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], f: &[T; STATES]) -> bool {
    const DIAGONAL: [usize; STATES] = {DIAGONAL};
    let variances: [T; STATES] = {VARIANCES};
    let mut d = T::ZERO;
    for i in 0..STATES {
        let e = x[i] - f[i];
        d += e * e / (p[DIAGONAL[i]] + variances[i]);
    }
    !(d <= {THRESHOLD})
}

impl firmware::emitted::Restart<f32, STATES, OUTPUTS, INPUTS, TARGETS> for StartedEkf {
    const FRESH: ([f32; STATES], [f32; COVARIANCE]) = ({X0_F32}, {P0_F32});

    #[inline(always)]
    fn disagrees(carried: &([f32; STATES], [f32; COVARIANCE]), map: &[f32; STATES]) -> bool {
        restart_disagrees(&carried.0, &carried.1, map)
    }
}

impl firmware::emitted::Restart<f64, STATES, OUTPUTS, INPUTS, TARGETS> for StartedEkf {
    const FRESH: ([f64; STATES], [f64; COVARIANCE]) = ({X0_F64}, {P0_F64});

    #[inline(always)]
    fn disagrees(carried: &([f64; STATES], [f64; COVARIANCE]), map: &[f64; STATES]) -> bool {
        restart_disagrees(&carried.0, &carried.1, map)
    }
}

/// The EKF from the centre of the state box ([`Ekf`]'s start and samples) that checks the map once,
/// at its first estimate, and restarts from it as [`StartedEkfObserver`] starts when the two disagree
/// (`d > τ`, [`RESTART_THRESHOLD`]): an estimate from the first sample, the map's guess-free start where the
/// box centre is far from the plant.
pub type RestartedEkfObserver = firmware::Restarted<f32, Design, StartedEkf, HORIZON, STATES, OUTPUTS, INPUTS, TARGETS>;
"#;
