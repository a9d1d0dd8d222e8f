//! Puts memory.x where the linker finds it, passes cortex-m-rt's linker script to this program's
//! binaries only (not through global rustflags), and writes the runners' and the size probe's design
//! selection.

use std::path::PathBuf;

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    std::fs::copy("memory.x", out.join("memory.x")).expect("copy memory.x");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rerun-if-changed=memory.x");

    // The runners (`on-target` for the map observer, `ekf` for the filter) link the one design named
    // by ON_TARGET_DESIGN.
    // ON_TARGET_KIND picks the runner's observer: the map (default), or `observer` (the design's
    // chosen kind), `corrected` or `started_ekf`.
    println!("cargo:rerun-if-env-changed=ON_TARGET_DESIGN");
    println!("cargo:rerun-if-env-changed=ON_TARGET_KIND");
    let (measured, fresh) = match std::env::var("ON_TARGET_KIND").unwrap_or_default().as_str() {
        "" | "map" => ("MapObserver", "map_observer()"),
        "observer" => ("Observer", "observer()"),
        "corrected" => ("CorrectedObserver", "CorrectedObserver::new()"),
        "started_ekf" => ("StartedEkfObserver", "StartedEkfObserver::new()"),
        other => panic!("ON_TARGET_KIND must be map, observer, corrected or started_ekf, got {other:?}"),
    };
    let runner = module_name("ON_TARGET_DESIGN");
    let runner = if runner.is_empty() {
        "compile_error!(\"set ON_TARGET_DESIGN to the generated design module to run\");\ntype Measured = ();\nfn fresh() -> Measured {}\nmod d { pub const TARGETS: usize = 0; pub const OUTPUTS: usize = 0; pub const INPUTS: usize = 0; pub const RECORDED_LEN: usize = 0; pub type Ekf = (); pub const STATES: usize = 0; }\n".to_owned()
    } else {
        format!("use generated::{runner} as d;\n/// The observer measured.\ntype Measured = d::{measured};\n/// A fresh one.\nfn fresh() -> Measured {{\n    d::{fresh}\n}}\n")
    };
    std::fs::write(out.join("design.rs"), runner).expect("write design.rs");

    // The size probe links one design (or none, for the baseline) chosen by PROBE_DESIGN: its map
    // observer, or with PROBE_KIND=ekf its extended Kalman filter.
    println!("cargo:rerun-if-env-changed=PROBE_DESIGN");
    println!("cargo:rerun-if-env-changed=PROBE_KIND");
    let design = module_name("PROBE_DESIGN");
    let kind = std::env::var("PROBE_KIND").unwrap_or_default();
    assert!(
        matches!(kind.as_str(), "" | "map" | "ekf"),
        "PROBE_KIND must be map or ekf, got {kind:?}"
    );
    let probe = if design == "__reachable_panic" {
        // Proves the check can fail: an index the compiler cannot bound.
        "/// Indexes out of bounds (for the check's own test).\nfn probe() -> ! {\n    let table = core::hint::black_box([0u8; 4]);\n    loop {\n        core::hint::black_box(table[core::hint::black_box(7usize)]);\n    }\n}\n".to_owned()
    } else if design.is_empty() {
        "/// The baseline: the same loop with no observer.\nfn probe() -> ! {\n    loop {\n        core::hint::black_box(core::hint::black_box(0.0f32));\n    }\n}\n".to_owned()
    } else if kind == "ekf" {
        format!(
            "/// Pushes samples into `{design}`'s extended Kalman filter and computes the targets, forever.\nfn probe() -> ! {{\n    use generated::{design} as d;\n    let mut filter = d::ekf();\n    loop {{\n        let y = core::hint::black_box([0.0f32; d::OUTPUTS]);\n        let u = core::hint::black_box([0.0f32; d::INPUTS]);\n        if let Ok(x) = filter.push(&y, &u) {{\n            core::hint::black_box(d::targets(&x, &u));\n        }}\n        core::hint::black_box(filter.state());\n        core::hint::black_box(filter.covariance());\n        if core::hint::black_box(false) {{\n            filter = d::ekf();\n        }}\n    }}\n}}\n"
        )
    } else {
        format!(
            "/// Pushes samples into `{design}`'s observer and estimates, forever.\nfn probe() -> ! {{\n    use generated::{design} as d;\n    let mut observer = d::map_observer();\n    loop {{\n        let y = core::hint::black_box([0.0f32; d::OUTPUTS]);\n        let u = core::hint::black_box([0.0f32; d::INPUTS]);\n        let _ = core::hint::black_box(observer.push(y, u));\n        core::hint::black_box(observer.estimate());\n        if core::hint::black_box(false) {{\n            observer.reset();\n        }}\n    }}\n}}\n"
        )
    };
    std::fs::write(out.join("probe_design.rs"), probe).expect("write probe_design.rs");
}

/// The value of `variable`, which must be empty or a module name.
fn module_name(variable: &str) -> String {
    let name = std::env::var(variable).unwrap_or_default();
    let valid = name.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    assert!(valid, "{variable} must be a design module name, got {name:?}");
    name
}
