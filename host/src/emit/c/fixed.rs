//! The map in integers in C (`<name>_fixed`), for a design whose spec asks for it: the same integers
//! as the Rust design file ([`crate::fixed_point::FixedPoint`]) and the operations of
//! `firmware::fixed::FixedTable::evaluate`, so that both give the same bits. The window holds
//! raw counts (each stored twice, as `firmware::Window`); a sample outside its declared range is
//! refused, which is what keeps the sums within 32 bits (the proof is in the Rust file and the
//! report).

use askama::Template;

use crate::fixed_point::FixedPoint;
use crate::spec::Design;

/// The fixed-point map's part of the header and of the source.
pub(super) struct FixedC {
    /// `<name>_fixed` and its functions' prototypes.
    pub header: String,
    /// The integers and the code.
    pub source: String,
}

/// The C of `design`'s integer map `fixed`.
pub(super) fn fixed(design: &Design, fixed: &FixedPoint) -> FixedC {
    let name = &design.name;
    let upper = name.to_uppercase();
    let (n, ny, nu) = (design.map.horizon, fixed.outputs.len(), fixed.inputs.len());
    let signals: Vec<(&str, &str, &crate::spec::RawScale)> = design
        .model
        .outputs
        .iter()
        .zip(&fixed.outputs)
        .map(|(o, s)| ("y", o.name.as_str(), s))
        .chain(
            design
                .model
                .inputs
                .iter()
                .zip(&fixed.inputs)
                .map(|(i, s)| ("u", i.as_str(), s)),
        )
        .collect();
    let mut ranges = String::new();
    let mut checks = String::new();
    let mut index = [0usize; 2];
    for (field, label, scale) in &signals {
        let i = &mut index[usize::from(*field == "u")];
        ranges += &format!(
            " * {field}[{i}] (`{label}`): raw in [{min}, {max}], value = {offset:?} + {scale:?} * raw\n",
            min = scale.min,
            max = scale.max,
            offset = scale.offset,
            scale = scale.scale,
        );
        checks += &format!("    inside &= in_range({field}[{i}], {}, {});\n", scale.min, scale.max);
        *i += 1;
    }
    let mut targets = String::new();
    let mut scales = String::new();
    let (mut tables, mut projections, mut estimates) = (String::new(), String::new(), String::new());
    for (t, (target, spec_target)) in fixed.targets.iter().zip(&design.targets).enumerate() {
        targets += &format!(
            " * estimate {t} (`{}`): LSB 2^{}, proven |fixed - f64 map| <= {:.2e}\n",
            spec_target.name,
            -target.lsb_bits,
            target.stated_bound()
        );
        scales += &format!(
            "#define {upper}_FIXED_LSB_EXPONENT_{t} ({exponent})\n\
             #define {upper}_FIXED_LSB_{t} {lsb:e}f\n",
            exponent = -target.lsb_bits,
            lsb = target.lsb() as f32,
        );
        let gains: Vec<String> = target.gains.iter().map(i32::to_string).collect();
        let segments: Vec<String> = target
            .segments
            .iter()
            .map(|[a, b]| format!("    {{ {a}, {b} }}"))
            .collect();
        tables += &format!(
            "\n/* `{label}` in integers: gains in regressor order (2^-{f} per count), then (A_k, B_k) in its LSB. */\n\
             static const int32_t FIXED_GAINS_{t}[{len}] = {{ {gains} }};\n\
             static const int32_t FIXED_SEGMENTS_{t}[{k}][2] = {{\n{segments}\n}};\n",
            label = spec_target.name,
            f = target.fraction_bits,
            len = gains.len(),
            gains = gains.join(", "),
            k = target.segments.len(),
            segments = segments.join(",\n"),
        );
        projections += &format!("    int32_t t_{t} = {};\n", target.offset);
        estimates += &format!(
            "    fixed_evaluate(t_{t}, FIXED_SEGMENTS_{t}, {f}u, {dropped}u, {p}u, {t_last}, &values[{t}], &saturation[{t}]);\n",
            f = target.fraction_bits,
            dropped = target.fraction_bits - target.product_bits,
            p = target.product_bits,
            t_last = target.t_last(),
        );
    }
    // Every target's sum in one pass, each sample read once (as the Rust file does).
    for crate::emit::fixed::Entry {
        field,
        sample,
        entry,
        gains,
    } in crate::emit::fixed::interleaved(fixed, n, ny, nu)
    {
        projections += &format!("    {{\n        const int32_t z = observer->{field}[next + {sample}u][{entry}];\n");
        for (t, gain) in gains {
            projections += &format!("        t_{t} += FIXED_GAINS_{t}[{gain}] * z;\n");
        }
        projections += "    }\n";
    }
    let header = super::text::render(&FixedH {
        name,
        upper: &upper,
        inputs: nu > 0,
        ranges: &ranges,
        targets: &targets,
        scales: &scales,
    });
    let source = super::text::render(&FixedSource {
        name,
        upper: &upper,
        inputs: nu > 0,
        tables: &tables,
        checks: &checks,
        projections: &projections,
        estimates: &estimates,
    });
    FixedC { header, source }
}

/// The integer map's part of the header: `ranges` and `targets` are lines of its comment, `scales`
/// the estimates' scale macros.
#[derive(Template)]
#[template(path = "c/fixed.h", escape = "none")]
struct FixedH<'a> {
    name: &'a str,
    upper: &'a str,
    inputs: bool,
    ranges: &'a str,
    targets: &'a str,
    scales: &'a str,
}

/// The integer map's part of the source: `tables`, then the code (`checks`: each value's range).
#[derive(Template)]
#[template(path = "c/fixed.c", escape = "none")]
struct FixedSource<'a> {
    name: &'a str,
    upper: &'a str,
    inputs: bool,
    tables: &'a str,
    checks: &'a str,
    projections: &'a str,
    estimates: &'a str,
}
