//! The box EKF checked by the map in C (`<name>_ekf_restart`, the Rust file's `EkfRestartObserver`):
//! `firmware::Restarted` over the map-started EKF's follower, with the check `restart_disagrees`.

use askama::Template;

use crate::emit::c::started;
use crate::emit::c::text::{float, render, CPart};
use crate::emit::model::observers::Observers;
use crate::emit::{EmitError, WatchLiterals};
use crate::plant::kalman;
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design's C, when the design has it (and the EKFs it runs on).
pub(crate) fn c(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<CPart>, EmitError> {
    let (Some(ekf), Some(_), Some(restart)) = (observers.ekf(), observers.started(), observers.restart()) else {
        return Ok(None);
    };
    let name = design.name.as_str();
    let upper = name.to_uppercase();
    let nx = code.dimensions.states;
    let terms = (0..nx)
        .map(|i| {
            Ok(format!(
                "    e = x[{i}] - f[{i}];\n    d += e * e / (p[{k}] + {v});\n",
                k = kalman::upper(nx, i, i),
                v = float(&format!("restart variance {i}"), restart.variances[i])?
            ))
        })
        .collect::<Result<String, EmitError>>()?;
    // The EKF's χ² watch: the carried mean passed with `x` and `P`, and reset with them.
    let chi_start = WatchLiterals::of(&ekf.watch, code.dimensions.outputs, float)?.map(|w| w.start);
    let (chi_arg, chi_field) = match chi_start {
        Some(_) => (", &o->chi", "    float chi;\n"),
        None => ("", ""),
    };
    let source = render(&RestartedC {
        name,
        upper: &upper,
        kind: "ekf_restart",
        terms: &terms,
        threshold: &float("restart threshold", restart.threshold)?,
        chi_arg,
        chi_start,
    });
    let header = started::header(
        name,
        "ekf_restart",
        "The EKF from the box centre that the map watches at every sample from its first estimate on,\n \
         * restarted from it where the two disagree (kind ekf_restart, the Rust EkfRestartObserver).",
        true,
        &format!("    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n{chi_field}"),
    );
    Ok(Some(CPart {
        header,
        source,
        programs: Vec::new(),
    }))
}

/// `ekf_restart`'s check and observer (`terms`: the check's sum; `chi_arg`, `chi_start`: the EKF's
/// watched mean as an argument and its start, empty and `None` where the EKF is not watched).
#[derive(Template)]
#[template(path = "ekf_restart/templates/restarted.c.askama", escape = "none")]
struct RestartedC<'a> {
    name: &'a str,
    upper: &'a str,
    kind: &'a str,
    terms: &'a str,
    threshold: &'a str,
    chi_arg: &'a str,
    chi_start: Option<String>,
}
