//! The design's model written out (`parameters`, `Plant`, `targets`, `Discrete`) and, when it has
//! one, its EKF (`Ekf`, `reference_ekf`, and the written-out samples `ekf_measured`/`ekf_unmeasured`):
//! what every model-based observer kind runs on.

use askama::Template;

use super::filter::{constants_docs, filter_observer, filter_type, q_constant, samples, vector, Names};
use super::rust_text::{body, list, literal, rows};
use crate::emit::{f32_literal, EmitError};
use crate::plant::kalman::{self, EkfConstants};
use crate::plant::{Covariance, ModelCode};
use crate::spec::Design;

/// The model and the EKF.
pub(super) fn model_and_ekf(
    design: &Design,
    code: &ModelCode,
    ekf: Option<&EkfConstants>,
) -> Result<String, EmitError> {
    let nx = code.dimensions.states;
    let ny = code.dimensions.outputs;
    let spec = |s: &str| crate::emit::doc_code(s);
    let parameters = code
        .parameters
        .iter()
        .map(|(name, value)| {
            Ok((
                spec(name),
                name.clone(),
                f32_literal(&format!("model.parameters.{name}"), *value)?,
                format!("{value:?}"),
            ))
        })
        .collect::<Result<Vec<_>, EmitError>>()?;
    let states = design.model.states.iter().zip(&design.model.derivatives);
    let equations = states
        .map(|(state, expr)| format!("d{}/dt = {}", spec(state), spec(expr.text())))
        .chain(
            design
                .model
                .outputs
                .iter()
                .map(|output| format!("{} = {}", spec(&output.name), spec(output.expr.text()))),
        )
        .chain(
            design
                .model
                .definitions
                .iter()
                .map(|d| format!("where {} = {}", spec(&d.name), spec(d.expr.text()))),
        )
        .collect();
    let mut text = ModelText {
        parameters,
        equations,
        derivative: &body(&code.derivative, code, design, "        ", |r| {
            format!("({}, {})", list(&r[..nx]), rows(&r[nx..], nx))
        })?,
        output: &body(&code.output, code, design, "        ", |r| {
            format!("({}, {})", list(&r[..ny]), rows(&r[ny..], nx))
        })?,
        targets: &body(&code.targets, code, design, "    ", list)?,
        substeps: design.substeps,
        chip_substeps: design.chip_substeps,
    }
    .render()?;
    let Some(ekf) = ekf else {
        return Ok(text);
    };
    text.push('\n');

    let full = |what: &str, covariance: &Covariance| -> Result<String, EmitError> {
        let n = covariance.size();
        let entries = (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                literal(&format!("{what}[{i}][{j}]"), covariance.entry(i, j))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(rows(&entries, n))
    };
    let fixed = design.filters.of("observer.ekf");
    let filter = kalman::filter_code(code, ekf);
    text.push_str(
        &EkfText {
            filter: &filter_type(&EKF, ekf, nx, code.dimensions.outputs)?,
            triangle: kalman::triangle(nx),
            x0: &vector("EKF x0", &ekf.x0)?,
            h: &literal("EKF substep", ekf.h)?,
            p0: &full("EKF P0", &ekf.p0)?,
            q: &full("EKF Q", &ekf.q)?,
            q_constant: &q_constant("EKF", "ekf", &ekf.q, fixed, EKF_Q_TUNED),
            constants: &constants_docs("ekf", fixed, EKF_TUNED),
            r: &vector("EKF R", &ekf.r)?,
            bounds: &bounds_call(&code.bounds)?,
            watch: &match ekf.watch.constants(code.dimensions.outputs) {
                Some(w) => format!(
                    "\n    .with_watch({}, {})",
                    literal("the watch's gain", w.gain)?,
                    literal("the watch's limit", w.limit)?
                ),
                None => String::new(),
            },
            watch_docs: &super::filter::watch_docs(ekf),
        }
        .render()?,
    );
    text.push_str(&filter_observer(&EKF, ekf, fixed, code.dimensions.outputs, "targets")?);
    text.push_str(&samples(&EKF, &filter, code, design)?);
    Ok(text)
}

/// The model's part of the file: its parameters (doc name, name, `f32` and `f64` literals), the
/// equations' doc lines, the straight-line bodies of `Plant`'s functions and of `targets`.
#[derive(Template)]
#[template(path = "model/plant.rs", escape = "none")]
struct ModelText<'a> {
    parameters: Vec<(String, String, String, String)>,
    equations: Vec<String>,
    derivative: &'a str,
    output: &'a str,
    targets: &'a str,
    substeps: usize,
    chip_substeps: usize,
}

/// The EKF's names in its frame.
const EKF: Names = Names {
    name: "Ekf",
    lower: "ekf",
    observer: "EkfBoxObserver",
    what: "The EKF",
    sample: "One sample",
};

/// `.with_bounds(lower, upper)` for the library filter when a state is bounded (`±∞` on an open
/// side), else nothing.
fn bounds_call(bounds: &[crate::spec::Bounds]) -> Result<String, EmitError> {
    if bounds.iter().all(|b| b.min.is_none() && b.max.is_none()) {
        return Ok(String::new());
    }
    let side = |value: Option<f64>, what: &str, infinity: &str| -> Result<String, EmitError> {
        match value {
            Some(v) => literal(what, v),
            None => Ok(format!("T::literal(f32::{infinity}, f64::{infinity})")),
        }
    };
    let lower = bounds
        .iter()
        .enumerate()
        .map(|(i, b)| side(b.min, &format!("state {i}'s lower bound"), "NEG_INFINITY"))
        .collect::<Result<Vec<_>, _>>()?;
    let upper = bounds
        .iter()
        .enumerate()
        .map(|(i, b)| side(b.max, &format!("state {i}'s upper bound"), "INFINITY"))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(format!("\n    .with_bounds({}, {})", list(&lower), list(&upper)))
}

/// `EKF_Q`'s docs when `gen` tuned it.
const EKF_Q_TUNED: &str =
    "/// The EKF's `Q` diagonal as `gen` chose it (f64): each state's process-noise variance per sample
/// period, in its unit squared ([`STATE_UNITS`]).";

/// The EKF's docs on its constants when `gen` tuned them all.
const EKF_TUNED: &str =
    "It starts at the centre of the state box with `P(0)` and `Q` diagonal as chosen by `gen` on the
/// tuning runs, `R` the outputs' noise variances.";

/// The EKF's constants, its filter type (`filter`), `ekf()` and the library filter it writes out
/// (`bounds`: its `.with_bounds(…)`, or nothing).
#[derive(Template)]
#[template(path = "model/ekf.rs", escape = "none")]
struct EkfText<'a> {
    filter: &'a str,
    triangle: usize,
    x0: &'a str,
    h: &'a str,
    p0: &'a str,
    q: &'a str,
    q_constant: &'a str,
    constants: &'a str,
    r: &'a str,
    bounds: &'a str,
    watch: &'a str,
    watch_docs: &'a str,
}
