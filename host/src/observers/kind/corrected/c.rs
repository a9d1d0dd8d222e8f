//! The model-corrected map in C (kind `corrected`, the Rust file's `CorrectedObserver`): the start-up
//! schedule and the clamp as tables, its three programs as functions, and `firmware::Started` over
//! the follower `Corrector`.

use askama::Template;

use crate::emit::c::program::function;
use crate::emit::c::started::{self, map_states, targets_of, Follower};
use crate::emit::c::text::{floats, CPart};
use crate::emit::model::observers::Observers;
use crate::emit::EmitError;
use crate::observers::kind::corrected::program::{correction_code, CorrectionCode, CorrectionConstants};
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design's C, when the design has it.
pub(crate) fn c(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<CPart>, EmitError> {
    let Some((constants, state_targets)) = observers.corrected() else {
        return Ok(None);
    };
    let programs = correction_code(code, constants);
    let (header, source) = corrected(&design.name, code, constants, &programs, state_targets)?;
    Ok(Some(CPart {
        header,
        source,
        programs: vec![programs.predict, programs.start_up, programs.steady],
    }))
}

/// The header's and the source's parts of the corrected map.
fn corrected(
    name: &str,
    code: &ModelCode,
    constants: &CorrectionConstants,
    programs: &CorrectionCode,
    state_targets: &[usize],
) -> Result<(String, String), EmitError> {
    let upper = name.to_uppercase();
    let (nx, nt) = (code.dimensions.states, code.dimensions.targets);
    let blends = constants.blends();
    let scheduled = nx + nx * code.dimensions.outputs;
    let rows = blends
        .iter()
        .enumerate()
        .map(|(j, row)| floats(&format!("corrected start-up blend {}", j + 1), row))
        .collect::<Result<Vec<_>, _>>()?;
    let (lower, upper_bounds) = (
        floats("corrected lower", &constants.lower)?,
        floats("corrected upper", &constants.upper)?,
    );
    let mut functions = function(
        "corrected_predict",
        "One sampling period of the model from x, the value alone: out = x+ (corrected_predict).",
        &["x", "u"],
        &programs.predict,
        code,
    )?;
    functions += &function(
        "corrected_start_up",
        "The correction during the start-up, g = (blends g_j, gains K_j): x before its clamp.",
        &["x", "y", "u", "f", "g"],
        &programs.start_up,
        code,
    )?;
    functions += &function(
        "corrected_steady",
        "The correction after the start-up: x before its clamp.",
        &["x", "y", "u", "f"],
        &programs.steady,
        code,
    )?;
    let follower = Follower {
        name,
        kind: "corrected",
        prefix: "corrected",
        predict: "corrected_lost",
        start_up: constants.start_up,
        steady_reads_map: programs.steady_reads_map,
        carried: "o->x",
        predicted: "o->x",
    };
    let source = crate::emit::c::render(&CorrectedC {
        name,
        upper: &upper,
        blends: rows.len(),
        scheduled,
        rows: &rows.join(",\n"),
        lower: &lower,
        upper_bounds: &upper_bounds,
        functions: &functions,
        map_states: &map_states("corrected", state_targets),
        targets_of: &targets_of(name, "corrected", state_targets, nt),
        observer: &started::observer(&follower, "    memset(o->x, 0, sizeof o->x);\n"),
    });
    let header = started::header(
        name,
        "corrected",
        "The model-corrected map (kind corrected, the Rust CorrectedObserver): the map's first estimate,\n \
         * then the model's prediction corrected by the output and, during the start-up, blended with the\n \
         * map; each state clamped to its learning range (flagged LOW or HIGH).",
        true,
        &format!("    float x[{upper}_STATES];\n    unsigned count;\n    int started;\n"),
    );
    Ok((header, source))
}

/// The corrected map's source: its tables (`blends` rows of `scheduled` numbers; none: no table), its
/// programs (`functions`), its follower and observer.
#[derive(Template)]
#[template(path = "corrected/templates/corrected.c.askama", escape = "none")]
struct CorrectedC<'a> {
    name: &'a str,
    upper: &'a str,
    blends: usize,
    scheduled: usize,
    rows: &'a str,
    lower: &'a str,
    upper_bounds: &'a str,
    functions: &'a str,
    map_states: &'a str,
    targets_of: &'a str,
    observer: &'a str,
}
