//! The moving-horizon estimate on the chip (`MheObserver`, kind `mhe`): the firmware's
//! [`firmware::mhe::Observer`] over the design's `Discrete` model, with the constants `gen` chose
//! (`observers::kind::mhe`): the same code the host runs in `f32` for the report's `mhe` row, so that
//! the chip's estimates are the report's, bit for bit.

use askama::Template;

use crate::emit::model::observers::Observers;
use crate::emit::model::rust_text::{list, literal};
use crate::emit::{EmitError, WatchLiterals};
use crate::observers::kind::mhe::run::ChipConstants;
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design file, when the design has it.
pub(crate) fn rust(design: &Design, _: &ModelCode, observers: &Observers<'_>) -> Result<Option<String>, EmitError> {
    let outputs = design.model.outputs.len();
    (observers.mhe())
        .map(|c| mhe(c, design.map.horizon, outputs))
        .transpose()
}

/// The text of `Mhe` and `MheObserver` with `constants`, over windows of `horizon` samples of
/// `outputs` outputs.
fn mhe(constants: &ChipConstants, horizon: usize, outputs: usize) -> Result<String, EmitError> {
    let values = |what: &str, values: &[f64]| -> Result<String, EmitError> {
        let items = values
            .iter()
            .enumerate()
            .map(|(i, v)| literal(&format!("chip MHE {what}[{i}]"), *v))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(list(&items))
    };
    Ok(MheText {
        iterations: constants.iterations,
        h: &literal("chip MHE substep", constants.h)?,
        weights: &values("weights", &constants.weights)?,
        prior: &values("prior", &constants.prior)?,
        lower: &values("lower", &constants.lower)?,
        upper: &values("upper", &constants.upper)?,
        start: &values("start", &constants.start)?,
        damping: &literal("chip MHE damping", constants.damping)?,
        watch: &match WatchLiterals::of(&constants.watch, horizon * outputs, |what, v| {
            literal(&format!("chip MHE {what}"), v)
        })? {
            None => "None".to_owned(),
            Some(w) => format!(
                "Some(firmware::emitted::mhe::Watch {{ start: {}, gain: {}, limit: {} }})",
                w.start, w.gain, w.limit
            ),
        },
    }
    .render()?)
}

/// `Mhe` and `MheObserver` (`T` literals, `iterations` a count).
#[derive(Template)]
#[template(path = "mhe/templates/mhe.rs.askama", escape = "none")]
struct MheText<'a> {
    iterations: usize,
    h: &'a str,
    weights: &'a str,
    prior: &'a str,
    lower: &'a str,
    upper: &'a str,
    start: &'a str,
    damping: &'a str,
    /// `None`, or `Some(Watch { … })`.
    watch: &'a str,
}
