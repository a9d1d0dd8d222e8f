//! The EKF started by the map (`StartedEkf`, `EkfMapObserver`, kind `ekf_map`): its Rust, filled
//! in by [`super::model_source`].

use askama::Template;

use crate::emit::EmitError;

/// The EKF started by the map: `p0` its `P(N−1)` diagonal's upper triangle (`T` literals), `p0_f64`
/// the diagonal, `state_targets` each state's target.
pub(super) fn started_ekf(p0: &str, p0_f64: &str, state_targets: &str) -> Result<String, EmitError> {
    Ok(StartedEkfText {
        p0,
        p0_f64,
        state_targets,
    }
    .render()?)
}

/// The EKF started by the map.
#[derive(Template)]
#[template(path = "model/started_ekf.rs", escape = "none")]
struct StartedEkfText<'a> {
    p0: &'a str,
    p0_f64: &'a str,
    state_targets: &'a str,
}
