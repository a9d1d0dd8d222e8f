//! The design spec: a TOML file describing the plant, the data to learn from and the maps to fit.
//!
//! [`load`] parses it (serde, unknown fields rejected) and validates every field into a [`Design`];
//! any problem becomes a [`SpecError`] naming the file, the field and what to change.

pub mod ast;
pub mod expr;
pub mod filters;
pub mod limits;
mod load;
pub mod model;
mod raw;
mod raw_choice;
mod raw_scenario;
pub mod search;
pub mod starts;
mod validate;
mod validate_chip;
mod validate_design;
mod validate_map;
mod validate_model;
mod validate_runs;
mod validate_states;

use std::path::PathBuf;

use serde::Deserialize;

pub use crate::output::format::readable;
use crate::spec::expr::Expression;
use crate::spec::model::{Model, ModelText};
pub use filters::{FixedFilter, FixedFilters};
pub use load::{load, parse};
pub use search::{Search, Taps};

/// A problem tied to one field of one spec file (also used for problems found while running it).
#[derive(Debug, thiserror::Error, PartialEq)]
#[error("{file}: `{field}`: {problem}\n  fix: {fix}")]
pub struct SpecError {
    /// The spec file, as given.
    pub file: String,
    /// Dotted path of the field (`map.horizon`, `model.derivatives.x2`, …).
    pub field: String,
    /// What is wrong.
    pub problem: String,
    /// What to change.
    pub fix: String,
}

/// How the paper's scale ambiguity is removed (see `identify`).
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Normalisation {
    /// A constant appended to `Z`; `dΓ/dη ≥ ε` sets the scale of `Γ` (invariant to `ε`, a shift; default).
    #[default]
    Intercept,
    /// The paper's equality `[∫₀¹ B] μ = (r_min + r_max)/2`, no constant in `Z` (faithful reproduction).
    Paper,
}

/// Which observer `observer()` is (`[observer] kind`); the report judges every kind either way.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ObserverKind {
    /// The best on the tuning runs by [`crate::observers::choose`]'s score (default).
    #[default]
    Auto,
    /// The fitted map `F(Z)` alone.
    Map,
    /// The map corrected by the model ([`crate::observers::kind::corrected::run`]).
    Corrected,
    /// The EKF started at the map's first estimate (`ekf_map`).
    EkfMap,
    /// The EKF started at the centre of the state box (`ekf_box`, the design's `ekf()`).
    EkfBox,
    /// The unscented Kalman filter from the centre of the state box (`ukf_box`, `ukf()`).
    UkfBox,
    /// The EKF from the centre of the state box, restarted from the map's first estimate when the
    /// two disagree (`ekf_restart`, `firmware::Restarted`).
    EkfRestart,
    /// The moving-horizon estimate with a fixed number of Gauss–Newton steps per sample (`mhe`,
    /// `firmware::mhe::Observer`): the on-line observer the map replaces, offered to `auto` only
    /// within `budget.instructions`.
    Mhe,
}

impl ObserverKind {
    /// Its name as users type it (spec, `--kind`) and as the report's rows name it.
    pub fn name(self) -> &'static str {
        match self {
            ObserverKind::Auto => "auto",
            ObserverKind::Map => "map",
            ObserverKind::Corrected => "corrected",
            ObserverKind::EkfMap => "ekf_map",
            ObserverKind::EkfBox => "ekf_box",
            ObserverKind::UkfBox => "ukf_box",
            ObserverKind::EkfRestart => "ekf_restart",
            ObserverKind::Mhe => "mhe",
        }
    }
}

/// Values of one state for the learning grid and the validation box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Axis {
    /// `points ≥ 2` even values from `min` to `max` (both in); validation draws uniformly there.
    Range {
        /// Lower bound.
        min: f64,
        /// Upper bound.
        max: f64,
        /// Grid points.
        points: usize,
    },
    /// The state is held at this value in every learning and validation run.
    Fixed(f64),
}

impl Axis {
    /// The grid values.
    pub fn grid(&self) -> Vec<f64> {
        match *self {
            Axis::Range { min, max, points } => (0..points)
                .map(|i| min + (max - min) * i as f64 / (points - 1) as f64)
                .collect(),
            Axis::Fixed(value) => vec![value],
        }
    }
}

/// A piecewise-constant random input: a fresh uniform value in `[min, max]` every `hold` samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InputProfile {
    /// Lower bound.
    pub min: f64,
    /// Upper bound.
    pub max: f64,
    /// Samples each value is held.
    pub hold: usize,
}

/// Settings of the learning set (paper Sect. IV).
#[derive(Clone, Debug)]
pub struct Learning {
    /// `N_s`: samples per simulated run.
    pub samples: usize,
    /// Seed of the input profiles and the noise.
    pub seed: u64,
    /// One axis per state, in state order; the grid is their Cartesian product.
    pub axes: Vec<Axis>,
    /// One profile per input, in input order.
    pub inputs: Vec<InputProfile>,
}

/// Settings of the validation set.
#[derive(Clone, Copy, Debug)]
pub struct Validation {
    /// Number of runs, each from a uniform random state in the box.
    pub trajectories: usize,
    /// Samples per run.
    pub samples: usize,
    /// Seed of the initial states, inputs and noise.
    pub seed: u64,
}

/// Settings of the fitted maps.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct MapSettings {
    /// `N`: measurements in the regressor.
    pub horizon: usize,
    /// `n_m` of the paper's basis.
    pub nm: usize,
    /// `β` of the paper's basis.
    pub beta: f64,
    /// Lower bound `ε` on `dΓ/dη` on the grid.
    pub epsilon: f64,
    /// How the scale of `Γ` is fixed.
    pub normalisation: Normalisation,
    /// Points of the monotonicity grid on `[0, 1]`.
    pub monotonicity_grid: usize,
    /// Non-zero gains kept per target (sparse `L`, [`crate::fit::identify::prune`]); `None`: all.
    pub taps: Option<usize>,
}

/// `[budget]`: what the chosen observer may cost on the chip, as [`crate::search::cost`] predicts it.
/// The search keeps only candidates within it; `auto` only kinds within it.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Budget {
    /// Instructions per sample in steady state.
    pub instructions: Option<u64>,
    /// Delay to the first estimate, `(N − 1) τ`, in the spec's time unit.
    pub first_estimate: Option<f64>,
    /// Flash the observer adds, in bytes.
    pub flash: Option<u64>,
}

/// A recorded-style estimation run: one trajectory from a given state with fresh noise (the paper's
/// Fig. 2, right, for Example 1; a plant's typical start-up).
#[derive(Clone, Debug)]
pub struct Scenario {
    /// Its name (`[[scenario]] name`; `scenario` for a single unnamed `[scenario]`).
    pub name: String,
    /// Initial state, in state order.
    pub x0: Vec<f64>,
    /// The paper's initial guess `x̂(0)` (`observer_x0`), in state order: the report adds the box
    /// filters' scenario figures from there, beside those from the box centre the chip starts at.
    pub observer_x0: Option<Vec<f64>>,
    /// Samples.
    pub samples: usize,
    /// Seed of its inputs and noise.
    pub seed: u64,
}

/// Membership of a family of designs that differ by the value of one measured output at the start of
/// a batch (the paper's Example 2: one design per initial biomass). The firmware picks the member whose
/// `value` is nearest to that output's first measurement.
#[derive(Clone, Debug, PartialEq)]
pub struct Family {
    /// The family's name (a lower-case identifier: it names a module in `generated/`).
    pub name: String,
    /// Index of the output that selects the member.
    pub output: usize,
    /// This member's value of that output.
    pub value: f64,
}

/// A quantity to estimate, `r = g(x)`.
#[derive(Clone, Debug)]
pub struct Target {
    /// Its name.
    pub name: String,
    /// Its unit, for plots and reports ("" when dimensionless).
    pub unit: String,
    /// `g`, over the model's scope.
    pub expr: Expression,
    /// Its weight in the score (`weight`, default 1; 0: estimated and reported, chosen for never).
    pub weight: f64,
}

/// A state's physical bounds, either side optional (`[model.bounds]`).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Bounds {
    /// The least value the state can take.
    pub min: Option<f64>,
    /// The largest.
    pub max: Option<f64>,
}

impl Bounds {
    /// The lower bound, `-∞` where there is none.
    pub fn lower(&self) -> f64 {
        self.min.unwrap_or(f64::NEG_INFINITY)
    }

    /// The upper bound, `+∞` where there is none.
    pub fn upper(&self) -> f64 {
        self.max.unwrap_or(f64::INFINITY)
    }
}

/// The most RK4 steps per sample the chip's model may take (`sampling.chip_substeps`).
pub const MAX_CHIP_SUBSTEPS: usize = 64;

/// A validated design.
#[derive(Clone, Debug)]
pub struct Design {
    /// The spec file it came from.
    pub file: PathBuf,
    /// Its name (a lower-case identifier).
    pub name: String,
    /// One line saying what it is.
    pub description: String,
    /// The plant.
    pub model: Model,
    /// Sample period `τ`.
    pub tau: f64,
    /// Unit of time (of `τ`), for plots and reports.
    pub time_unit: String,
    /// Each state's unit (`[model.units]`; "" where the spec gives none).
    pub state_units: Vec<String>,
    /// Each input's unit (`[model.units]`; "" where the spec gives none).
    pub input_units: Vec<String>,
    /// Each state's physical bounds (`[model.bounds]`; unbounded where the spec gives none): every
    /// observer that carries the model projects its state onto them.
    pub state_bounds: Vec<Bounds>,
    /// RK4 steps per sample period.
    pub substeps: usize,
    /// The learning set.
    pub learning: Learning,
    /// The validation set.
    pub validation: Validation,
    /// The tuning runs (`[tuning]`): what every tunable constant of an observer is chosen on, never
    /// what accuracy is reported on.
    pub tuning: Validation,
    /// The score's start-up in samples (`tuning.start_up`); `None`: [`mod@crate::observers::score::settle`].
    pub start_up: Option<usize>,
    /// RK4 steps per sample of the model on the chip (`sampling.chip_substeps`, default 1).
    pub chip_substeps: usize,
    /// The maps. With a [`Search`], until [`crate::search::settle`] puts the chosen values here: the
    /// largest candidate `N` (every run length was checked against it) and the first `n_m` and `β`.
    pub map: MapSettings,
    /// The design search, when a `[map]` field is `"auto"` or a list.
    pub search: Option<Search>,
    /// `[search] max_candidates`: the most candidates a search of this design may fit
    /// ([`crate::search::DEFAULT_MAX_CANDIDATES`] unless the spec raises or lowers it). Kept apart
    /// from [`Search`] so that `search --auto` honours it on a spec that fixes its `[map]`.
    pub max_candidates: usize,
    /// `[budget]` (no limit when absent).
    pub budget: Budget,
    /// The quantities to estimate.
    pub targets: Vec<Target>,
    /// The estimation scenarios (`[scenario]` or `[[scenario]]`), in spec order; the first is the
    /// one the headline figures, the noise draws and the estimation figure follow ([`Design::scenario`]).
    pub scenarios: Vec<Scenario>,
    /// The family this design belongs to, if any.
    pub family: Option<Family>,
    /// `[observer] kind`.
    pub observer: ObserverKind,
    /// The filters' constants the spec fixes (`[observer.<filter>]`); the rest are tuned.
    pub filters: FixedFilters,
    /// `[chip] arithmetic = "fixed"`: the integer map is emitted too, with these raw scalings.
    pub fixed: Option<FixedSpec>,
    /// SHA-256 of the spec text, in hex (provenance of generated files).
    pub spec_sha256: String,
}

/// What `[chip] arithmetic = "fixed"` asks for: each output's and input's raw scaling, as declared or
/// (`None`) left to the default Q format ([`crate::fixed_point`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FixedSpec {
    /// One per output, in the model's order.
    pub outputs: Vec<Option<RawScale>>,
    /// One per input, in the model's order.
    pub inputs: Vec<Option<RawScale>>,
}

/// How a raw integer sample maps to the model's unit: `value = offset + scale · raw`, raw in
/// `[min, max]` (a sample outside is refused on the chip).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RawScale {
    /// Model units per count.
    pub scale: f64,
    /// The value at raw 0.
    pub offset: f64,
    /// The smallest raw value the converter gives.
    pub min: i32,
    /// The largest.
    pub max: i32,
}

impl Design {
    /// The first scenario: the headline `scenario` and `transient` figures' (`None` without any).
    pub fn scenario(&self) -> Option<&Scenario> {
        self.scenarios.first()
    }

    /// An error about `field` of this design's spec.
    pub fn error(&self, field: impl Into<String>, problem: impl Into<String>, fix: impl Into<String>) -> SpecError {
        SpecError {
            file: self.file.display().to_string(),
            field: field.into(),
            problem: problem.into(),
            fix: fix.into(),
        }
    }
}

/// Module names of `generated/src/` that are not designs: `lib.rs` is the crate root.
pub const RESERVED_MODULES: &[&str] = &["lib"];

/// A lower-case identifier that is not a Rust keyword nor reserved: usable as a module name in
/// `generated/`.
fn is_module_name(name: &str) -> bool {
    name.chars().next().is_some_and(|c| c.is_ascii_lowercase())
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
        && !RUST_KEYWORDS.contains(&name)
        && !RESERVED_MODULES.contains(&name)
}

/// Names that would collide with the columns of the recorded and estimates CSV files (`time` or `t`,
/// `run`, `status`); names starting with [`RESERVED_PREFIXES`] would collide with their per-target
/// columns.
const RESERVED_NAMES: &[&str] = &["time", "t", "run", "status", "saturated"];

/// The longest unit, in characters: a label, not a sentence.
pub const MAX_LABEL: usize = 32;

/// Prefixes of the per-target columns: `saturated_<target>` in estimates, `truth_<target>` in recordings.
const RESERVED_PREFIXES: &[&str] = &["saturated_", "truth_"];

/// Names that cannot be a Rust module (the design name becomes one in `generated/`).
const RUST_KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern", "false", "fn",
    "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub", "ref", "return", "self",
    "static", "struct", "super", "trait", "true", "type", "unsafe", "use", "where", "while", "abstract", "become",
    "box", "do", "final", "macro", "override", "priv", "try", "typeof", "unsized", "virtual", "yield", "firmware",
    "core", "std",
];
