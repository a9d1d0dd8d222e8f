//! The model-corrected map (`Corrector`, `CorrectedObserver`, kind `corrected`): its schedule and
//! clamp as constants, its programs written out.

use askama::Template;

use super::program::{self as correction, CorrectionConstants};
use crate::emit::model::observers::Observers;
use crate::emit::model::rust_text::{body, list};
use crate::emit::{f32_literal, EmitError};
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design file, when the design has it.
pub(crate) fn rust(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<String>, EmitError> {
    observers
        .corrected()
        .map(|(constants, state_targets)| corrector(design, code, constants, state_targets))
        .transpose()
}

/// The model-corrected map's follower (`Corrector`), its programs and `CorrectedObserver`.
fn corrector(
    design: &Design,
    code: &ModelCode,
    constants: &CorrectionConstants,
    state_targets: &[usize],
) -> Result<String, EmitError> {
    let programs = correction::correction_code(code, constants);
    let pairs = |what: &str, values: &[f64]| -> Result<String, EmitError> {
        let entries = values
            .iter()
            .enumerate()
            .map(|(i, v)| Ok(format!("({}, {v:?})", f32_literal(&format!("{what}[{i}]"), *v)?)))
            .collect::<Result<Vec<_>, EmitError>>()?;
        Ok(list(&entries))
    };
    let blends = constants
        .blends()
        .iter()
        .enumerate()
        .map(|(j, row)| pairs(&format!("corrected start-up blend {}", j + 1), row).map(|r| format!("    {r},")))
        .collect::<Result<Vec<_>, _>>()?;
    let (lower, upper) = (
        pairs("corrected lower", &constants.lower)?,
        pairs("corrected upper", &constants.upper)?,
    );
    Ok(CorrectedText {
        start_up: constants.start_up,
        reads: programs.steady_reads_map,
        state_targets: &format!("{state_targets:?}"),
        blends: &blends.join("\n"),
        lower: &lower,
        upper: &upper,
        g: &format!("{:?}", constants.g),
        k: &format!("{:?}", constants.k),
        k0: &format!("{:?}", constants.k_start),
        t: &format!("{:?}", constants.schedule),
        lower_f64: &format!("{:?}", constants.lower),
        upper_f64: &format!("{:?}", constants.upper),
        predict_body: &body(&programs.predict, code, design, "    ", list)?,
        start_up_body: &body(&programs.start_up, code, design, "    ", list)?,
        steady_body: &body(&programs.steady, code, design, "    ", list)?,
    }
    .render()?)
}

/// The model-corrected map and its written-out programs (`…_body`; `…_f64`: f64 values, `lower`, `upper`
/// and `blends`: `(f32, f64)` pairs).
#[derive(Template)]
#[template(path = "corrected/templates/corrected.rs.askama", escape = "none")]
struct CorrectedText<'a> {
    start_up: usize,
    reads: bool,
    state_targets: &'a str,
    blends: &'a str,
    lower: &'a str,
    upper: &'a str,
    g: &'a str,
    k: &'a str,
    k0: &'a str,
    t: &'a str,
    lower_f64: &'a str,
    upper_f64: &'a str,
    predict_body: &'a str,
    start_up_body: &'a str,
    steady_body: &'a str,
}
