//! The EKF started by the map (`StartedEkf`, `EkfMapObserver`) in the design's Rust file: its
//! `P(N−1)` and each state's target, over the EKF's frame.

use askama::Template;

use crate::emit::model::observers::Observers;
use crate::emit::model::rust_text::{list, literal};
use crate::emit::{EmitError, WatchLiterals};
use crate::plant::kalman;
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design file, when the design has it (and the box EKF it runs on).
pub(crate) fn rust(_: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<String>, EmitError> {
    let (Some(ekf), Some((p0, state_targets))) = (observers.ekf(), observers.started()) else {
        return Ok(None);
    };
    let entries = kalman::diagonal_upper(p0)
        .iter()
        .enumerate()
        .map(|(i, v)| literal(&format!("map-started EKF P0[{i}]"), *v))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Some(
        StartedEkfText {
            p0: &list(&entries),
            p0_f64: &format!("{p0:?}"),
            state_targets: &format!("{state_targets:?}"),
            watch: WatchLiterals::of(&ekf.watch, code.dimensions.outputs, literal)?,
        }
        .render()?,
    ))
}

/// The EKF started by the map: `p0` its `P(N−1)` diagonal's upper triangle (`T` literals), `p0_f64`
/// the diagonal, `state_targets` each state's target, `watch` the box EKF's χ² watch where it has one.
#[derive(Template)]
#[template(path = "ekf_map/templates/ekf_map.rs.askama", escape = "none")]
struct StartedEkfText<'a> {
    p0: &'a str,
    p0_f64: &'a str,
    state_targets: &'a str,
    watch: Option<WatchLiterals>,
}
