//! Every shipped design's observers as C99 source (`generated/c/<name>.h`, `.c`, issue 33): every
//! kind compiles without a warning under strict flags, with the system's `cc` and with
//! `clang` when it is installed, and run over the design's recorded sequence (refused samples
//! included, then samples that saturate every table both ways) gives, sample for sample, the Rust
//! observer's acceptance, estimate bits and saturation flags, on the host and on the emulated
//! Cortex-M4F; where the model calls a `<math.h>` function that is not correctly rounded (E. coli's
//! `expf`), the estimates are held to `LIBM_TOLERANCE` instead.

use std::path::{Path, PathBuf};
use std::process::Command;

use integration_tests::chip_table;
use integration_tests::on_target::{
    c_table, compare, inexact, run_c_observer, run_shipped_on_board, sample_lines, shipped_cases, Case, Unavailable,
    STRICT_C_FLAGS,
};
use integration_tests::workspace_root;

#[test]
fn the_comparison_bites() {
    let rust = vec!["0 0 3f800000 0".to_owned()];
    // 1 + 2^-10 is within the tolerance where a C library's function may differ, not otherwise;
    // 1.0039 never is; a flag or a status never may differ.
    assert!(compare("within", &["0 0 3f800400 0".to_owned()], &rust, true).unwrap() > 0.0);
    assert!(compare("exact", &["0 0 3f800400 0".to_owned()], &rust, false).is_err());
    for wrong in ["0 0 3f808000 0", "0 0 3f800000 2", "1 0 3f800000 0", "0 2"] {
        assert!(
            compare("beyond", &[wrong.to_owned()], &rust, true).is_err(),
            "{wrong} passed"
        );
    }
}

/// Compiles `case`'s harness with its design's C in `c` by `compiler` at `-O2`, and runs it; `None`
/// when the compiler is not installed.
fn compile_and_run(compiler: &str, dir: &Path, c: &Path, case: &Case) -> Option<Vec<String>> {
    let (name, kind) = (case.name, case.kind);
    let source = dir.join(format!("{name}_{kind}_harness.c"));
    std::fs::write(&source, case.harness()).unwrap();
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
        let cc = compile_and_run("cc", dir, c, case);
        let clang = compile_and_run("clang", dir, c, case);
        if (cc.is_none() || clang.is_none()) && std::env::var_os("CI").is_some() {
            panic!("CI needs both C compilers, cc and clang (.ci/run installs them)");
        }
        for (compiler, lines) in [("cc", cc), ("clang", clang)] {
            let Some(lines) = lines else { continue };
            let what = format!("{} {} ({compiler})", case.name, case.kind);
            let largest = compare(&what, &lines, &case.expected, tolerant).unwrap_or_else(|e| panic!("{e}"));
            ran.push(if tolerant {
                format!("{what} within {largest:e}")
            } else {
                what
            });
        }
    }
    ran
}

/// Every shipped design's C compiles without a warning at every optimisation level (the compiler's
/// loop analyses differ between them), with `cc` and `clang` where installed.
#[test]
fn every_designs_c_compiles_without_warnings_at_every_optimisation_level() {
    let c = workspace_root().join("generated/c");
    let dir = scratch("levels");
    let mut compiled = 0;
    for name in integration_tests::on_target::design_names() {
        for compiler in ["cc", "clang"] {
            for level in ["-O0", "-O1", "-O2", "-O3", "-Os"] {
                let Ok(built) = Command::new(compiler)
                    .args(STRICT_C_FLAGS)
                    .args([level, "-c", "-o"])
                    .arg(dir.join(format!("{name}.o")))
                    .arg(c.join(format!("{name}.c")))
                    .output()
                else {
                    continue;
                };
                assert!(
                    built.status.success(),
                    "{compiler} {level} {name}: {}",
                    String::from_utf8_lossy(&built.stderr)
                );
                // No global mutable state: nothing in .data or .bss, only code and constants.
                let symbols = Command::new("nm")
                    .arg("--defined-only")
                    .arg(dir.join(format!("{name}.o")))
                    .output();
                if let Ok(symbols) = symbols {
                    let text = String::from_utf8_lossy(&symbols.stdout).into_owned();
                    let mutable: Vec<&str> = text
                        .lines()
                        .filter(|l| matches!(l.split_whitespace().nth(1), Some("b" | "B" | "d" | "D" | "C")))
                        .collect();
                    assert!(
                        mutable.is_empty(),
                        "{compiler} {level} {name}: mutable globals {mutable:?}"
                    );
                }
                compiled += 1;
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    // Both compilers in CI (.ci/run installs clang).
    assert!(compiled >= 70 || std::env::var_os("CI").is_none(), "{compiled}");
}

#[test]
fn every_designs_c_observers_compile_without_warnings_and_give_the_rust_bits() {
    let dir = scratch("shipped");
    let cases = shipped_cases();
    let ran = check_on_host(&cases, &workspace_root().join("generated/c"), &dir);
    let _ = std::fs::remove_dir_all(&dir);
    println!("C against Rust: {}", ran.join(", "));
    // The map, the box EKF and the MHE of 7 designs, and their 15 observers the map starts or checks.
    assert!(cases.len() >= 36, "{}", cases.len());
    assert!(ran.len() >= cases.len() || std::env::var_os("CI").is_none(), "{ran:?}");
}

/// The fixture whose tables have searched knots (see `integration_tests::SEARCHED_FIXTURE_SPEC`).
#[rustfmt::skip]
#[path = "../fixtures/vanderpol_beta7.rs"]
#[allow(dead_code)]
mod vanderpol_beta7;

/// No shipped design has searched knots: the fixture's C map, emitted here, takes the branch-free
/// search as its Rust file does. Nor constants a spec fixes: the fixture's C EKF has its spec's full
/// `Q`, `P(0)` and start, its C UKF its spec's `P(0)`, each with its Rust observer's bits.
#[test]
fn searched_knots_in_c_give_the_rust_bits() {
    // Its C as `gen` writes it, kept current beside its Rust by `generated_is_current`; each case by
    // both compilers.
    let spec = workspace_root().join(integration_tests::SEARCHED_FIXTURE_SPEC);
    let source = std::fs::read_to_string(spec.with_extension("c")).unwrap();
    assert!(source.contains("STARTS_0["), "the fixture's C does not search");
    let dir = scratch("searched");
    std::fs::copy(spec.with_extension("h"), dir.join("vanderpol_beta7.h")).unwrap();
    std::fs::write(dir.join("vanderpol_beta7.c"), &source).unwrap();
    let cases = [
        integration_tests::c_case!(
            crate::vanderpol_beta7,
            "vanderpol_beta7",
            "map",
            vanderpol_beta7::map_observer()
        ),
        integration_tests::c_case!(
            crate::vanderpol_beta7,
            "vanderpol_beta7",
            "ekf_box",
            vanderpol_beta7::BoxEkfObserver::new()
        ),
        integration_tests::c_case!(
            crate::vanderpol_beta7,
            "vanderpol_beta7",
            "ukf_box",
            vanderpol_beta7::UkfObserver::new()
        ),
    ];
    let ran = check_on_host(&cases, &dir, &dir);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        ran.len() == 2 * cases.len() || std::env::var_os("CI").is_none(),
        "{ran:?}"
    );
}

/// Every shipped design's C observers built by `arm-none-eabi-gcc -Os` for the Cortex-M4F and run on
/// the emulated board give the Rust bits too (or, with `expf`, estimates within `LIBM_TOLERANCE`);
/// the map and the integer map in a constant count of instructions per steady sample, saturated or
/// not, and no division;
/// and docs/chip.md's C table is what they measure (`cargo run -p integration-tests --bin
/// on-target-report` writes it).
#[test]
fn every_designs_c_observers_on_the_emulated_cortex_m4f_give_the_rust_bits() {
    let dir = scratch("board");
    let c = workspace_root().join("generated/c");
    let runs = match run_shipped_on_board(&c, &dir) {
        Err(missing @ Unavailable::Missing { .. }) if std::env::var_os("CI").is_none() => {
            eprintln!("skipped the C observers on the emulated board: {missing}");
            return;
        }
        Err(e) => panic!("{e}"),
        Ok(runs) => runs,
    };
    let _ = std::fs::remove_dir_all(&dir);
    for (case, run, _) in &runs {
        let what = format!("{} {} on the board", case.name, case.kind);
        assert_eq!(run.counts.len(), case.expected.len(), "{what}: one count per sample");
        assert!(
            run.flash_bytes > 0 && run.ram_bytes > 0 && run.stack_bytes > 0,
            "{what}: {run:?}"
        );
        if case.kind != "map" && case.kind != "fixed" {
            continue;
        }
        // The sequence takes every table to both ends.
        let flags: Vec<&str> = case
            .expected
            .iter()
            .flat_map(|l| l.split(' ').skip(3).step_by(2))
            .collect();
        assert!(
            flags.contains(&"1") && flags.contains(&"2"),
            "{what}: no saturation both ways"
        );
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
    let page = std::fs::read_to_string(workspace_root().join(chip_table::PAGE)).unwrap();
    // Example 1's map built with `-flto`, as a C firmware's release build may be: within 10 % of the
    // Rust build's instructions per sample (the same bits).
    let (case, run, _) = runs
        .iter()
        .find(|(case, _, _)| case.name == "vanderpol" && case.kind == "map")
        .expect("Example 1's map ran");
    let dir = scratch("board-lto");
    let linked = run_c_observer(case.name, case.kind, &case.harness(), &c, &dir, true).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(linked.lines, case.expected, "Example 1's map with -flto");
    let steady = |counts: &[(u64, u64)]| counts[case.horizon..case.recorded].iter().map(|c| c.0).max().unwrap();
    let rust = chip_table::rust_median(&page, "vanderpol", integration_tests::on_target::Kind::Map).unwrap();
    println!(
        "Example 1's map per steady sample: C {} (-Os), {} (-Os -flto); Rust {rust}",
        steady(&run.counts),
        steady(&linked.counts)
    );
    assert!(
        steady(&linked.counts) as f64 <= 1.10 * rust as f64,
        "Example 1's C map with -flto: {} instructions against Rust's {rust}",
        steady(&linked.counts)
    );
    let table = c_table(&runs, &|name, kind| chip_table::rust_median(&page, name, kind)).unwrap();
    println!("{table}");
    assert_eq!(
        chip_table::c_table_of(&page),
        Some(table.as_str()),
        "docs/chip.md's C table is not what the board measures: run `cargo run -p integration-tests --bin on-target-report`"
    );
}

/// The commands of the first `sh` block of `markdown`, each joined across its continuation lines.
fn shell_commands(markdown: &str) -> Vec<String> {
    let block = markdown
        .split("```sh\n")
        .nth(1)
        .and_then(|b| b.split("```").next())
        .unwrap_or("");
    block
        .replace("\\\n", " ")
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .filter(|l| !l.is_empty())
        .collect()
}

/// `examples/c/` on the emulated board, built and run by the commands its README gives: every line it
/// prints is the Rust `generated::vanderpol::observer()` over the same samples, which are the
/// recording's (`examples/board/data/run.csv`) rounded to f32.
#[test]
fn the_c_example_runs_on_the_emulated_board_as_the_rust_observer() {
    let root = workspace_root();
    let readme = std::fs::read_to_string(root.join("examples/c/README.md")).unwrap();
    let commands = shell_commands(&readme);
    assert_eq!(commands.len(), 2, "{commands:?}");
    let tools = ["arm-none-eabi-gcc", "qemu-system-arm"];
    if tools.iter().any(|t| Command::new(t).arg("--version").output().is_err()) {
        assert!(std::env::var_os("CI").is_none(), "CI needs {tools:?}");
        eprintln!("skipped the C example: {tools:?} not installed");
        return;
    }
    std::fs::create_dir_all(root.join("target")).unwrap();
    let built = Command::new("sh")
        .arg("-c")
        .arg(&commands[0])
        .current_dir(&root)
        .output()
        .unwrap();
    assert!(
        built.status.success(),
        "{}: {}",
        commands[0],
        String::from_utf8_lossy(&built.stderr)
    );
    let run = Command::new("timeout")
        .args(["120", "sh", "-c", &commands[1]])
        .current_dir(&root)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success() && text.contains("DONE"), "{}: {text}", commands[1]);
    // The samples main.c replays: the recording's y column in f32.
    let main = std::fs::read_to_string(root.join("examples/c/main.c")).unwrap();
    let array = main
        .split("RECORDED[SAMPLES] = {")
        .nth(1)
        .unwrap()
        .split("};")
        .next()
        .unwrap();
    let samples: Vec<f32> = array
        .split(',')
        .map(|v| v.trim().trim_end_matches('f').parse().unwrap())
        .collect();
    let csv = std::fs::read_to_string(root.join("examples/board/data/run.csv")).unwrap();
    let recorded: Vec<f32> = csv
        .lines()
        .skip(1)
        .map(|l| l.rsplit(',').next().unwrap().parse::<f64>().unwrap() as f32)
        .collect();
    assert_eq!(
        samples, recorded,
        "examples/c/main.c does not replay examples/board/data/run.csv"
    );
    let mut observer = generated::vanderpol::observer();
    let expected: Vec<String> = samples
        .iter()
        .enumerate()
        .map(|(k, &y)| {
            if observer.push([y], []).is_err() {
                return format!("{k} refused");
            }
            match observer.estimate() {
                None => format!("{k} no estimate yet"),
                Some(estimates) => {
                    let cells: String = estimates
                        .iter()
                        .map(|e| {
                            let flag = match e.saturation {
                                firmware::Saturation::Inside => "",
                                firmware::Saturation::Low => " (low)",
                                firmware::Saturation::High => " (high)",
                            };
                            format!(" {}{flag}", e.value)
                        })
                        .collect();
                    format!("{k}{cells}")
                }
            }
        })
        .collect();
    // The C prints 9 significant digits, Rust the shortest that reads back: compare the f32 they read as.
    let read = |line: &str| -> Vec<String> {
        line.split(' ')
            .map(|w| {
                w.parse::<f32>()
                    .map_or(w.to_owned(), |v| format!("{:08x}", v.to_bits()))
            })
            .collect()
    };
    let lines: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()))
        .collect();
    assert_eq!(lines.len(), expected.len(), "{text}");
    for (c, rust) in lines.iter().zip(&expected) {
        assert_eq!(read(c), read(rust), "C {c}, Rust {rust}");
    }
    assert!(
        expected.iter().filter(|l| l.contains('.')).count() >= 40,
        "{expected:?}"
    );
}

/// The README's C example compiles under the strict flags against the shipped C, as the unit of a
/// firmware that includes it.
#[test]
fn the_readmes_c_example_compiles() {
    let root = workspace_root();
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let example = readme
        .split("```c\n")
        .nth(1)
        .and_then(|b| b.split("```").next())
        .unwrap();
    assert!(example.lines().count() <= 15, "{example}");
    let dir = scratch("readme");
    let source = dir.join("firmware.c");
    std::fs::write(&source, example).unwrap();
    let Ok(built) = Command::new("cc")
        .args(STRICT_C_FLAGS)
        .args(["-O2", "-c", "-I"])
        .arg(root.join("generated/c"))
        .arg(&source)
        .arg("-o")
        .arg(dir.join("firmware.o"))
        .output()
    else {
        assert!(std::env::var_os("CI").is_none(), "CI needs a C compiler (cc)");
        return;
    };
    let _ = std::fs::remove_dir_all(&dir);
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
}
