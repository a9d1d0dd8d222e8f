//! The generated C observers (`generated/c/<name>.h`, `.c`) run over a design's recorded sequence:
//! the C program that does it ([`c_harness`]), the Rust observer's lines it must print
//! ([`rust_lines`]), and the run on the emulated board ([`run_c_observer`]) with its instructions per
//! sample, flash, RAM and stack.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use super::c_build::{compile_for_board, run_c_counted};
use super::elf::symbol_sizes;
use super::unavailable::{failed, Unavailable};

/// Warnings are errors; no fused multiply-add, no fast maths: IEEE single precision as Rust computes.
/// The optimisation level is the caller's.
pub const STRICT_C_FLAGS: [&str; 10] = [
    "-std=c99",
    "-Wvla",
    "-Wall",
    "-Wextra",
    "-Wpedantic",
    "-Wconversion",
    "-Wdouble-promotion",
    "-Werror",
    "-ffp-contract=off",
    "-fno-fast-math",
];

/// Words of stack the board harness paints below `main`'s frame before the samples run.
const PAINTED_WORDS: usize = 2048;

/// A C program that runs observer `<name>_<kind>` over `ys` and `us` (each value as the 32 bits of its
/// C type `scalar`: `float`, or the integer map's `int32_t`) and prints per sample `<push status>
/// <estimate status> [<bits> <flag>]…`, then `RAM <bytes>`, `STACK
/// <bytes>` (on the board: the deepest painted word any sample reached) and `DONE`. Each sample's
/// `push` + `estimate` runs between the markers `measure_start` and `measure_end`, as in the Rust
/// runners, so that the emulated board counts its instructions.
pub fn c_harness(
    name: &str,
    kind: &str,
    scalar: &str,
    ys: &[Vec<u32>],
    us: &[Vec<u32>],
    shape: (usize, usize, usize),
) -> String {
    let (outputs, inputs, targets) = shape;
    let ty = format!("{name}_{kind}");
    let rows = |rows: &[Vec<u32>], width: usize| -> String {
        rows.iter()
            .map(|row| {
                let cells: Vec<String> = (0..width.max(1))
                    .map(|i| format!("0x{:08x}u", row.get(i).copied().unwrap_or(0)))
                    .collect();
                format!("    {{{}}}", cells.join(", "))
            })
            .collect::<Vec<_>>()
            .join(",\n")
    };
    format!(
        "#include <stdio.h>\n#include <string.h>\n#include <stdint.h>\n#include \"{name}.h\"\n\
         static const unsigned int Y[{len}][{wy}] = {{\n{y}\n}};\n\
         static const unsigned int U[{len}][{wu}] = {{\n{u}\n}};\n\
         static {scalar} from_bits(unsigned int bits) {{ {scalar} v; memcpy(&v, &bits, sizeof v); return v; }}\n\
         static unsigned int to_bits({scalar} v) {{ unsigned int b; memcpy(&b, &v, sizeof b); return b; }}\n\
         void measure_start(void);\n\
         void measure_end(void);\n\
         __attribute__((noinline)) void measure_start(void) {{ __asm__ volatile(\"nop\"); }}\n\
         __attribute__((noinline)) void measure_end(void) {{ __asm__ volatile(\"nop\"); __asm__ volatile(\"nop\"); }}\n\
         #ifdef __arm__\n\
         #pragma GCC diagnostic ignored \"-Wuninitialized\"\n\
         #pragma GCC diagnostic ignored \"-Wmaybe-uninitialized\"\n\
         #pragma GCC diagnostic ignored \"-Wunused-but-set-variable\"\n\
         /* Stack: paint and read back the same frame (same locals) below main's, where `step` runs. */\n\
         __attribute__((noinline)) static void paint(void) {{\n\
         \x20   volatile uint32_t region[{painted}];\n\
         \x20   unsigned i;\n\
         \x20   for (i = 0u; i < {painted}u; ++i) region[i] = 0xA5A55A5Au;\n\
         }}\n\
         __attribute__((noinline)) static unsigned deepest(void) {{\n\
         \x20   volatile uint32_t region[{painted}];\n\
         \x20   unsigned i = 0u;\n\
         \x20   while (i < {painted}u && region[i] == 0xA5A55A5Au) ++i;\n\
         \x20   return ({painted}u - i) * 4u;\n\
         }}\n\
         #else\n\
         static void paint(void) {{}}\n\
         static unsigned deepest(void) {{ return 0u; }}\n\
         #endif\n\
         /* One sample, what a firmware does every period. */\n\
         __attribute__((noinline)) static {name}_status step({ty} *observer, const {scalar} *y, const {scalar} *u,\n\
         \x20                                             {scalar} *values, {name}_saturation *flags, {name}_status *estimated) {{\n\
         \x20   {name}_status pushed;\n\
         \x20   measure_start();\n\
         \x20   pushed = {ty}_push(observer, y, u);\n\
         \x20   *estimated = {ty}_estimate(observer, values, flags);\n\
         \x20   measure_end();\n\
         \x20   return pushed;\n\
         }}\n\
         int main(void) {{\n\
         \x20   static {ty} observer;\n\
         \x20   static {name}_status pushed[{len}u], estimated[{len}u];\n\
         \x20   static {scalar} values[{len}u][{targets}u];\n\
         \x20   static {name}_saturation flags[{len}u][{targets}u];\n\
         \x20   unsigned k, i, stack;\n\
         \x20   {ty}_init(&observer);\n\
         \x20   /* Nothing but `step` runs between the paint and the read-back (the results are printed\n\
         \x20      after): the deepest word changed is the deepest any sample went. */\n\
         \x20   paint();\n\
         \x20   for (k = 0u; k < {len}u; ++k) {{\n\
         \x20       {scalar} y[{wy}], u[{wu}];\n\
         \x20       for (i = 0u; i < {wy}u; ++i) y[i] = from_bits(Y[k][i]);\n\
         \x20       for (i = 0u; i < {wu}u; ++i) u[i] = from_bits(U[k][i]);\n\
         \x20       /* Without inputs the design ignores `u` (NULL would do). */\n\
         \x20       pushed[k] = step(&observer, y, u, values[k], flags[k], &estimated[k]);\n\
         \x20   }}\n\
         \x20   stack = deepest();\n\
         \x20   for (k = 0u; k < {len}u; ++k) {{\n\
         \x20       printf(\"%d %d\", (int)pushed[k], (int)estimated[k]);\n\
         \x20       if (estimated[k] == 0) {{\n\
         \x20           for (i = 0u; i < {targets}u; ++i) printf(\" %08x %d\", to_bits(values[k][i]), (int)flags[k][i]);\n\
         \x20       }}\n\
         \x20       printf(\"\\n\");\n\
         \x20   }}\n\
         {refused}\
         \x20   printf(\"RAM %u\\nSTACK %u\\nDONE\\n\", (unsigned)sizeof observer, stack);\n\
         \x20   return 0;\n\
         }}\n",
        len = ys.len(),
        wy = outputs.max(1),
        wu = inputs.max(1),
        y = rows(ys, outputs),
        u = rows(us, inputs),
        painted = PAINTED_WORDS,
        refused = if counts_refusals(kind) {
            "    printf(\"REFUSED %lu\\nRESTARTS %lu\\n\", (unsigned long)observer.refused, \
             (unsigned long)observer.restarts);\n"
        } else {
            ""
        },
    )
}

/// Whether C kind `kind` counts its refused samples (`refused`: its registry entry says so, the kinds
/// over the filters' shared rules); the harness then prints `REFUSED <count>` after the samples.
pub fn counts_refusals(kind: &str) -> bool {
    host::observers::kind::named(kind).is_some_and(|entry| entry.counts_refusals)
}

/// The lines of a harness's output that are samples (those [`c_harness`] prints first).
pub fn sample_lines(text: &str) -> Vec<String> {
    text.lines()
        .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()))
        .map(str::to_owned)
        .collect()
}

/// A value of the C observers: `float`, or the integer map's `int32_t`; the harness prints its bits.
pub trait CValue: Copy {
    /// Its C type.
    const C_TYPE: &'static str;
    /// Its 32 bits.
    fn bits(self) -> u32;
}

impl CValue for f32 {
    const C_TYPE: &'static str = "float";
    fn bits(self) -> u32 {
        self.to_bits()
    }
}

impl CValue for i32 {
    const C_TYPE: &'static str = "int32_t";
    fn bits(self) -> u32 {
        self as u32
    }
}

/// The C status of `observer`'s push of `(y, u)` (its `<name>_status`): 0 taken, 1 refused for a bad
/// value, 5 restarted (its [`firmware::Estimator::restarts`] went up).
pub fn status<O>(observer: &mut O, y: &[O::Scalar], u: &[O::Scalar]) -> u8
where
    O: firmware::Estimator,
    O::Outputs: for<'a> TryFrom<&'a [O::Scalar], Error: core::fmt::Debug>,
    O::Inputs: for<'a> TryFrom<&'a [O::Scalar], Error: core::fmt::Debug>,
{
    let before = observer.restarts();
    match observer.push(y.try_into().unwrap(), u.try_into().unwrap()) {
        Ok(()) => 0,
        Err(_) if observer.restarts() != before => 5,
        Err(_) => 1,
    }
}

/// What a Rust observer gives over the same sequence, printed as [`c_harness`] prints it.
pub fn rust_lines<O, V: CValue>(
    ys: &[Vec<V>],
    us: &[Vec<V>],
    mut observer: O,
    push: impl Fn(&mut O, &[V], &[V]) -> u8,
    estimate: impl Fn(&O) -> Option<Vec<(V, firmware::Saturation)>>,
) -> Vec<String> {
    ys.iter()
        .zip(us)
        .map(|(y, u)| {
            let pushed = push(&mut observer, y, u);
            match estimate(&observer) {
                None => format!("{pushed} 2"),
                Some(estimates) => {
                    let cells: String = estimates
                        .iter()
                        .map(|(v, s)| format!(" {:08x} {}", v.bits(), flag_number(*s)))
                        .collect();
                    format!("{pushed} 0{cells}")
                }
            }
        })
        .collect()
}

/// A saturation flag as the C enum's value.
fn flag_number(saturation: firmware::Saturation) -> u8 {
    match saturation {
        firmware::Saturation::Inside => 0,
        firmware::Saturation::Low => 1,
        firmware::Saturation::High => 2,
    }
}

/// One C observer on the emulated board.
#[derive(Clone, Debug)]
pub struct CBoardRun {
    /// The sample lines it printed.
    pub lines: Vec<String>,
    /// Instructions and divisions (`VDIV`, `VSQRT`) of each sample's `push` + `estimate`.
    pub counts: Vec<(u64, u64)>,
    /// Estimated Cortex-M4F cycles of each sample's `push` + `estimate` ([`super::timing`]).
    pub cycles: Vec<u64>,
    /// Bytes of code and tables of the design's C file that the program keeps.
    pub flash_bytes: u64,
    /// `sizeof` the observer.
    pub ram_bytes: u64,
    /// The deepest a sample's `push` + `estimate` reached below the caller's frame.
    pub stack_bytes: u64,
}

/// The board object of `<c>/<name>.c` compiled with `flags` into `dir`, once per design and flag set
/// for every kind's program (a design's C holds every kind: compiling it per kind took a fifth of the
/// board check); the board checks' workers share it, so one compiles while the other waits.
fn design_object(name: &str, c: &Path, dir: &Path, flags: &[&str]) -> Result<PathBuf, Unavailable> {
    static COMPILED: Mutex<BTreeSet<PathBuf>> = Mutex::new(BTreeSet::new());
    let lto = flags.contains(&"-flto");
    let object = dir.join(format!("{name}{}.board.o", if lto { ".lto" } else { "" }));
    let mut compiled = COMPILED.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if !(compiled.contains(&object) && object.exists()) {
        compile_for_board(&c.join(format!("{name}.c")), c, flags, &object)?;
        compiled.insert(object.clone());
    }
    Ok(object)
}

/// Builds `<c>/<name>.c` with `harness` (the text of [`c_harness`]) in `dir` by `arm-none-eabi-gcc
/// -Os` under [`STRICT_C_FLAGS`] for the Cortex-M4F (with `lto`, also `-flto`: the observer's
/// functions then inlined into the caller's), and runs it on the emulated board.
pub fn run_c_observer(
    name: &str,
    kind: &str,
    harness: &str,
    c: &Path,
    dir: &Path,
    lto: bool,
) -> Result<CBoardRun, Unavailable> {
    let harness_path = dir.join(format!("{name}_{kind}_board.c"));
    std::fs::write(&harness_path, harness).map_err(|e| failed(format!("{}: {e}", harness_path.display())))?;
    let mut flags: Vec<&str> = STRICT_C_FLAGS.to_vec();
    flags.extend(["-Os", "-ffunction-sections", "-fdata-sections"]);
    if lto {
        flags.push("-flto");
    }
    let observer = design_object(name, c, dir, &flags)?;
    let elf = dir.join(format!("{name}_{kind}.elf"));
    let (text, counts) = run_c_counted(&[observer.as_path(), harness_path.as_path()], c, &flags, &elf)?;
    let number = |key: &str| -> Result<u64, Unavailable> {
        text.lines()
            .find_map(|l| l.strip_prefix(key)?.trim().parse().ok())
            .ok_or_else(|| failed(format!("{name}_{kind}: no `{key}` line in:\n{text}")))
    };
    // The observer's object's symbols that the linker kept are the C observer's flash.
    let ours = symbol_sizes(&observer)?;
    let kept = symbol_sizes(&elf)?;
    let flash_bytes = kept
        .iter()
        .filter(|(symbol, _)| ours.contains_key(*symbol))
        .map(|(_, size)| size)
        .sum();
    Ok(CBoardRun {
        lines: sample_lines(&text),
        cycles: counts.iter().map(|c| c.cycles).collect(),
        counts: counts.iter().map(|c| (c.instructions, c.divisions)).collect(),
        flash_bytes,
        ram_bytes: number("RAM")?,
        stack_bytes: number("STACK")?,
    })
}
