//! A Kalman filter from the centre of the state box in C, the same for the EKF (`ekf_box`, the Rust
//! file's `BoxEkfObserver`) and the UKF (`ukf_box`, `UkfObserver`): the filter's start, its prediction
//! and its measured sample taken when finite (shared with the kinds the map starts over the EKF), and
//! the observer around it.

use super::floats;
use super::program::function;
use super::started;
use crate::emit::EmitError;
use crate::plant::kalman::{EkfConstants, FilterCode};
use crate::plant::ModelCode;

/// A filter's names in C.
pub(super) struct Filter {
    /// Its functions' prefix (`ekf`: `ekf_measured`, `ekf_predict`, …).
    pub lower: &'static str,
    /// Its constants' prefix (`EKF`: `EKF_X0`, `EKF_P0`).
    pub label: &'static str,
    /// Its box observer's kind (`ekf_box`).
    pub kind: &'static str,
}

/// The EKF's names.
pub(super) const EKF: Filter = Filter {
    lower: "ekf",
    label: "EKF",
    kind: "ekf_box",
};

/// The UKF's names.
pub(super) const UKF: Filter = Filter {
    lower: "ukf",
    label: "UKF",
    kind: "ukf_box",
};

/// The filter's two samples as C functions (`<lower>_measured`, `<lower>_unmeasured`), as the Rust
/// file's.
pub(super) fn samples(filter: &Filter, programs: &FilterCode, code: &ModelCode) -> Result<String, EmitError> {
    let (lower, label) = (filter.lower, filter.label);
    Ok(function(
        &format!("{lower}_measured"),
        &format!("One {label} sample with its measurement: out = (x(k|k), x+, P+) from (x, P), as the Rust file's {lower}_measured."),
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

/// A filter's start and one sample (`Ekf::push`, `Ukf::push`), shared by the kinds over it: the EKF's
/// (`EKF_X0`, `ekf_predict`, `ekf_measure`, over `ekf_measured`/`ekf_unmeasured`) or the UKF's.
pub(super) fn common(name: &str, filter: &Filter, constants: &EkfConstants) -> Result<String, EmitError> {
    let upper = name.to_uppercase();
    let (lower, label) = (filter.lower, filter.label);
    Ok(format!(
        "/* The {label}'s start: the centre of the state box and P(0)'s upper triangle. */\n\
         static const float {label}_X0[{upper}_STATES] = {x0};\n\
         static const float {label}_P0[{upper}_COVARIANCE] = {p0};\n\
         \n\
         /* The {label}'s prediction alone (a lost output), taken when finite. */\n\
         static void {lower}_predict(float *x, float *p, const float *u) {{\n\
         \x20   float out[{upper}_STATES + {upper}_COVARIANCE];\n\
         \x20   {lower}_unmeasured(x, p, u, out);\n\
         \x20   if (all_finite(out, {upper}_STATES + {upper}_COVARIANCE)) {{\n\
         \x20       memcpy(x, out, {upper}_STATES * sizeof *x);\n\
         \x20       memcpy(p, out + {upper}_STATES, {upper}_COVARIANCE * sizeof *p);\n\
         \x20   }}\n\
         }}\n\
         \n\
         /* The {label}'s sample with its measurement, taken when finite (1, the estimate x(k|k) in\n\
         \x20* `estimate`). */\n\
         static int {lower}_measure(float *x, float *p, const float *y, const float *u, float *estimate) {{\n\
         \x20   float out[2u * {upper}_STATES + {upper}_COVARIANCE];\n\
         \x20   {lower}_measured(x, p, y, u, out);\n\
         \x20   if (!all_finite(out + {upper}_STATES, {upper}_STATES + {upper}_COVARIANCE)) {{\n\
         \x20       return 0;\n\
         \x20   }}\n\
         \x20   memcpy(estimate, out, {upper}_STATES * sizeof *x);\n\
         \x20   memcpy(x, out + {upper}_STATES, {upper}_STATES * sizeof *x);\n\
         \x20   memcpy(p, out + 2u * {upper}_STATES, {upper}_COVARIANCE * sizeof *p);\n\
         \x20   return 1;\n\
         }}\n\n",
        x0 = floats(&format!("{label} x0"), &constants.x0)?,
        p0 = floats(&format!("{label} P0"), &constants.p0.upper())?,
    ))
}

/// The filter from the box centre (`ekf_box`, `ukf_box`): `push` of the filter, then the targets of
/// its estimate, each inside.
pub(super) fn box_observer(name: &str, filter: &Filter) -> String {
    let upper = name.to_uppercase();
    let (lower, label, kind) = (filter.lower, filter.label, filter.kind);
    format!(
        "void {name}_{kind}_init({name}_{kind} *o) {{\n\
         \x20   memcpy(o->x, {label}_X0, sizeof o->x);\n\
         \x20   memcpy(o->p, {label}_P0, sizeof o->p);\n\
         \x20   o->ready = 0;\n\
         }}\n\
         \n\
         {name}_status {name}_{kind}_push({name}_{kind} *o, const float *y, const float *u) {{\n\
         \x20   float estimate[{upper}_STATES];\n\
         \x20   unsigned i;\n\
         \x20   if (!inputs_finite(u)) {{\n\
         \x20       return {upper}_REFUSED;\n\
         \x20   }}\n\
         \x20   if (!accepts(y, u)) {{\n\
         \x20       {lower}_predict(o->x, o->p, u);\n\
         \x20       return {upper}_REFUSED;\n\
         \x20   }}\n\
         \x20   if (!{lower}_measure(o->x, o->p, y, u, estimate)) {{\n\
         \x20       return {upper}_REFUSED;\n\
         \x20   }}\n\
         \x20   targets(estimate, u, o->values);\n\
         \x20   for (i = 0u; i < {upper}_TARGETS; ++i) {{\n\
         \x20       o->flags[i] = {upper}_INSIDE;\n\
         \x20   }}\n\
         \x20   o->ready = 1;\n\
         \x20   return {upper}_OK;\n\
         }}\n\
         \n\
         {estimate}",
        estimate = started::estimate(name, kind),
    )
}
