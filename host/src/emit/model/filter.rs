//! A Kalman filter's frame on the chip, the same for the EKF (`Ekf`, [`super::plant`]) and the UKF
//! (`Ukf`, [`super::ukf`]): the filter type around its two written-out samples (`<lower>_measured`,
//! `<lower>_unmeasured`: `push`, the refusals, `P` as its upper triangle), and the filter from the
//! centre of the state box as an observer (`BoxEkfObserver`, `UkfObserver`: the runtime's
//! `firmware::FilterObserver` over the filter, which implements `firmware::emitted::Filter`).

use std::fmt::Write;

use super::rust_text::{body, f32_list, list, literal, rows};
use crate::emit::EmitError;
use crate::plant::kalman::{self, EkfConstants, FilterCode};
use crate::plant::{Covariance, ModelCode};
use crate::spec::{Design, FixedFilter};

/// One filter's names: its type (`Ekf`), its samples' prefix (`ekf`), its observer type
/// (`BoxEkfObserver`) and what filter that observer is ("The EKF"; its docs add where it starts).
pub(super) struct Names {
    pub(super) name: &'static str,
    pub(super) lower: &'static str,
    pub(super) observer: &'static str,
    pub(super) what: &'static str,
    /// How its samples' docs begin ("One sample").
    pub(super) sample: &'static str,
}

/// The filter type `names.name` with its constants' start (`{X0}`, `{P0}`: `T` literals).
pub(super) fn filter_type(names: &Names, constants: &EkfConstants, nx: usize) -> Result<String, EmitError> {
    let upper = constants.p0.upper();
    let full: Vec<String> = (0..nx * nx)
        .map(|k| format!("self.p[{}]", kalman::upper(nx, k / nx, k % nx)))
        .collect();
    let label = names.name.to_uppercase();
    Ok(FILTER_TEMPLATE
        .replace("{NAME}", names.name)
        .replace("{LOWER}", names.lower)
        .replace("{X0}", &vector(&format!("{label} x0"), &constants.x0)?)
        .replace("{P0}", &vector(&format!("{label} P0"), &upper)?)
        .replace("{COVARIANCE}", &rows(&full, nx)))
}

/// The observer around the filter (`names.observer`), started where the filter starts (`fixed`: the
/// spec's constants of this filter).
pub(super) fn filter_observer(
    names: &Names,
    constants: &EkfConstants,
    fixed: &FixedFilter,
) -> Result<String, EmitError> {
    let label = names.name.to_uppercase();
    let upper = constants.p0.upper();
    let start = match fixed.x0 {
        Some(_) => "the start the spec fixes",
        None => "the centre of the state box",
    };
    let what = format!("{} from {start}", names.what);
    Ok(OBSERVER_TEMPLATE
        .replace("{WHAT}", &what)
        .replace("{NAME}", names.name)
        .replace("{LOWER}", names.lower)
        .replace("{OBSERVER}", names.observer)
        .replace("{X0_F32}", &f32_list(&format!("{label} x0"), &constants.x0)?)
        .replace("{P0_F32}", &f32_list(&format!("{label} P0"), &upper)?))
}

/// The filter's two samples written out from its programs: `<lower>_measured` and `<lower>_unmeasured`.
pub(super) fn samples(
    names: &Names,
    filter: &FilterCode,
    code: &ModelCode,
    design: &Design,
) -> Result<String, EmitError> {
    let nx = code.dimensions.states;
    let (lower, sample) = (names.lower, names.sample);
    let mut text = String::new();
    let w = &mut text;
    writeln!(
        w,
        "\n/// {sample} with its measurement: `(x̂(k|k), x⁺, P⁺)` from `(x, P)`, written out by `gen`."
    )
    .ok();
    // A sigma point's spread √n may be a number clippy reads as a constant (√2).
    writeln!(
        w,
        "#[allow(unused_variables, non_snake_case, clippy::type_complexity, clippy::approx_constant)]"
    )
    .ok();
    writeln!(
        w,
        "fn {lower}_measured<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], y: &[T; OUTPUTS], u: &[T; INPUTS]) -> ([T; STATES], [T; STATES], [T; COVARIANCE]) {{"
    )
    .ok();
    w.push_str(&body(&filter.measured, code, design, "    ", |r| {
        format!("({}, {}, {})", list(&r[..nx]), list(&r[nx..2 * nx]), list(&r[2 * nx..]))
    })?);
    writeln!(w, "}}\n").ok();
    writeln!(
        w,
        "/// {sample} without its measurement (refused): `(x⁺, P⁺)` from `(x, P)`, written out by `gen`."
    )
    .ok();
    writeln!(w, "#[allow(unused_variables, non_snake_case, clippy::approx_constant)]").ok();
    writeln!(
        w,
        "fn {lower}_unmeasured<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], u: &[T; INPUTS]) -> ([T; STATES], [T; COVARIANCE]) {{"
    )
    .ok();
    w.push_str(&body(&filter.unmeasured, code, design, "    ", |r| {
        format!("({}, {})", list(&r[..nx]), list(&r[nx..]))
    })?);
    writeln!(w, "}}").ok();
    Ok(text)
}

/// `<LABEL>_Q` (`label`: `"EKF"`) with its docs: as tuned (`tuned`, the docs of the diagonal `gen`
/// chose), or as the spec fixes it (`[observer.<section>] q`): its diagonal, or its rows where it is
/// full (then `[[f64; STATES]; STATES]`).
pub(super) fn q_constant(label: &str, section: &str, q: &Covariance, fixed: &FixedFilter, tuned: &str) -> String {
    let Some(_) = fixed.q else {
        return format!("{tuned}\npub const {label}_Q: [f64; STATES] = {:?};", q.diagonal());
    };
    match q {
        Covariance::Diagonal(diagonal) => format!(
            "/// The {label}'s `Q` diagonal as the spec fixes it (`[observer.{section}] q`, f64): each state's\n\
             /// process-noise variance per sample period, in its unit squared ([`STATE_UNITS`]).\n\
             pub const {label}_Q: [f64; STATES] = {diagonal:?};"
        ),
        Covariance::Full(rows) => format!(
            "/// The {label}'s `Q` as the spec fixes it (`[observer.{section}] q`, f64), full, rows in state\n\
             /// order: the process-noise covariance per sample period, in the states' units ([`STATE_UNITS`]).\n\
             pub const {label}_Q: [[f64; STATES]; STATES] = {rows:?};"
        ),
    }
}

/// The filter's docs on where it starts and where its constants come from: `tuned` (the words of a
/// filter the spec fixes nothing of), or which the spec fixes (`[observer.<section>]`) and which
/// `gen` chose.
pub(super) fn constants_docs(section: &str, fixed: &FixedFilter, tuned: &str) -> String {
    if !fixed.any() {
        return tuned.to_owned();
    }
    let start = match fixed.x0 {
        Some(_) => format!("at the `x̂(0)` the spec fixes (`[observer.{section}] x0`)"),
        None => "at the centre of the state box".to_owned(),
    };
    let constant = |name: &str, key: &str, is_fixed: bool| match is_fixed {
        true => format!("{name} is the spec's (`[observer.{section}] {key}`)"),
        false => format!("{name} is diagonal, chosen by `gen` on the tuning runs"),
    };
    format!(
        "It starts {start}; {}, {}; `R` is the outputs' noise variances.",
        constant("`P(0)`", "p0", fixed.p0.is_some()),
        constant("`Q`", "q", fixed.q.is_some()),
    )
}

/// `values` as a list of `T` literals, each named `what[i]` in an error.
pub(super) fn vector(what: &str, values: &[f64]) -> Result<String, EmitError> {
    let entries = values
        .iter()
        .enumerate()
        .map(|(i, v)| literal(&format!("{what}[{i}]"), *v))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(list(&entries))
}

const FILTER_TEMPLATE: &str = r#"#[derive(Clone, Copy, Debug, PartialEq)]
pub struct {NAME}<T = f32> {
    /// `x̂`: after a sample, the prediction to the next one.
    x: [T; STATES],
    /// The upper triangle of `P`.
    p: [T; COVARIANCE],
}

impl<T: Scalar + Maths> Default for {NAME}<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T: Scalar + Maths> {NAME}<T> {
    /// A fresh filter.
    pub fn new() -> Self {
        {NAME} {
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
            let (estimate, x, p) = {LOWER}_measured(&self.x, &self.p, y, u);
            if finite(&x, &p) {
                (self.x, self.p) = (x, p);
                return Ok(estimate);
            }
        } else {
            let (x, p) = {LOWER}_unmeasured(&self.x, &self.p, u);
            if finite(&x, &p) {
                (self.x, self.p) = (x, p);
            }
        }
        Err(firmware::RejectedSample)
    }
}

"#;

const OBSERVER_TEMPLATE: &str = r#"
/// {WHAT} ([`{NAME}`], the same filter and constants) with the
/// observers' interface ([`firmware::FilterObserver`], [`firmware::Estimator`]): `push` takes a
/// sample, `estimate` gives the targets of the latest accepted one (each `Inside`: the filter does
/// not saturate), `reset` starts again. It has an estimate from the first accepted sample on; a
/// refused sample keeps the previous one.
pub type {OBSERVER} = firmware::FilterObserver<f32, {NAME}, STATES, OUTPUTS, INPUTS, TARGETS>;

impl firmware::emitted::Filter<f32, STATES, OUTPUTS, INPUTS, TARGETS> for {NAME}<f32> {
    const FRESH: Self = {NAME} { x: {X0_F32}, p: {P0_F32} };

    #[inline(always)]
    fn push(&mut self, y: &[f32; OUTPUTS], u: &[f32; INPUTS]) -> Result<[f32; STATES], firmware::RejectedSample> {
        {NAME}::push(self, y, u)
    }

    #[inline(always)]
    fn targets(x: &[f32; STATES], u: &[f32; INPUTS]) -> [f32; TARGETS] {
        targets(x, u)
    }
}

/// [`{OBSERVER}`]'s `push` and `estimate` in `f32`, compiled in this crate as when every design
/// wrote its own observer type: measured on the chip, without them the whole-program optimisation
/// inlines this design's filter samples differently, and every observer over them runs other
/// instruction counts. Not for calling: use the observer's methods.
#[doc(hidden)]
pub fn {LOWER}_observer_push(observer: &mut {OBSERVER}, y: [f32; OUTPUTS], u: [f32; INPUTS]) -> Result<(), firmware::RejectedSample> {
    observer.push(y, u)
}

/// See [`{LOWER}_observer_push`].
#[doc(hidden)]
pub fn {LOWER}_observer_estimate(observer: &{OBSERVER}) -> Option<[Estimate<f32>; TARGETS]> {
    observer.estimate()
}
"#;
