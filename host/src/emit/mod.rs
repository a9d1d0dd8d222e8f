//! Emission of the fitted maps as Rust source (askama templates in `host/templates/`).
//!
//! Each design becomes `generated/src/<design>.rs`: a provenance header, constant `f32` tables and a
//! `const fn` constructor, written only once the f32 tables have been checked against the f64 map on
//! every validation window and the scenario ([`crate::emit::precision`]); `generated/src/lib.rs` declares
//! every design file present. Every literal is
//! printed so that it parses back to the same `f32` bits, non-finite values are refused, and nothing in
//! the output depends on the machine, the time or the way `gen` was invoked: regeneration is byte for
//! byte.

pub mod families;
pub mod model;
pub mod precision;

use precision::{check_f32, F32Tables};

pub use families::{families, FamilyError, FamilyModule, Member};

use std::path::Path;

use askama::Template;

use crate::data::DataSet;
use crate::fit::DesignResult;
use crate::spec::Design;

/// Why a design cannot be emitted.
#[derive(Debug, thiserror::Error)]
pub enum EmitError {
    /// A coefficient is NaN, infinite, or beyond the range of `f32`.
    #[error("{what} = {} cannot be stored as a finite f32", crate::spec::readable(*value))]
    NotFinite {
        /// Which coefficient.
        what: String,
        /// Its value.
        value: f64,
    },
    /// A non-zero value that f32 rounds to zero or to a subnormal (losing its precision).
    #[error("{what} = {value:e} is below the normal f32 range (smallest {min:e}): the chip would see 0 or a value without precision; rescale it (e.g. change its units)", min = f32::MIN_POSITIVE)]
    Underflow {
        /// Which value.
        what: String,
        /// Its value.
        value: f64,
    },
    /// Two targets would get the same Rust constant name.
    #[error("targets `{first}` and `{second}` both become the constant `{constant}`")]
    NameClash {
        /// One target.
        first: String,
        /// The other.
        second: String,
        /// The constant both map to.
        constant: String,
    },
    /// A measurement or input of the validation data is beyond the range of f32: the chip could not
    /// hold it.
    #[error("the measurements and inputs reach {}, beyond the range of f32 (±3.4e38): rescale the outputs or inputs (their units) or lower the noise variance", crate::spec::readable(*value))]
    BeyondF32 {
        /// The largest magnitude seen.
        value: f64,
    },
    /// Rounded to f32, the tables do not reproduce the f64 map (see [`crate::emit::precision`]).
    #[error("target `{target}`: {mismatch}; lower `map.beta` or `map.nm`")]
    NotReproducibleInF32 {
        /// The target.
        target: String,
        /// Where it failed.
        mismatch: crate::emit::precision::F32Mismatch,
    },
    /// The map has no table the chip could evaluate.
    #[error("target `{target}`: Γ is so flat somewhere that a certified table of Γ⁻¹ would need more than {max} segments; lower `map.beta` (or `map.nm`), or use `normalisation = \"intercept\"`", max = crate::fit::inverse_table::MAX_SEGMENTS)]
    NoTable {
        /// The target.
        target: String,
    },
    /// The template failed to render.
    #[error("template: {0}")]
    Template(#[from] askama::Error),
}

/// The `f32` nearest `value`, printed so that it parses back to the same bits.
pub fn f32_literal(what: &str, value: f64) -> Result<String, EmitError> {
    let single = value as f32;
    if !single.is_finite() {
        return Err(EmitError::NotFinite {
            what: what.to_owned(),
            value,
        });
    }
    if value != 0.0 && (single == 0.0 || single.is_subnormal()) {
        return Err(EmitError::Underflow {
            what: what.to_owned(),
            value,
        });
    }
    // `{:?}` prints the shortest decimal that round-trips, always with a `.` or an exponent.
    Ok(format!("{single:?}"))
}

/// `text` made safe for a `//!` or `///` comment: control characters (a newline would end the
/// comment and let the rest be read as code) become spaces.
fn comment_text(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { ' ' } else { c }).collect()
}

/// Characters Markdown or rustdoc may read as markup: code spans and fences, emphasis, links, HTML
/// and its entities, headings, tables.
const MARKUP: &str = "\\`*_[]<>#|~&";

/// Spec text for the prose of a doc comment: one line, no leading blanks (an indented code block), and
/// every markup character escaped with a backslash, so that nothing a spec says can open a code fence
/// (a doctest that fails), a link or an HTML tag (rustdoc warnings) in the generated crate.
pub(crate) fn doc_prose(text: &str) -> String {
    let mut inert = String::new();
    for c in comment_text(text).trim_start().chars() {
        if MARKUP.contains(c) {
            inert.push('\\');
        }
        inert.push(c);
    }
    inert
}

/// Spec text inside a code span of a doc comment: one line, a backtick (which would end the span)
/// shown as `'`.
pub(crate) fn doc_code(text: &str) -> String {
    comment_text(text).replace('`', "'")
}

/// Literals of `values`, one per line (as rustfmt lays them out), indented by `indent` spaces.
fn literal_block(what: &str, values: &[f64], indent: usize) -> Result<String, EmitError> {
    let literals = values
        .iter()
        .enumerate()
        .map(|(i, &v)| f32_literal(&format!("{what}[{i}]"), v))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(literals
        .iter()
        .map(|l| format!("{}{l},", " ".repeat(indent)))
        .collect::<Vec<_>>()
        .join("\n"))
}

struct TargetTables {
    name: String,
    /// `, in <unit>` for the docs ("" without a unit).
    unit_phrase: String,
    const_name: String,
    upper: String,
    expr: String,
    rmse: String,
    max_error: String,
    linear_rmse: String,
    gains: String,
    offset: String,
    segments: String,
    segment_count: usize,
    knot_count: usize,
    /// The left knots `t_k` of a searched table (`None`: uniform knots).
    starts: Option<String>,
    /// The search's steps, written out (searched tables only).
    search_steps: Option<String>,
    t_max: String,
    r_min: String,
    r_max: String,
    proven_bound: String,
    sampled_error: String,
    dot: String,
    /// For a pruned `L`: how many gains are non-zero (empty when all are).
    taps_note: String,
}

/// `y[0].is_finite() & … & u[…].is_finite()`: every value, no early exit (`true` for none).
fn finite_check(outputs: usize, inputs: usize) -> String {
    let terms: Vec<String> = (0..outputs)
        .map(|i| format!("y[{i}].is_finite()"))
        .chain((0..inputs).map(|i| format!("u[{i}].is_finite()")))
        .collect();
    // Name what the check does not read, so that the emitted code has no unused-variable warning.
    let unused = match (outputs, inputs) {
        (0, 0) => "let _ = (y, u);\n        ",
        (_, 0) => "let _ = u;\n        ",
        (0, _) => "let _ = y;\n        ",
        _ => "",
    };
    if terms.is_empty() {
        format!("{unused}true")
    } else {
        format!("{unused}{}", terms.join(" & "))
    }
}

/// The doc line of a pruned `L` (sparse, `[map] taps`): which share of the gains the chip reads.
fn taps_note(gains: &[f32]) -> String {
    let kept = gains.iter().filter(|&&g| g != 0.0).count();
    if kept == gains.len() {
        String::new()
    } else {
        format!(
            "\n/// `L` is sparse: {kept} of the {} gains are non-zero, and only those are multiplied on the chip.",
            gains.len()
        )
    }
}

/// `+ GAINS_<upper>[i] * w[…].y[…]` for every regressor entry with a non-zero gain, in regressor
/// order, one per line: the window `w` is oldest first, so lag `l` is `w[N - 1 - l]`. Pruned taps
/// (gain exactly 0) are left out, as [`firmware::estimate_by_loops`] skips them.
fn dot_lines(upper: &str, gains: &[f32], horizon: usize, outputs: usize, inputs: usize) -> String {
    let mut lines = Vec::new();
    let mut i = 0;
    for (count, field) in [(outputs, "y"), (inputs, "u")] {
        for lag in 0..horizon {
            for m in 0..count {
                if gains[i] != 0.0 {
                    lines.push(format!(
                        "                    + GAINS_{upper}[{i}] * w[{}].{field}[{m}]",
                        horizon - 1 - lag
                    ));
                }
                i += 1;
            }
        }
    }
    lines.join("\n")
}

/// A `[&str; _]` literal of units.
fn units<'a>(units: impl IntoIterator<Item = &'a String>) -> String {
    format!("{:?}", units.into_iter().collect::<Vec<_>>())
}

/// `let k = firmware::search_step(&STARTS_<upper>, t, k, half);` for every step of the search over
/// `len` knots ([`firmware::search_halves`]).
fn search_steps(upper: &str, len: usize) -> String {
    firmware::search_halves(len)
        .map(|half| format!("                let k = firmware::search_step(&STARTS_{upper}, t, k, {half});"))
        .collect::<Vec<_>>()
        .join("\n")
}

#[derive(Template)]
#[template(path = "design.rs", escape = "none")]
struct DesignFile {
    name: String,
    description: String,
    command: String,
    version: &'static str,
    crate_name: String,
    spec_path: String,
    spec_path_literal: String,
    time_unit: String,
    /// `(N − 1) τ`.
    window: String,
    output_units: String,
    input_units: String,
    state_units: String,
    target_units: String,
    spec_hash: String,
    tau: String,
    horizon: usize,
    nm: usize,
    beta: f64,
    normalisation: String,
    outputs: Vec<String>,
    inputs: Vec<String>,
    output_list: String,
    input_list: String,
    regressor_len: usize,
    finite_check: String,
    /// `("kind", instructions)` of every observer kind, predicted.
    predicted: String,
    predicted_len: usize,
    targets: Vec<TargetTables>,
    recorded_len: usize,
    recorded_y: String,
    recorded_u: String,
    refused: Vec<usize>,
    states: usize,
    state_list: String,
    /// The `FAMILY` constant of a family's member ([`families::Member::declaration`]), else nothing.
    family: String,
    model: String,
}

/// Samples of the recorded sequence where a value is replaced by NaN, then by +∞, so that every
/// consumer of it (the on-target program, tests) checks that such samples are refused harmlessly.
pub fn refused_samples(len: usize) -> Vec<usize> {
    if len >= 3 {
        vec![len / 3, 2 * len / 3]
    } else {
        vec![]
    }
}

/// The recorded sequence an emitted design carries (`RECORDED_Y`, `RECORDED_U`), as rows of a
/// recording: `scenario`'s measurements and inputs rounded to `f32` as emitted, the
/// [`refused_samples`]' first output NaN, then +∞. What the chip runs, for the host to run too.
pub fn recorded_sequence(scenario: &crate::data::Run) -> Vec<crate::recording::Row> {
    let len = scenario.measurements.len();
    let exact = |row: &[f64]| -> Vec<f64> { row.iter().map(|&v| f64::from(v as f32)).collect() };
    scenario
        .measurements
        .iter()
        .zip(scenario.inputs.iter())
        .enumerate()
        .map(|(k, (y, u))| {
            let mut y = exact(y);
            if let (Some(value), Some(first)) = (refused_value(k, len), y.first_mut()) {
                *first = value;
            }
            crate::recording::Row {
                time: None,
                run: String::new(),
                y,
                u: exact(u),
            }
        })
        .collect()
}

/// The value that replaces the first output of sample `k` of a recorded sequence of `len` samples:
/// NaN at the first of the [`refused_samples`], +∞ at the second, `None` elsewhere.
fn refused_value(k: usize, len: usize) -> Option<f64> {
    match refused_samples(len).iter().position(|&r| r == k)? {
        0 => Some(f64::NAN),
        _ => Some(f64::INFINITY),
    }
}

/// Rows `[v, …],` of a recorded sequence, one sample per line, with the refused samples' first value
/// replaced by `f32::NAN` or `f32::INFINITY`.
fn recorded_rows(what: &str, rows: &crate::data::Rows, corrupt: bool) -> Result<String, EmitError> {
    let mut text = Vec::new();
    for (k, row) in rows.iter().enumerate() {
        let mut cells = row
            .iter()
            .enumerate()
            .map(|(i, &v)| f32_literal(&format!("{what}[{k}][{i}]"), v))
            .collect::<Result<Vec<_>, _>>()?;
        if let (true, Some(value), Some(first)) = (corrupt, refused_value(k, rows.len()), cells.first_mut()) {
            *first = if value.is_nan() {
                "f32::NAN".into()
            } else {
                "f32::INFINITY".into()
            };
        }
        text.push(format!("    [{}],", cells.join(", ")));
    }
    Ok(text.join("\n"))
}

#[derive(Template)]
#[template(path = "lib.rs", escape = "none")]
struct LibFile<'a> {
    version: &'static str,
    designs: &'a [String],
    families: &'a [FamilyModule],
}

/// The spec path as it should appear in generated files: relative to the workspace when inside it,
/// so that the text does not depend on where the checkout lives.
pub fn portable_spec_path(spec: &Path, workspace: &Path) -> String {
    let absolute = |p: &Path| p.canonicalize().unwrap_or_else(|_| p.to_owned());
    let spec = absolute(spec);
    spec.strip_prefix(absolute(workspace))
        .map(|p| p.to_string_lossy().replace('\\', "/"))
        .unwrap_or_else(|_| {
            spec.file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default()
        })
}

/// Names as the emitted docs list them: comma separated, `none` for none.
pub fn name_list(names: &[String]) -> String {
    if names.is_empty() {
        "none".to_owned()
    } else {
        names.join(", ")
    }
}

/// Where an emitted design file lives: what its examples, its `SPEC` and its "regenerate" line say.
#[derive(Clone, Copy, Debug)]
pub enum Placement<'a> {
    /// A module of the project's `generated` crate, regenerated by `gen`; `spec` is relative to the
    /// workspace.
    Generated {
        /// The spec's path.
        spec: &'a str,
    },
    /// The module of a standalone crate (`gen --spec`) whose library is `crate_name`, beside its copy of
    /// the spec (`spec.toml`); `source` is the spec as `gen` was given it.
    Standalone {
        /// The crate's library name.
        crate_name: &'a str,
        /// The spec `gen` read.
        source: &'a str,
    },
}

impl Placement<'_> {
    /// The crate the examples import.
    pub fn crate_name(&self) -> &str {
        match self {
            Placement::Generated { .. } => "generated",
            Placement::Standalone { crate_name, .. } => crate_name,
        }
    }

    /// `SPEC`: relative to the workspace, or the crate's own copy.
    pub fn spec_path(&self) -> &str {
        match self {
            Placement::Generated { spec } => spec,
            Placement::Standalone { .. } => STANDALONE_SPEC,
        }
    }

    /// The command that writes the file again.
    pub fn command(&self) -> String {
        match self {
            Placement::Generated { .. } => "cargo run -p host -- gen".to_owned(),
            Placement::Standalone { source, .. } => format!("cargo run -p host -- gen --spec {source}"),
        }
    }
}

/// A standalone crate's copy of its spec, relative to the crate.
pub const STANDALONE_SPEC: &str = "spec.toml";

/// The text of `generated/src/<design>.rs` (or of a standalone crate's module, as `placement` says).
pub fn design_file(
    design: &Design,
    result: &DesignResult,
    placement: &Placement<'_>,
    code: &crate::plant::ModelCode,
    observers: &model::Observers<'_>,
) -> Result<String, EmitError> {
    let list = name_list;
    let outputs: Vec<String> = design.model.outputs.iter().map(|o| o.name.clone()).collect();
    // The chip holds every sample in f32: data beyond its range cannot be what the map is checked on.
    let largest = result
        .validation
        .runs
        .iter()
        .chain(std::iter::once(&result.scenario))
        .flat_map(|run| run.measurements.iter().chain(&run.inputs).flatten())
        .map(|v| v.abs())
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    if largest > f64::from(f32::MAX) {
        return Err(EmitError::BeyondF32 { value: largest });
    }
    let mut targets: Vec<TargetTables> = Vec::new();
    for t in &result.targets {
        let target = &design.targets[t.index];
        let map = &t.fit.map;
        let const_name = format!("MAP_{}", target.name.to_uppercase());
        if let Some(other) = targets.iter().find(|o| o.const_name == const_name) {
            return Err(EmitError::NameClash {
                first: other.name.clone(),
                second: target.name.clone(),
                constant: const_name,
            });
        }
        let Some(table) = map.table.as_ref() else {
            return Err(EmitError::NoTable {
                target: target.name.clone(),
            });
        };
        // Rounded once: these f32 values are checked against the f64 map, then printed.
        let rounded = F32Tables::new(table);
        for data in [
            &result.validation,
            &DataSet {
                runs: vec![result.scenario.clone()],
                horizon: design.map.horizon,
            },
        ] {
            check_f32(table, &rounded, data).map_err(|mismatch| EmitError::NotReproducibleInF32 {
                target: target.name.clone(),
                mismatch,
            })?;
        }
        let what = |field: &str| format!("target `{}` {field}", target.name);
        let upper = target.name.to_uppercase();
        let widen = |values: &[f32]| values.iter().map(|&v| f64::from(v)).collect::<Vec<f64>>();
        let segments = rounded
            .segments
            .iter()
            .enumerate()
            .map(|(k, [a, b])| {
                Ok(format!(
                    "    [{}, {}],",
                    f32_literal(&what(&format!("segments[{k}].a")), f64::from(*a))?,
                    f32_literal(&what(&format!("segments[{k}].b")), f64::from(*b))?
                ))
            })
            .collect::<Result<Vec<_>, EmitError>>()?;
        targets.push(TargetTables {
            name: target.name.clone(),
            unit_phrase: if target.unit.is_empty() {
                String::new()
            } else {
                format!(", in {}", doc_code(&target.unit))
            },
            const_name,
            dot: dot_lines(
                &upper,
                &rounded.gains,
                design.map.horizon,
                outputs.len(),
                design.model.inputs.len(),
            ),
            search_steps: table.starts.as_ref().map(|starts| search_steps(&upper, starts.len())),
            taps_note: taps_note(&rounded.gains),
            upper,
            expr: doc_code(target.expr.text()),
            rmse: format!("{:.4}", t.validation.map.rmse),
            max_error: format!("{:.4}", t.validation.map.max_error),
            linear_rmse: format!("{:.4}", t.validation.linear.rmse),
            gains: literal_block(&what("gains"), &widen(&rounded.gains), 4)?,
            offset: f32_literal(&what("offset"), f64::from(rounded.offset))?,
            segments: segments.join("\n"),
            segment_count: table.segments.len(),
            knot_count: table.segments.len() + 1,
            starts: match &rounded.starts {
                None => None,
                Some(starts) => Some(literal_block(&what("starts"), &widen(starts), 4)?),
            },
            t_max: f32_literal(&what("t_max"), f64::from(rounded.t_max))?,
            r_min: f32_literal(&what("r_min"), f64::from(rounded.r_min))?,
            r_max: f32_literal(&what("r_max"), f64::from(rounded.r_max))?,
            proven_bound: format!("{:.2e}", table.proven_bound),
            sampled_error: format!("{:.2e}", table.sampled_error),
        });
    }
    let file = DesignFile {
        name: design.name.clone(),
        description: doc_prose(&design.description),
        command: doc_code(&placement.command()),
        version: env!("CARGO_PKG_VERSION"),
        crate_name: placement.crate_name().to_owned(),
        spec_path: doc_code(placement.spec_path()),
        spec_path_literal: format!("{:?}", placement.spec_path()),
        time_unit: doc_code(&design.time_unit),
        window: crate::recording::time_text(design.map.horizon - 1, design.tau),
        output_units: units(design.model.outputs.iter().map(|o| &o.unit)),
        input_units: units(&design.input_units),
        state_units: units(&design.state_units),
        target_units: units(design.targets.iter().map(|t| &t.unit)),
        spec_hash: design.spec_sha256.clone(),
        tau: f32_literal("sampling.tau", design.tau)?,
        horizon: design.map.horizon,
        nm: design.map.nm,
        beta: design.map.beta,
        normalisation: format!("{:?}", design.map.normalisation).to_lowercase(),
        output_list: list(&outputs),
        input_list: list(&design.model.inputs),
        outputs,
        inputs: design.model.inputs.clone(),
        regressor_len: design.map.horizon * (design.model.outputs.len() + design.model.inputs.len()),
        finite_check: finite_check(design.model.outputs.len(), design.model.inputs.len()),
        targets,
        recorded_len: result.scenario.measurements.len(),
        recorded_y: recorded_rows(
            "recorded y",
            &result.scenario.measurements,
            !design.model.outputs.is_empty(),
        )?,
        recorded_u: recorded_rows("recorded u", &result.scenario.inputs, false)?,
        refused: refused_samples(result.scenario.measurements.len()),
        states: design.model.states.len(),
        state_list: format!("{:?}", design.model.states),
        family: match Member::of(design)? {
            Some(member) => member.declaration(),
            None => String::new(),
        },
        predicted: observers
            .instructions
            .iter()
            .map(|(kind, instructions)| format!("(\"{kind}\", {instructions:.0})"))
            .collect::<Vec<_>>()
            .join(", "),
        predicted_len: observers.instructions.len(),
        // Last: the maps' checks above (data beyond f32, the sample period) name the cause where the
        // EKF's constants, derived from the same data, would only fail to be stored.
        model: model::model_source(design, code, observers)?.trim_end().to_owned(),
    };
    file.render().map(|text| text + "\n").map_err(EmitError::from)
}

/// The text of `generated/src/lib.rs` declaring `designs` (sorted by the caller) and `families`.
pub fn lib_file(designs: &[String], families: &[FamilyModule]) -> Result<String, EmitError> {
    LibFile {
        version: env!("CARGO_PKG_VERSION"),
        designs,
        families,
    }
    .render()
    .map(|text| text + "\n")
    .map_err(EmitError::from)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn literals_round_trip_to_the_same_f32_bits(bits in any::<u32>()) {
            let value = f32::from_bits(bits);
            prop_assume!(value.is_finite() && !value.is_subnormal()); // subnormals are refused
            let literal = f32_literal("x", value as f64).unwrap();
            prop_assert_eq!(literal.parse::<f32>().unwrap().to_bits(), bits, "{}", literal);
            prop_assert!(literal.contains('.') || literal.contains('e'), "{} is not a float literal", literal);
        }
    }

    #[test]
    fn spec_text_cannot_open_markup_in_the_docs() {
        // A code fence in a description made the generated file start a doctest that fails.
        let prose = doc_prose("   ```rust\nfn main() {} <b>[link] *x* # h");
        assert_eq!(prose, "\\`\\`\\`rust fn main() {} \\<b\\>\\[link\\] \\*x\\* \\# h");
        assert!(!doc_code("a`b").contains('`'));
    }

    proptest! {
        #[test]
        fn every_markup_character_of_the_prose_is_escaped(text in ".*") {
            let prose = doc_prose(&text);
            prop_assert!(!prose.contains('\n') && !prose.starts_with(' '));
            let mut escaped = false;
            for c in prose.chars() {
                prop_assert!(escaped || c == '\\' || !MARKUP.contains(c), "{prose}");
                escaped = !escaped && c == '\\';
            }
            prop_assert!(!escaped, "a trailing backslash would escape what follows: {prose}");
        }
    }

    #[test]
    fn comment_text_cannot_end_a_comment() {
        let text = comment_text("line\npub fn injected() {}\r\n");
        assert!(!text.contains('\n') && !text.contains('\r'));
    }

    #[test]
    fn values_that_underflow_in_f32_are_refused_and_zero_and_the_smallest_normal_are_not() {
        for value in [1e-300, -1e-300, 1e-40, f64::from(f32::MIN_POSITIVE) / 2.0] {
            assert!(
                matches!(f32_literal("x", value), Err(EmitError::Underflow { .. })),
                "{value:e}"
            );
        }
        for value in [0.0, -0.0, f64::from(f32::MIN_POSITIVE), 1e-37] {
            assert!(f32_literal("x", value).is_ok(), "{value:e}");
        }
    }

    #[test]
    fn non_finite_and_out_of_range_values_are_refused() {
        for value in [f64::NAN, f64::INFINITY, -f64::INFINITY, 1e39] {
            assert!(matches!(f32_literal("x", value), Err(EmitError::NotFinite { .. })));
        }
    }
}
