//! The box-started EKF checked by the map (`EkfRestartObserver`, kind `ekf_restart`): the check's
//! constants and `firmware::Restart` for the map-started EKF.

use askama::Template;

use crate::emit::model::observers::Observers;
use crate::emit::model::rust_text::{f32_list, list, literal};
use crate::emit::EmitError;
use crate::observers::kind::ekf_restart::run::RestartConstants;
use crate::plant::kalman::{self, EkfConstants};
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design file, when the design has it (and the EKFs it runs on).
pub(crate) fn rust(_: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<String>, EmitError> {
    match (observers.ekf(), observers.started(), observers.restart()) {
        (Some(ekf), Some(_), Some(restart)) => restarted(ekf, restart, code.dimensions.outputs).map(Some),
        _ => Ok(None),
    }
}

/// The box-started EKF checked by the map: `StartedEkf`'s `firmware::Restart` in `f32` and `f64`,
/// the check, and `EkfRestartObserver` (`outputs`: the filter's, the watch's start where it is
/// watched).
fn restarted(ekf: &EkfConstants, restart: &RestartConstants, outputs: usize) -> Result<String, EmitError> {
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
    Ok(RestartedText {
        threshold_f64: &format!("{:?}", restart.threshold),
        threshold: &literal("restart threshold", restart.threshold)?,
        variances_f64: &f64_list(&restart.variances),
        variances: &list(&variances),
        diagonal: &format!("{diagonal:?}"),
        x0_f32: &f32_list("EKF x0", &ekf.x0)?,
        p0_f32: &f32_list("EKF P0", &upper)?,
        x0_f64: &f64_list(&ekf.x0),
        p0_f64: &f64_list(&upper),
        // `StartedEkf`'s carried watched mean, at its start `m` (a literal of either type).
        chi: &match ekf.watch.constants(outputs) {
            Some(_) => format!(", {outputs}.0"),
            None => String::new(),
        },
    }
    .render()?)
}

/// The restarted EKF (`…_f64`: f64 values, the others `T` or f32 literals; `chi`: the fresh
/// watched mean after a comma, or nothing where the EKF is not watched).
#[derive(Template)]
#[template(path = "ekf_restart/templates/restarted.rs.askama", escape = "none")]
struct RestartedText<'a> {
    threshold_f64: &'a str,
    threshold: &'a str,
    variances_f64: &'a str,
    variances: &'a str,
    diagonal: &'a str,
    x0_f32: &'a str,
    p0_f32: &'a str,
    x0_f64: &'a str,
    p0_f64: &'a str,
    chi: &'a str,
}
