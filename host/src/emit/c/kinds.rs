//! The model-based kinds in C: the model's programs as functions ([`super::program`]), the helpers
//! they call, then each kind's own part in the registry's order (its entry's
//! [`crate::observers::kind::Kind::c`]), each with the Rust observer's steps in the same order.

use askama::Template;

use super::program::{calls, function, needs_math};
use super::text::render;
use crate::emit::model::observers::Observers;
use crate::emit::EmitError;
use crate::observers::kind::REGISTRY;
use crate::plant::{ModelCode, Program};
use crate::spec::Design;

/// The model-based kinds' part of the header and of the source.
#[derive(Default)]
pub(super) struct Kinds {
    /// Their structs and prototypes.
    pub header: String,
    /// Their programs and code.
    pub source: String,
    /// The kinds written, by name.
    pub names: Vec<&'static str>,
    /// Whether a program calls a function of `<math.h>`.
    pub needs_math: bool,
}

/// Every model-based kind `observers` has.
pub(super) fn kinds(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Kinds, EmitError> {
    let mut parts = Vec::new();
    for entry in &REGISTRY {
        if let Some(part) = entry.c.map(|c| c(design, code, observers)).transpose()?.flatten() {
            parts.push((entry.kind.name(), part));
        }
    }
    if parts.is_empty() {
        return Ok(Kinds::default());
    }
    let mut programs: Vec<&Program> = vec![&code.targets];
    programs.extend(parts.iter().flat_map(|(_, part)| &part.programs));
    let mut kinds = Kinds {
        needs_math: needs_math(&programs),
        ..Kinds::default()
    };
    kinds.source += &render(&KindsC {
        upper: &design.name.to_uppercase(),
        inputs: code.dimensions.inputs > 0,
        signum: calls(&programs, "signum"),
        exp: calls(&programs, "exp"),
        ln: calls(&programs, "ln"),
        fract: calls(&programs, "fract"),
    });
    kinds.source += &function(
        "targets",
        "The targets at state x and input u.",
        &["x", "u"],
        &code.targets,
        code,
    )?;
    for (name, part) in parts {
        kinds.header += &part.header;
        kinds.source += &part.source;
        kinds.names.push(name);
    }
    Ok(kinds)
}

/// What the model-based kinds share: the helpers the programs call, the checks of a sample's values.
#[derive(Template)]
#[template(path = "c/kinds.c", escape = "none")]
struct KindsC<'a> {
    upper: &'a str,
    inputs: bool,
    signum: bool,
    exp: bool,
    ln: bool,
    fract: bool,
}
