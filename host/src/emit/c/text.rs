//! The C text every emitter of a design's C writes with: `float` literals, a rendered template, and
//! one kind's part of the file ([`CPart`], what each kind's `c.rs` returns).

use askama::Template;

use crate::emit::EmitError;
use crate::plant::Program;

/// One kind's part of a design's C.
pub struct CPart {
    /// Its struct and prototypes.
    pub header: String,
    /// Its code.
    pub source: String,
    /// The programs it writes out as functions: they decide the helpers and `<math.h>`.
    pub programs: Vec<Program>,
}

/// A C `float` literal of `value` rounded to f32: the shortest decimal that round-trips, with `f`.
pub(crate) fn float(what: &str, value: f64) -> Result<String, EmitError> {
    Ok(format!("{}f", crate::emit::f32_literal(what, value)?))
}

/// `{ a, b, … }` of `values` (each rounded to f32), four per line.
pub(crate) fn floats(what: &str, values: &[f64]) -> Result<String, EmitError> {
    let items = values
        .iter()
        .enumerate()
        .map(|(i, &v)| float(&format!("{what}[{i}]"), v))
        .collect::<Result<Vec<_>, _>>()?;
    let lines: Vec<String> = items.chunks(4).map(|c| format!("    {}", c.join(", "))).collect();
    Ok(format!("{{\n{}\n}}", lines.join(",\n")))
}

/// The text of a template (every field's `Display` writes into a `String`, which cannot fail).
pub(crate) fn render(template: &impl Template) -> String {
    template.render().expect("a template renders into a String")
}
