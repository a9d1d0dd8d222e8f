//! The design's unscented Kalman filter (`Ukf`, `ukf()`, kind `ukf_box` as `UkfObserver`), written
//! beside the EKF by [`super::model_source`]: the same frame as the EKF's (`push`, the refusals, `P`
//! as its upper triangle, [`super::plant`]'s `COVARIANCE` and `finite`), each sample the straight-line
//! programs of [`crate::plant::unscented`].

use super::filter::{constants_docs, filter_observer, filter_type, q_constant, samples, Names};
use crate::emit::EmitError;
use crate::plant::kalman::EkfConstants;
use crate::plant::unscented::{kappa, unscented_code, ALPHA, BETA};
use crate::plant::ModelCode;
use crate::spec::Design;

/// The UKF, its observer and its two written-out samples.
pub(super) fn ukf(design: &Design, code: &ModelCode, ukf: &EkfConstants) -> Result<String, EmitError> {
    let nx = code.dimensions.states;
    let fixed = &design.filters.ukf;
    let mut text = UKF_TEMPLATE
        .replace("{FILTER}", &filter_type(&UKF, ukf, nx)?)
        .replace("{ALPHA}", &format!("{ALPHA:?}"))
        .replace("{BETA}", &format!("{BETA:?}"))
        .replace("{KAPPA}", &format!("{:?}", kappa(nx)))
        .replace("{Q_CONSTANT}", &q_constant("UKF", "ukf", &ukf.q, fixed, UKF_Q_TUNED))
        .replace("{CONSTANTS}", &constants_docs("ukf", fixed, UKF_TUNED));
    text.push_str(&filter_observer(&UKF, ukf, fixed)?);
    text.push_str(&samples(&UKF, &unscented_code(code, ukf), code, design)?);
    Ok(text)
}

/// The UKF's names in the filters' frame.
const UKF: Names = Names {
    name: "Ukf",
    lower: "ukf",
    observer: "UkfObserver",
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

const UKF_TEMPLATE: &str = r#"
{Q_CONSTANT}

/// This design's unscented Kalman filter, written out for its size by `gen`: the scaled unscented
/// transform (Wan & van der Merwe; α = {ALPHA}, β = {BETA}, κ = {KAPPA}: the cubature rule, `2n`
/// sigma points `x ± √n Lᵢ` of equal weight) from the Cholesky factor of `P` (each pivot floored: `P`
/// stays positive definite), every one through [`Discrete`], projected onto the model's bounds; each measured sample one joint update of every
/// output (`K = C S⁻¹` through the Cholesky factor of `S`, no inverse), `P` kept as its upper
/// triangle. {CONSTANTS}
///
/// A sample with a non-finite `y` is refused and only predicted; one with a non-finite `u` changes
/// nothing; a sample whose result is not finite is not taken.
{FILTER}/// A fresh UKF in `f32`, as the chip runs it.
pub fn ukf() -> Ukf {
    Ukf::new()
}
"#;
