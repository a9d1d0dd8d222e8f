//! The design's unscented Kalman filter (`Ukf`, `ukf()`, kind `ukf_box` as `UkfBoxObserver`), written
//! beside the EKF ([`crate::emit::model::model_source`]): the same frame as the EKF's (`push`, the refusals, `P`
//! as its upper triangle, `emit::model::plant`'s `COVARIANCE` and `finite`), each sample the straight-line
//! programs of [`crate::observers::kind::ukf_box::program`].

use askama::Template;

use crate::emit::model::filter::{
    constants_docs, filter_observer, filter_type, own_targets, q_constant, samples, Names,
};
use crate::emit::model::observers::Observers;
use crate::emit::EmitError;
use crate::observers::kind::ukf_box::program::{kappa, unscented_code, ALPHA, BETA};
use crate::plant::kalman::EkfConstants;
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design file, when the design has it (beside the EKF, whose frame it shares).
pub(crate) fn rust(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<String>, EmitError> {
    match (observers.ekf(), observers.constants.ukf_box()) {
        (Some(_), Some(constants)) => ukf(design, code, constants).map(Some),
        _ => Ok(None),
    }
}

/// The UKF, its observer and its two written-out samples.
fn ukf(design: &Design, code: &ModelCode, ukf: &EkfConstants) -> Result<String, EmitError> {
    let nx = code.dimensions.states;
    let fixed = super::FIXED.of(design);
    let mut text = UkfText {
        filter: &filter_type(&UKF, ukf, nx, code.dimensions.outputs)?,
        alpha: &format!("{ALPHA:?}"),
        beta: &format!("{BETA:?}"),
        kappa: &format!("{:?}", kappa(nx)),
        q_constant: &q_constant("UKF", "ukf", &ukf.q, fixed, UKF_Q_TUNED),
        constants: &constants_docs("ukf", fixed, UKF_TUNED),
        watch_docs: &crate::emit::model::filter::watch_docs(ukf),
        log: !code.log_coordinates.is_plant(),
    }
    .render()?;
    let filter = unscented_code(code, ukf);
    let (targets_function, targets) = own_targets(&UKF, &filter, code, design)?;
    text.push_str(&filter_observer(&UKF, ukf, fixed, code.dimensions.outputs, &targets)?);
    text.push_str(&samples(&UKF, &filter, code, design)?);
    text.push_str(&targets_function);
    Ok(text)
}

/// The UKF's names in the filters' frame.
const UKF: Names = Names {
    name: "Ukf",
    lower: "ukf",
    observer: "UkfBoxObserver",
    what: "The UKF",
    sample: "One UKF sample",
};

/// `UKF_Q`'s docs when `gen` tuned it.
const UKF_Q_TUNED: &str =
    "/// The UKF's `Q` diagonal as `gen` chose it (f64), tuned on its own: each state's process-noise
/// variance per sample period, in its unit squared ([`STATE_UNITS`]).";

/// The UKF's docs on its constants when `gen` tuned them all.
const UKF_TUNED: &str = "It starts at the centre of the state box with `P(0)` and `Q` diagonal as chosen by
/// `gen` on the tuning runs (its own, by the EKF's search), `R` the outputs' noise variances.";

/// The UKF's constants and its filter type (`filter`), with `ukf()`.
#[derive(Template)]
#[template(path = "ukf_box/templates/ukf.rs.askama", escape = "none")]
struct UkfText<'a> {
    filter: &'a str,
    alpha: &'a str,
    beta: &'a str,
    kappa: &'a str,
    q_constant: &'a str,
    constants: &'a str,
    watch_docs: &'a str,
    /// Whether it carries states in log coordinates.
    log: bool,
}
