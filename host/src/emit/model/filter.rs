//! A Kalman filter's frame on the chip, the same for every filter kind (the EKF's in
//! [`super::plant`], the others' in their kind's `emit.rs`): the filter type around its two
//! written-out samples (`<lower>_measured`, `<lower>_unmeasured`: `push`, the refusals, `P` as its
//! upper triangle), and the filter from the centre of the state box as an observer (its kind's type: the runtime's
//! `firmware::FilterObserver` over the filter, which implements `firmware::emitted::Filter`).

use askama::Template;

use super::rust_text::{body, f32_list, list, literal, rows};
use crate::emit::EmitError;
use crate::emit::{f32_literal, WatchLiterals};
use crate::plant::kalman::{self, EkfConstants, FilterCode};
use crate::plant::{Covariance, ModelCode};
use crate::spec::{Design, FixedFilter};

/// One filter's names: its type (`Ekf`), its samples' prefix (`ekf`), its observer type
/// (`EkfBoxObserver`) and what filter that observer is ("The EKF"; its docs add where it starts).
pub(crate) struct Names {
    pub(crate) name: &'static str,
    pub(crate) lower: &'static str,
    pub(crate) observer: &'static str,
    pub(crate) what: &'static str,
    /// How its samples' docs begin ("One sample").
    pub(crate) sample: &'static str,
}

/// The filter type `names.name` with its constants' start (`{X0}`, `{P0}`: `T` literals) and its
/// watch, if any (`outputs`: the filter's outputs).
pub(crate) fn filter_type(
    names: &Names,
    constants: &EkfConstants,
    nx: usize,
    outputs: usize,
) -> Result<String, EmitError> {
    let upper = constants.p0.upper();
    let watch = WatchLiterals::of(&constants.watch, outputs, literal)?;
    let full: Vec<String> = (0..nx * nx)
        .map(|k| format!("self.p[{}]", kalman::upper(nx, k / nx, k % nx)))
        .collect();
    let label = names.name.to_uppercase();
    let threshold = match constants.watch.threshold.is_finite() {
        true => format!("{:?}", constants.watch.threshold),
        false => "f64::INFINITY".to_owned(),
    };
    let watch_constants = format!(
        "/// The {label}'s χ² watch as `gen` chose it on the tuning runs ([`firmware::watch`]): the window `W`\n\
         /// over which the mean of its normalised innovations squared is kept, in samples.\n\
         pub const {label}_WATCH_WINDOW: usize = {};\n\
         /// See [`{label}_WATCH_WINDOW`]: the threshold `τ` (no unit) above which, times the number of\n\
         /// outputs, the mean restarts the filter; `f64::INFINITY`: not watched.\n\
         pub const {label}_WATCH_THRESHOLD: f64 = {threshold};\n\n",
        constants.watch.window
    );
    let filter = FilterType {
        name: names.name,
        lower: names.lower,
        x0: &vector(&format!("{label} x0"), &constants.x0)?,
        p0: &vector(&format!("{label} P0"), &upper)?,
        covariance: &rows(&full, nx),
        watch,
    }
    .render()?;
    Ok(filter + &watch_constants)
}

/// The observer around the filter (`names.observer`), started where the filter starts (`fixed`: the
/// spec's constants of this filter), its estimate's targets by the function `targets`.
pub(crate) fn filter_observer(
    names: &Names,
    constants: &EkfConstants,
    fixed: &FixedFilter,
    outputs: usize,
    targets: &str,
) -> Result<String, EmitError> {
    let label = names.name.to_uppercase();
    let upper = constants.p0.upper();
    let start = match fixed.x0 {
        Some(_) => "the start the spec fixes",
        None => "the centre of the state box",
    };
    let what = format!("{} from {start}", names.what);
    Ok(FilterObserver {
        what: &what,
        name: names.name,
        lower: names.lower,
        observer: names.observer,
        x0: &f32_list(&format!("{label} x0"), &constants.x0)?,
        p0: &f32_list(&format!("{label} P0"), &upper)?,
        chi: WatchLiterals::of(&constants.watch, outputs, f32_literal)?.map(|w| w.start),
        targets,
    }
    .render()?)
}

/// The targets of the filter's state, `<lower>_targets`, and the function its observer calls for
/// them: where it carries the model's log coordinates ([`ModelCode::logarithmic`]), written out from
/// `filter.targets` and called; else the model's `targets` under the filter's name (for code that
/// reads the filter's state generically), the observer calling `targets` itself.
pub(crate) fn own_targets(
    names: &Names,
    filter: &FilterCode,
    code: &ModelCode,
    design: &Design,
) -> Result<(String, String), EmitError> {
    let name = format!("{}_targets", names.lower);
    if code.log_coordinates.is_plant() {
        let text = format!(
            "/// The targets at the {what}'s state `x` and input `u`: the model's ([`targets`]), the {what}\n\
             /// carrying the states as they are.\n\
             pub fn {name}<T: Scalar + Maths>(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {{\n    targets(x, u)\n}}\n\n",
            what = names.name.to_uppercase(),
        );
        return Ok((text, "targets".to_owned()));
    }
    let carried: Vec<String> = design
        .model
        .states
        .iter()
        .zip(&code.log_coordinates.0)
        .filter_map(|(state, log)| {
            log.map(|log| format!("`{state}` as `ln({state} - {:?} + {:?})`", log.min, log.offset))
        })
        .collect();
    let body = body(&filter.targets, code, design, "    ", list)?;
    let text = format!(
        "/// The targets at the {what}'s state `x` and input `u`: it carries {carried} (log coordinates:\n\
         /// inside the bound without a clamp), the other states as they are. Written out by `gen`.\n\
         #[allow(unused_variables, non_snake_case, clippy::approx_constant)]\n\
         pub fn {name}<T: Scalar + Maths>(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {{\n{body}}}\n\n",
        what = names.name.to_uppercase(),
        carried = carried.join(", "),
    );
    Ok((text, name))
}

/// The filter's two samples written out from its programs: `<lower>_measured` and `<lower>_unmeasured`.
pub(crate) fn samples(
    names: &Names,
    filter: &FilterCode,
    code: &ModelCode,
    design: &Design,
) -> Result<String, EmitError> {
    let nx = code.dimensions.states;
    Ok(Samples {
        sample: names.sample,
        lower: names.lower,
        measured: &body(&filter.measured, code, design, "    ", |r| {
            let last = r.len() - 1;
            format!(
                "({}, {}, {}, {})",
                list(&r[..nx]),
                list(&r[nx..2 * nx]),
                list(&r[2 * nx..last]),
                r[last]
            )
        })?,
        unmeasured: &body(&filter.unmeasured, code, design, "    ", |r| {
            format!("({}, {})", list(&r[..nx]), list(&r[nx..]))
        })?,
    }
    .render()?)
}

/// The filter docs' sentence on its χ² watch: the window and the threshold `gen` chose, or that it
/// has none.
pub(crate) fn watch_docs(constants: &EkfConstants) -> String {
    let watch = constants.watch;
    match watch.threshold.is_finite() {
        true => format!(
            "\n/// Watched ([`firmware::watch`]): when the mean of its normalised innovations squared over about\n/// {} samples exceeds {} times the number of outputs, it restarts from its start.",
            watch.window, watch.threshold
        ),
        false => "\n/// Not watched: on the tuning runs every χ² watch on its innovations scored worse ([`firmware::watch`]).".to_owned(),
    }
}

/// `<LABEL>_Q` (`label`: `"EKF"`) with its docs: as tuned (`tuned`, the docs of the diagonal `gen`
/// chose), or as the spec fixes it (`[observer.<section>] q`): its diagonal, or its rows where it is
/// full (then `[[f64; STATES]; STATES]`).
pub(crate) fn q_constant(label: &str, section: &str, q: &Covariance, fixed: &FixedFilter, tuned: &str) -> String {
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
pub(crate) fn constants_docs(section: &str, fixed: &FixedFilter, tuned: &str) -> String {
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

/// The filter's two samples (`measured`, `unmeasured`: their bodies; `sample`: how their docs begin).
#[derive(Template)]
#[template(path = "model/samples.rs", escape = "none")]
struct Samples<'a> {
    sample: &'a str,
    lower: &'a str,
    measured: &'a str,
    unmeasured: &'a str,
}

/// The filter type `name` (`x0`, `p0`: its start; `covariance`: `P` from its triangle).
#[derive(Template)]
#[template(path = "model/filter.rs", escape = "none")]
struct FilterType<'a> {
    name: &'a str,
    lower: &'a str,
    x0: &'a str,
    p0: &'a str,
    covariance: &'a str,
    watch: Option<WatchLiterals>,
}

/// The observer `observer` around the filter `name` (`x0`, `p0`: its start in `f32`).
#[derive(Template)]
#[template(path = "model/filter_observer.rs", escape = "none")]
struct FilterObserver<'a> {
    what: &'a str,
    name: &'a str,
    lower: &'a str,
    observer: &'a str,
    x0: &'a str,
    p0: &'a str,
    /// The watched mean's start in `f32`, where the filter is watched.
    chi: Option<String>,
    /// The function giving the targets of its state: the model's `targets`, or the filter's own
    /// where it carries other coordinates.
    targets: &'a str,
}
