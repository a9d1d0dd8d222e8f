//! Lists, for the on-target tests, the observers of every generated design that the map starts or
//! checks (`firmware::Started`, `firmware::Restarted`): not every design has them, and code that
//! names one a design lacks does not compile, so the list is read from the generated sources
//! (`generated/src/<design>.rs`, where `gen` declares each as `pub type CorrectedObserver = …`,
//! `pub type StartedEkfObserver = …`, `pub type RestartedEkfObserver = …`, host/src/emit/model.rs)
//! and written as a macro, `for_each_started_observer!`, into `OUT_DIR/started_observers.rs`; with it
//! `for_each_fixed_observer!`, the designs whose source has the integer observer (`fixed_observer()`),
//! and `for_each_ukf_observer!`, those with the unscented Kalman filter (`UkfObserver`).

use std::path::{Path, PathBuf};

/// The type alias `gen` declares for each kind, the kind's variant of `on_target::Kind`, and the
/// firmware shell it is.
const STARTED: [(&str, &str, &str); 4] = [
    ("CorrectedObserver", "Corrected", "Started"),
    ("StartedEkfObserver", "StartedEkf", "Started"),
    ("RestartedEkfObserver", "RestartedEkf", "Restarted"),
    ("MheObserver", "Mhe", "mhe::Observer"),
];

fn main() {
    let sources = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/src");
    println!("cargo:rerun-if-changed={}", sources.display());
    let mut designs: Vec<(String, String)> = std::fs::read_dir(&sources)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", sources.display()))
        .map(|entry| entry.expect("a directory entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "rs") && !path.ends_with("lib.rs"))
        .map(|path| {
            let name = path
                .file_stem()
                .and_then(|s| s.to_str())
                .expect("a UTF-8 file name")
                .to_owned();
            let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
            (name, text)
        })
        .collect();
    designs.sort();
    let mut calls = String::new();
    for (name, text) in &designs {
        for (alias, kind, shell) in STARTED {
            if text.contains(&format!("\npub type {alias} = firmware::{shell}<")) {
                calls += &format!("        $callback!({name}, {kind}, {alias});\n");
            }
        }
    }
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    let text = format!(
        "/// Invokes `$callback!(design, kind, Type)` for every observer of a generated design that the\n/// map starts (`firmware::Started`): `kind` is its [`crate::on_target::Kind`] variant, `Type` its alias in the\n/// design's module. Written by `tests/build.rs` from the generated sources.\n#[macro_export]\nmacro_rules! for_each_started_observer {{\n    ($callback:ident) => {{\n{calls}    }};\n}}\n"
    );
    // The integer observer, where the design has one (`gen` writes `pub fn fixed_observer(`, or
    // `pub const fn`).
    let fixed: String = designs
        .iter()
        .filter(|(_, text)| text.contains("pub fn fixed_observer(") || text.contains("pub const fn fixed_observer("))
        .map(|(name, _)| format!("        $callback!({name});\n"))
        .collect();
    let text = format!(
        "{text}\n/// Invokes `$callback!(design)` for every generated design with an integer observer\n/// (`fixed_observer()`). Written by `tests/build.rs` from the generated sources.\n#[macro_export]\nmacro_rules! for_each_fixed_observer {{\n    ($callback:ident) => {{\n{fixed}    }};\n}}\n"
    );
    // The UKF from the box centre, where the design has one (`pub type UkfObserver = firmware::FilterObserver<…>`).
    let ukf: String = designs
        .iter()
        .filter(|(_, text)| text.contains("\npub type UkfObserver = firmware::FilterObserver<"))
        .map(|(name, _)| format!("        $callback!({name});\n"))
        .collect();
    let text = format!(
        "{text}\n/// Invokes `$callback!(design)` for every generated design with an unscented Kalman filter\n/// (`UkfObserver`). Written by `tests/build.rs` from the generated sources.\n#[macro_export]\nmacro_rules! for_each_ukf_observer {{\n    ($callback:ident) => {{\n{ukf}    }};\n}}\n"
    );
    std::fs::write(out.join("started_observers.rs"), text).expect("write started_observers.rs");
}
