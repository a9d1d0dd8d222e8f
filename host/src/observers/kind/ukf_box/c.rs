//! The UKF from the box centre in C (`<name>_ukf_box`, the Rust file's `UkfBoxObserver`): the box
//! filters' C (`emit::c::box_filter`) with the UKF's samples, written beside the EKF as in
//! the Rust file.

use super::program::unscented_code;
use crate::emit::c::box_filter::{box_part, Filter};
use crate::emit::c::text::CPart;
use crate::emit::model::observers::Observers;
use crate::emit::EmitError;
use crate::plant::ModelCode;
use crate::spec::Design;

/// The UKF's names in C.
const UKF: Filter = Filter {
    lower: "ukf",
    label: "UKF",
    kind: "ukf_box",
};

/// Its part of the design's C, when the design has it.
pub(crate) fn c(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<CPart>, EmitError> {
    let (Some(_), Some(ukf)) = (observers.ekf(), observers.constants.ukf_box()) else {
        return Ok(None);
    };
    box_part(
        &design.name,
        &UKF,
        ukf,
        unscented_code(code, ukf),
        code,
        "The unscented Kalman filter from the centre of the state box (kind ukf_box, the Rust\n \
         * UkfBoxObserver): an estimate from the first accepted sample; a sample with a non-finite output\n \
         * is refused and only predicted.",
        !code.log_coordinates.is_plant(),
    )
    .map(Some)
}
