//! `gen --spec` for a user's own design: a crate of its own, outside this repository, that builds for
//! the Cortex-M4F and passes its doc example on its own, while the project's `generated/` crate is
//! left exactly as it was.

use std::path::{Path, PathBuf};
use std::process::Command;

use host::standalone::{self, Destination, Runtime};
use indicatif::ProgressBar;

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

/// `cargo <args>` in `folder`, with a target folder in this workspace's `target/` shared between runs.
fn cargo(folder: &Path, args: &[&str]) {
    let target = integration_tests::workspace_root()
        .join("target")
        .join("standalone-check");
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

#[test]
fn a_user_spec_becomes_a_crate_that_builds_on_its_own_and_leaves_generated_alone() {
    let root = integration_tests::workspace_root();
    let generated_before = snapshot(&root.join("generated"));
    let scratch = std::env::temp_dir().join(format!("standalone-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).unwrap();
    // A user's spec, outside the repository: Example 1 under another name, fewer validation runs.
    let spec = scratch.join("my_oscillator.toml");
    let text = integration_tests::spec_text("vanderpol")
        .replacen("name = \"vanderpol\"", "name = \"my_oscillator\"", 1)
        .replacen("trajectories = 64", "trajectories = 16", 1);
    assert!(text.contains("name = \"my_oscillator\""));
    std::fs::write(&spec, &text).unwrap();
    let out = scratch.join("crate");
    let to = Destination {
        out: out.clone(),
        per_design: false,
        runtime: Runtime::Path(root.join("firmware")),
    };
    let outcomes = standalone::run(
        std::slice::from_ref(&spec),
        &to,
        true,
        |_| ProgressBar::hidden(),
        |_, _| {},
    )
    .unwrap();
    assert_eq!(outcomes.len(), 1);
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
    assert_eq!(std::fs::read_to_string(out.join("spec.toml")).unwrap(), text);
    let source = std::fs::read_to_string(out.join("src/my_oscillator.rs")).unwrap();
    assert!(source.contains("pub const SPEC: &str = \"spec.toml\";"));
    assert!(source.contains("my_oscillator_observer::my_oscillator::observer()"));
    let readme = std::fs::read_to_string(out.join("README.md")).unwrap();
    assert!(readme.contains("| x1 |") && readme.contains("![estimation](report/estimation.png)"));

    // It builds for the Cortex-M4F and its doc example runs, with no workspace around it.
    cargo(
        &out,
        &["build", "--offline", "--release", "--target", "thumbv7em-none-eabihf"],
    );
    cargo(&out, &["test", "--offline", "--doc"]);

    // The project's generated crate is untouched, byte for byte.
    assert!(
        generated_before == snapshot(&root.join("generated")),
        "gen --spec changed generated/"
    );
    // A second run with nothing changed rewrites nothing.
    let again = standalone::run(&[spec], &to, true, |_| ProgressBar::hidden(), |_, _| {}).unwrap();
    assert!(!again[0].changed);
    std::fs::remove_dir_all(&scratch).unwrap();
}
