//! Every shipped design's observers as C99 source (`generated/c/<name>.h`, `.c`, issue 33): every
//! kind but `mhe` compiles without a warning under strict flags, with the system's `cc` and with
//! `clang` when it is installed, and run over the design's recorded sequence (refused samples
//! included) gives, sample for sample, the Rust observer's acceptance, estimate bits and saturation
//! flags, on the host and on the emulated Cortex-M4F; where the model calls a `<math.h>` function that
//! is not correctly rounded (E. coli's `expf`), the estimates are held to [`LIBM_TOLERANCE`] instead.

use std::path::{Path, PathBuf};
use std::process::Command;

use integration_tests::on_target::{c_harness, run_c_observer, rust_lines, sample_lines, Unavailable, STRICT_C_FLAGS};
use integration_tests::workspace_root;

/// `<math.h>` functions whose result may differ by an ulp between C libraries and Rust's `libm`
/// (the correctly rounded `sqrtf`, `fabsf`, `floorf`, `fminf`, … give the same bits everywhere).
const INEXACT: [&str; 17] = [
    "expf(", "logf(", "log2f(", "log10f(", "powf(", "sinf(", "cosf(", "tanf(", "asinf(", "acosf(", "atanf(", "atan2f(",
    "sinhf(", "coshf(", "tanhf(", "cbrtf(", "asinhf(",
];

/// Where a design's C calls an [`INEXACT`] function: the largest |C − Rust| of an estimate allowed.
/// The same bound `on_target.rs` holds the chip's f32 followers to against the host's f64 (measured
/// there at most 9e-6); newlib's and glibc's `expf` against Rust's `libm` measure far below it (the
/// test prints the figure).
const LIBM_TOLERANCE: f32 = 1e-3;

/// One observer of a design: the C names, the sequence, and the Rust observer's lines.
struct Case {
    name: &'static str,
    kind: &'static str,
    ys: Vec<Vec<u32>>,
    us: Vec<Vec<u32>>,
    shape: (usize, usize, usize),
    horizon: usize,
    expected: Vec<String>,
}

impl Case {
    fn harness(&self) -> String {
        c_harness(self.name, self.kind, &self.ys, &self.us, self.shape)
    }
}

/// The case of observer `$observer` (kind `$kind`) of design module `$d`.
macro_rules! case {
    ($d:path, $name:expr, $kind:expr, $observer:expr) => {{
        use $d as d;
        let ys: Vec<Vec<f32>> = d::RECORDED_Y.iter().map(|y| y.to_vec()).collect();
        let us: Vec<Vec<f32>> = d::RECORDED_U.iter().map(|u| u.to_vec()).collect();
        let bits = |rows: &[Vec<f32>]| -> Vec<Vec<u32>> {
            rows.iter().map(|r| r.iter().map(|v| v.to_bits()).collect()).collect()
        };
        let expected = rust_lines(
            &ys,
            &us,
            $observer,
            |o, y, u| o.push(y.try_into().unwrap(), u.try_into().unwrap()).is_ok(),
            |o| {
                o.estimate()
                    .map(|e| e.iter().map(|e| (e.value, e.saturation)).collect())
            },
        );
        Case {
            name: $name,
            kind: $kind,
            ys: bits(&ys),
            us: bits(&us),
            shape: (d::OUTPUTS, d::INPUTS, d::TARGETS),
            horizon: d::HORIZON,
            expected,
        }
    }};
}

/// Every C observer of every shipped design: the map, the EKF from the box centre, and the observers
/// the map starts or checks (all but the moving-horizon one, which has no C form).
fn shipped_cases() -> Vec<Case> {
    let mut cases = Vec::new();
    macro_rules! design {
        ($design:ident) => {{
            use generated::$design as m;
            cases.push(case!(generated::$design, stringify!($design), "map", m::map_observer()));
            cases.push(case!(
                generated::$design,
                stringify!($design),
                "ekf_box",
                m::BoxEkfObserver::new()
            ));
        }};
    }
    generated::for_each_design!(design);
    macro_rules! started {
        ($design:ident, Mhe, $type:ident) => {};
        ($design:ident, $kind:ident, $type:ident) => {{
            let kind = integration_tests::on_target::Kind::$kind.report_name();
            cases.push(case!(
                generated::$design,
                stringify!($design),
                kind,
                generated::$design::$type::new()
            ));
        }};
    }
    integration_tests::for_each_started_observer!(started);
    cases
}

/// Whether design `name`'s C in `c` calls an [`INEXACT`] function.
fn inexact(c: &Path, name: &str) -> bool {
    let source = std::fs::read_to_string(c.join(format!("{name}.c"))).unwrap();
    INEXACT.iter().any(|f| source.contains(f))
}

/// `c` against `rust`, line by line: the same bits, or with `tolerant` the same statuses and flags
/// and every estimate within [`LIBM_TOLERANCE`]; the largest difference.
fn compare(what: &str, c: &[String], rust: &[String], tolerant: bool) -> f32 {
    assert_eq!(c.len(), rust.len(), "{what}: lines");
    let mut largest = 0.0f32;
    for (k, (c, rust)) in c.iter().zip(rust).enumerate() {
        if !tolerant {
            assert_eq!(c, rust, "{what} sample {k}: C, then Rust");
            continue;
        }
        let (a, b): (Vec<&str>, Vec<&str>) = (c.split(' ').collect(), rust.split(' ').collect());
        assert_eq!(a.len(), b.len(), "{what} sample {k}: {c} against {rust}");
        for (i, (x, y)) in a.iter().zip(&b).enumerate() {
            if i >= 2 && i % 2 == 0 {
                let value = |hex: &str| f32::from_bits(u32::from_str_radix(hex, 16).unwrap());
                let difference = (value(x) - value(y)).abs();
                assert!(difference <= LIBM_TOLERANCE, "{what} sample {k}: {c} against {rust}");
                largest = largest.max(difference);
            } else {
                assert_eq!(x, y, "{what} sample {k}: {c} against {rust}");
            }
        }
    }
    largest
}

#[test]
fn the_tolerant_comparison_bites() {
    let rust = vec!["0 0 3f800000 0".to_owned()];
    // 1 + 2^-10 is within the tolerance; 1.0039 is not; a flag or a status never may differ.
    assert!(compare("within", &["0 0 3f800400 0".to_owned()], &rust, true) > 0.0);
    for wrong in ["0 0 3f808000 0", "0 0 3f800000 2", "1 0 3f800000 0"] {
        let caught = std::panic::catch_unwind(|| compare("beyond", &[wrong.to_owned()], &rust, true));
        assert!(caught.is_err(), "{wrong} passed");
    }
}

/// Compiles `harness` with design `name`'s C in `c` by `compiler` at `-O2`, and runs it; `None` when
/// the compiler is not installed.
fn compile_and_run(compiler: &str, dir: &Path, c: &Path, name: &str, kind: &str, harness: &str) -> Option<Vec<String>> {
    let source = dir.join(format!("{name}_{kind}_harness.c"));
    std::fs::write(&source, harness).unwrap();
    let exe = dir.join(format!("{name}_{kind}-{compiler}"));
    let built = Command::new(compiler)
        .args(STRICT_C_FLAGS)
        .arg("-O2")
        .arg("-I")
        .arg(c)
        .arg(c.join(format!("{name}.c")))
        .arg(&source)
        .arg("-lm")
        .arg("-o")
        .arg(&exe)
        .output()
        .ok()?;
    assert!(
        built.status.success(),
        "{compiler} {name} {kind}: {}",
        String::from_utf8_lossy(&built.stderr)
    );
    let run = Command::new(&exe).output().unwrap();
    assert!(run.status.success(), "{name} {kind} harness ({compiler}) failed");
    Some(sample_lines(&String::from_utf8(run.stdout).unwrap()))
}

/// A scratch folder of this test binary's own.
fn scratch(what: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("c-source-{what}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `cases` (C in `c`) with every compiler there is and compares each with Rust; what ran.
fn check_on_host(cases: &[Case], c: &Path, dir: &Path) -> Vec<String> {
    let mut ran = Vec::new();
    for case in cases {
        // The sequence exercises refusals and the samples before the map's first estimate.
        assert!(
            case.expected.iter().any(|l| l.starts_with("1 ")),
            "{}: no refused sample",
            case.name
        );
        let tolerant = inexact(c, case.name);
        let harness = case.harness();
        let cc = compile_and_run("cc", dir, c, case.name, case.kind, &harness);
        if cc.is_none() && std::env::var_os("CI").is_some() {
            panic!("CI needs a C compiler (cc)");
        }
        let clang = compile_and_run("clang", dir, c, case.name, case.kind, &harness);
        for (compiler, lines) in [("cc", cc), ("clang", clang)] {
            let Some(lines) = lines else { continue };
            let what = format!("{} {} ({compiler})", case.name, case.kind);
            let largest = compare(&what, &lines, &case.expected, tolerant);
            ran.push(if tolerant {
                format!("{what} within {largest:e}")
            } else {
                what
            });
        }
    }
    ran
}

#[test]
fn every_designs_c_observers_compile_without_warnings_and_give_the_rust_bits() {
    let dir = scratch("shipped");
    let cases = shipped_cases();
    let ran = check_on_host(&cases, &workspace_root().join("generated/c"), &dir);
    let _ = std::fs::remove_dir_all(&dir);
    println!("C against Rust: {}", ran.join(", "));
    // The map and the box EKF of 7 designs, and their 10 observers the map starts or checks.
    assert!(cases.len() >= 24, "{}", cases.len());
    assert!(ran.len() >= cases.len() || std::env::var_os("CI").is_none(), "{ran:?}");
}

/// The fixture whose tables have searched knots (see `integration_tests::SEARCHED_FIXTURE_SPEC`).
#[rustfmt::skip]
#[path = "../fixtures/vanderpol_beta7.rs"]
#[allow(dead_code)]
mod vanderpol_beta7;

/// No shipped design has searched knots: the fixture's C map, emitted here, takes the branch-free
/// search as its Rust file does.
#[test]
fn searched_knots_in_c_give_the_rust_bits() {
    let spec = workspace_root().join(integration_tests::SEARCHED_FIXTURE_SPEC);
    let design = host::spec::load(&spec).unwrap();
    let c = host::emit::c::c_source(&design, &integration_tests::build(&design), None).unwrap();
    assert!(c.source.contains("STARTS_0["), "the fixture's C does not search");
    let dir = scratch("searched");
    std::fs::write(dir.join("vanderpol_beta7.h"), &c.header).unwrap();
    std::fs::write(dir.join("vanderpol_beta7.c"), &c.source).unwrap();
    let case = case!(
        crate::vanderpol_beta7,
        "vanderpol_beta7",
        "map",
        vanderpol_beta7::map_observer()
    );
    let ran = check_on_host(&[case], &dir, &dir);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(!ran.is_empty() || std::env::var_os("CI").is_none());
}

/// Every shipped design's C observers built by `arm-none-eabi-gcc -Os` for the Cortex-M4F and run on
/// the emulated board give the Rust bits too (or, with `expf`, estimates within [`LIBM_TOLERANCE`]);
/// the map in a constant count of instructions per steady sample and no division. The counts, flash,
/// RAM and stack are the C rows of docs/chip.md (`on-target-report`).
#[test]
fn every_designs_c_observers_on_the_emulated_cortex_m4f_give_the_rust_bits() {
    let dir = scratch("board");
    let c = workspace_root().join("generated/c");
    let mut figures = Vec::new();
    for case in shipped_cases() {
        let what = format!("{} {} on the board", case.name, case.kind);
        let run = match run_c_observer(case.name, case.kind, &case.harness(), &c, &dir) {
            Err(missing @ Unavailable::Missing { .. }) if std::env::var_os("CI").is_none() => {
                eprintln!("skipped the C observers on the emulated board: {missing}");
                return;
            }
            Err(e) => panic!("{what}: {e}"),
            Ok(run) => run,
        };
        let largest = compare(&what, &run.lines, &case.expected, inexact(&c, case.name));
        assert_eq!(run.counts.len(), case.expected.len(), "{what}: one count per sample");
        if case.kind == "map" {
            // Once the window is full, every accepted sample takes one path; no division.
            let steady: Vec<u64> = run
                .counts
                .iter()
                .zip(&case.expected)
                .skip(case.horizon)
                .filter(|(_, l)| l.starts_with("0 "))
                .map(|(&(n, _), _)| n)
                .collect();
            let (least, most) = (steady.iter().min().unwrap(), steady.iter().max().unwrap());
            assert_eq!(least, most, "{what}: the steady path varies: {steady:?}");
            assert!(
                run.counts.iter().all(|&(_, d)| d == 0),
                "{what}: a division or square root"
            );
        }
        assert!(
            run.flash_bytes > 0 && run.ram_bytes > 0 && run.stack_bytes > 0,
            "{what}: {run:?}"
        );
        let most = run.counts.iter().skip(case.horizon).map(|c| c.0).max().unwrap();
        figures.push(format!(
            "{} {}: ≤{most} instructions, {} B flash, {} B RAM, {} B stack, max |C − Rust| {largest:e}",
            case.name, case.kind, run.flash_bytes, run.ram_bytes, run.stack_bytes
        ));
    }
    let _ = std::fs::remove_dir_all(&dir);
    println!("C observers on the emulated Cortex-M4F (-Os):\n{}", figures.join("\n"));
}
