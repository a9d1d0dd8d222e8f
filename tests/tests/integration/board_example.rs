//! The board example (`examples/board/`, built for the emulated board) on QEMU: every line it prints
//! is what the host gets running the same generated observer in f32 over the same recorded CSV, read
//! by the host's own CSV reader (its estimates bit for bit: the example prints each value as the
//! shortest decimal that reads back as the same f32). The recording is the one the comment in
//! `examples/board/src/sensor.rs` says the tool makes. Without QEMU or the thumbv7em target the test
//! says so and passes, unless `CI` is set: CI must run it.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

use generated::vanderpol as design;
use integration_tests::on_target::{self, TargetSample, Unavailable};

/// Where the example is built: its own target folder, kept between runs.
fn target_dir() -> PathBuf {
    integration_tests::workspace_root().join("target").join("board-example")
}

/// Whether rustup has installed the Cortex-M4F standard library for the toolchain cargo runs.
fn target_installed() -> bool {
    let Ok(output) = Command::new("rustc").args(["--print", "sysroot"]).output() else {
        return false;
    };
    let sysroot = String::from_utf8_lossy(&output.stdout).trim().to_owned();
    Path::new(&sysroot).join("lib/rustlib/thumbv7em-none-eabihf").is_dir()
}

/// Builds the example for QEMU's mps2-an386 and returns its ELF.
fn build() -> PathBuf {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let output = Command::new(cargo)
        .current_dir(integration_tests::workspace_root())
        .args(["build", "--release", "--manifest-path", "examples/board/Cargo.toml"])
        .args(["--target", "thumbv7em-none-eabihf"])
        .args(["--no-default-features", "--features", "qemu-mps2-an386", "--target-dir"])
        .arg(target_dir())
        .output()
        .expect("run cargo");
    assert!(
        output.status.success(),
        "building the board example:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    target_dir().join("thumbv7em-none-eabihf/release/board-example")
}

/// The example's lines, one per sample, as [`TargetSample`]s: `<k> refused`, `<k> no estimate yet`
/// or `<k>` then `<target>=<value>` per target, `(low)` or `(high)` after a clamped value.
fn parse(lines: &[&str]) -> Vec<TargetSample> {
    lines
        .iter()
        .enumerate()
        .map(|(k, line)| {
            let (number, rest) = line.split_once(' ').unwrap_or_else(|| panic!("line {line:?}"));
            assert_eq!(number, k.to_string(), "sample numbers in order");
            match rest {
                "refused" => TargetSample {
                    accepted: false,
                    estimates: None,
                },
                "no estimate yet" => TargetSample {
                    accepted: true,
                    estimates: None,
                },
                estimates => {
                    let fields: Vec<&str> = estimates.split(' ').collect();
                    assert_eq!(fields.len(), design::TARGETS, "{line:?}: one field per target");
                    let estimates = fields
                        .iter()
                        .zip(design::TARGET_NAMES)
                        .map(|(field, name)| {
                            let value = field
                                .strip_prefix(name)
                                .and_then(|f| f.strip_prefix('='))
                                .unwrap_or_else(|| panic!("{line:?}: {name} expected"));
                            let (value, flag) = if let Some(v) = value.strip_suffix("(low)") {
                                (v, 'L')
                            } else if let Some(v) = value.strip_suffix("(high)") {
                                (v, 'H')
                            } else {
                                (value, 'I')
                            };
                            let value: f32 = value.parse().unwrap_or_else(|e| panic!("{line:?}: {e}"));
                            (value.to_bits(), flag)
                        })
                        .collect();
                    TargetSample {
                        accepted: true,
                        estimates: Some(estimates),
                    }
                }
            }
        })
        .collect()
}

/// What the example must print for the recording at `csv`: the design's observer run on the host in
/// f32 over the samples the host's CSV reader gets (each value rounded once, from f64, to f32); a
/// refused sample prints no estimate.
fn on_the_host(csv: &Path) -> Vec<TargetSample> {
    let spec = host::spec::load(&integration_tests::specs_folder().join("vanderpol.toml")).expect("the spec");
    let rows = host::recording::read(&spec, csv).expect("the recording reads");
    let mut observer = design::observer();
    rows.iter()
        .map(|row| {
            let y: [f32; design::OUTPUTS] = std::array::from_fn(|i| row.y[i] as f32);
            let u: [f32; design::INPUTS] = std::array::from_fn(|i| row.u[i] as f32);
            let accepted = observer.push(y, u).is_ok();
            TargetSample {
                accepted,
                estimates: observer
                    .estimate()
                    .filter(|_| accepted)
                    .map(|e| on_target::bits_and_flags(&e, f32::to_bits)),
            }
        })
        .collect()
}

#[test]
fn the_board_example_prints_the_hosts_estimates_on_the_emulated_board() {
    let root = integration_tests::workspace_root();
    let csv = root.join("examples/board/data/run.csv");

    // The recording is the tool's, made by the command in the sensor's comment (the spec's
    // scenario, 60 samples): nothing in it is typed by hand.
    let sensor = std::fs::read_to_string(root.join("examples/board/src/sensor.rs")).expect("sensor.rs");
    assert!(sensor.contains("simulate --design vanderpol --samples 60 --output examples/board/data/run.csv"));
    let scratch = std::env::temp_dir().join(format!("board-example-{}", std::process::id()));
    std::fs::create_dir_all(&scratch).expect("a scratch folder");
    let remade = scratch.join("run.csv");
    let spec = host::spec::load(&integration_tests::specs_folder().join("vanderpol.toml")).expect("the spec");
    let samples = host::commands::Simulation {
        samples: Some(60),
        ..Default::default()
    };
    host::commands::simulate(&spec, &samples, &remade).expect("simulate");
    assert_eq!(
        std::fs::read_to_string(&remade).expect("the remade recording"),
        std::fs::read_to_string(&csv).expect("examples/board/data/run.csv"),
        "examples/board/data/run.csv is not what the command in sensor.rs writes"
    );
    std::fs::remove_dir_all(&scratch).expect("remove the scratch folder");

    match on_target::require_emulator() {
        Err(missing @ Unavailable::Missing { .. }) if std::env::var_os("CI").is_none() => {
            println!("BOARD EXAMPLE TEST DID NOT RUN: {missing}");
            eprintln!("BOARD EXAMPLE TEST DID NOT RUN: {missing}");
            return;
        }
        Err(e) => panic!("the emulator: {e}"),
        Ok(()) => {}
    }
    if !target_installed() {
        let message = "the thumbv7em-none-eabihf target is not installed (rustup target add thumbv7em-none-eabihf)";
        assert!(std::env::var_os("CI").is_none(), "{message}");
        println!("BOARD EXAMPLE TEST DID NOT RUN: {message}");
        eprintln!("BOARD EXAMPLE TEST DID NOT RUN: {message}");
        return;
    }

    let elf = build();
    let (text, data, bss) = on_target::sizes(&elf).expect("arm-none-eabi-size");
    println!(
        "board example (qemu-mps2-an386): flash {} bytes, static RAM {} bytes",
        text + data,
        data + bss
    );
    let printed = on_target::run_on_emulator(&elf, &target_dir().join("run.out"), Duration::from_secs(60))
        .unwrap_or_else(|e| panic!("{e}"));
    let lines: Vec<&str> = printed.lines().collect();
    let host = on_the_host(&csv);
    assert_eq!(
        lines.first().copied(),
        Some(format!("vanderpol observer ({}), {} recorded samples", design::KIND, host.len()).as_str()),
        "the banner"
    );
    assert_eq!(lines.last().copied(), Some("end of the recording"));
    let board = parse(&lines[1..lines.len() - 1]);

    // Every sample: accepted or not, an estimate or not, and each estimate's bits and clamp flag.
    let differences = on_target::differences("board example", &board, &host);
    assert!(
        differences.is_empty(),
        "the board example and the host differ:\n{}",
        differences.join("\n")
    );
    // What was compared: the samples before the first estimate (the window filling, HORIZON - 1
    // samples, for the kinds the map starts; none for the EKFs from the box centre), then an estimate
    // of every target at every sample.
    let estimated = board.iter().filter(|s| s.estimates.is_some()).count();
    let without = match design::KIND {
        "ekf_box" | "ukf_box" | "ekf_restart" => 0,
        _ => design::HORIZON - 1,
    };
    assert_eq!(board.len(), 60);
    assert_eq!(estimated, 60 - without);
    println!(
        "board example: {} samples, {estimated} estimates of {} targets equal bit for bit",
        board.len(),
        design::TARGETS
    );

    // The first estimate the example's README and main.rs quote is the one it prints.
    let first = lines[design::HORIZON];
    for quoted in ["examples/board/README.md", "examples/board/src/main.rs"] {
        let text = std::fs::read_to_string(root.join(quoted)).expect("the example's file");
        assert!(
            text.contains(first),
            "{quoted} does not quote the first estimate {first:?}"
        );
    }

    // The comparison sees one bit of one printed value, and a clamp flag.
    let mut changed = board.clone();
    let last = changed
        .iter_mut()
        .rev()
        .find_map(|s| s.estimates.as_mut())
        .expect("an estimate");
    last[0].0 ^= 1;
    assert_eq!(on_target::differences("flipped", &changed, &host).len(), 1);
    let mut changed = board.clone();
    let last = changed
        .iter_mut()
        .rev()
        .find_map(|s| s.estimates.as_mut())
        .expect("an estimate");
    last[1].1 = if last[1].1 == 'I' { 'H' } else { 'I' };
    assert_eq!(on_target::differences("clamped", &changed, &host).len(), 1);
    // And the parser reads what the example writes for a clamped value and a refused sample.
    let odd = parse(&["0 refused", "1 x1=-2.5(low) x2=4(high)"]);
    assert_eq!(
        odd[0],
        TargetSample {
            accepted: false,
            estimates: None
        }
    );
    assert_eq!(
        odd[1].estimates,
        Some(vec![((-2.5f32).to_bits(), 'L'), (4.0f32.to_bits(), 'H')])
    );
}
