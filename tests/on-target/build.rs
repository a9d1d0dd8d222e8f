//! Puts the emulated board's memory.x where the linker finds it, passes cortex-m-rt's linker script
//! to this program's binaries only (not through global rustflags), and writes the board's stack
//! paint and the runners' and the size probe's design selection.

use std::path::PathBuf;

/// The design's chosen kind, `observer()`, in `ON_TARGET_KIND` / `PROBE_KIND`.
const CHOSEN: &str = "observer";

/// The box EKF in `PROBE_KIND`: its filter (`ekf()`), as the `ekf` runner measures it.
const EKF_BOX: &str = "ekf_box";

/// The integer observer: it takes the raw recorded sequence (`RECORDED_RAW_Y`, `RECORDED_RAW_U`,
/// `i32`) and its type is not named here, so the runner drives it through closures.
const FIXED: &str = "fixed";

/// The emulated board of each target, by its memory: the Cortex-M4F board (QEMU `mps2-an386`,
/// 4 MiB of each) and the Cortex-M0 one (QEMU `microbit`, nRF51: 256 KiB of flash, 16 KiB of RAM);
/// the memory layouts are compiled in, so that a runner written for a user's crate (whose manifest
/// lives elsewhere) links the same.
fn board(target: &str) -> (&'static str, &'static str, usize, usize) {
    if target.starts_with("thumbv6m") {
        // 16 KiB of RAM hold the results (at most 200 samples of ~24 bytes), the runner's frames and
        // the paint below them: 4 KiB each, ten times the deepest a soft-float sample reached.
        ("microbit", include_str!("memory/microbit.x"), 4096, 4096)
    } else {
        ("mps2-an386", include_str!("memory/mps2-an386.x"), 4096, 8192)
    }
}

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    let target = std::env::var("TARGET").unwrap_or_default();
    let (board, memory, painted, ekf_painted) = board(&target);
    std::fs::write(out.join("memory.x"), memory).expect("write memory.x");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rerun-if-changed=memory");
    // Bytes of stack the runners paint below their frame (`main.rs`, `bin/ekf.rs`).
    std::fs::write(
        out.join("board.rs"),
        format!(
            "/// The board this program is built for.\n#[allow(dead_code)]\nconst BOARD: &str = \"{board}\";\n/// Bytes of stack painted below the stack pointer of `run` (`on-target`).\n#[allow(dead_code)]\nconst PAINTED: usize = {painted};\n/// Bytes of stack painted below the stack pointer of `main` (`ekf`).\n#[allow(dead_code)]\nconst EKF_PAINTED: usize = {ekf_painted};\n"
        ),
    )
    .expect("write board.rs");

    // The runners (`on-target` for the observers that estimate from the map's window, `ekf` for the
    // filter from the box centre) link the one design named by ON_TARGET_DESIGN (design.rs).
    // ON_TARGET_KIND lists, comma-separated, the observers `on-target` runs one after the other, each
    // over the whole recorded sequence (kinds.rs, which `ekf` does not read): any kind the design
    // has, by its name (`map`, the default, `corrected`, `ekf_map`, …: the list `gen` wrote,
    // `<design>_observers!(new kind)` in its file, refuses one it lacks and names those it has), `observer` (the
    // design's chosen kind) or `fixed` (the integer observer, over the raw sequence).
    println!("cargo:rerun-if-env-changed=ON_TARGET_DESIGN");
    println!("cargo:rerun-if-env-changed=ON_TARGET_KIND");
    let requested = std::env::var("ON_TARGET_KIND").unwrap_or_default();
    let kinds: Vec<String> = if requested.is_empty() {
        vec!["map".to_owned()]
    } else {
        requested.split(',').map(|name| kind(name.trim(), "ON_TARGET_KIND")).collect()
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
        .map(|name| {
            if name == FIXED {
                format!("    run(\"{name}\", Driven::new(d::fixed_observer(), |o, y, u| o.push(y, u).is_ok(), |o| o.estimate()), &d::RECORDED_RAW_Y, &d::RECORDED_RAW_U);\n")
            } else {
                format!("    run(\"{name}\", {}, &d::RECORDED_Y, &d::RECORDED_U);\n", fresh(&runner, name))
            }
        })
        .collect();
    let kinds = format!("/// Runs every observer this program measures (ON_TARGET_KIND), one after the other.\nfn run_all() {{\n{runs}}}\n");
    std::fs::write(out.join("kinds.rs"), kinds).expect("write kinds.rs");

    // The size probe links one design (or none, for the baseline) chosen by PROBE_DESIGN: one of its
    // observers (PROBE_KIND, as ON_TARGET_KIND but one kind; `map` by default), or with
    // PROBE_KIND=ekf_box its extended Kalman filter (`ekf()`).
    println!("cargo:rerun-if-env-changed=PROBE_DESIGN");
    println!("cargo:rerun-if-env-changed=PROBE_KIND");
    let design = module_name("PROBE_DESIGN");
    let probe_kind = std::env::var("PROBE_KIND").unwrap_or_default();
    let probe = if design == "__reachable_panic" {
        // Proves the check can fail: an index the compiler cannot bound.
        "/// Indexes out of bounds (for the check's own test).\nfn probe() -> ! {\n    let table = core::hint::black_box([0u8; 4]);\n    loop {\n        core::hint::black_box(table[core::hint::black_box(7usize)]);\n    }\n}\n".to_owned()
    } else if design.is_empty() {
        "/// The baseline: the same loop with no observer.\nfn probe() -> ! {\n    loop {\n        core::hint::black_box(core::hint::black_box(0.0f32));\n    }\n}\n".to_owned()
    } else if probe_kind == EKF_BOX {
        format!(
            "/// Pushes samples into `{design}`'s extended Kalman filter and computes the targets, forever.\nfn probe() -> ! {{\n    use generated::{design} as d;\n    let mut filter = d::ekf();\n    loop {{\n        let y = core::hint::black_box([0.0f32; d::OUTPUTS]);\n        let u = core::hint::black_box([0.0f32; d::INPUTS]);\n        if let Ok(x) = filter.push(&y, &u) {{\n            core::hint::black_box(d::targets(&x, &u));\n        }}\n        core::hint::black_box(filter.state());\n        core::hint::black_box(filter.covariance());\n        if core::hint::black_box(false) {{\n            filter = d::ekf();\n        }}\n    }}\n}}\n"
        )
    } else {
        let name = if probe_kind.is_empty() {
            "map".to_owned()
        } else {
            kind(&probe_kind, "PROBE_KIND")
        };
        let (zero, fresh) = if name == FIXED {
            ("0i32", "d::fixed_observer()".to_owned())
        } else {
            ("0.0f32", fresh(&design, &name))
        };
        format!(
            "/// Pushes samples into `{design}`'s {name} observer and estimates, forever.\nfn probe() -> ! {{\n    use generated::{design} as d;\n    let mut observer = {fresh};\n    loop {{\n        let y = core::hint::black_box([{zero}; d::OUTPUTS]);\n        let u = core::hint::black_box([{zero}; d::INPUTS]);\n        let _ = core::hint::black_box(observer.push(y, u));\n        core::hint::black_box(observer.estimate());\n        if core::hint::black_box(false) {{\n            observer.reset();\n        }}\n    }}\n}}\n"
        )
    };
    std::fs::write(out.join("probe_design.rs"), probe).expect("write probe_design.rs");
}

/// The kind named `name` (read from `variable`): a name (of a kind, `observer` or `fixed`), which
/// the design's list of kinds checks (`<design>_observers!(new kind)`, exported by its file).
fn kind(name: &str, variable: &str) -> String {
    let valid = !name.is_empty() && name.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    assert!(valid, "{variable}: {name:?} is not an observer kind's name (`map`, `ekf_box`, …, `observer`, `fixed`)");
    name.to_owned()
}

/// The expression that makes a fresh observer of kind `name` of design `design` (not `fixed`): the
/// map by `map_observer()`, which a family module has too.
fn fresh(design: &str, name: &str) -> String {
    if name == CHOSEN {
        "d::observer()".to_owned()
    } else if name == "map" {
        "d::map_observer()".to_owned()
    } else {
        format!("generated::{design}_observers!(new {name})")
    }
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
