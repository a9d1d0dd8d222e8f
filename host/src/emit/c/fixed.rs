//! The map in integers in C (`<name>_fixed`), for a design whose spec asks for it: the same integers
//! as the Rust design file ([`crate::fixed_point::FixedPoint`]) and the operations of
//! `firmware::fixed::FixedTable::evaluate`, so that both give the same bits. The window holds
//! raw counts (each stored twice, as `firmware::Window`); a sample outside its declared range is
//! refused, which is what keeps the sums within 32 bits (the proof is in the Rust file and the
//! report).

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
            "\x20* {field}[{i}] (`{label}`): raw in [{min}, {max}], value = {offset:?} + {scale:?} * raw\n",
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
            "\x20* estimate {t} (`{}`): LSB 2^{}, proven |fixed - f64 map| <= {:.2e}\n",
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
    let inputs_field = if nu > 0 {
        format!("    int32_t u[2u * {upper}_HORIZON][{upper}_INPUTS];\n")
    } else {
        String::new()
    };
    let header = format!(
        "/* The map in integers, for chips without an FPU: raw converter counts in, each estimate an\n\
         \x20* integer in its target's LSB out, no float operation. Samples (a sample with a value outside\n\
         \x20* its range is refused: the proof that no sum overflows holds there):\n\
         {ranges}\
         \x20* Estimates (value = integer * LSB, in the target's unit):\n\
         {targets}\
         \x20* Allocate it anywhere (no heap is used) and call {name}_fixed_init. */\n\
         /* Estimate t's scale, in its target's unit: value = integer * 2^{upper}_FIXED_LSB_EXPONENT_t,\n\
         \x20* which is integer * {upper}_FIXED_LSB_t (a float, exact: a power of two). */\n\
         {scales}\
         typedef struct {{\n\
         \x20   int32_t y[2u * {upper}_HORIZON][{upper}_OUTPUTS];\n\
         {inputs_field}\
         \x20   unsigned next;\n\
         \x20   unsigned filled;\n\
         }} {name}_fixed;\n\
         \n\
         /* Empties the window. */\n\
         void {name}_fixed_init({name}_fixed *observer);\n\
         \n\
         /* Takes the raw sample of the current instant (u may be NULL when there is no input): {upper}_OK,\n\
         \x20* or {upper}_REFUSED for a value outside its range (the observer is unchanged). */\n\
         {name}_status {name}_fixed_push({name}_fixed *observer, const int32_t *y, const int32_t *u);\n\
         \n\
         /* Every target's estimate (in its LSB) into values[{upper}_TARGETS] and saturation[{upper}_TARGETS];\n\
         \x20* {upper}_NO_ESTIMATE_YET (nothing written) before the window is full. */\n\
         {name}_status {name}_fixed_estimate(const {name}_fixed *observer, int32_t *values, {name}_saturation *saturation);\n\
         \n"
    );
    let store = super::map::window_store(&upper, nu);
    let source = format!(
        "{tables}\n\
         /* Signed right shifts must be arithmetic (implementation-defined in C99; so on gcc, clang, armcc\n\
         \x20* and IAR): checked at compile time. */\n\
         typedef char fixed_shifts_are_arithmetic[((-8) >> 1) == -4 ? 1 : -1];\n\
         \n\
         /* a - b modulo 2^32 (no signed overflow, which C leaves undefined): t_last - t for any t. */\n\
         static int32_t wrapping_sub(int32_t a, int32_t b) {{\n\
         \x20   return (int32_t)((uint32_t)a - (uint32_t)b);\n\
         }}\n\
         \n\
         /* min <= v <= max, as one unsigned comparison. */\n\
         static int in_range(int32_t v, int32_t min, int32_t max) {{\n\
         \x20   return (uint32_t)v - (uint32_t)min <= (uint32_t)max - (uint32_t)min;\n\
         }}\n\
         \n\
         /* firmware::fixed::FixedTable::evaluate: t clamped to the table [0, t_last] by sign masks (no\n\
         \x20* branch: the same instructions whatever t is), then the segment and the position in it by shifts. */\n\
         static void fixed_evaluate(int32_t t, const int32_t segments[][2], unsigned f, unsigned dropped, unsigned p,\n\
         \x20                          int32_t t_last, int32_t *value, {name}_saturation *saturation) {{\n\
         \x20   const int32_t low = t >> 31;\n\
         \x20   const int32_t high = (wrapping_sub(t_last, t) >> 31) & ~low;\n\
         \x20   int32_t k;\n\
         \x20   int32_t position;\n\
         \x20   t &= ~low;\n\
         \x20   t ^= (t ^ t_last) & high;\n\
         \x20   k = t >> f;\n\
         \x20   position = (t - (int32_t)((uint32_t)k << f)) >> dropped;\n\
         \x20   *value = segments[k][0] + ((segments[k][1] * position) >> p);\n\
         \x20   *saturation = ({name}_saturation)((unsigned)(low & 1) | ((unsigned)high & 2u));\n\
         }}\n\
         \n\
         void {name}_fixed_init({name}_fixed *observer) {{\n\
         \x20   observer->next = 0u;\n\
         \x20   observer->filled = 0u;\n\
         }}\n\
         \n\
         {name}_status {name}_fixed_push({name}_fixed *observer, const int32_t *y, const int32_t *u) {{\n\
         \x20   unsigned i;\n\
         \x20   unsigned slot;\n\
         \x20   int inside = 1;\n\
         {checks}\
         \x20   if (!inside) {{\n\
         \x20       return {upper}_REFUSED;\n\
         \x20   }}\n\
         {store}\
         }}\n\
         \n\
         /* The sums are in int32_t: every stored sample is in range, where the proof says they fit. */\n\
         {name}_status {name}_fixed_estimate(const {name}_fixed *observer, int32_t *values, {name}_saturation *saturation) {{\n\
         \x20   const unsigned next = observer->next;\n\
         \x20   if (observer->filled < {upper}_HORIZON) {{\n\
         \x20       return {upper}_NO_ESTIMATE_YET;\n\
         \x20   }}\n\
         {projections}\
         {estimates}\
         \x20   return {upper}_OK;\n\
         }}\n\n"
    );
    FixedC { header, source }
}
