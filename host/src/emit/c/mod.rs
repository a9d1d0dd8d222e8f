//! A design's observers as portable C99 source (`<name>.h`, `<name>.c`), emitted from the same f32
//! tables and the same straight-line programs as the Rust design file, operation for operation, so
//! that without fused multiply-add the C observer gives the Rust observer's bits. One module per
//! piece: `map` (the map), `program` (a program as a C function, the model's functions: `exp` as
//! libm computes it, the correctly rounded ones from `<math.h>`; others would come from the C
//! library, within an ulp of Rust's), `filters` (the EKF kinds), `started` (what the observers the
//! map starts share), `corrected`, `mhe`, and `storage` (the Rust static library's interface over the
//! chosen kind).
//!
//! C99 with `float` only: no `malloc`, no recursion, no VLA, no global mutable state; `<math.h>` only
//! where the model calls a function; a value is finite when its exponent bits are not all ones. Each
//! kind is a struct the caller allocates (`<name>_<kind>`) with `_init`, `_push` and `_estimate`, the
//! Rust observer's `new`, `push` and `estimate`; `<name>_observer` names the design's chosen kind.

mod box_filter;
mod corrected;
mod filters;
mod fixed;
mod map;
mod mhe;
mod program;
mod started;
mod storage;

pub use storage::{mark, sample_period, storage_bound, MARK_BYTES};

use super::model::Observers;
use super::EmitError;
use crate::fit::DesignResult;
use crate::plant::ModelCode;
use crate::spec::Design;

/// The first word (up to its first `_`, lower case) of every name the C interface appends to a
/// design's `<name>_` or `<NAME>_`, besides the observer kinds' names ([`c_name_clash`] adds those
/// from the registry): types, calls, enum values and macros of the C source's header, of the Rust
/// static library's header and its symbols. `tests/tests/integration/c_source.rs` checks that every name in
/// every emitted header starts with one of them, so that a new suffix cannot slip past the check.
pub const C_SUFFIX_WORDS: &[&str] = &[
    "bad",
    "covariance",
    "estimate",
    "fixed",
    "h",
    "high",
    "horizon",
    "init",
    "inputs",
    "inside",
    "kind",
    "low",
    "no",
    "not",
    "observer",
    "ok",
    "outputs",
    "push",
    "refused",
    "sample",
    "saturation",
    "states",
    "status",
    "storage",
    "stored",
    "targets",
];

/// Whether designs `a` and `b`, written by one `gen` run, could declare the same C name; then the
/// word of the longer name that one of the shorter's names also begins with (the `map` of `vdp` and
/// `vdp_map`: `vdp_map_init` is both `vdp`'s map observer's `init` and `vdp_map`'s `init`).
///
/// Why refuse rather than rename: every C name is the design's name followed by `_` and a suffix
/// (`vdp_map`, `vdp_map_init`, `VDP_OK`), so a name users type and read in their firmware and in every
/// document stays the design's own; giving it a prefix or a separator (`vdp__map`) only for some
/// designs would make the names depend on which other specs were in the run. Two names can only
/// clash when one is the other followed by `_` and a word the interface appends (a name `b_Y` equal
/// to `a_X` needs `X` to begin with the rest of `b` after `a_`), so refusing exactly those pairs,
/// where the specs are read and before anything is fitted, leaves every other name free
/// (`vanderpol` beside `vanderpol_uncertain`). Designs written by separate runs are not compared:
/// linking two of them into one program is the user's choice of names.
pub fn c_name_clash(a: &str, b: &str) -> Option<String> {
    let (short, long) = if a.len() <= b.len() { (a, b) } else { (b, a) };
    let rest = long.strip_prefix(short)?.strip_prefix('_')?;
    let word = rest.split('_').next().unwrap_or(rest).to_ascii_lowercase();
    let a_kind = crate::observers::kind::REGISTRY
        .iter()
        .any(|k| k.kind.name().split('_').next() == Some(word.as_str()));
    let clashes = a_kind || C_SUFFIX_WORDS.contains(&word.as_str());
    clashes.then_some(word)
}

/// The header and the source of a design.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CSource {
    /// `<name>.h`.
    pub header: String,
    /// `<name>.c`.
    pub source: String,
}

/// A C `float` literal of `value` rounded to f32: the shortest decimal that round-trips, with `f`.
fn float(what: &str, value: f64) -> Result<String, EmitError> {
    Ok(format!("{}f", super::f32_literal(what, value)?))
}

/// `{ a, b, … }` of `values` (each rounded to f32), four per line.
fn floats(what: &str, values: &[f64]) -> Result<String, EmitError> {
    let items = values
        .iter()
        .enumerate()
        .map(|(i, &v)| float(&format!("{what}[{i}]"), v))
        .collect::<Result<Vec<_>, _>>()?;
    let lines: Vec<String> = items.chunks(4).map(|c| format!("    {}", c.join(", "))).collect();
    Ok(format!("{{\n{}\n}}", lines.join(",\n")))
}

/// The C source of `design`: its map (tables in `result`) and, given its model's programs and the
/// observers the Rust file has, every model-based kind.
pub fn c_source(
    design: &Design,
    result: &DesignResult,
    model: Option<(&ModelCode, &Observers<'_>)>,
) -> Result<CSource, EmitError> {
    let name = &design.name;
    let upper = name.to_uppercase();
    let (n, ny, nu, nt) = (
        design.map.horizon,
        design.model.outputs.len(),
        design.model.inputs.len(),
        design.targets.len(),
    );
    let map = map::map(design, result)?;
    let integer = match model.and_then(|(_, observers)| observers.fixed) {
        Some(point) => fixed::fixed(design, point),
        None => fixed::FixedC {
            header: String::new(),
            source: String::new(),
        },
    };
    let kinds = match model {
        Some((code, observers)) => filters::kinds(design, code, observers)?,
        None => filters::Kinds::default(),
    };
    let chosen = model.map(|(_, o)| o.kind.name());
    let (interface_header, interface_source) = match chosen {
        Some(kind) if kind == "map" || kinds.names.contains(&kind) => storage::storage_interface(design),
        _ => (String::new(), String::new()),
    };
    let alias = match chosen {
        Some(kind) if kind == "map" || kinds.names.contains(&kind) => format!(
            "/* This design's observer, of the kind `gen` chose or the spec named: {kind}. */\n\
             #define {upper}_KIND \"{kind}\"\n\
             typedef {name}_{kind} {name}_observer;\n\
             #define {name}_observer_init {name}_{kind}_init\n\
             #define {name}_observer_push {name}_{kind}_push\n\
             #define {name}_observer_estimate {name}_{kind}_estimate\n\n"
        ),
        Some(kind) => format!(
            "/* This design's observer is of kind {kind}, which has no C form: use the Rust crate. */\n\
             #define {upper}_KIND \"{kind}\"\n\n"
        ),
        None => String::new(),
    };
    let sizes = match model {
        Some((code, _)) => format!(
            "#define {upper}_STATES {nx}\n\
             /* Entries of a filter's covariance kept: its upper triangle. */\n\
             #define {upper}_COVARIANCE {cov}\n",
            nx = code.dimensions.states,
            cov = crate::plant::kalman::triangle(code.dimensions.states)
        ),
        None => String::new(),
    };
    let header = format!(
        "/* The `{name}` observers in C99, emitted by `mho gen` from the same tables and programs as the\n\
         \x20* Rust design file. Do not edit: regenerate. Build with -ffp-contract=off (no fused\n\
         \x20* multiply-add) to get the Rust observers' bits. Every observer lives in a struct you allocate\n\
         \x20* (no heap); call its _init first, then _push every sample and _estimate when you need it.\n\
         {licence} */\n\
         #ifndef {upper}_H\n\
         #define {upper}_H\n\
         \n\
         #include <stddef.h>\n\
         #include <stdint.h>\n\
         \n\
         /* C linkage for a C++ program that includes this header (the observers are compiled as C). */\n\
         #ifdef __cplusplus\n\
         extern \"C\" {{\n\
         #endif\n\
         \n\
         #define {upper}_OUTPUTS {ny}\n\
         #define {upper}_INPUTS {nu}\n\
         #define {upper}_TARGETS {nt}\n\
         /* The map's window, in samples: no map estimate before it is full. */\n\
         #define {upper}_HORIZON {n}\n\
         /* The sample period the design assumes, in its time unit: push one sample every period. */\n\
         #define {upper}_SAMPLE_PERIOD {tau}\n\
         {sizes}\
         \n\
         /* What every call returns: the observers' push and estimate, and the storage calls (the same\n\
         \x20* values as the Rust static library's c/include/{name}.h). */\n\
         typedef enum {{\n\
         \x20   {upper}_OK = 0,\n\
         \x20   /* The sample was refused: a NaN or infinite value (or a filter step whose result is not\n\
         \x20    * finite); the latest estimate is unchanged. */\n\
         \x20   {upper}_REFUSED = 1,\n\
         \x20   /* No estimate yet (the map: fewer than {upper}_HORIZON accepted samples since init). */\n\
         \x20   {upper}_NO_ESTIMATE_YET = 2,\n\
         \x20   /* The storage calls only: a null pointer, or storage too small or misaligned; nothing done. */\n\
         \x20   {upper}_BAD_ARGUMENT = 3,\n\
         \x20   /* The storage calls only: the storage holds no observer of this design. */\n\
         \x20   {upper}_NOT_INITIALISED = 4\n\
         }} {name}_status;\n\
         \n\
         /* Where an estimate lies against its range: inside, or held at its low or high end (the same\n\
         \x20* values from every call that reports it). */\n\
         typedef enum {{\n\
         \x20   {upper}_INSIDE = 0,\n\
         \x20   {upper}_LOW = 1,\n\
         \x20   {upper}_HIGH = 2\n\
         }} {name}_saturation;\n\
         \n\
         {map_header}\
         {fixed_header}\
         {kinds_header}\
         {alias}\
         {interface_header}\
         #ifdef __cplusplus\n\
         }}\n\
         #endif\n\
         \n\
         #endif\n",
        licence = super::licence_comment(" * "),
        tau = storage::sample_period(design),
        map_header = map.header,
        fixed_header = integer.header,
        kinds_header = kinds.header,
    );
    let math = if kinds.needs_math { "#include <math.h>\n" } else { "" };
    let inputs_check = if nu > 0 {
        format!(
            "    for (i = 0u; i < {upper}_INPUTS; ++i) {{\n\
             \x20       finite &= is_finite(u[i]);\n\
             \x20   }}\n"
        )
    } else {
        "    (void)u;\n".to_owned()
    };
    let body = format!("{}{}{}{interface_source}", map.source, integer.source, kinds.source);
    // Only where a follower checks a sample (an unused static function is a warning).
    let accepts = if body.contains("accepts(") {
        format!(
            "/* 1 when every output and input of a sample is finite (u is not read without inputs). */\n\
             static int accepts(const float *y, const float *u) {{\n\
             \x20   unsigned i;\n\
             \x20   int finite = 1;\n\
             \x20   for (i = 0u; i < {upper}_OUTPUTS; ++i) {{\n\
             \x20       finite &= is_finite(y[i]);\n\
             \x20   }}\n\
             {inputs_check}\
             \x20   return finite;\n\
             }}\n\
             \n"
        )
    } else {
        String::new()
    };
    let source = format!(
        "/* The `{name}` observers in C99, emitted by `mho gen`. Do not edit: regenerate.\n\
         {licence} */\n\
         #include <stdint.h>\n\
         #include <string.h>\n\
         {math}\
         #include <float.h>\n\
         #include \"{name}.h\"\n\
         \n\
         /* The Rust observer's bits need every float operation rounded on its own: no fused multiply-add\n\
         \x20* (gcc: -ffp-contract=off, the default of its ISO modes such as -std=c99; other compilers follow\n\
         \x20* the standard pragma below), no -ffast-math, and float evaluated as float: FLT_EVAL_METHOD 0,\n\
         \x20* or 16 or 32 (ISO/IEC TS 18661-3: types narrower than _Float16, or _Float32, are evaluated in\n\
         \x20* it, so float stays float; gcc says 16 for a Cortex-M55 or with AVX512-FP16 in its GNU modes). */\n\
         #if !defined(__GNUC__) || defined(__clang__)\n\
         #pragma STDC FP_CONTRACT OFF\n\
         #endif\n\
         {flt_eval_check}\
         \n\
         \n\
         /* The bits of v (memcpy: no aliasing, no conversion). */\n\
         static uint32_t bits_of(float v) {{\n\
         \x20   uint32_t x;\n\
         \x20   memcpy(&x, &v, sizeof x);\n\
         \x20   return x;\n\
         }}\n\
         \n\
         /* 1 when v is finite: its exponent is not all ones (an integer test, as Rust's is_finite). */\n\
         static int is_finite(float v) {{\n\
         \x20   return (bits_of(v) & 0x7fffffffu) < 0x7f800000u;\n\
         }}\n\
         \n\
         {accepts}\
         {selects}\
         {body}",
        selects = selects(&body),
        licence = super::licence_comment(" * "),
        flt_eval_check = FLT_EVAL_CHECK,
    );
    Ok(CSource { header, source })
}

/// The source's check that `float` expressions are evaluated in `float`, by `FLT_EVAL_METHOD`
/// (C99 5.2.4.2.2, ISO/IEC TS 18661-3 for 16 and up): accepted are 0 and the TS's 16 and 32, under
/// which every type narrower than `_Float16` (resp. `_Float32`) is evaluated in it and `float` in
/// `float` (gcc reports 16 for `-mcpu=cortex-m55` and for x86 with AVX512-FP16 outside its ISO
/// modes); refused, each with its reason, are 1 (`float` evaluated in `double`), 2 (in `long double`,
/// e.g. the x87), -1 (indeterminate) and every other value (a wider format: 64, 33, …).
const FLT_EVAL_CHECK: &str = "#if defined(FLT_EVAL_METHOD)
#if FLT_EVAL_METHOD == 1
#error \"float expressions are evaluated in double here (FLT_EVAL_METHOD 1): the observers need them evaluated in float\"
#elif FLT_EVAL_METHOD == 2
#error \"float expressions are evaluated in long double here (FLT_EVAL_METHOD 2, e.g. the x87): use SSE (gcc: -mfpmath=sse)\"
#elif FLT_EVAL_METHOD == -1
#error \"the format float expressions are evaluated in is indeterminate here (FLT_EVAL_METHOD -1): the observers need float\"
#elif FLT_EVAL_METHOD != 0 && FLT_EVAL_METHOD != 16 && FLT_EVAL_METHOD != 32
#error \"float expressions are evaluated in a format wider than float here (FLT_EVAL_METHOD not 0, 16 or 32)\"
#endif
#endif
";

/// The select helpers `body` calls (an unused static function is a warning): `choose_float`, one
/// `?:` per statement, which compilers make a conditional move; `select_bits` and `select_float`, by
/// masks, where a chain of selects on one condition would become a branch.
fn selects(body: &str) -> String {
    let mut text = String::new();
    if body.contains("choose_float(") {
        text += "/* c ? a : b, one select per statement: compilers make it a conditional move (an IT block on\n\
                 \x20* Thumb-2), where a chain of them on one condition may become a branch. */\n\
                 static float choose_float(int c, float a, float b) {\n\
                 \x20   return c ? a : b;\n\
                 }\n\n";
    }
    if body.contains("select_bits(") || body.contains("select_float(") {
        text += "/* c ? a : b by masks, without a branch (c is 0 or 1): the same instructions whatever c is. */\n\
                 static uint32_t select_bits(int c, uint32_t a, uint32_t b) {\n\
                 \x20   const uint32_t mask = 0u - (uint32_t)c;\n\
                 \x20   return (a & mask) | (b & ~mask);\n\
                 }\n\n";
    }
    if body.contains("select_float(") {
        text += "static float select_float(int c, float a, float b) {\n\
                 \x20   uint32_t x = select_bits(c, bits_of(a), bits_of(b));\n\
                 \x20   memcpy(&a, &x, sizeof a);\n\
                 \x20   return a;\n\
                 }\n\n";
    }
    text
}
