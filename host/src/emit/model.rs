//! The model of a design written out as Rust: one `let` per operation of its straight-line programs
//! ([`crate::plant::Program`]), in their order, generic over the firmware's [`firmware::Scalar`] so
//! that the chip runs it in `f32` and the host's tests in `f64`; and the design's EKF over it.
//!
//! Every number is written once for both precisions (`T::literal(f32, f64)`, each rounded here), every
//! function is the firmware's `Maths::…` (libm), every name a local of the spec's name with a prefix
//! (`x_` states, `u_` inputs; parameters are constants of module `parameters`), so nothing of the
//! spec's text is pasted into code.

use std::fmt::Write;

use crate::emit::{f32_literal, EmitError};
use crate::observers::restart::RestartConstants;
use crate::plant::correction::{self, CorrectionConstants};
use crate::plant::kalman::{self, EkfConstants};
use crate::plant::program::Leaf;
use crate::plant::{ModelCode, Op, Program};
use crate::spec::ast::Binary;
use crate::spec::{Design, ObserverKind};

/// `T::literal(single, double)` for `value`, the `f32` checked as [`f32_literal`] checks it.
fn literal(what: &str, value: f64) -> Result<String, EmitError> {
    Ok(format!("T::literal({}, {value:?})", f32_literal(what, value)?))
}

/// The right-hand side of operation `op`.
fn operation(op: &Op, code: &ModelCode, names: &Names<'_>) -> Result<String, EmitError> {
    Ok(match *op {
        Op::Number(v) => literal("a number of the model", v)?,
        Op::Leaf(Leaf::Parameter(i)) => {
            format!("T::literal(parameters::{0}.0, parameters::{0}.1)", code.parameters[i].0)
        }
        Op::Leaf(Leaf::State(i)) => format!("x[{i}]"),
        Op::Leaf(Leaf::Input(i)) => format!("u[{i}]"),
        Op::Leaf(Leaf::Covariance(k)) => format!("p[{k}]"),
        Op::Leaf(Leaf::Measurement(i)) => format!("y[{i}]"),
        Op::Leaf(Leaf::Map(i)) => format!("f[{i}]"),
        // Read from the start-up table where used: no copy of the row.
        Op::Leaf(Leaf::Blend(i)) => format!("T::literal(g[{i}].0, g[{i}].1)"),
        Op::Negate(a) => format!("-{}", names.of(a)),
        Op::Binary(b, x, y) => {
            let (x, y) = (names.of(x), names.of(y));
            match b {
                Binary::Add => format!("{x} + {y}"),
                Binary::Sub => format!("{x} - {y}"),
                Binary::Mul => format!("{x} * {y}"),
                Binary::Div => format!("{x} / {y}"),
                Binary::Pow => format!("Maths::powf({x}, {y})"),
                Binary::Atan2 => format!("Maths::atan2({x}, {y})"),
                Binary::Min => format!("Maths::min({x}, {y})"),
                Binary::Max => format!("Maths::max({x}, {y})"),
            }
        }
        Op::Call(f, a) => format!("Maths::{f}({})", names.of(a)),
        Op::AtLeast(a, b) => format!("firmware::bounds::at_least({}, {})", names.of(a), names.of(b)),
        Op::AtMost(a, b) => format!("firmware::bounds::at_most({}, {})", names.of(a), names.of(b)),
    })
}

/// The local each operation is bound to: `x_<state>`, `u_<input>`, `p_<parameter>`, or `t<index>`.
struct Names<'a> {
    program: &'a Program,
    design: &'a Design,
}

impl Names<'_> {
    fn of(&self, op: usize) -> String {
        let model = &self.design.model;
        match self.program.ops[op] {
            Op::Leaf(Leaf::State(i)) => format!("x_{}", model.states[i]),
            Op::Leaf(Leaf::Input(i)) => format!("u_{}", model.inputs[i]),
            Op::Leaf(Leaf::Parameter(i)) => format!("p_{}", model.parameters[i].0),
            Op::Leaf(Leaf::Covariance(k)) => format!("cov{k}"),
            Op::Leaf(Leaf::Measurement(i)) => format!("y_{}", model.outputs[i].name),
            Op::Leaf(Leaf::Map(i)) => format!("f_{}", model.states[i]),
            Op::Leaf(Leaf::Blend(i)) if i < model.states.len() => format!("g_{}", model.states[i]),
            Op::Leaf(Leaf::Blend(i)) => format!("k{}", i - model.states.len()),
            _ => format!("t{op}"),
        }
    }
}

/// The body of a function computing `program`: its `let`s, then `result` (the results by name).
fn body(
    program: &Program,
    code: &ModelCode,
    design: &Design,
    indent: &str,
    result: impl Fn(&[String]) -> String,
) -> Result<String, EmitError> {
    let names = Names { program, design };
    let mut text = String::new();
    for (i, op) in program.ops.iter().enumerate() {
        writeln!(
            text,
            "{indent}let {}: T = {};",
            names.of(i),
            operation(op, code, &names)?
        )
        .expect("write to a String");
    }
    let results: Vec<String> = program.results.iter().map(|&r| names.of(r)).collect();
    writeln!(text, "{indent}{}", result(&results)).expect("write to a String");
    Ok(text)
}

/// `[a, b, …]`.
fn list(items: &[String]) -> String {
    format!("[{}]", items.join(", "))
}

/// `[a, b, …]` of `values` as `f32` literals (each checked as [`f32_literal`] checks it, named
/// `what[i]`).
fn f32_list(what: &str, values: &[f64]) -> Result<String, EmitError> {
    let entries = values
        .iter()
        .enumerate()
        .map(|(i, v)| f32_literal(&format!("{what}[{i}]"), *v))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(list(&entries))
}

/// `[[…], …]`: `items` in rows of `width`.
fn rows(items: &[String], width: usize) -> String {
    if width == 0 {
        return format!("[[]; {}]", items.len());
    }
    list(&items.chunks(width).map(list).collect::<Vec<_>>())
}

/// The observers a design file carries besides its map, and which one `observer()` is.
#[derive(Clone, Copy, Debug)]
pub struct Observers<'a> {
    /// The EKF's constants (the peer, and the map-started EKF).
    pub ekf: Option<&'a EkfConstants>,
    /// The EKF started by the map: its `P(N−1)` diagonal and each state's target.
    pub started: Option<(&'a [f64], &'a [usize])>,
    /// The box-started EKF's check against the map (with `ekf` and `started`).
    pub restart: Option<&'a RestartConstants>,
    /// The model-corrected map's constants and each state's target.
    pub corrected: Option<(&'a CorrectionConstants, &'a [usize])>,
    /// `observer()`'s kind: `Map`, `Corrected` or `Ekf` (never `Auto`: chosen before).
    pub kind: ObserverKind,
    /// Every observer kind the design has and its predicted instructions per steady sample
    /// ([`crate::search::cost`]), in the report's order.
    pub instructions: &'a [(&'static str, f64)],
    /// SHA-256 of the tables saved with this file ([`crate::tables::Tables::content_sha256`]).
    pub tables_sha256: &'a str,
}

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

/// The Rust source of the design's model (`parameters`, `Plant`, `targets`), its EKF (`ekf`), its
/// model-based followers of the map, and `Observer` / `observer()` of the chosen kind.
pub fn model_source(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<String, EmitError> {
    let mut text = model_and_ekf(design, code, observers.ekf)?;
    if let Some((constants, state_targets)) = observers.corrected {
        text.push_str(&corrector(design, code, constants, state_targets)?);
    }
    if let (Some(_), Some((p0, state_targets))) = (observers.ekf, observers.started) {
        let upper = kalman::diagonal_upper(p0);
        let entries = upper
            .iter()
            .enumerate()
            .map(|(i, v)| literal(&format!("map-started EKF P0[{i}]"), *v))
            .collect::<Result<Vec<_>, _>>()?;
        text.push_str(
            &STARTED_EKF_TEMPLATE
                .replace("{P0}", &list(&entries))
                .replace("{P0_F64}", &format!("{p0:?}"))
                .replace("{STATE_TARGETS}", &format!("{state_targets:?}")),
        );
    }
    if let (Some(ekf), Some(_), Some(restart)) = (observers.ekf, observers.started, observers.restart) {
        text.push_str(&restarted(ekf, restart)?);
    }
    let (ty, what) = match observers.kind {
        ObserverKind::Corrected => ("CorrectedObserver", "the model-corrected map ([`CorrectedObserver`])"),
        ObserverKind::EkfMap => (
            "StartedEkfObserver",
            "the EKF started by the map ([`StartedEkfObserver`])",
        ),
        ObserverKind::EkfBox => (
            "BoxEkfObserver",
            "the EKF from the centre of the state box ([`BoxEkfObserver`])",
        ),
        ObserverKind::EkfRestart => (
            "RestartedEkfObserver",
            "the EKF from the centre of the state box, restarted by the map ([`RestartedEkfObserver`])",
        ),
        ObserverKind::Map | ObserverKind::Auto => ("MapObserver", "the map alone ([`MapObserver`])"),
    };
    let kind = match observers.kind {
        ObserverKind::Auto => "map",
        other => other.name(),
    };
    write!(
        text,
        "
/// The kind of [`Observer`] (`[observer] kind` of the spec, or `gen`'s choice for `auto`).
pub const KIND: &str = \"{kind}\";

/// This design's observer: {what}.
pub type Observer = {ty};

/// A fresh [`Observer`], holding no sample yet.
pub const fn observer() -> Observer {{
    {ty}::new()
}}

/// SHA-256 of the tables `gen` saved with this file (`design.json`'s `tables_sha256`): `estimate`
/// uses saved tables only beside the observer file written with them.
pub const TABLES_SHA256: &str = \"{tables}\";
",
        tables = observers.tables_sha256
    )
    .ok();
    Ok(text)
}

/// The box-started EKF checked by the map: `StartedEkf`'s `firmware::Restart` in `f32` and `f64`,
/// the check, and `RestartedEkfObserver`.
fn restarted(ekf: &EkfConstants, restart: &RestartConstants) -> Result<String, EmitError> {
    let nx = ekf.x0.len();
    let upper = kalman::diagonal_upper(&ekf.p0);
    let f64_list = |values: &[f64]| format!("{values:?}");
    let variances = restart
        .variances
        .iter()
        .enumerate()
        .map(|(i, v)| literal(&format!("restart variance {i}"), *v))
        .collect::<Result<Vec<_>, _>>()?;
    let diagonal: Vec<usize> = (0..nx).map(|i| kalman::upper(nx, i, i)).collect();
    Ok(RESTARTED_TEMPLATE
        .replace("{THRESHOLD_F64}", &format!("{:?}", restart.threshold))
        .replace("{THRESHOLD}", &literal("restart threshold", restart.threshold)?)
        .replace("{VARIANCES_F64}", &f64_list(&restart.variances))
        .replace("{VARIANCES}", &list(&variances))
        .replace("{DIAGONAL}", &format!("{diagonal:?}"))
        .replace("{X0_F32}", &f32_list("EKF x0", &ekf.x0)?)
        .replace("{P0_F32}", &f32_list("EKF P0", &upper)?)
        .replace("{X0_F64}", &f64_list(&ekf.x0))
        .replace("{P0_F64}", &f64_list(&upper)))
}

/// The restarted EKF (`{…}` filled in by [`restarted`]).
const RESTARTED_TEMPLATE: &str = r#"
/// The check of [`RestartedEkfObserver`] as `gen` chose it on the tuning runs (f64): the threshold `τ`
/// (no unit).
pub const RESTART_THRESHOLD: f64 = {THRESHOLD_F64};
/// See [`RESTART_THRESHOLD`]: each state's `e_i²`, the map's mean squared error on the tuning runs,
/// in its unit squared ([`STATE_UNITS`]).
pub const RESTART_VARIANCES: [f64; STATES] = {VARIANCES_F64};

/// Whether the filter's prediction `x` with covariance `p` and the map's states `f` disagree:
/// `d = Σ_i (x_i − f_i)² / (P_ii + e_i²) > τ`, or `d` is NaN. Runs once, at the map's first estimate.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
#[inline(always)]
fn restart_disagrees<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], f: &[T; STATES]) -> bool {
    const DIAGONAL: [usize; STATES] = {DIAGONAL};
    let variances: [T; STATES] = {VARIANCES};
    let mut d = T::ZERO;
    for i in 0..STATES {
        let e = x[i] - f[i];
        d += e * e / (p[DIAGONAL[i]] + variances[i]);
    }
    !(d <= {THRESHOLD})
}

impl firmware::Restart<f32, STATES, OUTPUTS, INPUTS, TARGETS> for StartedEkf {
    const FRESH: ([f32; STATES], [f32; COVARIANCE]) = ({X0_F32}, {P0_F32});

    #[inline(always)]
    fn disagrees(carried: &([f32; STATES], [f32; COVARIANCE]), map: &[f32; STATES]) -> bool {
        restart_disagrees(&carried.0, &carried.1, map)
    }
}

impl firmware::Restart<f64, STATES, OUTPUTS, INPUTS, TARGETS> for StartedEkf {
    const FRESH: ([f64; STATES], [f64; COVARIANCE]) = ({X0_F64}, {P0_F64});

    #[inline(always)]
    fn disagrees(carried: &([f64; STATES], [f64; COVARIANCE]), map: &[f64; STATES]) -> bool {
        restart_disagrees(&carried.0, &carried.1, map)
    }
}

/// The EKF from the centre of the state box ([`Ekf`]'s start and samples) that checks the map once,
/// at its first estimate, and restarts from it as [`StartedEkfObserver`] starts when the two disagree
/// (`d > τ`, [`RESTART_THRESHOLD`]): an estimate from the first sample, the map's guess-free start where the
/// box centre is far from the plant.
pub type RestartedEkfObserver = firmware::Restarted<f32, Design, StartedEkf, HORIZON, OUTPUTS, INPUTS, TARGETS, STATES>;
"#;

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
    let mut text = CORRECTED_TEMPLATE
        .replace("{START_UP}", &constants.start_up.to_string())
        .replace("{READS}", &programs.steady_reads_map.to_string())
        .replace("{STATE_TARGETS}", &format!("{state_targets:?}"))
        .replace("{BLENDS}", &blends.join("\n"))
        .replace("{LOWER}", &pairs("corrected lower", &constants.lower)?)
        .replace("{UPPER}", &pairs("corrected upper", &constants.upper)?)
        .replace("{G}", &format!("{:?}", constants.g))
        .replace("{K}", &format!("{:?}", constants.k))
        .replace("{K0}", &format!("{:?}", constants.k_start))
        .replace("{T}", &format!("{:?}", constants.schedule))
        .replace("{LOWER_F64}", &format!("{:?}", constants.lower))
        .replace("{UPPER_F64}", &format!("{:?}", constants.upper));
    let w = &mut text;
    writeln!(
        w,
        "\n/// One sampling period of the model from `x`, the value alone: `x⁺`, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "fn corrected_predict<T: Scalar + Maths>(x: &[T; STATES], u: &[T; INPUTS]) -> [T; STATES] {{"
    )
    .ok();
    w.push_str(&body(&programs.predict, code, design, "    ", list)?);
    writeln!(w, "}}\n").ok();
    writeln!(
        w,
        "/// The correction during the start-up, `g` = (blend `g_j`, gain `K_j`) given: `x̂` before its clamp, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "fn corrected_start_up<T: Scalar + Maths>(x: &[T; STATES], y: &[T; OUTPUTS], u: &[T; INPUTS], f: &[T; STATES], g: &[(f32, f64); SCHEDULED]) -> [T; STATES] {{"
    )
    .ok();
    w.push_str(&body(&programs.start_up, code, design, "    ", list)?);
    writeln!(w, "}}\n").ok();
    writeln!(
        w,
        "/// The correction after the start-up (`G` as numbers): `x̂` before its clamp, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "fn corrected_steady<T: Scalar + Maths>(x: &[T; STATES], y: &[T; OUTPUTS], u: &[T; INPUTS], f: &[T; STATES]) -> [T; STATES] {{"
    )
    .ok();
    w.push_str(&body(&programs.steady, code, design, "    ", list)?);
    writeln!(w, "}}").ok();
    Ok(text)
}

/// The model-corrected map around its written-out programs (`{…}` filled in by [`corrector`]).
const CORRECTED_TEMPLATE: &str = r#"
/// The model-corrected map's constants as `gen` chose them (f64): `G` (no unit), `K` (states ×
/// outputs, row by row, in state unit per output unit), the schedule `T` (in samples), and each
/// state's clamp (in its unit); units in [`STATE_UNITS`] and [`OUTPUT_UNITS`].
pub const CORRECTED_G: [f64; STATES] = {G};
/// See [`CORRECTED_G`].
pub const CORRECTED_K: [f64; STATES * OUTPUTS] = {K};
/// See [`CORRECTED_G`]: the start-up gain `K₀`.
pub const CORRECTED_K_START: [f64; STATES * OUTPUTS] = {K0};
/// See [`CORRECTED_G`].
pub const CORRECTED_SCHEDULE: f64 = {T};
/// See [`CORRECTED_G`].
pub const CORRECTED_LOWER: [f64; STATES] = {LOWER_F64};
/// See [`CORRECTED_G`].
pub const CORRECTED_UPPER: [f64; STATES] = {UPPER_F64};

/// Entries of one row of [`CORRECTED_BLENDS`]: a blend per state, then the gain.
const SCHEDULED: usize = STATES + STATES * OUTPUTS;

/// The model-corrected map's start-up schedule, `j = 1 … J`: the blends
/// `g_j = G + (1 − G) / (1 + j / T)` per state, then the gains `K_j = K + (K₀ − K) / (1 + j / T)`
/// (states × outputs, row by row), each as `(f32, f64)`.
#[rustfmt::skip]
static CORRECTED_BLENDS: [[(f32, f64); SCHEDULED]; {START_UP}] = [
{BLENDS}
];

/// The model-corrected map on the chip: `x̂(N−1) = F(Z)`, then
/// `x̂ = clamp(x̄ + g_j ⊙ (F(Z) − x̄) + K_j (y − h(x̄, u)))` with `x̄` the model's prediction, as chosen
/// by `gen` on the tuning runs: `G = {G}`, `K = {K}`, `K₀ = {K0}` (states × outputs, row by row),
/// `T = {T}`, `J = {START_UP}`. The clamp is each state's learning range.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Corrector;

impl<T: Scalar + Maths> firmware::Follower<T, STATES, OUTPUTS, INPUTS, TARGETS> for Corrector {
    type Carried = [T; STATES];
    const START_UP: usize = {START_UP};
    const STEADY_READS_MAP: bool = {READS};
    const STATE_TARGETS: [usize; STATES] = {STATE_TARGETS};

    #[inline(always)]
    fn start(first: &[T; STATES], u: &[T; INPUTS]) -> Option<[T; STATES]> {
        let next = corrected_predict(first, u);
        next.iter().all(|v| v.is_finite()).then_some(next)
    }

    #[inline(always)]
    fn follow(
        x: &[T; STATES],
        j: usize,
        start_up: bool,
        f: &[T; STATES],
        y: &[T; OUTPUTS],
        u: &[T; INPUTS],
    ) -> Option<([T; STATES], [Estimate<T>; STATES])> {
        // Loops rather than `array::map`, which the compiler turns into copies at `opt-level = "s"`.
        fn pick<T: Scalar, const M: usize>(pairs: &[(f32, f64); M]) -> [T; M] {
            let mut out = [T::ZERO; M];
            for (out, &(single, double)) in out.iter_mut().zip(pairs) {
                *out = T::literal(single, double);
            }
            out
        }
        let raw = if start_up {
            let row = CORRECTED_BLENDS.get(j.wrapping_sub(1)).unwrap_or(&[(0.0, 0.0); SCHEDULED]);
            corrected_start_up(x, y, u, f, row)
        } else {
            corrected_steady(x, y, u, f)
        };
        let states = firmware::started::clamp(&raw, &pick(&{LOWER}), &pick(&{UPPER}));
        let mut estimate = [T::ZERO; STATES];
        for (e, s) in estimate.iter_mut().zip(&states) {
            *e = s.value;
        }
        let next = corrected_predict(&estimate, u);
        next.iter().all(|v| v.is_finite()).then_some((next, states))
    }

    /// A lost output: the model's period from `x̄` (no correction; the next estimate is clamped).
    #[inline(always)]
    fn predict(x: &[T; STATES], u: &[T; INPUTS]) -> Option<[T; STATES]> {
        let next = corrected_predict(x, u);
        next.iter().all(|v| v.is_finite()).then_some(next)
    }

    #[inline(always)]
    fn targets(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {
        targets(x, u)
    }
}

/// The model-corrected map over this design's map.
pub type CorrectedObserver = firmware::Started<f32, Design, Corrector, HORIZON, OUTPUTS, INPUTS, TARGETS, STATES>;
"#;

/// The EKF started by the map (`{…}` filled in by [`model_source`]).
const STARTED_EKF_TEMPLATE: &str = r#"
/// `P(N−1)` diagonal of [`StartedEkf`] (f64), as `gen` chose it, in each state's unit squared
/// ([`STATE_UNITS`]).
pub const STARTED_P0: [f64; STATES] = {P0_F64};

/// The EKF started at the map's first estimate `x̂(N−1) = F(Z)` with `P(N−1)` diagonal, each variance
/// the map's mean squared error on the tuning runs, then [`Ekf`]'s samples (same `Q` and `R`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StartedEkf;

impl<T: Scalar + Maths> firmware::Follower<T, STATES, OUTPUTS, INPUTS, TARGETS> for StartedEkf {
    type Carried = ([T; STATES], [T; COVARIANCE]);
    const START_UP: usize = 0;
    const STEADY_READS_MAP: bool = false;
    const STATE_TARGETS: [usize; STATES] = {STATE_TARGETS};

    #[inline(always)]
    fn start(first: &[T; STATES], u: &[T; INPUTS]) -> Option<([T; STATES], [T; COVARIANCE])> {
        let (x, p) = ekf_unmeasured(first, &{P0}, u);
        finite(&x, &p).then_some((x, p))
    }

    #[inline(always)]
    fn follow(
        carried: &([T; STATES], [T; COVARIANCE]),
        _: usize,
        _: bool,
        _: &[T; STATES],
        y: &[T; OUTPUTS],
        u: &[T; INPUTS],
    ) -> Option<(([T; STATES], [T; COVARIANCE]), [Estimate<T>; STATES])> {
        let (estimate, x, p) = ekf_measured(&carried.0, &carried.1, y, u);
        let mut inside = [Estimate { value: T::ZERO, saturation: firmware::Saturation::Inside }; STATES];
        for (e, &value) in inside.iter_mut().zip(&estimate) {
            e.value = value;
        }
        finite(&x, &p).then_some(((x, p), inside))
    }

    /// A lost output: the filter's prediction alone, as [`Ekf::push`] runs it.
    #[inline(always)]
    fn predict(carried: &([T; STATES], [T; COVARIANCE]), u: &[T; INPUTS]) -> Option<([T; STATES], [T; COVARIANCE])> {
        let (x, p) = ekf_unmeasured(&carried.0, &carried.1, u);
        finite(&x, &p).then_some((x, p))
    }

    #[inline(always)]
    fn targets(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {
        targets(x, u)
    }
}

/// The EKF started by this design's map.
pub type StartedEkfObserver = firmware::Started<f32, Design, StartedEkf, HORIZON, OUTPUTS, INPUTS, TARGETS, STATES>;
"#;

/// The model and the EKF.
fn model_and_ekf(design: &Design, code: &ModelCode, ekf: Option<&EkfConstants>) -> Result<String, EmitError> {
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

    let diagonal = |what: &str, values: &[f64]| -> Result<String, EmitError> {
        let n = values.len();
        let entries = (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                literal(&format!("{what}[{i}][{j}]"), if i == j { values[i] } else { 0.0 })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(rows(&entries, n))
    };
    let vector = |what: &str, values: &[f64]| -> Result<String, EmitError> {
        let entries = values
            .iter()
            .enumerate()
            .map(|(i, v)| literal(&format!("{what}[{i}]"), *v))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(list(&entries))
    };
    let filter = kalman::filter_code(code, ekf);
    let triangle = kalman::triangle(nx);
    let upper = kalman::diagonal_upper(&ekf.p0);
    let full: Vec<String> = (0..nx * nx)
        .map(|k| format!("self.p[{}]", kalman::upper(nx, k / nx, k % nx)))
        .collect();
    write!(
        w,
        "{}",
        EKF_TEMPLATE
            .replace("{TRIANGLE}", &triangle.to_string())
            .replace("{X0}", &vector("EKF x0", &ekf.x0)?)
            .replace("{P0}", &vector("EKF P0", &upper)?)
            .replace("{COVARIANCE}", &rows(&full, nx))
            .replace("{H}", &literal("EKF substep", ekf.h)?)
            .replace("{P0_FULL}", &diagonal("EKF P0", &ekf.p0)?)
            .replace("{Q}", &diagonal("EKF Q", &ekf.q)?)
            .replace("{Q_F64}", &format!("{:?}", ekf.q))
            .replace("{R}", &vector("EKF R", &ekf.r)?)
            .replace("{BOUNDS}", &bounds_call(&code.bounds)?)
    )
    .ok();
    write!(
        w,
        "{}",
        BOX_EKF_TEMPLATE
            .replace("{X0_F32}", &f32_list("EKF x0", &ekf.x0)?)
            .replace("{P0_F32}", &f32_list("EKF P0", &upper)?)
    )
    .ok();
    writeln!(
        w,
        "\n/// One sample with its measurement: `(x̂(k|k), x⁺, P⁺)` from `(x, P)`, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case, clippy::type_complexity)]").ok();
    writeln!(
        w,
        "fn ekf_measured<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], y: &[T; OUTPUTS], u: &[T; INPUTS]) -> ([T; STATES], [T; STATES], [T; COVARIANCE]) {{"
    )
    .ok();
    w.push_str(&body(&filter.measured, code, design, "    ", |r| {
        format!("({}, {}, {})", list(&r[..nx]), list(&r[nx..2 * nx]), list(&r[2 * nx..]))
    })?);
    writeln!(w, "}}\n").ok();
    writeln!(
        w,
        "/// One sample without its measurement (refused): `(x⁺, P⁺)` from `(x, P)`, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case)]").ok();
    writeln!(
        w,
        "fn ekf_unmeasured<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], u: &[T; INPUTS]) -> ([T; STATES], [T; COVARIANCE]) {{"
    )
    .ok();
    w.push_str(&body(&filter.unmeasured, code, design, "    ", |r| {
        format!("({}, {})", list(&r[..nx]), list(&r[nx..]))
    })?);
    writeln!(w, "}}").ok();
    Ok(text)
}

/// The design's filter type around its written-out sample (`{…}` filled in by [`model_source`]).
/// [`Ekf`] as an observer with the map's interface (`{…}` filled in by [`model_and_ekf`]).
const BOX_EKF_TEMPLATE: &str = r#"
/// The EKF from the centre of the state box ([`Ekf`], the same filter and constants) with the
/// observers' interface: `push` takes a sample, `estimate` gives the targets of the latest accepted
/// one (each `Inside`: the filter does not saturate), `reset` starts again. It has an estimate from
/// the first accepted sample on; a refused sample keeps the previous one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxEkfObserver {
    filter: Ekf<f32>,
    latest: Option<[Estimate<f32>; TARGETS]>,
}

impl Default for BoxEkfObserver {
    fn default() -> Self {
        Self::new()
    }
}

impl BoxEkfObserver {
    /// A fresh observer (the filter at its start), holding no sample yet.
    pub const fn new() -> Self {
        BoxEkfObserver {
            filter: Ekf { x: {X0_F32}, p: {P0_F32} },
            latest: None,
        }
    }

    /// Takes the sample `(y, u)`: [`Ekf::push`], then the targets of its estimate `x̂(k|k)`.
    pub fn push(&mut self, y: [f32; OUTPUTS], u: [f32; INPUTS]) -> Result<(), firmware::RejectedSample> {
        let x = self.filter.push(&y, &u)?;
        let values = targets(&x, &u);
        let mut latest = [Estimate { value: 0.0, saturation: firmware::Saturation::Inside }; TARGETS];
        for (e, value) in latest.iter_mut().zip(values) {
            e.value = value;
        }
        self.latest = Some(latest);
        Ok(())
    }

    /// The targets of the latest accepted sample; `None` before the first.
    pub fn estimate(&self) -> Option<[Estimate<f32>; TARGETS]> {
        self.latest
    }

    /// Back to the start: the filter at the box centre, no estimate.
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// Whether it has an estimate.
    pub fn is_ready(&self) -> bool {
        self.latest.is_some()
    }
}
"#;

const EKF_TEMPLATE: &str = r#"
/// Entries of the EKF's covariance kept: its upper triangle, row by row (it is symmetric).
pub const COVARIANCE: usize = {TRIANGLE};

/// The EKF's `Q` diagonal as `gen` chose it (f64): each state's process-noise variance per sample
/// period, in its unit squared ([`STATE_UNITS`]).
pub const EKF_Q: [f64; STATES] = {Q_F64};

/// This design's extended Kalman filter, written out for its size by `gen`: the library's
/// [`firmware::Ekf`] over [`Discrete`] ([`reference_ekf`], same constants), with each sample as
/// straight-line code (no loop, no structural zero or one multiplied, `P` as its upper triangle).
/// It starts at the centre of the state box with `P(0)` and `Q` diagonal as chosen by `gen` on the
/// tuning runs, `R` the outputs' noise variances.
///
/// Each sample: every output's scalar update in Joseph form, then the prediction over one sampling
/// period. A sample with a non-finite `y` is refused and only predicted; one with a non-finite `u`
/// changes nothing; a sample whose result is not finite (the model overflowed) is not taken.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ekf<T = f32> {
    /// `x̂`: after a sample, the prediction to the next one.
    x: [T; STATES],
    /// The upper triangle of `P`.
    p: [T; COVARIANCE],
}

impl<T: Scalar + Maths> Default for Ekf<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Scalar + Maths> Ekf<T> {
    /// A fresh filter.
    pub fn new() -> Self {
        Ekf {
            x: {X0},
            p: {P0},
        }
    }

    /// The current estimate (after a sample, the prediction to the next one).
    pub fn state(&self) -> [T; STATES] {
        self.x
    }

    /// The current covariance `P`.
    pub fn covariance(&self) -> [[T; STATES]; STATES] {
        {COVARIANCE}
    }

    /// Takes the sample `(y, u)`; returns the estimate given it, `x̂(k|k)`, or refuses it (see the
    /// type's docs). The same operations run for every accepted sample.
    pub fn push(&mut self, y: &[T; OUTPUTS], u: &[T; INPUTS]) -> Result<[T; STATES], firmware::RejectedSample> {
        if !u.iter().all(|v| v.is_finite()) {
            return Err(firmware::RejectedSample);
        }
        if y.iter().all(|v| v.is_finite()) {
            let (estimate, x, p) = ekf_measured(&self.x, &self.p, y, u);
            if finite(&x, &p) {
                (self.x, self.p) = (x, p);
                return Ok(estimate);
            }
        } else {
            let (x, p) = ekf_unmeasured(&self.x, &self.p, u);
            if finite(&x, &p) {
                (self.x, self.p) = (x, p);
            }
        }
        Err(firmware::RejectedSample)
    }
}

/// Whether every entry of a filter's state and covariance is finite.
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
