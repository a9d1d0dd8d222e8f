//! Shared helpers of the integration tests: the shipped specs and designs built from them.

pub mod on_target;
pub mod tolerance;

use std::path::{Path, PathBuf};

use host::pipeline::{self, DesignResult};
use host::spec::{self, Design};

/// The folder of the specs shipped with the host.
pub fn specs_folder() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("host")
        .join("specs")
}

/// The text of a shipped spec.
pub fn spec_text(name: &str) -> String {
    std::fs::read_to_string(specs_folder().join(format!("{name}.toml"))).expect("shipped spec")
}

/// Parses spec text as if it were the file `name.toml`.
pub fn design(name: &str, text: &str) -> Design {
    spec::parse(Path::new(&format!("{name}.toml")), text).expect("valid spec")
}

/// The workspace root.
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every shipped spec file, sorted.
pub fn shipped_specs() -> Vec<PathBuf> {
    let mut specs: Vec<PathBuf> = std::fs::read_dir(specs_folder())
        .expect("host/specs")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    specs.sort();
    specs
}

/// Loads a spec given relative to the workspace (as generated files record it).
pub fn load_relative(spec: &str) -> Design {
    spec::load(&workspace_root().join(spec)).expect("valid spec")
}

/// Builds a design (data, fits, evaluation) without progress output.
pub fn build(design: &Design) -> DesignResult {
    pipeline::run(design, &indicatif::ProgressBar::hidden()).expect("the design builds")
}
