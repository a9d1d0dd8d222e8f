//! The EKF started by the map in C (`<name>_ekf_map`, the Rust file's `EkfMapObserver`): the
//! follower `StartedEkf` (start at the map's states with its `P(N−1)`, then the EKF's samples, every
//! state inside) and its observer, over the box EKF's `ekf_predict` and `ekf_measure`.

use askama::Template;

use crate::emit::c::started::{self, map_states, targets_of, Follower};
use crate::emit::c::text::{float, floats, render, CPart};
use crate::emit::model::observers::Observers;
use crate::emit::{EmitError, WatchLiterals};
use crate::plant::kalman;
use crate::plant::ModelCode;
use crate::spec::Design;

/// Its part of the design's C, when the design has it (and the box EKF it runs on).
pub(crate) fn c(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<Option<CPart>, EmitError> {
    let (Some(ekf), Some((p0, state_targets))) = (observers.ekf(), observers.started()) else {
        return Ok(None);
    };
    let name = design.name.as_str();
    let upper = name.to_uppercase();
    let targets = code.dimensions.targets;
    let watch = WatchLiterals::of(&ekf.watch, code.dimensions.outputs, float)?;
    let (carried, chi) = match watch {
        Some(_) => ("o->x, o->p, &o->chi", "    float chi;\n"),
        None => ("o->x, o->p", ""),
    };
    let follower = Follower {
        name,
        kind: "ekf_map",
        prefix: "started_ekf",
        predict: "ekf_predict",
        start_up: 0,
        steady_reads_map: false,
        carried,
        predicted: "o->x, o->p",
    };
    let source = render(&StartedEkfC {
        name,
        upper: &upper,
        p0: &floats("map-started EKF P0", &kalman::diagonal_upper(p0))?,
        map_states: &map_states("started_ekf", state_targets),
        targets_of: &targets_of(name, "started_ekf", state_targets, targets),
        watch,
        observer: &started::observer(
            &follower,
            "    memcpy(o->x, EKF_X0, sizeof o->x);\n    memcpy(o->p, EKF_P0, sizeof o->p);\n",
        ),
    });
    let header = started::header(
        name,
        "ekf_map",
        "The EKF started at the map's first estimate (kind ekf_map, the Rust EkfMapObserver).",
        true,
        &format!(
            "    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n{chi}    unsigned count;\n    int started;\n"
        ),
    );
    Ok(Some(CPart {
        header,
        source,
        programs: Vec::new(),
    }))
}

/// `ekf_map`'s follower and observer (`watch`: the box EKF's χ² watch, where it has one).
#[derive(Template)]
#[template(path = "ekf_map/templates/ekf_map.c.askama", escape = "none")]
struct StartedEkfC<'a> {
    name: &'a str,
    upper: &'a str,
    p0: &'a str,
    map_states: &'a str,
    targets_of: &'a str,
    watch: Option<WatchLiterals>,
    observer: &'a str,
}
