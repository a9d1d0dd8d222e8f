//! The map in C (`<name>_map`): the same f32 tables as the Rust design file
//! ([`crate::emit::precision::F32Tables`]), the dot product summed term by term in the Rust file's
//! order ([`crate::emit::terms::dot_terms`]) and the certified `Γ⁻¹` table evaluated as
//! `firmware::InverseTable::evaluate` does, saturation flags included. The observer is the last `N`
//! samples, each stored twice so that the window is always contiguous (as `firmware::Window`).

use super::{float, floats};
use crate::emit::precision::F32Tables;
use crate::emit::terms::dot_terms;
use crate::emit::EmitError;
use crate::fit::DesignResult;
use crate::spec::Design;

/// The map's part of the header (its struct and functions) and of the source (its tables and code).
pub(super) struct MapC {
    /// `<name>_map` and its functions' prototypes.
    pub header: String,
    /// The tables, the table's evaluation and the three functions.
    pub source: String,
}

/// `values` in f64 (exactly), for [`floats`].
fn widen(values: &[f32]) -> Vec<f64> {
    values.iter().map(|&v| f64::from(v)).collect()
}

/// The C of `design`'s map (its targets' tables in `result`).
pub(super) fn map(design: &Design, result: &DesignResult) -> Result<MapC, EmitError> {
    let name = &design.name;
    let upper = name.to_uppercase();
    let (n, ny, nu) = (
        design.map.horizon,
        design.model.outputs.len(),
        design.model.inputs.len(),
    );
    let mut tables = String::new();
    // Every projection first, then every table: the window is read once (a store to `values` could
    // alias it, which makes the compiler read it again for each target).
    let (mut projections, mut estimates) = (String::new(), String::new());
    for (t, target) in result.targets.iter().enumerate() {
        let label = &design.targets[target.index].name;
        let Some(table) = target.fit.map.table.as_ref() else {
            return Err(EmitError::NoTable { target: label.clone() });
        };
        let rounded = F32Tables::new(table);
        let what = |field: &str| format!("target `{label}` {field}");
        let segments = rounded
            .segments
            .iter()
            .enumerate()
            .map(|(k, [a, b])| {
                Ok(format!(
                    "    {{ {}, {} }}",
                    float(&what(&format!("segments[{k}].a")), f64::from(*a))?,
                    float(&what(&format!("segments[{k}].b")), f64::from(*b))?
                ))
            })
            .collect::<Result<Vec<_>, EmitError>>()?;
        tables += &format!(
            "\n/* `{label}`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */\n\
             static const float GAINS_{t}[{}] = {};\n\
             static const float SEGMENTS_{t}[{}][2] = {{\n{}\n}};\n",
            rounded.gains.len(),
            floats(&what("gains"), &widen(&rounded.gains))?,
            rounded.segments.len(),
            segments.join(",\n"),
        );
        let terms: String = dot_terms(&rounded.gains, n, ny, nu)
            .iter()
            .map(|term| {
                let field = if term.input { "u" } else { "y" };
                format!(
                    "\n        + GAINS_{t}[{}] * observer->{field}[next + {}u][{}]",
                    term.gain, term.sample, term.entry
                )
            })
            .collect();
        let count = rounded.segments.len();
        let (search, segment, start) = match &rounded.starts {
            // One segment: nothing to look up.
            None if count == 1 => (String::new(), format!("SEGMENTS_{t}[0]"), "0.0f".to_owned()),
            None => (
                format!("    const uint32_t k_{t} = uniform_segment(t_{t}, {count}u);\n"),
                format!("SEGMENTS_{t}[k_{t}]"),
                "0.0f".to_owned(),
            ),
            Some(starts) => {
                tables += &format!(
                    "static const float STARTS_{t}[{}] = {};\n",
                    starts.len(),
                    floats(&what("starts"), &widen(starts))?
                );
                // `firmware::search_step` for every step of `firmware::search_halves`, then the clamp
                // of `evaluate_segment`.
                let steps: String = firmware::search_halves(starts.len())
                    .map(|half| {
                        format!(
                            "    k_{t} = select_bits(STARTS_{t}[k_{t} + {half}u] <= t_{t}, k_{t} + {half}u, k_{t});\n"
                        )
                    })
                    .collect();
                (
                    format!(
                        "    unsigned k_{t} = 0u;\n{steps}    k_{t} = k_{t} < {last}u ? k_{t} : {last}u;\n",
                        last = count - 1
                    ),
                    format!("SEGMENTS_{t}[k_{t}]"),
                    format!("STARTS_{t}[k_{t}]"),
                )
            }
        };
        projections += &format!(
            "    const float t_{t} = {offset}{terms};\n",
            offset = float(&what("offset"), f64::from(rounded.offset))?
        );
        estimates += &format!(
            "{search}    evaluate(t_{t}, {segment}, {start}, {t_max}, {r_min}, {r_max}, &values[{t}], &saturation[{t}]);\n",
            t_max = float(&what("t_max"), f64::from(rounded.t_max))?,
            r_min = float(&what("r_min"), f64::from(rounded.r_min))?,
            r_max = float(&what("r_max"), f64::from(rounded.r_max))?,
        );
    }
    let inputs_field = if nu > 0 {
        format!("    float u[2u * {upper}_HORIZON][{upper}_INPUTS];\n")
    } else {
        String::new()
    };
    let header = format!(
        "/* The map observer: the last {upper}_HORIZON samples, each stored twice so that the window is\n\
         \x20* always contiguous. Allocate it anywhere (no heap is used) and call {name}_map_init. */\n\
         typedef struct {{\n\
         \x20   float y[2u * {upper}_HORIZON][{upper}_OUTPUTS];\n\
         {inputs_field}\
         \x20   unsigned next;\n\
         \x20   unsigned filled;\n\
         }} {name}_map;\n\
         \n\
         /* Empties the window (a fresh observer, or a new run). */\n\
         void {name}_map_init({name}_map *observer);\n\
         \n\
         /* Takes the sample of the current instant: y[{upper}_OUTPUTS] and u[{upper}_INPUTS] (u may be\n\
         \x20* NULL when there is no input). {upper}_OK, or {upper}_REFUSED for a NaN or infinite value\n\
         \x20* (the observer is unchanged). */\n\
         {name}_status {name}_map_push({name}_map *observer, const float *y, const float *u);\n\
         \n\
         /* The estimate of every target from the last {upper}_HORIZON samples into values[{upper}_TARGETS]\n\
         \x20* and saturation[{upper}_TARGETS]; {upper}_NO_ESTIMATE_YET (nothing written) before the window is full. */\n\
         {name}_status {name}_map_estimate(const {name}_map *observer, float *values, {name}_saturation *saturation);\n\
         \n"
    );
    let store = window_store(&upper, nu);
    // The check written out here rather than a call of `accepts`, which the compiler keeps out of line
    // where the followers call it too (about 10 instructions more per sample).
    let check_inputs = if nu > 0 {
        format!(
            "    for (i = 0u; i < {upper}_INPUTS; ++i) {{\n\
             \x20       finite &= is_finite(u[i]);\n\
             \x20   }}\n"
        )
    } else {
        String::new()
    };
    // Only where a table of more than one segment is uniform: an unused static function is a warning.
    let uniform = if estimates.contains("uniform_segment(") {
        "/* floor(t) for 0 <= t, at most count - 1: a uniform table's segment. Any other t (negative, NaN,\n\
         \x20* infinite) gives some segment, whose value evaluate replaces by r_min or r_max. The clamp is an\n\
         \x20* unsigned minimum of the bits of |t|, which are ordered as the values: the conversion is always\n\
         \x20* defined, and the same instructions run whatever t is. */\n\
         static uint32_t uniform_segment(float t, uint32_t count) {\n\
         \x20   const uint32_t magnitude = bits_of(t) & 0x7fffffffu;\n\
         \x20   const uint32_t last = bits_of((float)(count - 1u));\n\
         \x20   const uint32_t least = magnitude < last ? magnitude : last;\n\
         \x20   float clamped;\n\
         \x20   memcpy(&clamped, &least, sizeof clamped);\n\
         \x20   return (uint32_t)clamped;\n\
         }\n\
         \n"
    } else {
        ""
    };
    let source = format!(
        "{tables}\n\
         {uniform}\
         /* r(t) on one segment (a, b) starting at `start`, held at r_min below 0 (or NaN) and r_max above\n\
         \x20* t_max (t_max >= 0: never both); as firmware::InverseTable, by one select per statement, which\n\
         \x20* compilers make a conditional move (an IT block on Thumb-2): the same instructions whatever t is. */\n\
         static void evaluate(float t, const float *segment, float start, float t_max, float r_min, float r_max,\n\
         \x20                    float *value, {name}_saturation *saturation) {{\n\
         \x20   const int low = !(t >= 0.0f);\n\
         \x20   const int high = t > t_max;\n\
         \x20   float r = segment[0] + segment[1] * (t - start);\n\
         \x20   r = choose_float(high, r_max, r);\n\
         \x20   r = choose_float(low, r_min, r);\n\
         \x20   *value = r;\n\
         \x20   *saturation = ({name}_saturation)((unsigned)low | (unsigned)high << 1);\n\
         }}\n\
         \n\
         void {name}_map_init({name}_map *observer) {{\n\
         \x20   observer->next = 0u;\n\
         \x20   observer->filled = 0u;\n\
         }}\n\
         \n\
         {name}_status {name}_map_push({name}_map *observer, const float *y, const float *u) {{\n\
         \x20   unsigned i;\n\
         \x20   unsigned slot;\n\
         \x20   int finite = 1;\n\
         \x20   for (i = 0u; i < {upper}_OUTPUTS; ++i) {{\n\
         \x20       finite &= is_finite(y[i]);\n\
         \x20   }}\n\
         {check_inputs}\
         \x20   if (!finite) {{\n\
         \x20       return {upper}_REFUSED;\n\
         \x20   }}\n\
         {store}\
         }}\n\
         \n\
         {name}_status {name}_map_estimate(const {name}_map *observer, float *values, {name}_saturation *saturation) {{\n\
         \x20   const unsigned next = observer->next;\n\
         \x20   if (observer->filled < {upper}_HORIZON) {{\n\
         \x20       return {upper}_NO_ESTIMATE_YET;\n\
         \x20   }}\n\
         {projections}\
         {estimates}\
         \x20   return {upper}_OK;\n\
         }}\n\n"
    );
    Ok(MapC { header, source })
}

/// The end of a map's `_push` (the float map's and the integer map's): the accepted sample stored
/// twice in the window (so that the last N are contiguous from `next`), the write position and the
/// count moved on, and `OK` returned.
pub(super) fn window_store(upper: &str, nu: usize) -> String {
    let store_inputs = if nu > 0 {
        format!(
            "    for (i = 0u; i < {upper}_INPUTS; ++i) {{\n\
             \x20       observer->u[slot][i] = u[i];\n\
             \x20       observer->u[slot + {upper}_HORIZON][i] = u[i];\n\
             \x20   }}\n"
        )
    } else {
        "    (void)u;\n".to_owned()
    };
    format!(
        "    slot = observer->next;\n\
         \x20   for (i = 0u; i < {upper}_OUTPUTS; ++i) {{\n\
         \x20       observer->y[slot][i] = y[i];\n\
         \x20       observer->y[slot + {upper}_HORIZON][i] = y[i];\n\
         \x20   }}\n\
         {store_inputs}\
         \x20   observer->next = slot + 1u >= {upper}_HORIZON ? 0u : slot + 1u;\n\
         \x20   observer->filled += (unsigned)(observer->filled < {upper}_HORIZON);\n\
         \x20   return {upper}_OK;\n"
    )
}
