//! Every C observer of the shipped designs as a case to run (`generated/c/<name>.c` against the Rust
//! observer of the same kind over the same samples), the comparison of their outputs, the runs on the
//! emulated board, and the C table of `docs/chip.md` built from them.

use std::path::Path;

use super::c_observers::{c_harness, run_c_observer, CBoardRun};
use super::unavailable::Unavailable;
use super::{phases, spread, Board, Kind};

/// `<math.h>` functions whose result may differ by an ulp between C libraries and Rust's `libm`
/// (the correctly rounded `sqrtf`, `fabsf`, `floorf`, `fminf`, … give the same bits everywhere, and
/// `exp` is emitted as libm's own algorithm, `libm_expf`). Matched as a call, ` name(`.
pub const INEXACT: [&str; 19] = [
    "expf(", "logf(", "log2f(", "log10f(", "powf(", "sinf(", "cosf(", "tanf(", "asinf(", "acosf(", "atanf(", "atan2f(",
    "sinhf(", "coshf(", "tanhf(", "cbrtf(", "asinhf(", "acoshf(", "atanhf(",
];

/// Where a design's C calls an [`INEXACT`] function: the largest |C − Rust| of an estimate allowed.
/// The bound `on_target.rs` holds the chip's f32 followers to against the host's f64 (measured there
/// at most 9e-6). No shipped design calls such a function.
pub const LIBM_TOLERANCE: f32 = 1e-3;

/// One observer of a design: the C names, the sequence, and the Rust observer's lines.
#[derive(Clone, Debug)]
pub struct Case {
    /// The design.
    pub name: &'static str,
    /// The kind, as the C names it (`<name>_<kind>`).
    pub kind: &'static str,
    /// The C type of its values: `float`, or the integer map's `int32_t`.
    pub scalar: &'static str,
    /// Outputs per sample, as the bits of `scalar`.
    pub ys: Vec<Vec<u32>>,
    /// Inputs per sample, as the bits of `scalar`.
    pub us: Vec<Vec<u32>>,
    /// Outputs, inputs, targets.
    pub shape: (usize, usize, usize),
    /// The map's horizon.
    pub horizon: usize,
    /// Samples of the recorded sequence (the first of `ys`; the rest saturate the tables).
    pub recorded: usize,
    /// What the Rust observer prints ([`super::rust_lines`]).
    pub expected: Vec<String>,
}

impl Case {
    /// Its C program ([`c_harness`]).
    pub fn harness(&self) -> String {
        c_harness(self.name, self.kind, self.scalar, &self.ys, &self.us, self.shape)
    }
}

/// A design's recorded sequence, then `horizon` samples of every output at +1000 and `horizon` at
/// −1000 (the inputs held): the map's tables saturate both ways, so that a data-dependent branch in
/// the C would show as a varying count; then samples that overflow the filters and non-finite
/// inputs, and the recording's start again.
pub fn extended<const NY: usize, const NU: usize>(
    ys: &[[f32; NY]],
    us: &[[f32; NU]],
    horizon: usize,
) -> (Vec<Vec<f32>>, Vec<Vec<f32>>) {
    let mut y: Vec<Vec<f32>> = ys.iter().map(|y| y.to_vec()).collect();
    let mut u: Vec<Vec<f32>> = us.iter().map(|u| u.to_vec()).collect();
    let held = u.last().cloned().unwrap_or_default();
    for level in [1000.0, -1000.0] {
        for _ in 0..horizon {
            y.push(vec![level; NY]);
            u.push(held.clone());
        }
    }
    // Outputs that overflow the filters, a NaN and an infinite input (refused, or predicted over),
    // then the recording's first samples again: what happens after.
    let first = ys[0].to_vec();
    for (outputs, inputs) in [
        (vec![1e30; NY], held.clone()),
        (vec![-3e38; NY], held.clone()),
        (first.clone(), vec![f32::NAN; NU]),
        (first, vec![f32::INFINITY; NU]),
    ] {
        y.push(outputs);
        u.push(inputs);
    }
    for k in 0..horizon.min(ys.len()) {
        y.push(ys[k].to_vec());
        u.push(us[k].to_vec());
    }
    (y, u)
}

/// The [`Case`] of observer `$observer` (C kind `$kind`) of design module `$d`, named `$name`.
#[macro_export]
macro_rules! c_case {
    ($d:path, $name:expr, $kind:expr, $observer:expr) => {{
        use $d as d;
        let (ys, us) = $crate::on_target::extended(&d::RECORDED_Y, &d::RECORDED_U, d::HORIZON);
        let bits = |rows: &[Vec<f32>]| -> Vec<Vec<u32>> {
            rows.iter().map(|r| r.iter().map(|v| v.to_bits()).collect()).collect()
        };
        let expected = $crate::on_target::rust_lines(
            &ys,
            &us,
            $observer,
            |o, y, u| $crate::on_target::status(o, y, u),
            |o| {
                o.estimate()
                    .map(|e| e.iter().map(|e| (e.value, e.saturation)).collect())
            },
        );
        $crate::on_target::Case {
            name: $name,
            kind: $kind,
            scalar: "float",
            ys: bits(&ys),
            us: bits(&us),
            shape: (d::OUTPUTS, d::INPUTS, d::TARGETS),
            horizon: d::HORIZON,
            recorded: d::RECORDED_LEN,
            expected,
        }
    }};
}

/// Every C observer of every shipped design (every kind `gen` wrote for it), in the order of the
/// on-target table.
pub fn shipped_cases() -> Vec<Case> {
    let mut cases = Vec::new();
    // Every kind `gen` listed for every design.
    macro_rules! of {
        ($design:ident, $kind:ident, $type:ident) => {{
            cases.push(c_case!(
                generated::$design,
                stringify!($design),
                stringify!($kind),
                generated::$design::$type::new()
            ));
        }};
    }
    generated::for_each_observer!(of);
    // The integer map over the recorded raw sequence, which ends with every table saturated both ways
    // and has its refused samples (`RECORDED_RAW_*`).
    macro_rules! fixed {
        ($design:ident, $type:ident) => {{
            use generated::$design as d;
            let (ys, us) = (rows(&d::RECORDED_RAW_Y), rows(&d::RECORDED_RAW_U));
            let expected = super::rust_lines(
                &ys,
                &us,
                d::fixed_observer(),
                |o, y, u| super::status(o, y, u),
                |o| {
                    o.estimate()
                        .map(|e| e.iter().map(|e| (e.value, e.saturation)).collect())
                },
            );
            let bits = |rows: &[Vec<i32>]| -> Vec<Vec<u32>> {
                rows.iter()
                    .map(|r| r.iter().map(|&v| super::CValue::bits(v)).collect())
                    .collect()
            };
            cases.push(Case {
                name: stringify!($design),
                kind: Kind::Fixed.name(),
                scalar: "int32_t",
                ys: bits(&ys),
                us: bits(&us),
                shape: (d::OUTPUTS, d::INPUTS, d::TARGETS),
                horizon: d::HORIZON,
                recorded: d::RECORDED_LEN,
                expected,
            });
        }};
    }
    generated::for_each_fixed_observer!(fixed);
    let order = |c: &Case| (c.name, Kind::named(c.kind));
    cases.sort_by_key(order);
    cases
}

/// Fixed-width rows as vectors.
fn rows<const W: usize>(rows: &[[i32; W]]) -> Vec<Vec<i32>> {
    rows.iter().map(|r| r.to_vec()).collect()
}

/// Whether design `name`'s C in `c` calls an [`INEXACT`] function.
pub fn inexact(c: &Path, name: &str) -> bool {
    let source = std::fs::read_to_string(c.join(format!("{name}.c"))).unwrap_or_default();
    INEXACT.iter().any(|f| source.contains(&format!(" {f}")))
}

/// `c` against `rust`, line by line: the same bits, or with `tolerant` the same statuses and flags
/// and every estimate within [`LIBM_TOLERANCE`]; the largest difference, or the first disagreement.
pub fn compare(what: &str, c: &[String], rust: &[String], tolerant: bool) -> Result<f32, String> {
    if c.len() != rust.len() {
        return Err(format!("{what}: {} lines, Rust {}", c.len(), rust.len()));
    }
    let mut largest = 0.0f32;
    for (k, (c, rust)) in c.iter().zip(rust).enumerate() {
        let wrong = || format!("{what} sample {k}: C {c}, Rust {rust}");
        let (a, b): (Vec<&str>, Vec<&str>) = (c.split(' ').collect(), rust.split(' ').collect());
        if a.len() != b.len() {
            return Err(wrong());
        }
        for (i, (x, y)) in a.iter().zip(&b).enumerate() {
            if x == y {
                continue;
            }
            // Tokens 2, 4, …: estimate bits; the statuses and flags between them must be equal.
            let value = |hex: &str| f32::from_bits(u32::from_str_radix(hex, 16).unwrap_or(u32::MAX));
            let difference = (value(x) - value(y)).abs();
            if !(tolerant && i >= 2 && i % 2 == 0 && difference <= LIBM_TOLERANCE) {
                return Err(wrong());
            }
            largest = largest.max(difference);
        }
    }
    Ok(largest)
}

/// Every shipped C observer run on the emulated board (C in `c`, scratch files in `dir`), each with
/// its largest difference to the Rust observer, or the first disagreement.
/// Two at a time (the emulator is single-threaded; the machines that run this have two cores).
pub fn run_shipped_on_board(c: &Path, dir: &Path) -> Result<Vec<(Case, CBoardRun, f32)>, Unavailable> {
    let one = |case: Case| -> Result<(Case, CBoardRun, f32), Unavailable> {
        let run = run_c_observer(case.name, case.kind, &case.harness(), c, dir, false)?;
        let largest = compare(
            &format!("{} {} on the board", case.name, case.kind),
            &run.lines,
            &case.expected,
            inexact(c, case.name),
        )
        .map_err(Unavailable::Failed)?;
        Ok((case, run, largest))
    };
    let cases = shipped_cases();
    type Numbered = Vec<(usize, Case)>;
    let (even, odd): (Numbered, Numbered) = cases.into_iter().enumerate().partition(|(i, _)| i % 2 == 0);
    let mut runs: Vec<(usize, (Case, CBoardRun, f32))> = std::thread::scope(|scope| {
        let worker = |half: Vec<(usize, Case)>| {
            scope.spawn(move || {
                half.into_iter()
                    .map(|(i, case)| one(case).map(|run| (i, run)))
                    .collect::<Result<Vec<_>, Unavailable>>()
            })
        };
        let (first, second) = (worker(even), worker(odd));
        let mut all = first.join().expect("a board worker panicked")?;
        all.extend(second.join().expect("a board worker panicked")?);
        Ok::<_, Unavailable>(all)
    })?;
    runs.sort_by_key(|(i, _)| *i);
    Ok(runs.into_iter().map(|(_, run)| run).collect())
}

/// The C table of `docs/chip.md`: each C observer's instructions per sample over the recorded
/// sequence once started (min / median / max, [`phases`]), their estimated cycles and time at
/// 80 MHz ([`super::timing`]), the Rust build's median beside it, its
/// divisions, stack, flash and RAM, and its largest difference to the Rust observer.
pub fn c_table(
    runs: &[(Case, CBoardRun, f32)],
    rust_medians: &dyn Fn(&str, Kind) -> Option<u64>,
) -> Result<String, String> {
    let mut table = String::from(
        "| design | C observer | instructions per sample, steady (min / median / max) | estimated cycles, steady (median / max) | µs per sample at 80 MHz (median) | Rust build (median) | VDIV + VSQRT per sample (max) | stack bytes | flash bytes | RAM bytes | max \\|C − Rust\\| |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for (case, run, largest) in runs {
        let what = format!("{} {}", case.name, case.kind);
        let kind = Kind::named(case.kind).ok_or_else(|| format!("{what}: no such kind"))?;
        let recorded = &case.expected[..case.recorded];
        let accepted: Vec<bool> = recorded.iter().map(|l| l.starts_with("0 ")).collect();
        let estimated: Vec<bool> = recorded.iter().map(|l| l.starts_with("0 0")).collect();
        let counts: Vec<u64> = run.counts[..case.recorded].iter().map(|c| c.0).collect();
        let start_up = super::start_up(case.name, kind).ok_or_else(|| format!("{what}: no start-up"))?;
        let steady = phases(&counts, &accepted, &estimated, start_up)
            .map_err(|e| format!("{what}: {e}"))?
            .steady;
        let (min, median, max) = spread(&steady);
        let cycles = run
            .cycles
            .get(..case.recorded)
            .ok_or_else(|| format!("{what}: no cycles"))?;
        let cycles = phases(cycles, &accepted, &estimated, start_up)
            .map_err(|e| format!("{what}: {e}"))?
            .steady;
        let (_, cycles, cycles_max) = spread(&cycles);
        let time = Board::Mps2An386.microseconds(cycles);
        let divisions = run.counts[..case.recorded].iter().map(|c| c.1).max().unwrap_or(0);
        let rust = rust_medians(case.name, kind).map_or("—".to_owned(), |n| n.to_string());
        table += &format!(
            "| `{}` | `{}_{}` | {min} / {median} / {max} | {cycles} / {cycles_max} | {time:.2} | {rust} | {divisions} | {} | {} | {} | {} |\n",
            case.name,
            case.name,
            case.kind,
            run.stack_bytes,
            run.flash_bytes,
            run.ram_bytes,
            if *largest == 0.0 {
                "0 (same bits)".to_owned()
            } else {
                format!("{largest:.1e}")
            },
        );
    }
    Ok(table)
}
