//! The model-based kinds in C: the model's programs as functions ([`super::program`]), then the
//! EKF from the box centre (`ekf_box`, the Rust file's `BoxEkfObserver`, [`super::box_filter`]), the
//! UKF from the box centre (`ukf_box`, `UkfObserver`), the EKF the map starts
//! (`ekf_map`, `StartedEkfObserver`), the box EKF the map checks once (`ekf_restart`,
//! `RestartedEkfObserver`), the model-corrected map (`corrected`, [`super::corrected`]) and the
//! moving-horizon estimate (`mhe`, [`super::mhe`]), each with the Rust observer's steps in the same
//! order.

use super::box_filter::{self, EKF, UKF};
use super::program::{function, helpers, needs_math};
use super::started::{self, map_states, targets_of, Follower};
use super::{corrected, float, floats, mhe};
use crate::emit::model::Observers;
use crate::emit::EmitError;
use crate::plant::correction;
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
    let filter = observers.ekf.map(|ekf| kalman::filter_code(code, ekf));
    // Beside the EKF, as in the Rust file.
    let unscented = observers
        .ekf
        .and(observers.ukf)
        .map(|ukf| (ukf, crate::plant::unscented::unscented_code(code, ukf)));
    let correction = observers
        .corrected
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
    if observers.mhe.is_some() {
        programs.extend([&code.derivative, &code.output]);
    }
    if observers.ekf.is_none() && observers.corrected.is_none() && observers.mhe.is_none() {
        return Ok(Kinds::default());
    }
    let mut kinds = Kinds {
        needs_math: needs_math(&programs),
        ..Kinds::default()
    };
    let source = &mut kinds.source;
    *source += &helpers(&programs);
    let inputs = if code.dimensions.inputs > 0 {
        format!(
            "    unsigned i;\n\
             \x20   int finite = 1;\n\
             \x20   for (i = 0u; i < {upper}_INPUTS; ++i) {{\n\
             \x20       finite &= is_finite(u[i]);\n\
             \x20   }}\n\
             \x20   return finite;\n"
        )
    } else {
        "    (void)u;\n    return 1;\n".to_owned()
    };
    *source += &format!(
        "\n/* 1 when every input is finite. */\n\
         static int inputs_finite(const float *u) {{\n{inputs}}}\n\n"
    );
    *source += "/* 1 when the n values from v are finite. */\n\
         static int all_finite(const float *v, unsigned n) {\n\
         \x20   unsigned i;\n\
         \x20   int finite = 1;\n\
         \x20   for (i = 0u; i < n; ++i) {\n\
         \x20       finite &= is_finite(v[i]);\n\
         \x20   }\n\
         \x20   return finite;\n\
         }\n\n";
    *source += &function(
        "targets",
        "The targets at state x and input u.",
        &["x", "u"],
        &code.targets,
        code,
    )?;
    if let (Some(ekf), Some(filter)) = (observers.ekf, &filter) {
        *source += &box_filter::samples(&EKF, filter, code)?;
        *source += &box_filter::common(name, &EKF, ekf)?;
        kinds.header += &started::header(
            name,
            "ekf_box",
            "The EKF from the centre of the state box (kind ekf_box, the Rust BoxEkfObserver): an estimate\n \
             * from the first accepted sample; a sample with a non-finite output is refused and only predicted.",
            false,
            &format!("    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n"),
        );
        kinds.source += &box_filter::box_observer(name, &EKF);
        kinds.names.push("ekf_box");
        if let Some((p0, state_targets)) = observers.started {
            kinds.source += &started_ekf(name, p0, state_targets, nt)?;
            kinds.header += &started::header(
                name,
                "ekf_map",
                "The EKF started at the map's first estimate (kind ekf_map, the Rust StartedEkfObserver).",
                true,
                &format!(
                    "    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n    unsigned count;\n    int started;\n"
                ),
            );
            kinds.names.push("ekf_map");
            if let Some(restart) = observers.restart {
                kinds.source += &restarted(name, nx, &restart.variances, restart.threshold)?;
                kinds.header += &started::header(
                    name,
                    "ekf_restart",
                    "The EKF from the box centre that checks the map once, at its first estimate, and restarts\n \
                     * from it where the two disagree (kind ekf_restart, the Rust RestartedEkfObserver).",
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
             * UkfObserver): an estimate from the first accepted sample; a sample with a non-finite output\n \
             * is refused and only predicted.",
            false,
            &format!("    float x[{upper}_STATES];\n    float p[{upper}_COVARIANCE];\n"),
        );
        kinds.source += &box_filter::box_observer(name, &UKF);
        kinds.names.push("ukf_box");
    }
    if let (Some((constants, state_targets)), Some(programs)) = (observers.corrected, &correction) {
        let (header, source) = corrected::corrected(name, code, constants, programs, state_targets)?;
        kinds.header += &header;
        kinds.source += &source;
        kinds.names.push("corrected");
    }
    if let Some(constants) = observers.mhe {
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
    Ok(format!(
        "/* P(N-1)'s upper triangle of the EKF the map starts. */\n\
         static const float STARTED_P0[{upper}_COVARIANCE] = {p0};\n\
         \n\
         {map_states}\
         {targets_of}\
         /* StartedEkf::start: one prediction from the map's states with STARTED_P0, taken when finite. */\n\
         static int started_ekf_start(const float *first, const float *u, float *x, float *p) {{\n\
         \x20   float out[{upper}_STATES + {upper}_COVARIANCE];\n\
         \x20   ekf_unmeasured(first, STARTED_P0, u, out);\n\
         \x20   if (!all_finite(out, {upper}_STATES + {upper}_COVARIANCE)) {{\n\
         \x20       return 0;\n\
         \x20   }}\n\
         \x20   memcpy(x, out, {upper}_STATES * sizeof *x);\n\
         \x20   memcpy(p, out + {upper}_STATES, {upper}_COVARIANCE * sizeof *p);\n\
         \x20   return 1;\n\
         }}\n\
         \n\
         /* StartedEkf::follow: the EKF's sample, every state inside. */\n\
         static int started_ekf_follow(float *x, float *p, unsigned j, int start_up, const float *map, const float *y,\n\
         \x20                             const float *u, float *states, {name}_saturation *flags) {{\n\
         \x20   unsigned i;\n\
         \x20   (void)j;\n\
         \x20   (void)start_up;\n\
         \x20   (void)map;\n\
         \x20   for (i = 0u; i < {upper}_STATES; ++i) {{\n\
         \x20       flags[i] = {upper}_INSIDE;\n\
         \x20   }}\n\
         \x20   return ekf_measure(x, p, y, u, states);\n\
         }}\n\
         \n\
         {observer}",
        p0 = floats("map-started EKF P0", &kalman::diagonal_upper(p0))?,
        map_states = map_states("started_ekf", state_targets, targets),
        targets_of = targets_of(name, "started_ekf", state_targets, targets),
        observer = started::observer(
            &follower,
            "    memcpy(o->x, EKF_X0, sizeof o->x);\n    memcpy(o->p, EKF_P0, sizeof o->p);\n"
        ),
    ))
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
    Ok(format!(
        "/* Whether the filter's prediction x (covariance p) and the map's states f disagree:\n\
         \x20* d = sum_i (x_i - f_i)^2 / (P_ii + e_i^2) > threshold, or d is NaN (restart_disagrees). */\n\
         static int restart_disagrees(const float *x, const float *p, const float *f) {{\n\
         \x20   float d = 0.0f;\n\
         \x20   float e;\n\
         {terms}\
         \x20   return !(d <= {threshold});\n\
         }}\n\
         \n\
         /* Restarted::check, at the map's first estimate: 1 when the filter restarted from the map. */\n\
         static int restart_check({name}_ekf_restart *o, const float *y, const float *u) {{\n\
         \x20   float all[{upper}_TARGETS], map[{upper}_STATES];\n\
         \x20   {name}_saturation all_flags[{upper}_TARGETS];\n\
         \x20   (void){name}_map_push(&o->window, y, u);\n\
         \x20   if (o->window.filled < {upper}_HORIZON) {{\n\
         \x20       return 0;\n\
         \x20   }}\n\
         \x20   o->checked = 1;\n\
         \x20   (void){name}_map_estimate(&o->window, all, all_flags);\n\
         \x20   started_ekf_map_states(all, map);\n\
         \x20   if (!restart_disagrees(o->x, o->p, map) || !started_ekf_start(map, u, o->x, o->p)) {{\n\
         \x20       return 0;\n\
         \x20   }}\n\
         \x20   memcpy(o->values, all, sizeof all);\n\
         \x20   memcpy(o->flags, all_flags, sizeof all_flags);\n\
         \x20   o->ready = 1;\n\
         \x20   return 1;\n\
         }}\n\
         \n\
         void {name}_ekf_restart_init({name}_ekf_restart *o) {{\n\
         \x20   {name}_map_init(&o->window);\n\
         \x20   memcpy(o->x, EKF_X0, sizeof o->x);\n\
         \x20   memcpy(o->p, EKF_P0, sizeof o->p);\n\
         \x20   o->checked = 0;\n\
         \x20   o->ready = 0;\n\
         }}\n\
         \n\
         {name}_status {name}_ekf_restart_push({name}_ekf_restart *o, const float *y, const float *u) {{\n\
         \x20   float states[{upper}_STATES];\n\
         \x20   {name}_saturation state_flags[{upper}_STATES];\n\
         \x20   if (!accepts(y, u)) {{\n\
         \x20       if (inputs_finite(u)) {{\n\
         \x20           ekf_predict(o->x, o->p, u);\n\
         \x20       }}\n\
         \x20       return {upper}_REFUSED;\n\
         \x20   }}\n\
         \x20   if (!o->checked && restart_check(o, y, u)) {{\n\
         \x20       return {upper}_OK;\n\
         \x20   }}\n\
         \x20   if (!started_ekf_follow(o->x, o->p, 1u, 0, NULL, y, u, states, state_flags)) {{\n\
         \x20       return {upper}_REFUSED;\n\
         \x20   }}\n\
         \x20   started_ekf_targets_of(states, state_flags, u, o->values, o->flags);\n\
         \x20   o->ready = 1;\n\
         \x20   return {upper}_OK;\n\
         }}\n\
         \n\
         {estimate}",
        threshold = float("restart threshold", threshold)?,
        estimate = started::estimate(name, "ekf_restart"),
    ))
}
