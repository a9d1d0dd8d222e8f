//! `generated/src/<design>.rs` (or a standalone crate's module): the design's tables, checked in
//! f32, its docs and recorded sequence, and its model (the `design.rs` template).

use askama::Template;

use super::model;
use super::precision::{check_f32, F32Tables};
use super::recorded::recorded_rows;
use super::{doc_code, doc_prose, f32_literal, name_list, refused_samples, EmitError, Member, Placement};
use crate::data::DataSet;
use crate::fit::DesignResult;
use crate::spec::Design;

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

/// `+ GAINS_<upper>[i] * w[…].y[…]` for every term of the dot product ([`super::terms::dot_terms`]),
/// one per line.
fn dot_lines(upper: &str, gains: &[f32], horizon: usize, outputs: usize, inputs: usize) -> String {
    super::terms::dot_terms(gains, horizon, outputs, inputs)
        .iter()
        .map(|t| {
            let field = if t.input { "u" } else { "y" };
            format!(
                "                    + GAINS_{upper}[{}] * w[{}].{field}[{}]",
                t.gain, t.sample, t.entry
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// A `[&str; _]` literal of units.
fn units<'a>(units: impl IntoIterator<Item = &'a String>) -> String {
    format!("{:?}", units.into_iter().collect::<Vec<_>>())
}

/// `let k = firmware::emitted::search_step(&STARTS_<upper>, t, k, half);` for every step of the search over
/// `len` knots ([`firmware::emitted::search_halves`]).
fn search_steps(upper: &str, len: usize) -> String {
    firmware::emitted::search_halves(len)
        .map(|half| format!("                let k = firmware::emitted::search_step(&STARTS_{upper}, t, k, {half});"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// What the emitted docs and constants call a map: a target, or a helper map of a state.
struct MapLabel<'a> {
    /// "target" or "helper map", for error messages.
    what: &'static str,
    name: &'a str,
    unit: &'a str,
    expr: &'a str,
    /// The constants' suffix (`MAP_<upper>`, `GAINS_<upper>`, …).
    upper: String,
}

/// One map's tables as the template prints them, checked in f32 on the validation runs and the
/// scenario.
fn map_tables(
    design: &Design,
    result: &DesignResult,
    label: &MapLabel<'_>,
    t: &crate::fit::TargetResult,
) -> Result<TargetTables, EmitError> {
    let outputs = design.model.outputs.len();
    let map = &t.fit.map;
    let Some(table) = map.table.as_ref() else {
        return Err(EmitError::NoTable {
            target: label.name.to_owned(),
        });
    };
    // Rounded once: these f32 values are checked against the f64 map, then printed.
    let rounded = F32Tables::new(table);
    for data in [
        &result.runs.validation,
        &DataSet {
            runs: vec![result.runs.scenario.clone()],
            horizon: design.map.horizon,
        },
    ] {
        check_f32(table, &rounded, data).map_err(|mismatch| EmitError::NotReproducibleInF32 {
            target: label.name.to_owned(),
            mismatch,
        })?;
    }
    let what = |field: &str| format!("{} `{}` {field}", label.what, label.name);
    let upper = label.upper.clone();
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
    Ok(TargetTables {
        name: label.name.to_owned(),
        unit_phrase: if label.unit.is_empty() {
            String::new()
        } else {
            format!(", in {}", doc_code(label.unit))
        },
        const_name: format!("MAP_{}", label.upper),
        dot: dot_lines(
            &upper,
            &rounded.gains,
            design.map.horizon,
            outputs,
            design.model.inputs.len(),
        ),
        search_steps: table.starts.as_ref().map(|starts| search_steps(&upper, starts.len())),
        taps_note: taps_note(&rounded.gains),
        upper,
        expr: doc_code(label.expr),
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
    })
}

#[derive(Template)]
#[template(path = "design.rs", escape = "none")]
struct DesignFile {
    name: String,
    description: String,
    command: String,
    licence: String,
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
    /// The helper maps ([`crate::fit::helpers`]): a `StartDesign` of the targets' and these rows.
    helpers: Vec<TargetTables>,
    recorded_len: usize,
    recorded_y: String,
    recorded_u: String,
    refused: Vec<usize>,
    states: usize,
    state_list: String,
    /// The `FAMILY` constant of a family's member ([`super::families::Member::declaration`]), else nothing.
    family: String,
    model: String,
    /// The integer map's section ([`super::fixed`]), or nothing.
    fixed: String,
    /// Every observer kind the design has, in the report's order: its name and its type.
    observers: Vec<(&'static str, &'static str)>,
    /// Whether the design has the integer map (`FixedObserver`).
    has_fixed: bool,
}

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
    within_f32(result)?;
    let mut targets: Vec<TargetTables> = Vec::new();
    let labels = result.targets.iter().map(|t| {
        let target = &design.targets[t.index];
        let label = MapLabel {
            what: "target",
            name: &target.name,
            unit: &target.unit,
            expr: target.expr.text(),
            upper: target.name.to_uppercase(),
        };
        (label, t)
    });
    // A helper map's constants are `MAP_HELPER_<STATE>`: a target may share the state's name.
    let helpers = result.helpers.iter().flatten().map(|t| {
        let state = &design.model.states[t.index];
        let label = MapLabel {
            what: "helper map",
            name: state,
            unit: &design.state_units[t.index],
            expr: state,
            upper: format!("HELPER_{}", state.to_uppercase()),
        };
        (label, t)
    });
    let count = result.targets.len();
    for (label, t) in labels.chain(helpers) {
        let tables = map_tables(design, result, &label, t)?;
        if let Some(other) = targets.iter().find(|o| o.const_name == tables.const_name) {
            return Err(EmitError::NameClash {
                first: other.name.clone(),
                second: label.name.to_owned(),
                constant: tables.const_name,
            });
        }
        targets.push(tables);
    }
    let helpers = targets.split_off(count);
    let file = DesignFile {
        name: design.name.clone(),
        description: doc_prose(&design.description),
        command: doc_code(&placement.command()),
        licence: super::licence_comment("//! "),
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
        helpers,
        recorded_len: result.runs.scenario.measurements.len(),
        recorded_y: recorded_rows(
            "recorded y",
            &result.runs.scenario.measurements,
            !design.model.outputs.is_empty(),
        )?,
        recorded_u: recorded_rows("recorded u", &result.runs.scenario.inputs, false)?,
        refused: refused_samples(result.runs.scenario.measurements.len()),
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
        fixed: observers.fixed.map_or(String::new(), |fixed| {
            super::fixed::fixed_source(design, fixed, &super::recorded_sequence(&result.runs.scenario))
        }),
        observers: observers
            .instructions
            .iter()
            .filter_map(|(kind, _)| crate::observers::kind::named(kind))
            .map(|entry| (entry.kind.name(), entry.observer_type))
            .collect(),
        has_fixed: observers.fixed.is_some(),
    };
    file.render().map(|text| text + "\n").map_err(EmitError::from)
}

/// The chip holds every sample in f32: validation or scenario data beyond its range cannot be what
/// the map is checked on ([`EmitError::BeyondF32`]).
pub fn within_f32(result: &DesignResult) -> Result<(), EmitError> {
    let largest = result
        .runs
        .validation
        .runs
        .iter()
        .chain(std::iter::once(&result.runs.scenario))
        .flat_map(|run| run.measurements.iter().chain(&run.inputs).flatten())
        .map(|v| v.abs())
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    if largest > f64::from(f32::MAX) {
        return Err(EmitError::BeyondF32 { value: largest });
    }
    Ok(())
}
