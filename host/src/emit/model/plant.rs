//! The design's model written out (`parameters`, `Plant`, `targets`, `Discrete`) and, when it has
//! one, its EKF (`Ekf`, `reference_ekf`, and the written-out samples `ekf_measured`/`ekf_unmeasured`):
//! what every model-based observer kind runs on.

use std::fmt::Write;

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
    let mut text = String::new();
    let w = &mut text;
    let spec = |s: &str| crate::emit::doc_code(s);
    if !code.parameters.is_empty() {
        writeln!(
            w,
            "/// The spec's parameters (`[model.parameters]`), each as `(f32, f64)`."
        )
        .ok();
        writeln!(w, "#[allow(non_upper_case_globals)]\npub mod parameters {{").ok();
        for (name, value) in &code.parameters {
            writeln!(w, "    /// `{}`.", spec(name)).ok();
            writeln!(
                w,
                "    pub const {name}: (f32, f64) = ({}, {value:?});",
                f32_literal(&format!("model.parameters.{name}"), *value)?
            )
            .ok();
        }
        writeln!(w, "}}\n").ok();
    }
    writeln!(
        w,
        "/// The spec's model on the chip, written out from its expression trees by `gen`:"
    )
    .ok();
    writeln!(w, "///").ok();
    writeln!(w, "/// ```text").ok();
    for (state, expr) in design.model.states.iter().zip(&design.model.derivatives) {
        writeln!(w, "/// d{}/dt = {}", spec(state), spec(expr.text())).ok();
    }
    for output in &design.model.outputs {
        writeln!(w, "/// {} = {}", spec(&output.name), spec(output.expr.text())).ok();
    }
    for definition in &design.model.definitions {
        writeln!(
            w,
            "/// where {} = {}",
            spec(&definition.name),
            spec(definition.expr.text())
        )
        .ok();
    }
    writeln!(w, "/// ```").ok();
    writeln!(w, "///").ok();
    writeln!(
        w,
        "/// with the Jacobians `∂f/∂x` and `∂h/∂x` (symbolic, shared subexpressions computed once)."
    )
    .ok();
    writeln!(
        w,
        "#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]\npub struct Plant;\n"
    )
    .ok();
    writeln!(
        w,
        "impl<T: Scalar + Maths> firmware::Model<T, STATES, OUTPUTS, INPUTS> for Plant {{"
    )
    .ok();
    writeln!(w, "    #[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "    fn derivative(&self, x: &[T; STATES], u: &[T; INPUTS]) -> ([T; STATES], [[T; STATES]; STATES]) {{"
    )
    .ok();
    w.push_str(&body(&code.derivative, code, design, "        ", |r| {
        format!("({}, {})", list(&r[..nx]), rows(&r[nx..], nx))
    })?);
    writeln!(w, "    }}\n").ok();
    writeln!(w, "    #[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "    fn output(&self, x: &[T; STATES], u: &[T; INPUTS]) -> ([T; OUTPUTS], [[T; STATES]; OUTPUTS]) {{"
    )
    .ok();
    w.push_str(&body(&code.output, code, design, "        ", |r| {
        format!("({}, {})", list(&r[..ny]), rows(&r[ny..], nx))
    })?);
    writeln!(w, "    }}\n}}\n").ok();
    writeln!(
        w,
        "/// The targets at state `x` and input `u`, in [`TARGET_NAMES`] order: what the EKF's estimate"
    )
    .ok();
    writeln!(w, "/// gives for each.").ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "pub fn targets<T: Scalar + Maths>(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {{"
    )
    .ok();
    w.push_str(&body(&code.targets, code, design, "    ", list)?);
    writeln!(w, "}}\n").ok();
    writeln!(
        w,
        "/// RK4 steps per sample in the chip's model (the learning simulation takes {}).",
        design.substeps
    )
    .ok();
    writeln!(w, "pub const CHIP_SUBSTEPS: usize = {};\n", design.chip_substeps).ok();
    writeln!(
        w,
        "/// One sampling period of [`Plant`] by [`CHIP_SUBSTEPS`] RK4 steps, the input held."
    )
    .ok();
    writeln!(w, "pub type Discrete<T> = firmware::Rk4<T, Plant, CHIP_SUBSTEPS>;").ok();
    let Some(ekf) = ekf else {
        return Ok(text);
    };
    writeln!(w).ok();

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
    let fixed = &design.filters.ekf;
    let filter = kalman::filter_code(code, ekf);
    write!(
        w,
        "{}",
        EKF_TEMPLATE
            .replace("{FILTER}", &filter_type(&EKF, ekf, nx)?)
            .replace("{TRIANGLE}", &kalman::triangle(nx).to_string())
            .replace("{X0}", &vector("EKF x0", &ekf.x0)?)
            .replace("{H}", &literal("EKF substep", ekf.h)?)
            .replace("{P0_FULL}", &full("EKF P0", &ekf.p0)?)
            .replace("{Q}", &full("EKF Q", &ekf.q)?)
            .replace("{Q_CONSTANT}", &q_constant("EKF", "ekf", &ekf.q, fixed, EKF_Q_TUNED))
            .replace("{CONSTANTS}", &constants_docs("ekf", fixed, EKF_TUNED))
            .replace("{R}", &vector("EKF R", &ekf.r)?)
            .replace("{BOUNDS}", &bounds_call(&code.bounds)?)
    )
    .ok();
    w.push_str(&filter_observer(&EKF, ekf, fixed)?);
    w.push_str(&samples(&EKF, &filter, code, design)?);
    Ok(text)
}

/// The EKF's names in its frame.
const EKF: Names = Names {
    name: "Ekf",
    lower: "ekf",
    observer: "BoxEkfObserver",
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

const EKF_TEMPLATE: &str = r#"
/// Entries of the EKF's covariance kept: its upper triangle, row by row (it is symmetric).
pub const COVARIANCE: usize = {TRIANGLE};

{Q_CONSTANT}

/// This design's extended Kalman filter, written out for its size by `gen`: the library's
/// [`firmware::Ekf`] over [`Discrete`] ([`reference_ekf`], same constants), with each sample as
/// straight-line code (no loop, no structural zero or one multiplied, `P` as its upper triangle).
/// {CONSTANTS}
///
/// Each sample: every output's scalar update in Joseph form, then the prediction over one sampling
/// period. A sample with a non-finite `y` is refused and only predicted; one with a non-finite `u`
/// changes nothing; a sample whose result is not finite (the model overflowed) is not taken.
{FILTER}/// Whether every entry of a filter's state and covariance is finite.
fn finite<T: Scalar>(x: &[T; STATES], p: &[T; COVARIANCE]) -> bool {
    x.iter().chain(p).all(|v| v.is_finite())
}

/// A fresh EKF in `f32`, as the chip runs it.
pub fn ekf() -> Ekf {
    Ekf::new()
}

/// The library filter this design's [`Ekf`] writes out, with the same constants: what the tests
/// check the written-out one against.
pub fn reference_ekf<T: Scalar + Maths>() -> firmware::Ekf<T, Discrete<T>, STATES, OUTPUTS, INPUTS> {
    firmware::Ekf::new(
        firmware::Rk4::new(Plant, {H}),
        {X0},
        {P0_FULL},
        {Q},
        {R},
    ){BOUNDS}
}
"#;
