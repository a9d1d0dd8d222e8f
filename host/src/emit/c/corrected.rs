//! The model-corrected map in C (kind `corrected`, the Rust file's `CorrectedObserver`): the start-up
//! schedule and the clamp as tables, its three programs as functions, and `firmware::Started` over
//! the follower `Corrector`.

use super::floats;
use super::program::function;
use super::started::{self, map_states, targets_of, Follower};
use crate::emit::EmitError;
use crate::plant::correction::{CorrectionCode, CorrectionConstants};
use crate::plant::ModelCode;

/// The header's and the source's parts of the corrected map.
pub(super) fn corrected(
    name: &str,
    code: &ModelCode,
    constants: &CorrectionConstants,
    programs: &CorrectionCode,
    state_targets: &[usize],
) -> Result<(String, String), EmitError> {
    let upper = name.to_uppercase();
    let (nx, nt) = (code.dimensions.states, code.dimensions.targets);
    let blends = constants.blends();
    let scheduled = nx + nx * code.dimensions.outputs;
    let rows = blends
        .iter()
        .enumerate()
        .map(|(j, row)| floats(&format!("corrected start-up blend {}", j + 1), row))
        .collect::<Result<Vec<_>, _>>()?;
    // A schedule of no rows has no table (C has no empty arrays): every estimate then takes `G`.
    let (table, row) = if rows.is_empty() {
        (String::new(), "CORRECTED_NO_BLEND".to_owned())
    } else {
        (
            format!(
                "/* The start-up schedule, j = 1 … {j}: the blends g_j per state, then the gains K_j (states x\n\
                 \x20* outputs, row by row). */\n\
                 static const float CORRECTED_BLENDS[{j}][{scheduled}] = {{\n{rows}\n}};\n",
                j = rows.len(),
                rows = rows.join(",\n"),
            ),
            format!(
                "(j >= 1u && j <= {j}u) ? CORRECTED_BLENDS[j - 1u] : CORRECTED_NO_BLEND",
                j = rows.len()
            ),
        )
    };
    let mut source = format!(
        "{table}\
         static const float CORRECTED_NO_BLEND[{scheduled}] = {{ 0.0f }};\n\
         /* The clamp of each state: its map's learning range. */\n\
         static const float CORRECTED_LOWER[{upper}_STATES] = {lower};\n\
         static const float CORRECTED_UPPER[{upper}_STATES] = {upper_bounds};\n\n",
        lower = floats("corrected lower", &constants.lower)?,
        upper_bounds = floats("corrected upper", &constants.upper)?,
    );
    source += &function(
        "corrected_predict",
        "One sampling period of the model from x, the value alone: out = x+ (corrected_predict).",
        &["x", "u"],
        &programs.predict,
        code,
    )?;
    source += &function(
        "corrected_start_up",
        "The correction during the start-up, g = (blends g_j, gains K_j): x before its clamp.",
        &["x", "y", "u", "f", "g"],
        &programs.start_up,
        code,
    )?;
    source += &function(
        "corrected_steady",
        "The correction after the start-up: x before its clamp.",
        &["x", "y", "u", "f"],
        &programs.steady,
        code,
    )?;
    let follower = Follower {
        name,
        kind: "corrected",
        prefix: "corrected",
        predict: "corrected_lost",
        start_up: constants.start_up,
        steady_reads_map: programs.steady_reads_map,
        carried: "o->x",
    };
    source += &format!(
        "{map_states}\
         {targets_of}\
         /* Corrector::start: the model's period from the map's first estimate (or from the states after\n\
         \x20* a correction), taken into x when finite. */\n\
         static int corrected_start(const float *first, const float *u, float *x) {{\n\
         \x20   float next[{upper}_STATES];\n\
         \x20   corrected_predict(first, u, next);\n\
         \x20   if (!all_finite(next, {upper}_STATES)) {{\n\
         \x20       return 0;\n\
         \x20   }}\n\
         \x20   memcpy(x, next, sizeof next);\n\
         \x20   return 1;\n\
         }}\n\
         \n\
         /* Corrector::follow: the correction of the prediction x (the start-up's blend and gain, or\n\
         \x20* G's), clamped to the states' ranges by selects, then the model's period from it. */\n\
         static int corrected_follow(float *x, unsigned j, int start_up, const float *f, const float *y, const float *u,\n\
         \x20                           float *states, {name}_saturation *flags) {{\n\
         \x20   float raw[{upper}_STATES];\n\
         \x20   unsigned i;\n\
         \x20   if (start_up) {{\n\
         \x20       corrected_start_up(x, y, u, f, {row}, raw);\n\
         \x20   }} else {{\n\
         \x20       corrected_steady(x, y, u, f, raw);\n\
         \x20   }}\n\
         \x20   for (i = 0u; i < {upper}_STATES; ++i) {{\n\
         \x20       const int low = !(raw[i] >= CORRECTED_LOWER[i]);\n\
         \x20       const int out = low | (raw[i] > CORRECTED_UPPER[i]);\n\
         \x20       const float edge = select_float(low, CORRECTED_LOWER[i], CORRECTED_UPPER[i]);\n\
         \x20       const uint32_t flag = select_bits(low, (uint32_t){upper}_LOW, (uint32_t){upper}_HIGH);\n\
         \x20       states[i] = select_float(out, edge, raw[i]);\n\
         \x20       flags[i] = ({name}_saturation)select_bits(out, flag, (uint32_t){upper}_INSIDE);\n\
         \x20   }}\n\
         \x20   return corrected_start(states, u, x);\n\
         }}\n\
         \n\
         /* Corrector::predict: a lost output, the model's period from x (no correction). */\n\
         static void corrected_lost(float *x, const float *u) {{\n\
         \x20   (void)corrected_start(x, u, x);\n\
         }}\n\
         \n\
         {observer}",
        map_states = map_states("corrected", state_targets, nt),
        targets_of = targets_of(name, "corrected", state_targets, nt),
        observer = started::observer(&follower, "    memset(o->x, 0, sizeof o->x);\n"),
    );
    let header = started::header(
        name,
        "corrected",
        "The model-corrected map (kind corrected, the Rust CorrectedObserver): the map's first estimate,\n \
         * then the model's prediction corrected by the output and, during the start-up, blended with the\n \
         * map; each state clamped to its learning range (flagged LOW or HIGH).",
        true,
        &format!("    float x[{upper}_STATES];\n    unsigned count;\n    int started;\n"),
    );
    Ok((header, source))
}
