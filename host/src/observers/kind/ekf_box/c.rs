//! The EKF from the box centre in C (`<name>_ekf_box`, the Rust file's `EkfBoxObserver`): the box
//! filters' C (`emit::c::box_filter`) with the EKF's samples; the kinds the map starts over
//! the EKF call its `ekf_predict` and `ekf_measure`.

use crate::emit::c::box_filter::{box_part, Filter};
use crate::emit::c::text::CPart;
use crate::emit::model::observers::Observers;
use crate::emit::EmitError;
use crate::plant::kalman;
use crate::plant::ModelCode;
use crate::spec::Design;

/// The EKF's names in C.
pub(crate) const EKF: Filter = Filter {
    lower: "ekf",
    label: "EKF",
    kind: "ekf_box",
};

/// Its part of the design's C, when the design has it.
pub(crate) fn c(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<CPart>, EmitError> {
    let Some(ekf) = observers.ekf() else {
        return Ok(None);
    };
    box_part(
        &design.name,
        &EKF,
        ekf,
        kalman::filter_code(code, ekf),
        code,
        "The EKF from the centre of the state box (kind ekf_box, the Rust EkfBoxObserver): an estimate\n \
         * from the first accepted sample; a sample with a non-finite output is refused and only predicted.",
        false,
    )
    .map(Some)
}
