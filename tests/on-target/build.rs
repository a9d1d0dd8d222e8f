//! Puts memory.x where the linker finds it, passes cortex-m-rt's linker script to this program's
//! binaries only (not through global rustflags), and writes the runners' and the size probe's design
//! selection.

use std::path::PathBuf;

/// An observer kind the runner and the probe know: its name in `ON_TARGET_KIND` / `PROBE_KIND` and
/// the expression, in the design's module, that makes a fresh one.
const KINDS: [(&str, &str); 6] = [
    ("map", "map_observer()"),
    ("observer", "observer()"),
    ("corrected", "CorrectedObserver::new()"),
    ("started_ekf", "StartedEkfObserver::new()"),
    ("restarted_ekf", "RestartedEkfObserver::new()"),
    ("mhe", "MheObserver::new()"),
];

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    std::fs::copy("memory.x", out.join("memory.x")).expect("copy memory.x");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rerun-if-changed=memory.x");

    // The runners (`on-target` for the observers that estimate from the map's window, `ekf` for the
    // filter from the box centre) link the one design named by ON_TARGET_DESIGN (design.rs).
    // ON_TARGET_KIND lists, comma-separated, the observers `on-target` runs one after the other, each
    // over the whole recorded sequence (kinds.rs, which `ekf` does not read): `map` (the default),
    // `observer` (the design's chosen kind), `corrected`, `started_ekf`, `restarted_ekf`, `mhe`.
    println!("cargo:rerun-if-env-changed=ON_TARGET_DESIGN");
    println!("cargo:rerun-if-env-changed=ON_TARGET_KIND");
    let requested = std::env::var("ON_TARGET_KIND").unwrap_or_default();
    let kinds: Vec<(&str, &str)> = if requested.is_empty() {
        vec![KINDS[0]]
    } else {
        requested
            .split(',')
            .map(|name| kind(name.trim(), "ON_TARGET_KIND"))
            .collect()
    };
    let runner = module_name("ON_TARGET_DESIGN");
    let design = if runner.is_empty() {
        "compile_error!(\"set ON_TARGET_DESIGN to the generated design module to run\");\nmod d { pub const TARGETS: usize = 0; pub const OUTPUTS: usize = 0; pub const INPUTS: usize = 0; pub const RECORDED_LEN: usize = 0; pub type Ekf = (); pub const STATES: usize = 0; }\n".to_owned()
    } else {
        format!("use generated::{runner} as d;\n")
    };
    std::fs::write(out.join("design.rs"), design).expect("write design.rs");
    let runs: String = kinds
        .iter()
        .filter(|_| !runner.is_empty())
        .map(|(name, fresh)| format!("    run(\"{name}\", d::{fresh});\n"))
        .collect();
    let kinds = format!("/// Runs every observer this program measures (ON_TARGET_KIND), one after the other.\nfn run_all() {{\n{runs}}}\n");
    std::fs::write(out.join("kinds.rs"), kinds).expect("write kinds.rs");

    // The size probe links one design (or none, for the baseline) chosen by PROBE_DESIGN: one of its
    // observers (PROBE_KIND, as ON_TARGET_KIND but one kind; `map` by default), or with
    // PROBE_KIND=ekf its extended Kalman filter.
    println!("cargo:rerun-if-env-changed=PROBE_DESIGN");
    println!("cargo:rerun-if-env-changed=PROBE_KIND");
    let design = module_name("PROBE_DESIGN");
    let probe_kind = std::env::var("PROBE_KIND").unwrap_or_default();
    let probe = if design == "__reachable_panic" {
        // Proves the check can fail: an index the compiler cannot bound.
        "/// Indexes out of bounds (for the check's own test).\nfn probe() -> ! {\n    let table = core::hint::black_box([0u8; 4]);\n    loop {\n        core::hint::black_box(table[core::hint::black_box(7usize)]);\n    }\n}\n".to_owned()
    } else if design.is_empty() {
        "/// The baseline: the same loop with no observer.\nfn probe() -> ! {\n    loop {\n        core::hint::black_box(core::hint::black_box(0.0f32));\n    }\n}\n".to_owned()
    } else if probe_kind == "ekf" {
        format!(
            "/// Pushes samples into `{design}`'s extended Kalman filter and computes the targets, forever.\nfn probe() -> ! {{\n    use generated::{design} as d;\n    let mut filter = d::ekf();\n    loop {{\n        let y = core::hint::black_box([0.0f32; d::OUTPUTS]);\n        let u = core::hint::black_box([0.0f32; d::INPUTS]);\n        if let Ok(x) = filter.push(&y, &u) {{\n            core::hint::black_box(d::targets(&x, &u));\n        }}\n        core::hint::black_box(filter.state());\n        core::hint::black_box(filter.covariance());\n        if core::hint::black_box(false) {{\n            filter = d::ekf();\n        }}\n    }}\n}}\n"
        )
    } else {
        let (name, fresh) = if probe_kind.is_empty() {
            KINDS[0]
        } else {
            kind(&probe_kind, "PROBE_KIND")
        };
        format!(
            "/// Pushes samples into `{design}`'s {name} observer and estimates, forever.\nfn probe() -> ! {{\n    use generated::{design} as d;\n    let mut observer = d::{fresh};\n    loop {{\n        let y = core::hint::black_box([0.0f32; d::OUTPUTS]);\n        let u = core::hint::black_box([0.0f32; d::INPUTS]);\n        let _ = core::hint::black_box(observer.push(y, u));\n        core::hint::black_box(observer.estimate());\n        if core::hint::black_box(false) {{\n            observer.reset();\n        }}\n    }}\n}}\n"
        )
    };
    std::fs::write(out.join("probe_design.rs"), probe).expect("write probe_design.rs");
}

/// The kind named `name` (read from `variable`); an unknown name stops the build and says which exist.
fn kind(name: &str, variable: &str) -> (&'static str, &'static str) {
    KINDS.into_iter().find(|(known, _)| *known == name).unwrap_or_else(|| {
        let known: Vec<&str> = KINDS.iter().map(|(known, _)| *known).collect();
        let ekf = if variable == "PROBE_KIND" {
            " (or ekf: the filter)"
        } else {
            ""
        };
        panic!(
            "{variable}: unknown observer kind {name:?}; the kinds are {}{ekf}",
            known.join(", ")
        )
    })
}

/// The value of `variable`, which must be empty or a module name.
fn module_name(variable: &str) -> String {
    let name = std::env::var(variable).unwrap_or_default();
    let valid = name
        .chars()
        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    assert!(valid, "{variable} must be a design module name, got {name:?}");
    name
}
