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
    c_table, compare, counts_refusals, inexact, run_c_observer, run_shipped_on_board, sample_lines, shipped_cases,
    Case, Unavailable, STRICT_C_FLAGS,
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

/// The object of `name`'s C in `c`, compiled by `compiler` at `-O2` under the strict flags into
/// `dir` once and linked with each of its kinds' harnesses after (a design's C holds every kind:
/// compiling it per kind took most of this check's time); `None` when the compiler is not installed.
fn design_object(compiler: &str, dir: &Path, c: &Path, name: &str) -> Option<PathBuf> {
    let object = dir.join(format!("{name}-{compiler}.o"));
    if object.exists() {
        return Some(object);
    }
    let built = Command::new(compiler)
        .args(STRICT_C_FLAGS)
        .arg("-O2")
        .arg("-I")
        .arg(c)
        .arg("-c")
        .arg(c.join(format!("{name}.c")))
        .arg("-o")
        .arg(&object)
        .output()
        .ok()?;
    assert!(
        built.status.success(),
        "{compiler} {name}: {}",
        String::from_utf8_lossy(&built.stderr)
    );
    Some(object)
}

/// Compiles `case`'s harness by `compiler` at `-O2`, links it with its design's C in `c`
/// ([`design_object`]) and runs it; `None` when the compiler is not installed.
fn compile_and_run(compiler: &str, dir: &Path, c: &Path, case: &Case) -> Option<Vec<String>> {
    let (name, kind) = (case.name, case.kind);
    let object = design_object(compiler, dir, c, name)?;
    let source = dir.join(format!("{name}_{kind}_harness.c"));
    std::fs::write(&source, case.harness()).unwrap();
    let exe = dir.join(format!("{name}_{kind}-{compiler}"));
    let built = Command::new(compiler)
        .args(STRICT_C_FLAGS)
        .arg("-O2")
        .arg("-I")
        .arg(c)
        .arg(&object)
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
    let text = String::from_utf8(run.stdout).unwrap();
    if counts_refusals(kind) {
        // The C counters (one place, `counted.c`) against the Rust observer's refused samples and
        // restarts (status 1 and 5 of its lines).
        let refused = case.expected.iter().filter(|l| l.starts_with("1 ")).count();
        let restarts = case.expected.iter().filter(|l| l.starts_with("5 ")).count();
        assert!(
            text.contains(&format!("\nREFUSED {refused}\nRESTARTS {restarts}\n")),
            "{name} {kind} ({compiler}): the Rust observer refused {refused} samples and restarted \
             {restarts} times, the C counted otherwise"
        );
    }
    Some(sample_lines(&text))
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
            crate::vanderpol_beta7::map_observer()
        ),
        integration_tests::c_case!(
            crate::vanderpol_beta7,
            "vanderpol_beta7",
            "ekf_box",
            crate::vanderpol_beta7::EkfBoxObserver::new()
        ),
        integration_tests::c_case!(
            crate::vanderpol_beta7,
            "vanderpol_beta7",
            "ukf_box",
            crate::vanderpol_beta7::UkfBoxObserver::new()
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
    let rust = chip_table::rust_median(
        &page,
        "vanderpol",
        integration_tests::on_target::Kind::Of(integration_tests::on_target::ObserverKind::Map),
    )
    .unwrap();
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

/// `text` without its `/* … */` comments and with each string literal emptied: the C a compiler reads.
fn code_of(text: &str) -> String {
    let mut code = String::new();
    let mut rest = text;
    while let Some(start) = rest.find(['/', '"']) {
        code.push_str(&rest[..start]);
        rest = &rest[start..];
        if let Some(after) = rest.strip_prefix("/*") {
            let end = after.find("*/").map_or(after.len(), |e| e + 2);
            // Keep the lines, so that a line number still points at its line.
            code.extend(after[..end].chars().filter(|&c| c == '\n'));
            rest = &after[end..];
        } else if let Some(after) = rest.strip_prefix('"') {
            let mut end = 0;
            let bytes = after.as_bytes();
            while end < bytes.len() && bytes[end] != b'"' {
                end += if bytes[end] == b'\\' { 2 } else { 1 };
            }
            code.push_str("\"\"");
            rest = &after[(end + 1).min(after.len())..];
        } else {
            code.push('/');
            rest = &rest[1..];
        }
    }
    code.push_str(rest);
    code
}

/// Every design's emitted C: `(name, header, source)` of the shipped designs (`generated/c/`) and of
/// the fixture with searched knots.
fn emitted_c() -> Vec<(String, PathBuf, PathBuf)> {
    let root = workspace_root();
    let mut designs: Vec<(String, PathBuf, PathBuf)> = integration_tests::on_target::design_names()
        .into_iter()
        .map(|name| {
            let c = root.join("generated/c");
            (
                name.to_owned(),
                c.join(format!("{name}.h")),
                c.join(format!("{name}.c")),
            )
        })
        .collect();
    let fixture = root.join(integration_tests::SEARCHED_FIXTURE_SPEC);
    designs.push((
        "vanderpol_beta7".to_owned(),
        fixture.with_extension("h"),
        fixture.with_extension("c"),
    ));
    designs
}

/// Whether `tool` runs here; in CI its absence fails the test.
fn have(tool: &str) -> bool {
    let there = Command::new(tool).arg("--version").output().is_ok();
    assert!(there || std::env::var_os("CI").is_none(), "CI needs {tool}");
    if !there {
        eprintln!("skipped: {tool} not installed");
    }
    there
}

/// Issue 48: a C++ firmware includes the C observers' header. Every emitted header compiles as C++,
/// and a C++ program (Example 1's map harness, compiled by `c++`) links with the observers compiled
/// as C by `cc` and prints the Rust observer's bits: the header gives its declarations C linkage
/// (`extern "C"`), without which the C++ program refers to mangled names the C object lacks.
#[test]
fn a_cpp_program_includes_every_header_and_links_the_c_observers() {
    if !have("c++") || !have("cc") {
        return;
    }
    let dir = scratch("cpp");
    for (name, header, _) in emitted_c() {
        let text = std::fs::read_to_string(&header).unwrap();
        assert!(
            text.contains("#ifdef __cplusplus\nextern \"C\" {\n#endif"),
            "{name}.h has no C linkage for C++"
        );
        let unit = dir.join(format!("{name}.cpp"));
        std::fs::write(&unit, format!("#include \"{}\"\n", header.display())).unwrap();
        let built = Command::new("c++")
            .args(["-std=c++11", "-Wall", "-Wextra", "-Werror", "-fsyntax-only"])
            .arg(&unit)
            .output()
            .unwrap();
        assert!(
            built.status.success(),
            "{name}.h as C++: {}",
            String::from_utf8_lossy(&built.stderr)
        );
    }
    let c = workspace_root().join("generated/c");
    let case = integration_tests::c_case!(
        generated::vanderpol,
        "vanderpol",
        "map",
        generated::vanderpol::map_observer()
    );
    let object = dir.join("vanderpol.o");
    let built = Command::new("cc")
        .args(STRICT_C_FLAGS)
        .args(["-O2", "-c", "-o"])
        .arg(&object)
        .arg(c.join("vanderpol.c"))
        .output()
        .unwrap();
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
    let harness = dir.join("harness.cpp");
    std::fs::write(&harness, case.harness()).unwrap();
    let exe = dir.join("harness");
    let linked = Command::new("c++")
        .args(["-std=c++11", "-O2", "-I"])
        .arg(&c)
        .arg(&harness)
        .arg(&object)
        .arg("-o")
        .arg(&exe)
        .output()
        .unwrap();
    assert!(
        linked.status.success(),
        "the C++ program does not link with the C observers: {}",
        String::from_utf8_lossy(&linked.stderr)
    );
    let run = Command::new(&exe).output().unwrap();
    assert!(run.status.success());
    let lines = sample_lines(&String::from_utf8(run.stdout).unwrap());
    compare("vanderpol map from C++", &lines, &case.expected, false).unwrap_or_else(|e| panic!("{e}"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The `float` literals of C `code` (comments and strings removed) that have no `f` suffix: each
/// would be a `double`, and the arithmetic around it too.
fn double_literals(code: &str) -> Vec<String> {
    let mut found = Vec::new();
    let bytes = code.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let starts =
            bytes[i].is_ascii_digit() && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
        if !starts {
            i += 1;
            continue;
        }
        let mut end = i;
        let mut floating = false;
        while end < bytes.len() {
            let c = bytes[end];
            if c.is_ascii_digit() || c == b'.' {
                floating |= c == b'.';
            } else if (c == b'e' || c == b'E') && !code[i..end].starts_with("0x") {
                floating = true;
                if matches!(bytes.get(end + 1), Some(b'-' | b'+')) {
                    end += 1;
                }
            } else {
                break;
            }
            end += 1;
        }
        let hex = code[i..].starts_with("0x") || code[i..].starts_with("0X");
        if floating && !hex && !matches!(bytes.get(end), Some(b'f' | b'F')) {
            let line = code[..i].matches('\n').count() + 1;
            found.push(format!("line {line}: {}", &code[i..end]));
        }
        while end < bytes.len() && (bytes[end].is_ascii_alphanumeric() || bytes[end] == b'_') {
            end += 1;
        }
        i = end.max(i + 1);
    }
    found
}

/// Issue 48: one status enum and one saturation enum per design (the observers' and the static
/// library's calls return the same `<name>_status`; the library's flags are `<name>_saturation`),
/// `<NAME>_SAMPLE_PERIOD` defined once, and every floating literal of every header and source a
/// `float` (`0.1f`, not the `double` `0.1`).
#[test]
fn one_status_one_saturation_one_period_and_every_literal_a_float() {
    let check = double_literals("x = 0.5f + 1e-3f; y = 0x1e3u; z = a1.5; w = 2.0;\n v = 0.1 * 3;");
    assert_eq!(check, ["line 1: 2.0", "line 2: 0.1"]);
    for (name, header, source) in emitted_c() {
        let upper = name.to_uppercase();
        let text = code_of(&std::fs::read_to_string(&header).unwrap());
        assert_eq!(text.matches("typedef enum").count(), 2, "{name}.h: enums");
        assert_eq!(text.matches(&format!("}} {name}_status;")).count(), 1, "{name}.h");
        assert_eq!(text.matches(&format!("}} {name}_saturation;")).count(), 1, "{name}.h");
        for value in [
            "OK = 0",
            "REFUSED = 1",
            "NO_ESTIMATE_YET = 2",
            "BAD_ARGUMENT = 3",
            "NOT_INITIALISED = 4",
            "RESTARTED = 5",
        ] {
            assert!(text.contains(&format!("{upper}_{value}")), "{name}.h: {value}");
        }
        assert!(!text.contains("int8_t"), "{name}.h: a second saturation encoding");
        let periods: Vec<&str> = text
            .lines()
            .filter(|l| l.starts_with(&format!("#define {upper}_SAMPLE_PERIOD ")))
            .collect();
        assert_eq!(periods.len(), 1, "{name}.h: {periods:?}");
        assert!(periods[0].ends_with('f'), "{name}.h: {}", periods[0]);
        for file in [&header, &source] {
            let doubles = double_literals(&code_of(&std::fs::read_to_string(file).unwrap()));
            assert!(doubles.is_empty(), "{}: double literals {doubles:?}", file.display());
        }
    }
}

/// Issue 48: the names of a design's C are its name, `_` and a word [`host::emit::c::C_SUFFIX_WORDS`]
/// or the observer kinds hold, so that the check refusing designs whose names would clash in one
/// `gen` run (`host::emit::c::c_name_clash`) knows every name the interface declares.
#[test]
fn every_c_name_begins_with_a_word_the_clash_check_knows() {
    let kinds = ["map", "ekf", "ukf", "corrected", "mhe"];
    for (name, header, source) in emitted_c() {
        for file in [header, source] {
            let code = code_of(&std::fs::read_to_string(&file).unwrap());
            for prefix in [format!("{name}_"), format!("{}_", name.to_uppercase())] {
                for (at, _) in code.match_indices(&prefix) {
                    if at > 0 && (code.as_bytes()[at - 1].is_ascii_alphanumeric() || code.as_bytes()[at - 1] == b'_') {
                        continue;
                    }
                    let word: String = code[at + prefix.len()..]
                        .chars()
                        .take_while(char::is_ascii_alphanumeric)
                        .collect::<String>()
                        .to_ascii_lowercase();
                    assert!(
                        host::emit::c::C_SUFFIX_WORDS.contains(&word.as_str()) || kinds.contains(&word.as_str()),
                        "{}: `{prefix}{word}…` begins with a word c_name_clash does not know",
                        file.display()
                    );
                }
            }
        }
    }
}

/// Issue 48: the observers of every shipped design (vanderpol beside vanderpol_uncertain, …, and
/// two_tanks, with an input) compile into one C program: no name is declared twice, and each design's
/// chosen observer runs beside the others.
#[test]
fn every_shipped_design_links_into_one_c_program() {
    if !have("cc") {
        return;
    }
    let dir = scratch("together");
    let c = workspace_root().join("generated/c");
    let names = integration_tests::on_target::design_names();
    let mut program = String::from("#include <stdio.h>\n");
    for name in &names {
        program += &format!("#include \"{name}.h\"\n");
    }
    program += "int main(void) {\n    unsigned k;\n";
    for name in &names {
        let upper = name.to_uppercase();
        program += &format!(
            "    {{\n        static {name}_observer o;\n        float y[{upper}_OUTPUTS] = {{0}}, u[{upper}_INPUTS + 1] = {{0}};\n\
             \x20       float x[{upper}_TARGETS];\n        {name}_saturation s[{upper}_TARGETS];\n\
             \x20       {name}_observer_init(&o);\n\
             \x20       int pushed = 0;\n\
             \x20       for (k = 0u; k < {upper}_HORIZON; ++k) {{\n            pushed += (int){name}_observer_push(&o, y, u);\n        }}\n\
             \x20       printf(\"{name} %d %d\\n\", pushed, (int){name}_observer_estimate(&o, x, s));\n    }}\n"
        );
    }
    program += "    return 0;\n}\n";
    std::fs::write(dir.join("all.c"), &program).unwrap();
    let exe = dir.join("all");
    let built = Command::new("cc")
        .args(STRICT_C_FLAGS)
        .args(["-O1", "-I"])
        .arg(&c)
        .arg(dir.join("all.c"))
        .args(names.iter().map(|n| c.join(format!("{n}.c"))))
        .args(["-lm", "-o"])
        .arg(&exe)
        .output()
        .unwrap();
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
    let run = Command::new(&exe).output().unwrap();
    let text = String::from_utf8(run.stdout).unwrap();
    assert!(run.status.success(), "{text}");
    assert_eq!(text.lines().count(), names.len(), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 48: the C source accepts every `FLT_EVAL_METHOD` under which `float` expressions are
/// evaluated in `float`: 0, and ISO/IEC TS 18661-3's 16 and 32 (gcc says 16 for a Cortex-M55 with
/// its half-precision unit, and for x86 with AVX512-FP16, outside its ISO modes); it refuses 1, 2
/// and -1, each with its reason. `arm-none-eabi-gcc -mcpu=cortex-m55 -mfloat-abi=hard -c` compiles
/// it (the check once blamed the x87 there); other values are forced with `-D__FLT_EVAL_METHOD__`,
/// which gcc's and clang's `<float.h>` read in their ISO C99 mode.
#[test]
fn the_float_evaluation_check_accepts_float_and_refuses_wider_formats_with_the_reason() {
    let c = workspace_root().join("generated/c");
    if have("arm-none-eabi-gcc") {
        let dir = scratch("m55");
        for std in [None, Some("-std=c99")] {
            let built = Command::new("arm-none-eabi-gcc")
                .args([
                    "-mcpu=cortex-m55",
                    "-mthumb",
                    "-mfloat-abi=hard",
                    "-O2",
                    "-ffp-contract=off",
                    "-c",
                ])
                .args(std)
                .arg(c.join("vanderpol.c"))
                .arg("-o")
                .arg(dir.join("vanderpol.o"))
                .output()
                .unwrap();
            assert!(
                built.status.success(),
                "Cortex-M55 ({std:?}): {}",
                String::from_utf8_lossy(&built.stderr)
            );
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
    if !have("cc") {
        return;
    }
    for (method, reason) in [
        ("0", None),
        ("16", None),
        ("32", None),
        ("1", Some("evaluated in double")),
        ("2", Some("evaluated in long double")),
        ("-1", Some("indeterminate")),
        ("64", Some("wider than float")),
    ] {
        let built = Command::new("cc")
            .args(["-std=c99", "-fsyntax-only", "-U__FLT_EVAL_METHOD__"])
            .arg(format!("-D__FLT_EVAL_METHOD__={method}"))
            .arg("-I")
            .arg(&c)
            .arg(c.join("vanderpol.c"))
            .output()
            .unwrap();
        let errors = String::from_utf8_lossy(&built.stderr);
        match reason {
            None => assert!(built.status.success(), "FLT_EVAL_METHOD {method}: {errors}"),
            Some(reason) => assert!(
                !built.status.success()
                    && errors.contains(reason)
                    && (method == "64" || errors.contains(&format!("FLT_EVAL_METHOD {method}"))),
                "FLT_EVAL_METHOD {method}: {errors}"
            ),
        }
    }
}

/// Issue 48: the moving-horizon observer refuses a NaN or infinite measurement and stores nothing,
/// while its window fills as after, in Rust and in C alike (it once stored it and said `OK` until
/// the window was full): pushing one among the first samples returns `REFUSED`, and every later
/// estimate is the bits of an observer that never saw it.
#[test]
fn the_mhe_refuses_a_non_finite_measurement_while_its_window_fills() {
    use generated::vanderpol as d;
    let samples: Vec<f32> = d::RECORDED_Y
        .iter()
        .map(|y| y[0])
        .filter(|y| y.is_finite())
        .take(d::HORIZON + 5)
        .collect();
    // The Rust observer: the sample refused, the rest as if it never came.
    for bad in [f32::NAN, f32::INFINITY] {
        let (mut with, mut without) = (d::MheObserver::new(), d::MheObserver::new());
        for (k, &y) in samples.iter().enumerate() {
            if k == 3 {
                assert!(with.push([bad], []).is_err(), "Rust MHE took {bad} while filling");
            }
            assert_eq!(with.push([y], []).is_ok(), without.push([y], []).is_ok());
            let bits = |o: &d::MheObserver| o.estimate().map(|e| e.map(|e| e.value.to_bits()));
            assert_eq!(bits(&with), bits(&without), "sample {k}");
        }
        assert!(with.estimate().is_some());
    }
    if !have("cc") {
        return;
    }
    // The C observer, the same way: statuses and bits printed, then compared.
    let rows: Vec<String> = samples.iter().map(|y| format!("0x{:08x}u", y.to_bits())).collect();
    let program = format!(
        "#include <stdio.h>\n#include <string.h>\n#include \"vanderpol.h\"\n\
         static const unsigned int Y[{len}] = {{ {rows} }};\n\
         static void print(const vanderpol_mhe *o) {{\n\
         \x20   float x[VANDERPOL_TARGETS];\n    vanderpol_saturation s[VANDERPOL_TARGETS];\n    unsigned t, b;\n\
         \x20   if (vanderpol_mhe_estimate(o, x, s) != VANDERPOL_OK) {{ printf(\" none\"); return; }}\n\
         \x20   for (t = 0u; t < VANDERPOL_TARGETS; ++t) {{ memcpy(&b, &x[t], sizeof b); printf(\" %08x\", b); }}\n\
         }}\n\
         int main(void) {{\n\
         \x20   static vanderpol_mhe with, without;\n    unsigned k;\n    float bad[2];\n\
         \x20   const unsigned bits[2] = {{0x7fc00000u, 0x7f800000u}};\n\
         \x20   memcpy(bad, bits, sizeof bad);\n\
         \x20   vanderpol_mhe_init(&with);\n    vanderpol_mhe_init(&without);\n\
         \x20   for (k = 0u; k < {len}u; ++k) {{\n\
         \x20       float y;\n        memcpy(&y, &Y[k], sizeof y);\n\
         \x20       if (k == 3u) printf(\"refused %d %d\\n\", (int)vanderpol_mhe_push(&with, &bad[0], NULL), (int)vanderpol_mhe_push(&with, &bad[1], NULL));\n\
         \x20       printf(\"%d\", (int)vanderpol_mhe_push(&with, &y, NULL));\n        print(&with);\n\
         \x20       printf(\" |%d\", (int)vanderpol_mhe_push(&without, &y, NULL));\n        print(&without);\n        printf(\"\\n\");\n\
         \x20   }}\n    return 0;\n}}\n",
        len = samples.len(),
        rows = rows.join(", "),
    );
    let dir = scratch("mhe-nan");
    std::fs::write(dir.join("mhe.c"), program).unwrap();
    let c = workspace_root().join("generated/c");
    let exe = dir.join("mhe");
    let built = Command::new("cc")
        .args(STRICT_C_FLAGS)
        .args(["-O1", "-I"])
        .arg(&c)
        .arg(dir.join("mhe.c"))
        .arg(c.join("vanderpol.c"))
        .args(["-lm", "-o"])
        .arg(&exe)
        .output()
        .unwrap();
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
    let run = Command::new(&exe).output().unwrap();
    let text = String::from_utf8(run.stdout).unwrap();
    assert!(run.status.success(), "{text}");
    assert!(
        text.starts_with("0 none |0 none\n") && text.contains("refused 1 1\n"),
        "{text}"
    );
    for line in text.lines().filter(|l| !l.starts_with("refused")) {
        let (with, without) = line.split_once(" |").unwrap();
        assert_eq!(with, without, "C: {text}");
    }
    assert!(!text.lines().last().unwrap().contains("none"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 48: each estimate of the integer map has its scale as macros, `value = integer ·
/// 2^<NAME>_FIXED_LSB_EXPONENT_t = integer · <NAME>_FIXED_LSB_t`, the Rust design file's
/// `FIXED_LSB[t]` (emitted by other code, read here as the compiled constant).
#[test]
fn the_integer_maps_scale_macros_are_the_rust_files_lsb() {
    let c = workspace_root().join("generated/c");
    let mut checked = 0;
    macro_rules! check {
        ($design:ident) => {{
            use generated::$design as d;
            let name = stringify!($design);
            let upper = name.to_uppercase();
            let header = std::fs::read_to_string(c.join(format!("{name}.h"))).unwrap();
            for (t, &lsb) in d::FIXED_LSB.iter().enumerate() {
                let value = |macro_name: String| -> String {
                    let line = header
                        .lines()
                        .find(|l| l.starts_with(&format!("#define {macro_name} ")))
                        .unwrap_or_else(|| panic!("{name}.h: no {macro_name}"));
                    line.split_whitespace().nth(2).unwrap().to_owned()
                };
                let exponent: i32 = value(format!("{upper}_FIXED_LSB_EXPONENT_{t}"))
                    .trim_matches(|c| c == '(' || c == ')')
                    .parse()
                    .unwrap();
                assert_eq!(2f64.powi(exponent), lsb, "{name} estimate {t}");
                let scale: f32 = value(format!("{upper}_FIXED_LSB_{t}"))
                    .trim_end_matches('f')
                    .parse()
                    .unwrap();
                assert_eq!(f64::from(scale), lsb, "{name} estimate {t}");
                checked += 1;
            }
        }};
    }
    check!(vanderpol);
    check!(two_tanks);
    check!(ecoli_x0_2);
    assert!(checked >= 6, "{checked}");
}

/// Issue 48: the repository's licence files are there (the Apache text whole), and every emitted
/// file (the C headers and sources, the Rust design files and `lib.rs`) says in its header what its
/// user may do with it ([`host::emit::LICENCE`]).
#[test]
fn every_emitted_file_states_its_licence() {
    let root = workspace_root();
    let apache = std::fs::read_to_string(root.join("LICENSE-APACHE")).unwrap();
    assert!(apache.contains("Version 2.0, January 2004") && apache.contains("END OF TERMS AND CONDITIONS"));
    assert!(apache.contains("9. Accepting Warranty or Additional Liability."));
    let mit = std::fs::read_to_string(root.join("LICENSE-MIT")).unwrap();
    assert!(mit.contains("Permission is hereby granted, free of charge"));
    let mut files: Vec<PathBuf> = Vec::new();
    for (_, header, source) in emitted_c() {
        files.extend([header, source]);
    }
    for entry in std::fs::read_dir(root.join("generated/src")).unwrap() {
        files.push(entry.unwrap().path());
    }
    files.push(root.join(integration_tests::SEARCHED_FIXTURE_SPEC).with_extension("rs"));
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let head: String = text.lines().take(12).collect::<Vec<_>>().join("\n");
        for line in host::emit::LICENCE {
            assert!(
                head.contains(line),
                "{}: no licence statement in its header",
                file.display()
            );
        }
    }
    assert!(files.len() >= 24, "{}", files.len());
}
