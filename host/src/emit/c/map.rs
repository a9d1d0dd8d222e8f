//! The map in C (`<name>_map`): the same f32 tables as the Rust design file
//! ([`crate::emit::precision::F32Tables`]), the dot product summed term by term in the Rust file's
//! order ([`crate::emit::terms::dot_terms`]) and the certified `Γ⁻¹` table evaluated as
//! `firmware::InverseTable::evaluate` does, saturation flags included. The observer is the last `N`
//! samples, each stored twice so that the window is always contiguous (as `firmware::Window`).

use askama::Template;

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
    // alias it, which makes the compiler read it again for each target). Row by row: the targets',
    // then the helper maps' ([`crate::fit::helpers`]), which only `start_map_estimate` computes.
    let mut rows: Vec<(String, String)> = Vec::new();
    let labels = (result
        .targets
        .iter()
        .map(|t| (format!("target `{}`", design.targets[t.index].name), t)))
    .chain(
        result
            .helpers
            .iter()
            .flatten()
            .map(|t| (format!("helper map `{}`", design.model.states[t.index]), t)),
    );
    for (t, (label, target)) in labels.enumerate() {
        let label = &label;
        let Some(table) = target.fit.map.table.as_ref() else {
            return Err(EmitError::NoTable { target: label.clone() });
        };
        let rounded = F32Tables::new(table);
        let what = |field: &str| format!("{label} {field}");
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
            "\n/* {label}: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */\n\
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
        let projection = format!(
            "    const float t_{t} = {offset}{terms};\n",
            offset = float(&what("offset"), f64::from(rounded.offset))?
        );
        let estimate = format!(
            "{search}    evaluate(t_{t}, {segment}, {start}, {t_max}, {r_min}, {r_max}, &values[{t}], &saturation[{t}]);\n",
            t_max = float(&what("t_max"), f64::from(rounded.t_max))?,
            r_min = float(&what("r_min"), f64::from(rounded.r_min))?,
            r_max = float(&what("r_max"), f64::from(rounded.r_max))?,
        );
        rows.push((projection, estimate));
    }
    let nt = result.targets.len();
    let text = |rows: &[(String, String)]| -> (String, String) {
        (
            rows.iter().map(|r| r.0.as_str()).collect(),
            rows.iter().map(|r| r.1.as_str()).collect(),
        )
    };
    let (projections, estimates) = text(&rows[..nt]);
    let start = if rows.len() == nt {
        format!("\n#define {upper}_MAP_ROWS {upper}_TARGETS\n#define start_map_estimate {name}_map_estimate\n")
    } else {
        let (projections, estimates) = text(&rows);
        format!(
            "\n/* The map the map-started kinds read: the targets' rows, then a helper map per state that no\n \
             * target is. */\n#define {upper}_MAP_ROWS {rows}u\n\
             static inline {name}_status start_map_estimate(const {name}_map *observer, float *values, {name}_saturation *saturation) {{\n    \
             const unsigned next = observer->next;\n    \
             if (observer->filled < {upper}_HORIZON) {{\n        return {upper}_NO_ESTIMATE_YET;\n    }}\n\
             {projections}{estimates}    return {upper}_OK;\n}}\n",
            rows = rows.len()
        )
    };
    let header = super::text::render(&MapH {
        name,
        upper: &upper,
        inputs: nu > 0,
    });
    let source = super::text::render(&MapSource {
        name,
        upper: &upper,
        inputs: nu > 0,
        tables: &tables,
        // Only where a table of more than one segment is uniform: an unused static function is a
        // warning.
        uniform: rows.iter().any(|r| r.1.contains("uniform_segment(")),
        projections: &projections,
        estimates: &estimates,
    }) + &start;
    Ok(MapC { header, source })
}

/// The map's part of the header.
#[derive(Template)]
#[template(path = "c/map.h", escape = "none")]
struct MapH<'a> {
    name: &'a str,
    upper: &'a str,
    inputs: bool,
}

/// The map's part of the source: `tables`, then the code, which computes every projection first
/// (`projections`), then every table (`estimates`).
#[derive(Template)]
#[template(path = "c/map.c", escape = "none")]
struct MapSource<'a> {
    name: &'a str,
    upper: &'a str,
    inputs: bool,
    tables: &'a str,
    uniform: bool,
    projections: &'a str,
    estimates: &'a str,
}
