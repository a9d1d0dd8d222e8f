//! A Kalman filter from the centre of the state box in C, the same for every filter kind that starts
//! there (each names its [`Filter`]): the filter's start, its prediction and its measured sample taken
//! when finite (shared with the kinds the map starts over the EKF), and the observer around it.

use askama::Template;

use super::program::function;
use super::started;
use super::text::{float, floats, CPart};
use crate::emit::{EmitError, WatchLiterals};
use crate::plant::kalman::{EkfConstants, FilterCode};
use crate::plant::ModelCode;

/// A filter's names in C.
pub(crate) struct Filter {
    /// Its functions' prefix (`ekf`: `ekf_measured`, `ekf_predict`, …).
    pub lower: &'static str,
    /// Its constants' prefix (`EKF`: `EKF_X0`, `EKF_P0`).
    pub label: &'static str,
    /// Its box observer's kind (`ekf_box`).
    pub kind: &'static str,
}

/// The whole C of the filter from the box centre of `design`: its samples, its start, its observer
/// (`what`: the header's comment on the observer's struct). `own_targets`: the filter carries the
/// model's log coordinates, and its estimate's targets are its own function (`<lower>_targets`).
pub(crate) fn box_part(
    name: &str,
    filter: &Filter,
    constants: &EkfConstants,
    programs: FilterCode,
    code: &ModelCode,
    what: &str,
    own_targets: bool,
) -> Result<CPart, EmitError> {
    let upper = name.to_uppercase();
    let outputs = code.dimensions.outputs;
    let watch = WatchLiterals::of(&constants.watch, outputs, float)?;
    let chi = match watch {
        Some(_) => "    float chi; /* the watched mean of the normalised innovations squared */\n",
        None => "",
    };
    let (targets, targets_source) = match own_targets {
        true => {
            let targets = format!("{}_targets", filter.lower);
            let source = function(
                &targets,
                &format!(
                    "The targets at the {} state x (in its log coordinates) and input u.",
                    filter.label
                ),
                &["x", "u"],
                &programs.targets,
                code,
            )?;
            (targets, source)
        }
        false => ("targets".to_owned(), String::new()),
    };
    Ok(CPart {
        header: started::header(
            name,
            filter.kind,
            what,
            false,
            &format!("    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n{chi}"),
        ),
        source: samples(filter, &programs, code)?
            + &targets_source
            + &common(name, filter, constants)?
            + &box_observer(name, filter, watch, &targets),
        programs: vec![programs.measured, programs.unmeasured, programs.targets],
    })
}

/// The filter's two samples as C functions (`<lower>_measured`, `<lower>_unmeasured`), as the Rust
/// file's.
fn samples(filter: &Filter, programs: &FilterCode, code: &ModelCode) -> Result<String, EmitError> {
    let (lower, label) = (filter.lower, filter.label);
    Ok(function(
        &format!("{lower}_measured"),
        &format!("One {label} sample with its measurement: out = (x(k|k), x+, P+, nis) from (x, P), nis the normalised innovation squared, as the Rust file's {lower}_measured."),
        &["x", "p", "y", "u"],
        &programs.measured,
        code,
    )? + &function(
        &format!("{lower}_unmeasured"),
        &format!("One {label} sample without its measurement: out = (x+, P+) from (x, P), as the Rust file's {lower}_unmeasured."),
        &["x", "p", "u"],
        &programs.unmeasured,
        code,
    )?)
}

/// A filter's start and one sample (the Rust file's `push` of the filter), shared by the kinds over
/// it: for the EKF `EKF_X0`, `ekf_predict`, `ekf_measure`, over `ekf_measured`/`ekf_unmeasured`.
fn common(name: &str, filter: &Filter, constants: &EkfConstants) -> Result<String, EmitError> {
    let (lower, label) = (filter.lower, filter.label);
    Ok(super::text::render(&FilterC {
        upper: &name.to_uppercase(),
        lower,
        label,
        x0: &floats(&format!("{label} x0"), &constants.x0)?,
        p0: &floats(&format!("{label} P0"), &constants.p0.upper())?,
    }))
}

/// The filter from the box centre: `push` of the filter, then the targets of its estimate, each inside.
fn box_observer(name: &str, filter: &Filter, watch: Option<WatchLiterals>, targets: &str) -> String {
    super::text::render(&BoxObserver {
        targets,
        name,
        upper: &name.to_uppercase(),
        lower: filter.lower,
        label: filter.label,
        kind: filter.kind,
        watch,
    })
}

/// A filter's start and sample (`x0`, `p0`: its start).
#[derive(Template)]
#[template(path = "c/filter.c", escape = "none")]
struct FilterC<'a> {
    upper: &'a str,
    lower: &'a str,
    label: &'a str,
    x0: &'a str,
    p0: &'a str,
}

/// The observer of a filter from the box centre.
#[derive(Template)]
#[template(path = "c/box_observer.c", escape = "none")]
struct BoxObserver<'a> {
    name: &'a str,
    upper: &'a str,
    lower: &'a str,
    label: &'a str,
    kind: &'a str,
    watch: Option<WatchLiterals>,
    /// The function giving the targets of its estimate.
    targets: &'a str,
}
