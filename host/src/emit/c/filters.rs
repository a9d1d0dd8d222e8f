//! The model-based kinds in C: the model's programs as functions ([`super::program`]), then the
//! EKF from the box centre (`ekf_box`, the Rust file's `EkfBoxObserver`, [`super::box_filter`]), the
//! UKF from the box centre (`ukf_box`, `UkfBoxObserver`), the EKF the map starts
//! (`ekf_map`, `EkfMapObserver`), the box EKF the map checks once (`ekf_restart`,
//! `EkfRestartObserver`), the model-corrected map (`corrected`, [`super::corrected`]) and the
//! moving-horizon estimate (`mhe`, [`super::mhe`]), each with the Rust observer's steps in the same
//! order.

use askama::Template;

use super::box_filter::{self, EKF, UKF};
use super::program::{calls, function, needs_math};
use super::started::{self, map_states, targets_of, Follower};
use super::{float, floats};
use crate::emit::model::Observers;
use crate::emit::EmitError;
use crate::observers::kind::corrected::c as corrected;
use crate::observers::kind::corrected::program as correction;
use crate::observers::kind::mhe::c as mhe;
use crate::plant::kalman;
use crate::plant::{ModelCode, Program};
use crate::spec::Design;

/// The model-based kinds' part of the header and of the source.
#[derive(Default)]
pub(super) struct Kinds {
    /// Their structs and prototypes.
    pub header: String,
    /// Their programs and code.
    pub source: String,
    /// The kinds written, by name.
    pub names: Vec<&'static str>,
    /// Whether a program calls a function of `<math.h>`.
    pub needs_math: bool,
}

/// Every model-based kind `observers` has.
pub(super) fn kinds(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Kinds, EmitError> {
    let name = design.name.as_str();
    let upper = name.to_uppercase();
    let (nx, nt) = (code.dimensions.states, code.dimensions.targets);
    let filter = observers.ekf().map(|ekf| kalman::filter_code(code, ekf));
    // Beside the EKF, as in the Rust file.
    let unscented = observers
        .ekf()
        .and(observers.ukf())
        .map(|ukf| (ukf, crate::observers::kind::ukf_box::program::unscented_code(code, ukf)));
    let correction = observers
        .corrected()
        .map(|(constants, _)| correction::correction_code(code, constants));
    let mut programs: Vec<&Program> = vec![&code.targets];
    if let Some(filter) = &filter {
        programs.extend([&filter.measured, &filter.unmeasured]);
    }
    if let Some((_, filter)) = &unscented {
        programs.extend([&filter.measured, &filter.unmeasured]);
    }
    if let Some(c) = &correction {
        programs.extend([&c.predict, &c.start_up, &c.steady]);
    }
    if observers.mhe().is_some() {
        programs.extend([&code.derivative, &code.output]);
    }
    if observers.ekf().is_none() && observers.corrected().is_none() && observers.mhe().is_none() {
        return Ok(Kinds::default());
    }
    let mut kinds = Kinds {
        needs_math: needs_math(&programs),
        ..Kinds::default()
    };
    let source = &mut kinds.source;
    *source += &super::render(&KindsC {
        upper: &upper,
        inputs: code.dimensions.inputs > 0,
        signum: calls(&programs, "signum"),
        exp: calls(&programs, "exp"),
        fract: calls(&programs, "fract"),
    });
    *source += &function(
        "targets",
        "The targets at state x and input u.",
        &["x", "u"],
        &code.targets,
        code,
    )?;
    if let (Some(ekf), Some(filter)) = (observers.ekf(), &filter) {
        *source += &box_filter::samples(&EKF, filter, code)?;
        *source += &box_filter::common(name, &EKF, ekf)?;
        kinds.header += &started::header(
            name,
            "ekf_box",
            "The EKF from the centre of the state box (kind ekf_box, the Rust EkfBoxObserver): an estimate\n \
             * from the first accepted sample; a sample with a non-finite output is refused and only predicted.",
            false,
            &format!("    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n"),
        );
        kinds.source += &box_filter::box_observer(name, &EKF);
        kinds.names.push("ekf_box");
        if let Some((p0, state_targets)) = observers.started() {
            kinds.source += &started_ekf(name, p0, state_targets, nt)?;
            kinds.header += &started::header(
                name,
                "ekf_map",
                "The EKF started at the map's first estimate (kind ekf_map, the Rust EkfMapObserver).",
                true,
                &format!(
                    "    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n    unsigned count;\n    int started;\n"
                ),
            );
            kinds.names.push("ekf_map");
            if let Some(restart) = observers.restart() {
                kinds.source += &restarted(name, nx, &restart.variances, restart.threshold)?;
                kinds.header += &started::header(
                    name,
                    "ekf_restart",
                    "The EKF from the box centre that checks the map once, at its first estimate, and restarts\n \
                     * from it where the two disagree (kind ekf_restart, the Rust EkfRestartObserver).",
                    true,
                    &format!("    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n    int checked;\n"),
                );
                kinds.names.push("ekf_restart");
            }
        }
    }
    if let Some((ukf, filter)) = &unscented {
        kinds.source += &box_filter::samples(&UKF, filter, code)?;
        kinds.source += &box_filter::common(name, &UKF, ukf)?;
        kinds.header += &started::header(
            name,
            "ukf_box",
            "The unscented Kalman filter from the centre of the state box (kind ukf_box, the Rust\n \
             * UkfBoxObserver): an estimate from the first accepted sample; a sample with a non-finite output\n \
             * is refused and only predicted.",
            false,
            &format!("    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n"),
        );
        kinds.source += &box_filter::box_observer(name, &UKF);
        kinds.names.push("ukf_box");
    }
    if let (Some((constants, state_targets)), Some(programs)) = (observers.corrected(), &correction) {
        let (header, source) = corrected::corrected(name, code, constants, programs, state_targets)?;
        kinds.header += &header;
        kinds.source += &source;
        kinds.names.push("corrected");
    }
    if let Some(constants) = observers.mhe() {
        let (header, source) = mhe::mhe(name, code, constants, design.chip_substeps)?;
        kinds.header += &header;
        kinds.source += &source;
        kinds.names.push("mhe");
    }
    Ok(kinds)
}

/// `ekf_map`: the follower `StartedEkf` (start at the map's states with its `P(N−1)`, then the EKF's
/// samples, every state inside) and its observer.
fn started_ekf(name: &str, p0: &[f64], state_targets: &[usize], targets: usize) -> Result<String, EmitError> {
    let upper = name.to_uppercase();
    let follower = Follower {
        name,
        kind: "ekf_map",
        prefix: "started_ekf",
        predict: "ekf_predict",
        start_up: 0,
        steady_reads_map: false,
        carried: "o->x, o->p",
    };
    Ok(super::render(&StartedEkfC {
        name,
        upper: &upper,
        p0: &floats("map-started EKF P0", &kalman::diagonal_upper(p0))?,
        map_states: &map_states("started_ekf", state_targets, targets),
        targets_of: &targets_of(name, "started_ekf", state_targets, targets),
        observer: &started::observer(
            &follower,
            "    memcpy(o->x, EKF_X0, sizeof o->x);\n    memcpy(o->p, EKF_P0, sizeof o->p);\n",
        ),
    }))
}

/// `ekf_restart`: `firmware::Restarted` over `StartedEkf`, with the check `restart_disagrees`.
fn restarted(name: &str, nx: usize, variances: &[f64], threshold: f64) -> Result<String, EmitError> {
    let upper = name.to_uppercase();
    let terms = (0..nx)
        .map(|i| {
            Ok(format!(
                "    e = x[{i}] - f[{i}];\n    d += e * e / (p[{k}] + {v});\n",
                k = kalman::upper(nx, i, i),
                v = float(&format!("restart variance {i}"), variances[i])?
            ))
        })
        .collect::<Result<String, EmitError>>()?;
    Ok(super::render(&RestartedC {
        name,
        upper: &upper,
        kind: "ekf_restart",
        terms: &terms,
        threshold: &float("restart threshold", threshold)?,
    }))
}

/// What the model-based kinds share: the helpers the programs call, the checks of a sample's values.
#[derive(Template)]
#[template(path = "c/kinds.c", escape = "none")]
struct KindsC<'a> {
    upper: &'a str,
    inputs: bool,
    signum: bool,
    exp: bool,
    fract: bool,
}

/// `ekf_map`'s follower and observer.
#[derive(Template)]
#[template(path = "c/started_ekf.c", escape = "none")]
struct StartedEkfC<'a> {
    name: &'a str,
    upper: &'a str,
    p0: &'a str,
    map_states: &'a str,
    targets_of: &'a str,
    observer: &'a str,
}

/// `ekf_restart`'s check and observer (`terms`: the check's sum).
#[derive(Template)]
#[template(path = "c/restarted.c", escape = "none")]
struct RestartedC<'a> {
    name: &'a str,
    upper: &'a str,
    kind: &'a str,
    terms: &'a str,
    threshold: &'a str,
}
