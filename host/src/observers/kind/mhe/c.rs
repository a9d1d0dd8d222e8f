//! The moving-horizon estimate in C (kind `mhe`, the Rust file's `MheObserver`):
//! `firmware::mhe::Observer` over the design's RK4 model written out with the same loops and the
//! same operations in the same order (`Rk4::step` with its Jacobian, the normal equations, the
//! `L D Lᵀ` solve, the projection onto the box), so that it gives the Rust observer's bits. Not
//! straight-line code: loops over the states and the window, as the firmware's generic code.

use askama::Template;

use crate::emit::c::program::function;
use crate::emit::c::text::{floats, CPart};
use crate::emit::model::observers::Observers;
use crate::emit::{EmitError, WatchLiterals};
use crate::observers::kind::mhe::run::ChipConstants;
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design's C, when the design has it.
pub(crate) fn c(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<CPart>, EmitError> {
    let Some(constants) = observers.mhe() else {
        return Ok(None);
    };
    let (header, source) = mhe(&design.name, code, constants, design.chip_substeps, design.map.horizon)?;
    Ok(Some(CPart {
        header,
        source,
        programs: vec![code.derivative.clone(), code.output.clone()],
    }))
}

/// The header's and the source's parts of the moving-horizon observer.
fn mhe(
    name: &str,
    code: &ModelCode,
    constants: &ChipConstants,
    substeps: usize,
    horizon: usize,
) -> Result<(String, String), EmitError> {
    let upper = name.to_uppercase();
    let nu = code.dimensions.inputs;
    let one = |what: &str, v: f64| crate::emit::c::text::float(&format!("chip MHE {what}"), v);
    let mut source = function(
        "model_derivative",
        "The model's derivative f(x, u), then its Jacobian row by row (the Rust file's Plant::derivative).",
        &["x", "u"],
        &code.derivative,
        code,
    )?;
    source += &function(
        "model_output",
        "The model's outputs h(x, u), then their Jacobian row by row (the Rust file's Plant::output).",
        &["x", "u"],
        &code.output,
        code,
    )?;
    let (weights, prior) = (
        floats("chip MHE weights", &constants.weights)?,
        floats("chip MHE prior", &constants.prior)?,
    );
    source += &crate::emit::c::render(&MheC {
        name,
        upper: &upper,
        // The window's inputs: none is read where the design has no input.
        inputs: nu > 0,
        weights: &weights,
        prior: &prior,
        lower: &floats("chip MHE lower", &constants.lower)?,
        upper_bounds: &floats("chip MHE upper", &constants.upper)?,
        start: &floats("chip MHE start", &constants.start)?,
        damping: &one("damping", constants.damping)?,
        h: &one("substep", constants.h)?,
        iterations: constants.iterations,
        substeps,
        watch: WatchLiterals::of(&constants.watch, horizon * code.dimensions.outputs, |what, v| {
            one(what, v)
        })?,
    });
    let header = crate::emit::c::render(&MheH {
        name,
        upper: &upper,
        inputs: nu > 0,
        iterations: constants.iterations,
        watched: constants.watch.threshold.is_finite(),
    });
    Ok((header, source + &crate::emit::c::started::estimate(name, "mhe")))
}

/// The observer's part of the header.
#[derive(Template)]
#[template(path = "mhe/templates/mhe.h.askama", escape = "none")]
struct MheH<'a> {
    name: &'a str,
    upper: &'a str,
    inputs: bool,
    iterations: usize,
    /// Whether the observer keeps a watched mean.
    watched: bool,
}

/// The observer's constants and code (`NX` is the design's states).
#[derive(Template)]
#[template(path = "mhe/templates/mhe.c.askama", escape = "none")]
struct MheC<'a> {
    name: &'a str,
    upper: &'a str,
    inputs: bool,
    weights: &'a str,
    prior: &'a str,
    lower: &'a str,
    upper_bounds: &'a str,
    start: &'a str,
    damping: &'a str,
    h: &'a str,
    iterations: usize,
    substeps: usize,
    /// The watch's constants over the windows' costs (`m N` outputs), where watched.
    watch: Option<WatchLiterals>,
}
