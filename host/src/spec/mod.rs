//! The design spec: a TOML file describing the plant, the data to learn from and the maps to fit.
//!
//! [`load`] parses it (serde, unknown fields rejected) and validates every field into a [`Design`];
//! any problem becomes a [`SpecError`] naming the file, the field and what to change.

pub mod expr;
pub mod model;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use sha2::Digest;

use crate::spec::expr::Expression;
use crate::spec::model::{Model, ModelText};

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
    /// A constant appended to `Z`; the scale of `Γ` is set by `dΓ/dη ≥ ε`. Invariant to a shift of the
    /// target and to `ε` (default).
    #[default]
    Intercept,
    /// The paper's equality `[∫₀¹ B] μ = (r_min + r_max)/2`, no constant in `Z` (faithful reproduction).
    Paper,
}

/// Values of one state for the learning grid and the validation box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Axis {
    /// `points ≥ 2` evenly spaced values from `min` to `max` (both included); validation draws
    /// uniformly in `[min, max]`.
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
}

/// A recorded-style estimation run: one trajectory from a given state with fresh noise (the paper's
/// Fig. 2, right, for Example 1).
#[derive(Clone, Debug)]
pub struct Scenario {
    /// Initial state, in state order.
    pub x0: Vec<f64>,
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
}

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
    /// RK4 steps per sample period.
    pub substeps: usize,
    /// The learning set.
    pub learning: Learning,
    /// The validation set.
    pub validation: Validation,
    /// The maps.
    pub map: MapSettings,
    /// The quantities to estimate.
    pub targets: Vec<Target>,
    /// The estimation scenario, if the spec has one.
    pub scenario: Option<Scenario>,
    /// The family this design belongs to, if any.
    pub family: Option<Family>,
    /// SHA-256 of the spec text, in hex (provenance of generated files).
    pub spec_sha256: String,
}

impl Design {
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

/// A lower-case identifier that is not a Rust keyword: usable as a module name in `generated/`.
fn is_module_name(name: &str) -> bool {
    name.chars().next().is_some_and(|c| c.is_ascii_lowercase())
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
        && !RUST_KEYWORDS.contains(&name)
}

/// Names that would collide with the columns `time`, `run` and `saturated` of recorded CSV files.
const RESERVED_NAMES: &[&str] = &["time", "run", "saturated"];

/// Names that cannot be a Rust module (the design name becomes one in `generated/`).
const RUST_KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern", "false", "fn",
    "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub", "ref", "return", "self",
    "static", "struct", "super", "trait", "true", "type", "unsafe", "use", "where", "while", "abstract", "become",
    "box", "do", "final", "macro", "override", "priv", "try", "typeof", "unsized", "virtual", "yield", "firmware",
    "core", "std",
];

// ---------------------------------------------------------------------------------------------------
// The file as written.

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSpec {
    name: String,
    #[serde(default)]
    description: String,
    model: RawModel,
    sampling: RawSampling,
    learning: RawLearning,
    validation: RawValidation,
    map: RawMap,
    targets: Vec<RawNamedExpr>,
    scenario: Option<RawScenario>,
    family: Option<RawFamily>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFamily {
    name: String,
    output: String,
    value: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScenario {
    x0: BTreeMap<String, f64>,
    samples: usize,
    seed: u64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawModel {
    states: Vec<String>,
    #[serde(default)]
    inputs: Vec<String>,
    #[serde(default)]
    parameters: BTreeMap<String, f64>,
    #[serde(default)]
    definitions: Vec<RawNamedExpr>,
    derivatives: BTreeMap<String, String>,
    outputs: Vec<RawOutput>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawNamedExpr {
    name: String,
    expr: String,
    #[serde(default)]
    unit: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawOutput {
    name: String,
    expr: String,
    noise_variance: f64,
    #[serde(default)]
    unit: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSampling {
    tau: f64,
    #[serde(default = "default_time_unit")]
    time_unit: String,
    #[serde(default = "default_substeps")]
    substeps: usize,
}

fn default_time_unit() -> String {
    "s".into()
}

fn default_substeps() -> usize {
    10
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLearning {
    samples: usize,
    seed: u64,
    grid: BTreeMap<String, RawAxis>,
    #[serde(default)]
    inputs: BTreeMap<String, RawInputProfile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAxis {
    min: Option<f64>,
    max: Option<f64>,
    points: Option<usize>,
    value: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawInputProfile {
    min: f64,
    max: f64,
    hold: usize,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawValidation {
    trajectories: usize,
    samples: usize,
    seed: u64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMap {
    horizon: usize,
    nm: usize,
    beta: f64,
    epsilon: f64,
    #[serde(default)]
    normalisation: Normalisation,
    #[serde(default = "default_grid")]
    monotonicity_grid: usize,
}

fn default_grid() -> usize {
    201
}

// ---------------------------------------------------------------------------------------------------

/// Reads, parses and validates a spec file.
pub fn load(path: &Path) -> Result<Design, SpecError> {
    let text = std::fs::read_to_string(path).map_err(|e| SpecError {
        file: path.display().to_string(),
        field: "(file)".into(),
        problem: format!("cannot read the file: {e}"),
        fix: "give the path of an existing, readable design spec (TOML)".into(),
    })?;
    parse(path, &text)
}

/// Parses and validates spec text; `path` is only used in messages and kept in the design.
pub fn parse(path: &Path, text: &str) -> Result<Design, SpecError> {
    let file = path.display().to_string();
    let raw: RawSpec = toml::from_str(text).map_err(|e| SpecError {
        file: file.clone(),
        field: e
            .span()
            .map(|s| format!("(line {})", 1 + text[..s.start].matches('\n').count()))
            .unwrap_or_else(|| "(document)".into()),
        problem: e.message().trim().to_owned(),
        fix: "correct the TOML at that line; see host/specs/vanderpol.toml for a complete example".into(),
    })?;
    let mut design = Validator {
        file,
        path: path.to_owned(),
    }
    .design(raw)?;
    design.spec_sha256 = sha2::Sha256::digest(text.as_bytes())
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    Ok(design)
}

struct Validator {
    file: String,
    path: PathBuf,
}

impl Validator {
    fn err(&self, field: impl Into<String>, problem: impl Into<String>, fix: impl Into<String>) -> SpecError {
        SpecError {
            file: self.file.clone(),
            field: field.into(),
            problem: problem.into(),
            fix: fix.into(),
        }
    }

    fn identifier(&self, field: &str, name: &str) -> Result<(), SpecError> {
        let mut chars = name.chars();
        let valid = matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
            && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
        if RESERVED_NAMES.contains(&name) {
            return Err(self.err(
                field,
                format!("`{name}` is reserved: it names a column of the CSV files `simulate` and `estimate` use"),
                format!("rename it (reserved: {})", RESERVED_NAMES.join(", ")),
            ));
        }
        if valid {
            Ok(())
        } else {
            Err(self.err(
                field,
                format!("`{name}` is not a valid name"),
                "use letters, digits and `_`, starting with a letter",
            ))
        }
    }

    fn positive(&self, field: &str, value: f64, what: &str) -> Result<f64, SpecError> {
        if value.is_finite() && value > 0.0 {
            Ok(value)
        } else {
            Err(self.err(
                field,
                format!("{what} must be a finite number > 0, got {value}"),
                format!("set `{field}` to a positive value"),
            ))
        }
    }

    fn design(&self, raw: RawSpec) -> Result<Design, SpecError> {
        let name_ok = is_module_name(&raw.name);
        if !name_ok {
            return Err(self.err(
                "name",
                format!("`{}` is not a lower-case identifier, or is reserved", raw.name),
                "use lower-case letters, digits and `_`, starting with a letter, not a Rust keyword (it names a module in generated/)",
            ));
        }
        let model = self.model(&raw.model)?;
        let tau = self.positive("sampling.tau", raw.sampling.tau, "the sample period τ")?;
        if raw.sampling.substeps == 0 {
            return Err(self.err(
                "sampling.substeps",
                "RK4 needs at least one step per sample",
                "set `sampling.substeps` to 1 or more (10 is usual)",
            ));
        }
        let map = self.map(&raw.map)?;
        let learning = self.learning(&raw.learning, &model, map.horizon)?;
        let validation = self.validation(&raw.validation, map.horizon)?;
        let targets = self.targets(&raw.targets, &model)?;
        let family = raw
            .family
            .as_ref()
            .map(|f| self.family(f, &model, &raw.name))
            .transpose()?;
        let scenario = raw
            .scenario
            .as_ref()
            .map(|s| self.scenario(s, &model, map.horizon))
            .transpose()?;
        Ok(Design {
            file: self.path.clone(),
            name: raw.name,
            description: raw.description,
            model,
            tau,
            time_unit: raw.sampling.time_unit.clone(),
            substeps: raw.sampling.substeps,
            learning,
            validation,
            map,
            targets,
            scenario,
            family,
            spec_sha256: String::new(),
        })
    }

    fn family(&self, raw: &RawFamily, model: &Model, design: &str) -> Result<Family, SpecError> {
        if !is_module_name(&raw.name) || raw.name == design {
            return Err(self.err(
                "family.name",
                format!("`{}` cannot name the family's module", raw.name),
                "use a lower-case identifier that is not a Rust keyword and differs from every design name",
            ));
        }
        let output = model.outputs.iter().position(|o| o.name == raw.output).ok_or_else(|| {
            let names: Vec<&str> = model.outputs.iter().map(|o| o.name.as_str()).collect();
            self.err(
                "family.output",
                format!("`{}` is not an output", raw.output),
                format!("name one of the outputs: {}", names.join(", ")),
            )
        })?;
        if !raw.value.is_finite() {
            return Err(self.err(
                "family.value",
                format!("{} is not finite", raw.value),
                "give this member's value of the output",
            ));
        }
        Ok(Family {
            name: raw.name.clone(),
            output,
            value: raw.value,
        })
    }

    fn scenario(&self, raw: &RawScenario, model: &Model, horizon: usize) -> Result<Scenario, SpecError> {
        for key in raw.x0.keys() {
            if !model.states.contains(key) {
                return Err(self.err(
                    format!("scenario.x0.{key}"),
                    format!("`{key}` is not a state"),
                    "give one initial value per state",
                ));
            }
        }
        let x0 = model
            .states
            .iter()
            .map(|state| match raw.x0.get(state) {
                Some(v) if v.is_finite() => Ok(*v),
                Some(v) => Err(self.err(
                    format!("scenario.x0.{state}"),
                    format!("{v} is not finite"),
                    "give a finite initial value",
                )),
                None => Err(self.err(
                    format!("scenario.x0.{state}"),
                    format!("no initial value for `{state}`"),
                    format!("add `{state} = …` to `scenario.x0`"),
                )),
            })
            .collect::<Result<_, _>>()?;
        if raw.samples < horizon {
            return Err(self.err(
                "scenario.samples",
                format!("{} samples hold no window of N = {horizon}", raw.samples),
                "set `scenario.samples` ≥ `map.horizon`",
            ));
        }
        Ok(Scenario {
            x0,
            samples: raw.samples,
            seed: raw.seed,
        })
    }

    fn model(&self, raw: &RawModel) -> Result<Model, SpecError> {
        if raw.states.is_empty() {
            return Err(self.err(
                "model.states",
                "the model has no state",
                "list the state names, e.g. `states = [\"x1\", \"x2\"]`",
            ));
        }
        if raw.outputs.is_empty() {
            return Err(self.err(
                "model.outputs",
                "the model has no measured output",
                "add a `[[model.outputs]]` table with `name`, `expr` and `noise_variance`",
            ));
        }
        let mut seen: Vec<(String, String)> = Vec::new();
        let mut declare = |field: String, name: &str| -> Result<(), SpecError> {
            self.identifier(&field, name)?;
            if let Some((_, first)) = seen.iter().find(|(n, _)| *n == name) {
                return Err(self.err(
                    field,
                    format!("`{name}` is already declared at `{first}`"),
                    "give every state, input, parameter, definition and output its own name",
                ));
            }
            seen.push((name.to_owned(), field));
            Ok(())
        };
        for (i, s) in raw.states.iter().enumerate() {
            declare(format!("model.states[{i}]"), s)?;
        }
        for (i, s) in raw.inputs.iter().enumerate() {
            declare(format!("model.inputs[{i}]"), s)?;
        }
        for (name, value) in &raw.parameters {
            declare(format!("model.parameters.{name}"), name)?;
            if !value.is_finite() {
                return Err(self.err(
                    format!("model.parameters.{name}"),
                    format!("value {value} is not finite"),
                    "give a finite number",
                ));
            }
        }
        for (i, d) in raw.definitions.iter().enumerate() {
            declare(format!("model.definitions[{i}].name"), &d.name)?;
        }
        for (i, o) in raw.outputs.iter().enumerate() {
            declare(format!("model.outputs[{i}].name"), &o.name)?;
            let field = format!("model.outputs[{i}].noise_variance");
            if !(o.noise_variance.is_finite() && o.noise_variance >= 0.0) {
                return Err(self.err(
                    field,
                    format!("a variance must be finite and ≥ 0, got {}", o.noise_variance),
                    "give the variance of the measurement noise (0 for none)",
                ));
            }
        }
        for key in raw.derivatives.keys() {
            if !raw.states.contains(key) {
                return Err(self.err(
                    format!("model.derivatives.{key}"),
                    format!("`{key}` is not a state"),
                    format!(
                        "give one derivative per state of `model.states` ({})",
                        raw.states.join(", ")
                    ),
                ));
            }
        }
        let mut derivatives = Vec::new();
        for state in &raw.states {
            let text = raw.derivatives.get(state).ok_or_else(|| {
                self.err(
                    format!("model.derivatives.{state}"),
                    format!("no derivative for state `{state}`"),
                    format!("add `{state} = \"…\"` (dx/dt) under `[model.derivatives]`"),
                )
            })?;
            derivatives.push(text.clone());
        }
        let parameters: Vec<(String, f64)> = raw.parameters.iter().map(|(k, v)| (k.clone(), *v)).collect();
        let definitions: Vec<(String, String)> = raw
            .definitions
            .iter()
            .map(|d| (d.name.clone(), d.expr.clone()))
            .collect();
        let outputs: Vec<(String, String, f64, String)> = raw
            .outputs
            .iter()
            .map(|o| (o.name.clone(), o.expr.clone(), o.noise_variance, o.unit.clone()))
            .collect();
        Model::compile(&ModelText {
            states: &raw.states,
            inputs: &raw.inputs,
            parameters: &parameters,
            definitions: &definitions,
            derivatives: &derivatives,
            outputs: &outputs,
        })
        .map_err(|e| self.err(e.field, e.error.to_string(), e.error.fix()))
    }

    fn map(&self, raw: &RawMap) -> Result<MapSettings, SpecError> {
        if raw.horizon == 0 {
            return Err(self.err(
                "map.horizon",
                "the horizon N must be at least 1",
                "set `map.horizon` to the number of past measurements to use (the paper uses 10 and 3)",
            ));
        }
        if raw.nm == 0 {
            return Err(self.err("map.nm", "n_m must be at least 1", "set `map.nm` (the paper uses 5)"));
        }
        let beta = self.positive("map.beta", raw.beta, "β")?;
        if beta * (raw.nm as f64 - 1.0) > 30.0 {
            return Err(self.err(
                "map.beta",
                format!(
                    "β·(n_m - 1) = {} makes basis odds ratios reach e^{:.0}: the basis degenerates to steps",
                    beta * (raw.nm as f64 - 1.0),
                    beta * (raw.nm as f64 - 1.0)
                ),
                "keep β·(n_m - 1) ≤ 30 (β of 0.5 to 3 is usual)",
            ));
        }
        let epsilon = self.positive("map.epsilon", raw.epsilon, "ε")?;
        if raw.monotonicity_grid < 3 {
            return Err(self.err(
                "map.monotonicity_grid",
                format!(
                    "{} points cannot constrain the slope of Γ on [0, 1]",
                    raw.monotonicity_grid
                ),
                "use 201 or more points",
            ));
        }
        Ok(MapSettings {
            horizon: raw.horizon,
            nm: raw.nm,
            beta,
            epsilon,
            normalisation: raw.normalisation,
            monotonicity_grid: raw.monotonicity_grid,
        })
    }

    fn learning(&self, raw: &RawLearning, model: &Model, horizon: usize) -> Result<Learning, SpecError> {
        if raw.samples <= horizon {
            return Err(self.err(
                "map.horizon",
                format!(
                    "N = {horizon} leaves no window in runs of N_s = {} samples (N must be < N_s)",
                    raw.samples
                ),
                "lower `map.horizon` or raise `learning.samples`",
            ));
        }
        for key in raw.grid.keys() {
            if !model.states.contains(key) {
                return Err(self.err(
                    format!("learning.grid.{key}"),
                    format!("`{key}` is not a state"),
                    format!("give one axis per state ({})", model.states.join(", ")),
                ));
            }
        }
        let axes = model
            .states
            .iter()
            .map(|state| {
                let field = format!("learning.grid.{state}");
                let raw = raw.grid.get(state).ok_or_else(|| {
                    self.err(&field, format!("no axis for state `{state}`"), format!("add `grid.{state} = {{ min = …, max = …, points = … }}` (or `{{ value = … }}` to hold it fixed)"))
                })?;
                self.axis(&field, raw)
            })
            .collect::<Result<Vec<_>, _>>()?;
        for key in raw.inputs.keys() {
            if !model.inputs.contains(key) {
                return Err(self.err(
                    format!("learning.inputs.{key}"),
                    format!("`{key}` is not an input"),
                    "give one profile per input of `model.inputs`",
                ));
            }
        }
        let inputs = model
            .inputs
            .iter()
            .map(|input| {
                let field = format!("learning.inputs.{input}");
                let p = raw.inputs.get(input).ok_or_else(|| {
                    self.err(
                        &field,
                        format!("no profile for input `{input}`"),
                        format!("add `inputs.{input} = {{ min = …, max = …, hold = … }}` under `[learning]`"),
                    )
                })?;
                if !(p.min.is_finite() && p.max.is_finite() && p.min <= p.max && (p.max - p.min).is_finite()) {
                    return Err(self.err(
                        format!("{field}.min"),
                        format!("the range [{}, {}] is not a finite interval", p.min, p.max),
                        "give finite bounds with min ≤ max",
                    ));
                }
                if p.hold == 0 {
                    return Err(self.err(
                        format!("{field}.hold"),
                        "an input value must be held at least one sample",
                        "set `hold` to 1 or more samples",
                    ));
                }
                Ok(InputProfile {
                    min: p.min,
                    max: p.max,
                    hold: p.hold,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Learning {
            samples: raw.samples,
            seed: raw.seed,
            axes,
            inputs,
        })
    }

    fn axis(&self, field: &str, raw: &RawAxis) -> Result<Axis, SpecError> {
        match (raw.min, raw.max, raw.points, raw.value) {
            (None, None, None, Some(value)) if value.is_finite() => Ok(Axis::Fixed(value)),
            (None, None, None, Some(value)) => Err(self.err(
                format!("{field}.value"),
                format!("{value} is not finite"),
                "give a finite value",
            )),
            (Some(min), Some(max), Some(points), None) => {
                if !(min.is_finite() && max.is_finite() && (max - min).is_finite()) {
                    return Err(self.err(
                        format!("{field}.min"),
                        format!("the bounds [{min}, {max}] are not finite"),
                        "give finite bounds",
                    ));
                }
                if min > max {
                    return Err(self.err(
                        format!("{field}.max"),
                        format!("the box is inverted: min = {min} > max = {max}"),
                        "swap `min` and `max`",
                    ));
                }
                if min == max {
                    return Err(self.err(
                        format!("{field}.max"),
                        format!("the box is empty: min = max = {min}"),
                        "widen the interval, or hold the state fixed with `{ value = … }`",
                    ));
                }
                if points == 0 {
                    return Err(self.err(
                        format!("{field}.points"),
                        "a grid of 0 points has no initial state",
                        "set `points` to 2 or more",
                    ));
                }
                if points == 1 {
                    return Err(self.err(
                        format!("{field}.points"),
                        "one point cannot span [min, max]",
                        "set `points` to 2 or more, or hold the state fixed with `{ value = … }`",
                    ));
                }
                Ok(Axis::Range { min, max, points })
            }
            _ => Err(self.err(
                field,
                "an axis is either `{ min, max, points }` or `{ value }`",
                format!("write `{field} = {{ min = …, max = …, points = … }}` or `{{ value = … }}`"),
            )),
        }
    }

    fn validation(&self, raw: &RawValidation, horizon: usize) -> Result<Validation, SpecError> {
        if raw.trajectories == 0 {
            return Err(self.err(
                "validation.trajectories",
                "no validation run: accuracy could not be reported",
                "set `validation.trajectories` to 1 or more (50 or more is sensible)",
            ));
        }
        if raw.samples < horizon {
            return Err(self.err(
                "validation.samples",
                format!("runs of {} samples hold no window of N = {horizon}", raw.samples),
                "set `validation.samples` ≥ `map.horizon`",
            ));
        }
        Ok(Validation {
            trajectories: raw.trajectories,
            samples: raw.samples,
            seed: raw.seed,
        })
    }

    fn targets(&self, raw: &[RawNamedExpr], model: &Model) -> Result<Vec<Target>, SpecError> {
        if raw.is_empty() {
            return Err(self.err(
                "targets",
                "nothing to estimate",
                "add a `[[targets]]` table with `name` and `expr` (e.g. a state name)",
            ));
        }
        let scope = model.scope();
        let mut targets: Vec<Target> = Vec::new();
        for (i, t) in raw.iter().enumerate() {
            self.identifier(&format!("targets[{i}].name"), &t.name)?;
            if targets.iter().any(|other| other.name == t.name) {
                return Err(self.err(
                    format!("targets[{i}].name"),
                    format!("target `{}` is declared twice", t.name),
                    "give each target its own name",
                ));
            }
            let expr = Expression::compile(&t.expr, &scope)
                .map_err(|e| self.err(format!("targets[{i}].expr"), e.to_string(), e.fix()))?;
            targets.push(Target {
                name: t.name.clone(),
                unit: t.unit.clone(),
                expr,
            });
        }
        Ok(targets)
    }
}
