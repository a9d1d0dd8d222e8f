//! Shared helpers of the integration tests: the shipped specs and designs built from them.

pub mod chip_table;
pub mod doc_numbers;
pub mod on_target;

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};

use host::fit::inverse_table::InverseTable;
use host::fit::maps::FittedMap;
use host::fit::DesignResult;
use host::spec::{self, Design};

/// The spec of the test fixture whose tables have searched knots, relative to the workspace; its
/// generated file sits beside it (`.rs`).
pub const SEARCHED_FIXTURE_SPEC: &str = "tests/fixtures/vanderpol_beta7.toml";

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
    host::generate::workspace_root().expect("the tests run inside the checkout")
}

/// Every shipped spec file, sorted (what `gen` runs by default).
pub fn shipped_specs() -> Vec<PathBuf> {
    host::generate::shipped_specs().expect("host/specs")
}

/// Loads a spec given relative to the workspace (as generated files record it), settled as `gen`
/// settles it ([`settled`]).
pub fn load_relative(spec: &str) -> Design {
    load_settled(&workspace_root().join(spec))
}

/// Loads a spec and settles its design search ([`settled`]).
pub fn load_settled(path: &std::path::Path) -> Design {
    settled(spec::load(path).expect("valid spec"))
}

/// `design` with the `N`, `n_m` and `β` its search chooses, as `gen` emits it (unchanged without a
/// search); each search runs once per spec text and test binary.
pub fn settled(design: Design) -> Design {
    static SETTLED: OnceLock<Mutex<HashMap<String, host::spec::MapSettings>>> = OnceLock::new();
    if design.search.is_none() {
        return design;
    }
    let key = format!("{} {}", design.name, design.spec_sha256);
    let known = SETTLED
        .get_or_init(Default::default)
        .lock()
        .expect("no test panicked holding it")
        .get(&key)
        .copied();
    match known {
        Some(map) => Design { map, ..design },
        None => {
            let learning = host::data::learning_set(&design).expect("the learning runs simulate");
            let tuning = host::data::tuning_set(&design).expect("the tuning runs simulate");
            let bar = indicatif::ProgressBar::hidden();
            let (design, _) = host::search::settle(design, &learning, &tuning, &bar).expect("the search runs");
            SETTLED
                .get_or_init(Default::default)
                .lock()
                .expect("no test panicked holding it")
                .insert(key, design.map);
            design
        }
    }
}

/// The largest `|table(v) - r(Γ⁻¹(v))|` of `map` over `points + 1` values of `v` uniform in
/// `[Γ(0), Γ(1)]`, the exact side by the f64 bisection, the table side by the firmware code the chip runs.
pub fn dense_error(map: &FittedMap, table: &InverseTable, points: usize) -> f64 {
    let gamma = map.gamma();
    let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
    let scale = table.t_max() / (v1 - v0);
    let evaluator = table.as_firmware();
    let span = map.r_max - map.r_min;
    (0..=points)
        .map(|i| {
            let v = v0 + (v1 - v0) * i as f64 / points as f64;
            let exact = map.r_min + span * gamma.inverse(v).eta;
            (evaluator.evaluate((v - v0) * scale).value - exact).abs()
        })
        .fold(0.0, f64::max)
}

/// Builds a design (data, fits, evaluation) without progress output, once per spec text and test
/// binary: the fit is deterministic, and most tests read the same few designs.
pub fn build(design: &Design) -> Arc<DesignResult> {
    type Cell = Arc<OnceLock<Arc<DesignResult>>>;
    static BUILDS: OnceLock<Mutex<HashMap<String, Cell>>> = OnceLock::new();
    // The settings too: a searched spec's design differs from its settled one by them alone.
    let key = format!("{} {} {:?}", design.name, design.spec_sha256, design.map);
    let cell: Cell = {
        let mut builds = BUILDS
            .get_or_init(Default::default)
            .lock()
            .expect("no test panicked holding it");
        builds.entry(key).or_default().clone()
    };
    cell.get_or_init(|| Arc::new(build_fresh(design))).clone()
}

/// `gen`'s whole job on the spec at `path` (the fit, every kind tuned and judged, the references and
/// the floor, the emitted Rust and C), in memory, once per spec and test binary: a comparison costs
/// more than the fit, and `generated_is_current` (every shipped design), the gates, the tuning and
/// the saved-tables tests read the same ones. The committed `generated/` files, written by another
/// process, are what shows that the job is deterministic.
pub fn emitted(path: &Path) -> Arc<host::generate::Emitted> {
    type Cell = Arc<OnceLock<Arc<host::generate::Emitted>>>;
    static EMITTED: OnceLock<Mutex<HashMap<PathBuf, Cell>>> = OnceLock::new();
    let cell: Cell = {
        let mut emitted = EMITTED
            .get_or_init(Default::default)
            .lock()
            .expect("no test panicked holding it");
        let key = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
        emitted.entry(key).or_default().clone()
    };
    cell.get_or_init(|| {
        let design = spec::load(path).expect("valid spec");
        Arc::new(
            host::generate::emit_design(design, path, None, &indicatif::ProgressBar::hidden())
                .expect("the design generates"),
        )
    })
    .clone()
}

/// [`emitted`] of the shipped spec `name` (`host/specs/<name>.toml`).
pub fn shipped(name: &str) -> Arc<host::generate::Emitted> {
    emitted(&specs_folder().join(format!("{name}.toml")))
}

/// Builds a design without the cache (to show that a build is deterministic).
pub fn build_fresh(design: &Design) -> DesignResult {
    host::generate::simulate_and_fit(design, &indicatif::ProgressBar::hidden()).expect("the design builds")
}

/// The host's constants of a generated design module `$d`'s map-started observers, read back from
/// what it emitted: the model-corrected map's (`CORRECTED_*`, its follower's `START_UP`) and the EKF's
/// (`EKF_Q`, the spec's noise; the map gives `x̂` and `STARTED_P0` the covariance, so `x0` and `p0`
/// are unused). What the host mirrors run to be compared with the generated code.
#[macro_export]
macro_rules! emitted_constants {
    ($d:ident, $design:expr) => {{
        let design: &host::spec::Design = $design;
        let h = design.tau / design.chip_substeps as f64;
        (
            host::observers::kind::corrected::program::CorrectionConstants {
                g: $d::CORRECTED_G.to_vec(),
                k: $d::CORRECTED_K.to_vec(),
                k_start: $d::CORRECTED_K_START.to_vec(),
                schedule: $d::CORRECTED_SCHEDULE,
                start_up: <$d::Corrector as firmware::emitted::Follower<
                    f32,
                    { $d::STATES },
                    { $d::OUTPUTS },
                    { $d::INPUTS },
                    { $d::TARGETS },
                >>::START_UP,
                lower: $d::CORRECTED_LOWER.to_vec(),
                upper: $d::CORRECTED_UPPER.to_vec(),
                substeps: design.chip_substeps,
                h,
            },
            host::plant::kalman::EkfConstants {
                x0: vec![0.0; $d::STATES],
                p0: host::plant::Covariance::Diagonal(vec![0.0; $d::STATES]),
                // The shipped designs' `Q` is tuned: a diagonal.
                q: host::plant::Covariance::Diagonal($d::EKF_Q.to_vec()),
                r: design.model.outputs.iter().map(|o| o.noise_variance).collect(),
                substeps: design.chip_substeps,
                h,
                watch: host::plant::kalman::Watch {
                    window: $d::EKF_WATCH_WINDOW,
                    threshold: $d::EKF_WATCH_THRESHOLD,
                },
            },
        )
    }};
}

/// The `mho` command line (package `host`) as a user runs it: built (in this workspace's debug profile, where the
/// tests' own copy of the host library already is, so only the binary is linked) on first use.
pub fn host_command() -> std::process::Command {
    static BUILT: OnceLock<PathBuf> = OnceLock::new();
    let binary = BUILT.get_or_init(|| {
        let root = workspace_root();
        let built = std::process::Command::new(env!("CARGO"))
            .args(["build", "--offline", "-q", "-p", "host", "--bin", "mho"])
            .current_dir(&root)
            .output()
            .expect("cargo runs");
        assert!(
            built.status.success(),
            "cargo build -p host: {}",
            String::from_utf8_lossy(&built.stderr)
        );
        let target = std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root.join("target"), PathBuf::from);
        target
            .join("debug")
            .join(format!("mho{}", std::env::consts::EXE_SUFFIX))
    });
    std::process::Command::new(binary)
}

/// A saturation as the estimates file and the C interface write it: -1 low, 0 inside, 1 high.
pub fn saturation_flag(saturation: firmware::Saturation) -> i8 {
    match saturation {
        firmware::Saturation::Low => -1,
        firmware::Saturation::Inside => 0,
        firmware::Saturation::High => 1,
    }
}

/// One row of an estimates file after its `time` (and `run`) cells, written from a generated
/// observer's own output: `status`, each target's value, each target's flag, empty cells without an
/// estimate. `accepted` is whether `push` took the sample; `targets` the design's count.
pub fn estimates_row(accepted: bool, estimates: Option<&[firmware::Estimate<f32>]>, targets: usize) -> String {
    let empty = |status: &str| format!("{status}{}", ",".repeat(2 * targets));
    match (accepted, estimates) {
        (false, _) => empty("refused"),
        (true, None) => empty("no_estimate_yet"),
        (true, Some(e)) => {
            let values = e.iter().map(|e| format!("{}", f64::from(e.value)));
            let flags = e.iter().map(|e| saturation_flag(e.saturation).to_string());
            std::iter::once("ok".to_owned())
                .chain(values)
                .chain(flags)
                .collect::<Vec<_>>()
                .join(",")
        }
    }
}
