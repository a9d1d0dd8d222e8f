//! The own-system walkthrough (the README's tour and `docs/guide.md`, *Your own system*), end to end
//! in a temporary folder, as a user types it: `gen --spec` makes a crate of its own, outside this
//! repository, that builds for the Cortex-M4F and passes its doc example; its C library, linked into
//! a C program by the system's C compiler and by `arm-none-eabi-gcc` for the emulated board, gives
//! the Rust observer's numbers bit for bit; `on-target-report -- --crate` measures it on the emulated
//! board into its own README; `simulate`, `estimate --precision f32` (the Rust observer's bits again)
//! and `plot` on a recording; and the repository (`generated/` byte for byte, and `git status`) is
//! left as it was.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Mutex, MutexGuard, OnceLock, PoisonError};

/// Every file under `folder` with its bytes, sorted.
fn snapshot(folder: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut files = Vec::new();
    for entry in std::fs::read_dir(folder).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files.extend(snapshot(&path));
        } else {
            files.push((path.clone(), std::fs::read(&path).unwrap()));
        }
    }
    files.sort();
    files
}

/// `host <args>`, which must succeed; its standard output.
fn host(args: &[&str]) -> String {
    let output = integration_tests::host_command().args(args).output().unwrap();
    assert!(
        output.status.success(),
        "host {args:?}:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout).unwrap()
}

fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// `git status --porcelain` of the repository (every change, untracked files included); empty
/// outside a git checkout.
fn git_status(root: &Path) -> String {
    Command::new("git")
        .args(["status", "--porcelain", "--untracked-files=all"])
        .current_dir(root)
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).into_owned())
        .unwrap_or_default()
}

/// Whether `tool` cannot be started.
fn tool_missing(tool: &str) -> bool {
    Command::new(tool).arg("--version").output().is_err()
}

/// The target folder the standalone crates are built in: in this workspace's `target/`, shared between
/// runs.
fn target_folder() -> PathBuf {
    integration_tests::workspace_root()
        .join("target")
        .join("standalone-check")
}

/// `cargo <args>` in `folder`, in [`target_folder`].
fn cargo(folder: &Path, args: &[&str]) {
    let target = target_folder();
    let output = Command::new(env!("CARGO"))
        .args(args)
        .current_dir(folder)
        .env("CARGO_TARGET_DIR", &target)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "cargo {args:?} in {}:\n{}",
        folder.display(),
        String::from_utf8_lossy(&output.stderr)
    );
}

/// The walkthrough's crate: a user's spec, outside the repository (Example 1 under another name: the
/// same data and fits, so its observer is `generated::vanderpol`'s, which the C program is held
/// against), made a crate by `gen --spec` as a user types it (the README's tour), once per process.
/// Each case below holds it while it runs (one rewrites its files and puts them back), and ends by
/// checking that the repository is as it was before the walkthrough.
struct Walkthrough {
    root: PathBuf,
    scratch: PathBuf,
    spec: PathBuf,
    /// The spec's text.
    text: String,
    /// The crate.
    out: PathBuf,
    generated_before: Vec<(PathBuf, Vec<u8>)>,
    status_before: String,
    /// Cases that have finished: the last of [`Walkthrough::CASES`] removes the scratch folder.
    finished: usize,
}

impl Walkthrough {
    const CASES: usize = 6;

    fn generate() -> Self {
        let root = integration_tests::workspace_root();
        let generated_before = snapshot(&root.join("generated"));
        let status_before = git_status(&root);
        let scratch = std::env::temp_dir().join(format!("standalone-test-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&scratch);
        std::fs::create_dir_all(&scratch).unwrap();
        let spec = scratch.join("my_oscillator.toml");
        let text =
            integration_tests::spec_text("vanderpol").replacen("name = \"vanderpol\"", "name = \"my_oscillator\"", 1);
        assert!(text.contains("name = \"my_oscillator\""));
        std::fs::write(&spec, &text).unwrap();
        let out = scratch.join("crate");
        host(&[
            "gen",
            "--spec",
            s(&spec),
            "--out",
            s(&out),
            "--runtime-path",
            s(&root.join("firmware")),
            "--strict",
        ]);
        // The C program the C cases build (against the library, the source, for the board).
        std::fs::write(scratch.join("replay.c"), replay_source()).unwrap();
        Walkthrough {
            root,
            scratch,
            spec,
            text,
            out,
            generated_before,
            status_before,
            finished: 0,
        }
    }

    /// The crate's one C99 source file (`c-source/*.c`).
    fn c_source(&self) -> PathBuf {
        let sources: Vec<PathBuf> = std::fs::read_dir(self.out.join("c-source"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "c"))
            .collect();
        assert_eq!(sources.len(), 1, "{sources:?}");
        sources[0].clone()
    }

    /// The project's generated crate is untouched, byte for byte, nor anything else of the
    /// repository; the last case to finish removes the scratch folder.
    fn finish(&mut self) {
        assert!(
            self.generated_before == snapshot(&self.root.join("generated")),
            "gen --spec changed generated/"
        );
        assert_eq!(
            git_status(&self.root),
            self.status_before,
            "the walkthrough changed the repository"
        );
        self.finished += 1;
        if self.finished == Self::CASES {
            std::fs::remove_dir_all(&self.scratch).unwrap();
        }
    }
}

/// The walkthrough, generated on first use; held until the case ends.
fn walkthrough() -> MutexGuard<'static, Walkthrough> {
    static WALKTHROUGH: OnceLock<Mutex<Walkthrough>> = OnceLock::new();
    WALKTHROUGH
        .get_or_init(|| Mutex::new(Walkthrough::generate()))
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
}

#[test]
fn the_users_crate_has_its_files_its_spec_and_a_licence_statement() {
    let mut w = walkthrough();
    let (out, text) = (&w.out, &w.text);
    for file in [
        "Cargo.toml",
        "README.md",
        "spec.toml",
        "src/lib.rs",
        "src/my_oscillator.rs",
        "report/report.md",
        "report/report.json",
        "report/estimation.png",
    ] {
        assert!(out.join(file).is_file(), "{file} missing");
    }
    assert_eq!(std::fs::read_to_string(out.join("spec.toml")).unwrap(), *text);
    let source = std::fs::read_to_string(out.join("src/my_oscillator.rs")).unwrap();
    assert!(source.contains("pub const SPEC: &str = \"spec.toml\";"));
    assert!(source.contains("my_oscillator_observer::my_oscillator::observer()"));
    let readme = std::fs::read_to_string(out.join("README.md")).unwrap();
    assert!(readme.contains("| x1 |") && readme.contains("![estimation](report/estimation.png)"));
    // What the user may do with the files: stated in the crate's README, manifests and every emitted
    // source (issue 48).
    assert!(
        readme.contains(&host::emit::LICENCE.join(" ")),
        "README: no licence statement"
    );
    for file in ["Cargo.toml", "c/Cargo.toml"] {
        let manifest = std::fs::read_to_string(out.join(file)).unwrap();
        assert!(
            manifest.contains("\nlicense = \"MIT OR Apache-2.0\"\n"),
            "{file}: {manifest}"
        );
    }
    for file in [
        "Cargo.toml",
        "c/Cargo.toml",
        "src/lib.rs",
        "src/my_oscillator.rs",
        "c/src/lib.rs",
        "c/include/my_oscillator.h",
        "c-source/my_oscillator.h",
        "c-source/my_oscillator.c",
    ] {
        let text = std::fs::read_to_string(out.join(file)).unwrap();
        assert!(
            host::emit::LICENCE.iter().all(|line| text.contains(line)),
            "{file}: no licence statement"
        );
    }
    w.finish();
}

/// It builds for the Cortex-M4F and its doc example runs, with no workspace around it.
#[test]
fn the_users_crate_builds_for_the_cortex_m4f_and_its_doc_example_runs() {
    let mut w = walkthrough();
    let out = &w.out;
    cargo(
        out,
        &["build", "--offline", "--release", "--target", "thumbv7em-none-eabihf"],
    );
    cargo(out, &["test", "--offline", "--doc"]);
    w.finish();
}

/// Its observers as C99 source (the route without a Rust toolchain) compile without a warning under
/// the strict flags (their bits: `c_source.rs`, on the shipped designs).
#[test]
fn the_users_c_source_compiles_without_a_warning() {
    let mut w = walkthrough();
    let scratch = &w.scratch;
    let built = Command::new("cc")
        .args(integration_tests::on_target::STRICT_C_FLAGS)
        .args(["-O2", "-c", "-o"])
        .arg(scratch.join("c-source.o"))
        .arg(w.c_source())
        .output()
        .unwrap();
    assert!(built.status.success(), "cc: {}", String::from_utf8_lossy(&built.stderr));
    w.finish();
}

/// Its C library, linked into a C program by the system's compiler, and its C source in the same
/// program: the Rust observer's bits.
#[test]
fn the_users_c_library_and_c_source_give_the_rust_bits() {
    let mut w = walkthrough();
    let (out, scratch) = (&w.out, &w.scratch);
    let c = out.join("c");
    cargo(&c, &["build", "--offline", "--release"]);
    let library = target_folder().join("release/libmy_oscillator_observer_c.a");
    let program = scratch.join("replay");
    // With AddressSanitizer and UndefinedBehaviorSanitizer where the toolchain has them: a call that
    // reads or writes beyond the storage the program gave it stops the program.
    let compile = |sanitizers: &[&str]| {
        Command::new("cc")
            .args(["-std=c99", "-Wall", "-Werror", "-O1"])
            .args(sanitizers)
            .arg("-o")
            .arg(&program)
            .arg(scratch.join("replay.c"))
            .arg("-I")
            .arg(c.join("include"))
            .arg(&library)
            .output()
            .unwrap()
    };
    let mut compiled = compile(&[
        "-fsanitize=address,undefined",
        "-fno-sanitize-recover=all",
        "-fno-omit-frame-pointer",
    ]);
    if !compiled.status.success() {
        eprintln!(
            "the C program without sanitizers (cc could not build it with them: {})",
            String::from_utf8_lossy(&compiled.stderr)
        );
        compiled = compile(&[]);
    }
    assert!(
        compiled.status.success(),
        "cc: {}",
        String::from_utf8_lossy(&compiled.stderr)
    );
    let run = Command::new(&program).output().unwrap();
    assert!(run.status.success(), "replay: {}", String::from_utf8_lossy(&run.stderr));
    let printed = String::from_utf8(run.stdout).unwrap();
    assert_eq!(printed, rust_replay());
    assert!(printed.lines().filter(|l| l.split(' ').nth(2) == Some("0")).count() > 50);
    assert!(
        printed.lines().any(|l| l.split(' ').nth(1) == Some("1")),
        "no refused sample"
    );
    // The same program against the C source instead of the library (no Rust toolchain): the same
    // calls, statuses and checks, the same bits.
    let from_source = scratch.join("replay-source");
    let built = Command::new("cc")
        .args(["-std=c99", "-Wall", "-Werror", "-O1", "-ffp-contract=off", "-o"])
        .arg(&from_source)
        .arg(scratch.join("replay.c"))
        .arg(w.c_source())
        .arg("-I")
        .arg(out.join("c-source"))
        .arg("-lm")
        .output()
        .unwrap();
    assert!(built.status.success(), "cc: {}", String::from_utf8_lossy(&built.stderr));
    let run = Command::new(&from_source).output().unwrap();
    assert!(
        run.status.success(),
        "replay (C source): {}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert_eq!(
        String::from_utf8(run.stdout).unwrap(),
        printed,
        "the C source against the library"
    );
    w.finish();
}

/// The same C program for the Cortex-M4F, by arm-none-eabi-gcc against the library built for
/// thumbv7em, on the emulated board (semihosting prints): the same bits; then the crate measured
/// there into its own README.
#[test]
fn the_users_c_program_gives_the_rust_bits_on_the_emulated_board_and_is_measured_there() {
    let mut w = walkthrough();
    let (root, out, scratch, spec) = (&w.root, &w.out, &w.scratch, &w.spec);
    if tool_missing("arm-none-eabi-gcc") || tool_missing("qemu-system-arm") {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI needs arm-none-eabi-gcc (gcc-arm-none-eabi, libnewlib-arm-none-eabi) and qemu-system-arm"
        );
        eprintln!("skipped the C program on the emulated Cortex-M4F: arm-none-eabi-gcc or qemu-system-arm missing");
    } else {
        let c = out.join("c");
        cargo(
            &c,
            &["build", "--offline", "--release", "--target", "thumbv7em-none-eabihf"],
        );
        let library = target_folder().join("thumbv7em-none-eabihf/release/libmy_oscillator_observer_c.a");
        let board = root.join("tests/c");
        let elf = scratch.join("replay.elf");
        let compiled = Command::new("arm-none-eabi-gcc")
            .args(["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16"])
            .args([
                "-std=c99",
                "-Wall",
                "-Werror",
                "-O1",
                "--specs=rdimon.specs",
                "-Wl,--gc-sections",
            ])
            .arg("-T")
            .arg(board.join("mps2-an386.ld"))
            .arg("-o")
            .arg(&elf)
            .arg(board.join("startup.c"))
            .arg(scratch.join("replay.c"))
            .arg("-I")
            .arg(c.join("include"))
            .arg(&library)
            .output()
            .unwrap();
        assert!(
            compiled.status.success(),
            "arm-none-eabi-gcc: {}",
            String::from_utf8_lossy(&compiled.stderr)
        );
        let run = Command::new("timeout")
            .args([
                "120",
                "qemu-system-arm",
                "-machine",
                "mps2-an386",
                "-cpu",
                "cortex-m4",
                "-nographic",
            ])
            .args([
                "-monitor",
                "none",
                "-serial",
                "none",
                "-semihosting-config",
                "enable=on,target=native",
                "-kernel",
            ])
            .arg(&elf)
            .stdin(std::process::Stdio::null())
            .output()
            .unwrap();
        assert!(run.status.success(), "qemu: {}", String::from_utf8_lossy(&run.stderr));
        assert_eq!(String::from_utf8(run.stdout).unwrap(), rust_replay());

        measured_on_the_emulated_board(spec, out);
    }
    w.finish();
}

/// Recorded data: a run of the plant, then the design's estimates over it by the tables `gen` saved
/// beside the crate, in the chip's f32: the Rust observer's bits; and its figure.
#[test]
fn the_users_saved_tables_estimate_a_recording_as_the_rust_observer_and_plot_it() {
    let mut w = walkthrough();
    let (out, scratch, spec) = (&w.out, &w.scratch, &w.spec);
    let run = scratch.join("run.csv");
    host(&["simulate", "--spec", s(spec), "--output", s(&run)]);
    let estimates = scratch.join("estimates.csv");
    host(&[
        "estimate",
        "--spec",
        s(spec),
        "--input",
        s(&run),
        "--output",
        s(&estimates),
        "--tables",
        s(&out.join("report/design.json")),
        "--precision",
        "f32",
    ]);
    let written = std::fs::read_to_string(&estimates).unwrap();
    assert_eq!(written, rust_estimates(&std::fs::read_to_string(&run).unwrap()));
    assert!(written.matches(",ok,").count() > 50, "{written}");
    // And its figure: every target against its truth.
    host(&[
        "plot",
        "--spec",
        s(spec),
        "--input",
        s(&run),
        "--estimates",
        s(&estimates),
    ]);
    for figure in ["estimates.png", "estimates.svg"] {
        let bytes = std::fs::read(scratch.join(figure)).unwrap();
        assert!(bytes.len() > 10_000, "{figure}: {} bytes", bytes.len());
    }
    w.finish();
}

/// `on-target-report -- --crate DIR` on the walkthrough's crate: every observer's figures go into the
/// crate's report and README (never the project's `docs/chip.md`), checked there against the host;
/// `gen --spec` again writes the same README (the figures are kept while the source is the one
/// measured); and tables that do not compute what the chip computes are refused, nothing written.
fn measured_on_the_emulated_board(spec: &Path, out: &Path) {
    let report = || {
        Command::new(env!("CARGO_BIN_EXE_on-target-report"))
            .arg("--crate")
            .arg(out)
            .output()
            .unwrap()
    };
    let before = std::fs::read_to_string(out.join("README.md")).unwrap();
    assert!(before.contains("Not measured for this generated source yet"));
    let run = report();
    assert!(
        run.status.success(),
        "on-target-report --crate: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    // What it prints is the section, and the README changed by that section alone.
    let section = String::from_utf8(run.stdout).unwrap();
    let readme = std::fs::read_to_string(out.join("README.md")).unwrap();
    assert_eq!(host::report::on_target::splice(&before, &section), Some(readme.clone()));
    let rows: Vec<&str> = section
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| l.split(" | ").next().unwrap())
        .collect();
    assert_eq!(
        rows,
        // In the order of the observer kinds' registry (`host::observers::kind::REGISTRY`).
        [
            "| `map_observer()`",
            "| `ekf()`",
            "| `UkfBoxObserver`",
            "| `CorrectedObserver`",
            "| `EkfMapObserver`",
            "| `EkfRestartObserver`",
            "| `MheObserver`"
        ],
        "{section}"
    );
    let markdown = std::fs::read_to_string(out.join("report/report.md")).unwrap();
    assert!(markdown.contains(&section), "report.md shows the same figures");
    assert!(out.join("report/on_target.json").is_file());

    host(&[
        "gen",
        "--spec",
        s(spec),
        "--out",
        s(out),
        "--runtime-path",
        s(&integration_tests::workspace_root().join("firmware")),
    ]);
    assert_eq!(
        std::fs::read_to_string(out.join("README.md")).unwrap(),
        readme,
        "gen again keeps the figures"
    );

    // One gain of the saved table off by 1 %: tables that no longer compute what the chip computes.
    // As edited by hand, they no longer hash to their `tables_sha256`; with that hash fixed up too,
    // the observer beside them does not carry it. Either way they are refused and nothing is written,
    // by `on-target-report` and by `estimate`.
    let path = out.join("report/design.json");
    let saved = std::fs::read_to_string(&path).unwrap();
    let mut tables = host::tables::Tables::read(&path).unwrap().unwrap();
    let table = tables.maps[0].table.as_mut().unwrap();
    table.gains[0] *= 1.01;
    let (recording, estimates) = (
        out.with_file_name("edited-run.csv"),
        out.with_file_name("edited-estimates.csv"),
    );
    std::fs::write(&recording, "y\n0.5\n0.6\n").unwrap();
    for (fixed_up, message) in [(false, "changed since `gen` wrote it"), (true, "not the observer file")] {
        if fixed_up {
            tables.tables_sha256 = tables.content_sha256();
        }
        std::fs::write(&path, tables.to_json()).unwrap();
        let run = report();
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert!(!run.status.success() && stderr.contains(message), "{stderr}");
        assert_eq!(
            std::fs::read_to_string(out.join("README.md")).unwrap(),
            readme,
            "nothing written"
        );
        let run = integration_tests::host_command()
            .args([
                "estimate",
                "--spec",
                s(spec),
                "--input",
                s(&recording),
                "--output",
                s(&estimates),
            ])
            .args(["--tables", s(&path), "--precision", "f32"])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&run.stderr);
        let message = if fixed_up { "TABLES_SHA256 differs" } else { message };
        assert!(!run.status.success() && stderr.contains(message), "{stderr}");
        assert!(!estimates.exists());
    }
    std::fs::write(&path, saved).unwrap();
}

/// The estimates file of the Rust observer (the design's, `generated::vanderpol`) over the `y` column
/// of the simulated run `csv`: `time,status,x1,x2,saturated_x1,saturated_x2`.
fn rust_estimates(csv: &str) -> String {
    use generated::vanderpol as d;
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let (time, y) = (0, header.iter().position(|h| *h == "y").unwrap());
    let mut observer = d::observer();
    let mut text = String::from("time,status,x1,x2,saturated_x1,saturated_x2\n");
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        let sample: f32 = cells[y].parse().unwrap();
        let accepted = observer.push([sample], []).is_ok();
        let row = integration_tests::estimates_row(accepted, observer.estimate().as_ref().map(|e| &e[..]), d::TARGETS);
        text += &format!("{},{row}\n", cells[time]);
    }
    text
}

/// The C program: every recorded sample of Example 1's scenario pushed, the estimates printed as bits,
/// one line per sample: `k push-status estimate-status [bits saturation]…`.
fn replay_source() -> String {
    use generated::vanderpol as d;
    let rows: Vec<String> = d::RECORDED_Y
        .iter()
        .map(|y| format!("{{0x{:08x}u}}", y[0].to_bits()))
        .collect();
    let tau = format!("{:?}", d::SAMPLE_PERIOD);
    format!(
        r#"#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "my_oscillator.h"

static const uint32_t samples[{len}][MY_OSCILLATOR_OUTPUTS] = {{ {rows} }};
static uint8_t storage[MY_OSCILLATOR_STORAGE_SIZE] __attribute__((aligned(MY_OSCILLATOR_STORAGE_ALIGN)));
static uint8_t zeroed[MY_OSCILLATOR_STORAGE_SIZE] __attribute__((aligned(MY_OSCILLATOR_STORAGE_ALIGN)));
static uint8_t small[16] __attribute__((aligned(MY_OSCILLATOR_STORAGE_ALIGN)));

int main(void) {{
    /* Storage `init` never made an observer in (zeroed, or one it refused as too small) is refused by
       every call, which reads its first 16 bytes and nothing else (the sanitizers watch). */
    float y0[MY_OSCILLATOR_OUTPUTS] = {{0}};
    float x0[MY_OSCILLATOR_TARGETS];
    if (my_oscillator_estimate(zeroed, x0, NULL) != MY_OSCILLATOR_NOT_INITIALISED) return 5;
    if (my_oscillator_push(zeroed, y0, NULL) != MY_OSCILLATOR_NOT_INITIALISED) return 6;
    if (my_oscillator_init(small, sizeof small) != MY_OSCILLATOR_BAD_ARGUMENT) return 7;
    if (my_oscillator_push(small, y0, NULL) != MY_OSCILLATOR_NOT_INITIALISED) return 8;
    if (my_oscillator_estimate(small, x0, NULL) != MY_OSCILLATOR_NOT_INITIALISED) return 9;
    if (my_oscillator_init(storage, sizeof storage) != MY_OSCILLATOR_OK) return 2;
    if (my_oscillator_storage_size() > sizeof storage) return 3;
    if (MY_OSCILLATOR_SAMPLE_PERIOD != {tau}f) return 4; /* the header states the design's period, a float */
    for (int k = 0; k < {len}; k++) {{
        float y[MY_OSCILLATOR_OUTPUTS];
        memcpy(y, samples[k], sizeof y);
        int pushed = my_oscillator_push(storage, y, NULL);
        float x[MY_OSCILLATOR_TARGETS];
        my_oscillator_saturation saturation[MY_OSCILLATOR_TARGETS];
        int status = my_oscillator_estimate(storage, x, saturation);
        printf("%d %d %d", k, pushed, status);
        for (int t = 0; status == MY_OSCILLATOR_OK && t < MY_OSCILLATOR_TARGETS; t++) {{
            uint32_t bits;
            memcpy(&bits, &x[t], sizeof bits);
            printf(" %08lx %d", (unsigned long)bits, (int)saturation[t]);
        }}
        printf("\n");
    }}
    return 0;
}}
"#,
        len = d::RECORDED_LEN,
        rows = rows.join(", "),
        tau = tau,
    )
}

/// What [`replay_source`] prints, from the Rust observer.
fn rust_replay() -> String {
    use generated::vanderpol as d;
    use std::fmt::Write as _;
    let mut observer = d::observer();
    let mut text = String::new();
    for (k, (y, u)) in d::RECORDED_Y.iter().zip(d::RECORDED_U.iter()).enumerate() {
        let pushed = u8::from(observer.push(*y, *u).is_err());
        let estimates = observer.estimate();
        let _ = write!(text, "{k} {pushed} {}", if estimates.is_some() { 0 } else { 2 });
        for e in estimates.iter().flatten() {
            // The C enum `my_oscillator_saturation`: INSIDE 0, LOW 1, HIGH 2 on both routes.
            let flag = match e.saturation {
                firmware::Saturation::Inside => 0,
                firmware::Saturation::Low => 1,
                firmware::Saturation::High => 2,
            };
            let _ = write!(text, " {:08x} {flag}", e.value.to_bits());
        }
        text.push('\n');
    }
    text
}

/// The installed tool, anywhere: run from a folder with no checkout above it and given no runtime,
/// `mho gen --spec` writes a crate that carries the `firmware` runtime (the checkout's sources, byte
/// for byte) and builds offline for the Cortex-M4F with nothing but the toolchain.
#[test]
fn the_tool_writes_a_crate_that_builds_outside_the_checkout() {
    let dir = std::env::temp_dir().join(format!("mho-anywhere-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    assert!(
        !dir.ancestors().any(|d| d.join("host/specs").is_dir()),
        "{} is inside a checkout",
        dir.display()
    );
    // Example 1 with 8 validation and 8 tuning runs: a quicker fit, the same crate layout.
    let text = integration_tests::spec_text("vanderpol")
        .replacen("name = \"vanderpol\"", "name = \"plant\"", 1)
        .replacen("\ntrajectories = 64", "\ntrajectories = 8", 1)
        .replacen("[tuning]", "[tuning]\ntrajectories = 8", 1);
    std::fs::write(dir.join("plant.toml"), text).unwrap();
    let run = integration_tests::host_command()
        .args(["gen", "--spec", "plant.toml", "--out", "plant-observer"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let out = dir.join("plant-observer");
    let manifest = std::fs::read_to_string(out.join("Cargo.toml")).unwrap();
    assert!(manifest.contains("firmware = { path = \"firmware\" }"), "{manifest}");
    let root = integration_tests::workspace_root();
    for file in ["src/lib.rs", "src/map.rs", "src/ekf.rs", "src/restarted.rs"] {
        assert_eq!(
            std::fs::read(out.join("firmware").join(file)).unwrap(),
            std::fs::read(root.join("firmware").join(file)).unwrap(),
            "firmware/{file}"
        );
    }
    cargo(
        &out,
        &["build", "--offline", "--release", "--target", "thumbv7em-none-eabihf"],
    );
    let _ = std::fs::remove_dir_all(&dir);
}
