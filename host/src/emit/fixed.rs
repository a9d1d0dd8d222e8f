//! The integer map of a design that asks for it (`[chip] arithmetic = "fixed"`) as Rust: the raw
//! ranges and scalings, each target's integers with its proven bound and its overflow proof (checked
//! again by the compiler, [`firmware::emitted::fixed::reach`]), the design for [`firmware::fixed::Observer`]
//! with the range check and the dot products written out, and the recorded sequence in raw counts.

use crate::fixed_point::{raw_rows, FixedPoint};
use crate::spec::{Design, RawScale};

/// The section appended to the design's module.
pub fn fixed_source(design: &Design, fixed: &FixedPoint, recorded: &[crate::recording::Row]) -> String {
    let (n, ny, nu) = (design.map.horizon, fixed.outputs.len(), fixed.inputs.len());
    let ranges = |scales: &[RawScale]| {
        let cells: Vec<String> = scales.iter().map(|s| format!("[{}, {}]", s.min, s.max)).collect();
        format!("[{}]", cells.join(", "))
    };
    let pairs = |scales: &[RawScale]| {
        let cells: Vec<String> = scales
            .iter()
            .map(|s| format!("({:?}, {:?})", s.scale, s.offset))
            .collect();
        format!("[{}]", cells.join(", "))
    };
    let mut text = format!(
        "\n\n// The map in integers (`[chip] arithmetic = \"fixed\"`), for chips without an FPU: see\n\
         // [`firmware::fixed`] for the formula and `host::fixed_point` for the proof.\n\n\
         /// Each output's raw range `[min, max]`, as [`fixed_observer`] takes it: a sample outside is refused.\n\
         pub const RAW_OUTPUT_RANGES: [[i32; 2]; OUTPUTS] = {};\n\
         /// Each input's raw range `[min, max]`.\n\
         pub const RAW_INPUT_RANGES: [[i32; 2]; INPUTS] = {};\n\
         /// Each output's `(scale, offset)`: its value in [`OUTPUT_UNITS`] is `offset + scale · raw` (the\n\
         /// spec's `[chip.raw]`, or the default 16-bit Q format). Not read on the chip: the gains hold it.\n\
         pub const RAW_OUTPUT_SCALES: [(f64, f64); OUTPUTS] = {};\n\
         /// Each input's `(scale, offset)`, in [`INPUT_UNITS`].\n\
         pub const RAW_INPUT_SCALES: [(f64, f64); INPUTS] = {};\n\
         /// Each target's LSB: an integer estimate `e` is `e · FIXED_LSB[t]` in [`TARGET_UNITS`].\n\
         pub const FIXED_LSB: [f64; TARGETS] = [{}];\n\
         /// Each target's proven `|fixed-point estimate − f64 map|`, in [`TARGET_UNITS`] (see its map).\n\
         pub const FIXED_BOUND: [f64; TARGETS] = [{}];\n",
        ranges(&fixed.outputs),
        ranges(&fixed.inputs),
        pairs(&fixed.outputs),
        pairs(&fixed.inputs),
        fixed
            .targets
            .iter()
            .map(|t| format!("{:?}", t.lsb()))
            .collect::<Vec<_>>()
            .join(", "),
        fixed
            .targets
            .iter()
            .map(|t| format!("{:.2e}", t.stated_bound()))
            .collect::<Vec<_>>()
            .join(", "),
    );
    let mut maps = Vec::new();
    let mut uppers: Vec<String> = Vec::new();
    for (target, spec_target) in fixed.targets.iter().zip(&design.targets) {
        let upper = spec_target.name.to_uppercase();
        let range = target.range;
        let b = &target.bound;
        let gains: Vec<String> = target.gains.iter().map(|g| format!("    {g},")).collect();
        let segments: Vec<String> = target
            .segments
            .iter()
            .map(|[a, b]| format!("    [{a}, {b}],"))
            .collect();
        text += &format!(
            "\n/// Gains of `{name}` in integers: the float gains times each signal's scale, times 2^{f}, rounded.\n\
             const FIXED_GAINS_{upper}: [i32; REGRESSOR_LEN] = [\n{gains}\n];\n\n\
             /// `(A_k, B_k)`: `{name}` at knot `k` and its slope per unit of `t`, in its LSB 2^{minus}{r}.\n\
             #[rustfmt::skip]\n\
             const FIXED_SEGMENTS_{upper}: [[i32; 2]; {k}] = [\n{segments}\n];\n\n\
             /// `{name}` in integers: `t` in 2^-{f}, position {p} bits, LSB 2^{minus}{r}. Proven: |fixed − f64 map| ≤ {total:.2e}\n\
             /// ({share:.3} % of the range: the table's {table:.2e}, the gains' rounding {gains_term:.2e}, the\n\
             /// integer table {evaluation:.2e}). No overflow for samples in range: |C| + Σ|G_i| M_i + K 2^F =\n\
             /// {reach} ≤ 2³¹ − 1, checked below at compile time.\n\
             pub const FIXED_MAP_{upper}: firmware::emitted::fixed::FixedMap<'static> = firmware::emitted::fixed::FixedMap {{\n    \
                 gains: &FIXED_GAINS_{upper},\n    offset: {offset},\n    table: firmware::emitted::fixed::FixedTable {{\n        \
                 segments: &FIXED_SEGMENTS_{upper},\n        fraction_bits: {f},\n        dropped_bits: {dropped},\n        \
                 product_bits: {p},\n        t_last: {t_last},\n    }},\n}};\n\n\
             const _: () = assert!(\n    firmware::emitted::fixed::reach(&FIXED_MAP_{upper}, HORIZON, &RAW_OUTPUT_RANGES, &RAW_INPUT_RANGES) <= i32::MAX as i64\n);\n",
            name = spec_target.name,
            gains = gains.join("\n"),
            segments = segments.join("\n"),
            k = target.segments.len(),
            f = target.fraction_bits,
            p = target.product_bits,
            dropped = target.fraction_bits - target.product_bits,
            minus = if target.lsb_bits >= 0 { "-" } else { "" },
            r = target.lsb_bits.abs(),
            total = target.stated_bound(),
            share = 100.0 * b.total() / range,
            table = b.table,
            gains_term = b.gains,
            evaluation = b.evaluation,
            reach = target.reach,
            offset = target.offset,
            t_last = target.t_last(),
        );
        maps.push(format!("FIXED_MAP_{upper}"));
        uppers.push(upper);
    }
    // Every target's sum over the window, interleaved: each window value is loaded once and added
    // to every target that weighs it, so that no core with few registers (the Cortex-M0 has 8 low
    // ones) holds one target's values for the next (integers: any order gives the same bits).
    let entries = interleaved(fixed, n, ny, nu);
    let weighed = |t: usize| entries.iter().any(|e| e.gains.iter().any(|&(g, _)| g == t));
    let mut dots = String::new();
    for (t, upper) in uppers.iter().enumerate() {
        let mutable = if weighed(t) { "mut " } else { "" };
        dots += &format!("        let {mutable}t{t} = FIXED_MAP_{upper}.offset;\n");
    }
    for Entry {
        field,
        sample,
        entry,
        gains,
    } in &entries
    {
        dots += &format!("        let z = w[{sample}].{field}[{entry}];\n");
        for (t, gain) in gains {
            dots += &format!(
                "        t{t} = t{t}.wrapping_add(FIXED_GAINS_{}[{gain}].wrapping_mul(z));\n",
                uppers[*t]
            );
        }
    }
    // Every target's clamp signs through one `black_box` (FixedTable::signs says why), then the tables.
    let masks: Vec<String> = uppers
        .iter()
        .enumerate()
        .map(|(t, upper)| format!("FIXED_MAP_{upper}.table.signs(t{t})"))
        .collect();
    let clamped: Vec<String> = uppers
        .iter()
        .enumerate()
        .map(|(t, upper)| format!("            FIXED_MAP_{upper}.table.clamped(t{t}, signs[{t}]),"))
        .collect();
    let tables = format!(
        "        let signs = core::hint::black_box([{}]);\n        [\n{}\n        ]",
        masks.join(", "),
        clamped.join("\n")
    );
    let checks: Vec<String> = fixed
        .outputs
        .iter()
        .enumerate()
        .map(|(i, s)| format!("firmware::emitted::fixed::in_range(y[{i}], {}, {})", s.min, s.max))
        .chain(
            fixed
                .inputs
                .iter()
                .enumerate()
                .map(|(i, s)| format!("firmware::emitted::fixed::in_range(u[{i}], {}, {})", s.min, s.max)),
        )
        .collect();
    let unused = match (ny, nu) {
        (0, 0) => "let _ = (y, u);\n        ",
        (_, 0) => "let _ = u;\n        ",
        (0, _) => "let _ = y;\n        ",
        _ => "",
    };
    let rows = |rows: Vec<Vec<i32>>| {
        rows.iter()
            .map(|row| {
                format!(
                    "    [{}],",
                    row.iter().map(i32::to_string).collect::<Vec<_>>().join(", ")
                )
            })
            .collect::<Vec<_>>()
            .join("\n")
    };
    let y: Vec<Vec<f64>> = recorded.iter().map(|r| r.y.clone()).collect();
    let u: Vec<Vec<f64>> = recorded.iter().map(|r| r.u.clone()).collect();
    text += &format!(
        "\n/// This design in integers, for [`firmware::fixed::Observer`]: the range check and the dot products\n\
         /// written out.\n\
         pub struct Fixed;\n\n\
         impl firmware::emitted::fixed::FixedDesign<HORIZON, OUTPUTS, INPUTS, TARGETS> for Fixed {{\n    \
             const MAPS: [firmware::emitted::fixed::FixedMap<'static>; TARGETS] = [{maps}];\n    \
             const OUTPUT_RANGES: [[i32; 2]; OUTPUTS] = RAW_OUTPUT_RANGES;\n    \
             const INPUT_RANGES: [[i32; 2]; INPUTS] = RAW_INPUT_RANGES;\n\n    \
             #[inline(always)]\n    \
             fn accepts(y: &[i32; OUTPUTS], u: &[i32; INPUTS]) -> bool {{\n        {unused}{checks}\n    }}\n\n    \
             #[inline(always)]\n    \
             fn estimate(w: &[Sample<i32, OUTPUTS, INPUTS>; HORIZON]) -> [Estimate<i32>; TARGETS] {{\n{dots}{tables}\n    }}\n}}\n\n\
         /// The fixed-point observer: raw counts in ([`RAW_OUTPUT_RANGES`]), estimates in [`FIXED_LSB`] out.\n\
         pub type FixedObserver = firmware::fixed::Observer<Fixed, HORIZON, OUTPUTS, INPUTS, TARGETS>;\n\n\
         /// A fixed-point observer with no samples yet.\n\
         #[must_use]\n\
         pub const fn fixed_observer() -> FixedObserver {{\n    FixedObserver::new()\n}}\n\n\
         /// [`RECORDED_Y`] in raw counts (rounded and clamped as a converter would); its refused samples are\n\
         /// `max + 1`, out of range, so that the fixed-point observer refuses them too, and its last `2 N`\n\
         /// samples are every signal's raw minimum, then maximum, so that whoever runs it sees the tables\n\
         /// saturate (and can check that the chip takes the same instructions then).\n\
         #[rustfmt::skip]\n\
         pub const RECORDED_RAW_Y: [[i32; OUTPUTS]; RECORDED_LEN] = [\n{raw_y}\n];\n\n\
         /// [`RECORDED_U`] in raw counts.\n\
         #[rustfmt::skip]\n\
         pub const RECORDED_RAW_U: [[i32; INPUTS]; RECORDED_LEN] = [\n{raw_u}\n];",
        maps = maps.join(", "),
        checks = if checks.is_empty() { "true".to_owned() } else { checks.join(" & ") },
        tables = tables,
        raw_y = rows(saturating_end(raw_rows(&y, &fixed.outputs), &fixed.outputs, n)),
        raw_u = rows(saturating_end(raw_rows(&u, &fixed.inputs), &fixed.inputs, n)),
    );
    text
}

/// One value of the window and every target's non-zero gain on it.
pub(super) struct Entry {
    /// `"y"` or `"u"`.
    pub field: &'static str,
    /// The sample of the window, oldest first.
    pub sample: usize,
    /// Which output or input.
    pub entry: usize,
    /// `(target, gain index)`.
    pub gains: Vec<(usize, usize)>,
}

/// The window's values in regressor order, each with every target's non-zero gain on it.
pub(super) fn interleaved(fixed: &FixedPoint, horizon: usize, outputs: usize, inputs: usize) -> Vec<Entry> {
    let mut entries: Vec<Entry> = Vec::new();
    for (t, target) in fixed.targets.iter().enumerate() {
        let nonzero: Vec<f32> = target.gains.iter().map(|&g| g as f32).collect();
        for term in super::terms::dot_terms(&nonzero, horizon, outputs, inputs) {
            let field = if term.input { "u" } else { "y" };
            match entries
                .iter_mut()
                .find(|e| (e.field, e.sample, e.entry) == (field, term.sample, term.entry))
            {
                Some(e) => e.gains.push((t, term.gain)),
                None => entries.push(Entry {
                    field,
                    sample: term.sample,
                    entry: term.entry,
                    gains: vec![(t, term.gain)],
                }),
            }
        }
    }
    // Regressor order: outputs before inputs, newest sample first.
    entries.sort_by_key(|e| (e.field == "u", std::cmp::Reverse(e.sample), e.entry));
    entries
}

/// `rows` with its last `2 N` samples replaced by every signal's raw minimum (`N` samples), then its
/// maximum (`N`), when at least `N` samples of the recording are left before them; a refused sample
/// among them stays as it is.
fn saturating_end(mut rows: Vec<Vec<i32>>, scales: &[RawScale], horizon: usize) -> Vec<Vec<i32>> {
    let len = rows.len();
    if len >= 3 * horizon {
        for (k, row) in rows.iter_mut().enumerate().skip(len - 2 * horizon) {
            // The refused samples stay: every consumer checks them.
            if row.iter().zip(scales).all(|(v, s)| (s.min..=s.max).contains(v)) {
                let high = k >= len - horizon;
                *row = scales.iter().map(|s| if high { s.max } else { s.min }).collect();
            }
        }
    }
    rows
}
