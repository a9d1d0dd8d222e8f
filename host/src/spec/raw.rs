//! The spec as TOML spells it (serde, unknown fields refused); [`super::validate`] turns it into a
//! [`super::Design`].

use std::collections::BTreeMap;

use serde::Deserialize;

pub(super) use super::raw_choice::RawChoice;
pub(super) use super::raw_scenario::{RawScenario, RawScenarios};
use super::{Normalisation, ObserverKind};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSpec {
    pub(super) name: String,
    #[serde(default)]
    pub(super) description: String,
    pub(super) model: RawModel,
    pub(super) sampling: RawSampling,
    pub(super) learning: RawLearning,
    pub(super) validation: RawValidation,
    pub(super) tuning: Option<RawTuning>,
    pub(super) map: RawMap,
    pub(super) targets: Vec<RawTarget>,
    pub(super) scenario: Option<RawScenarios>,
    pub(super) family: Option<RawFamily>,
    pub(super) observer: Option<RawObserver>,
    pub(super) budget: Option<RawBudget>,
    pub(super) search: Option<RawSearch>,
    pub(super) chip: Option<RawChip>,
}

/// `[chip]`: the arithmetic the chip computes the map in, and (for `"fixed"`) each signal's raw
/// integer scaling by name (`[chip.raw.<output or input>]`).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawChip {
    #[serde(default)]
    pub(super) arithmetic: Arithmetic,
    #[serde(default)]
    pub(super) raw: BTreeMap<String, RawScaling>,
}

/// `[chip] arithmetic`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum Arithmetic {
    /// `f32` only (the default).
    #[default]
    Float,
    /// Also the integer map ([`super::FixedSpec`]).
    Fixed,
}

/// `[chip.raw.<signal>]`: `value = offset + scale · raw` for raw in `[min, max]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawScaling {
    pub(super) scale: f64,
    #[serde(default)]
    pub(super) offset: f64,
    pub(super) min: i64,
    pub(super) max: i64,
}

/// `[search]`: how large a design search may be. The value is read as any TOML value so that a
/// negative, fractional or quoted number is refused by [`super::validate`] with the field's own fix.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSearch {
    pub(super) max_candidates: Option<toml::Value>,
}

/// `[budget]`: what the chosen observer may cost on the chip (every field optional).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawBudget {
    pub(super) instructions: Option<u64>,
    pub(super) first_estimate: Option<f64>,
    pub(super) flash: Option<u64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawObserver {
    #[serde(default)]
    pub(super) kind: ObserverKind,
    pub(super) ekf: Option<RawFilter>,
    pub(super) ukf: Option<RawFilter>,
}

impl RawObserver {
    /// Every `[observer.<filter>]` section a spec may give, by its full name, in the spec's order.
    pub(super) fn filter_sections(&self) -> [(&'static str, Option<&RawFilter>); 2] {
        [("observer.ekf", self.ekf.as_ref()), ("observer.ukf", self.ukf.as_ref())]
    }
}

/// `[observer.<filter>]`: a filter's constants fixed instead of tuned, each optional.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFilter {
    pub(super) x0: Option<BTreeMap<String, f64>>,
    pub(super) q: Option<RawCovariance>,
    pub(super) p0: Option<RawCovariance>,
}

/// A covariance as a spec writes it: its diagonal by state name, or its rows in state order.
#[derive(Deserialize)]
#[serde(
    untagged,
    expecting = "a table of variances by state name (`{ x1 = 0.1, x2 = 0.2 }`, the diagonal) or a list of rows (`[[0.1, 0.0], [0.0, 0.2]]`, the full matrix)"
)]
pub(super) enum RawCovariance {
    Diagonal(BTreeMap<String, f64>),
    Full(Vec<Vec<f64>>),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFamily {
    pub(super) name: String,
    pub(super) output: String,
    pub(super) value: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawModel {
    pub(super) states: Vec<String>,
    #[serde(default)]
    pub(super) inputs: Vec<String>,
    #[serde(default)]
    pub(super) parameters: BTreeMap<String, RawParameter>,
    #[serde(default)]
    pub(super) definitions: Vec<RawNamedExpr>,
    pub(super) derivatives: BTreeMap<String, String>,
    pub(super) outputs: Vec<RawOutput>,
    #[serde(default)]
    pub(super) units: BTreeMap<String, String>,
    #[serde(default)]
    pub(super) bounds: BTreeMap<String, RawBounds>,
}

/// `[model.bounds]`: a state's physical bounds, one side or both (`X = { min = 0.0 }`).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawBounds {
    pub(super) min: Option<f64>,
    pub(super) max: Option<f64>,
}

/// A parameter: a number (`a = 4.0`), or a nominal value with the range the plant's true value may
/// lie in (`a = { value = 4.0, min = 3.6, max = 4.4 }`).
pub(super) enum RawParameter {
    Known(f64),
    Uncertain(RawRange),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawRange {
    pub(super) value: f64,
    pub(super) min: f64,
    pub(super) max: f64,
}

/// By hand rather than `#[serde(untagged)]`: an untagged enum answers any mistake inside the table
/// (a missing `max`, a misspelt key) with "data did not match any variant"; this visitor hands the
/// table to [`RawRange`], whose own message names the key.
impl<'de> Deserialize<'de> for RawParameter {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl<'de> serde::de::Visitor<'de> for Visitor {
            type Value = RawParameter;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a number, or a table `{ value = …, min = …, max = … }`")
            }

            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<RawParameter, E> {
                Ok(RawParameter::Known(v))
            }

            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<RawParameter, E> {
                Ok(RawParameter::Known(v as f64))
            }

            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<RawParameter, E> {
                Ok(RawParameter::Known(v as f64))
            }

            fn visit_map<A: serde::de::MapAccess<'de>>(self, map: A) -> Result<RawParameter, A::Error> {
                RawRange::deserialize(serde::de::value::MapAccessDeserializer::new(map)).map(RawParameter::Uncertain)
            }
        }
        deserializer.deserialize_any(Visitor)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawNamedExpr {
    pub(super) name: String,
    pub(super) expr: String,
    /// A definition's unit: accepted for the spec's reader (as before targets had their own table),
    /// read by nothing.
    #[serde(default)]
    #[allow(dead_code)]
    pub(super) unit: String,
}

/// `[[targets]]`: a named expression with its unit and its weight in the score.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawTarget {
    pub(super) name: String,
    pub(super) expr: String,
    #[serde(default)]
    pub(super) unit: String,
    pub(super) weight: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawOutput {
    pub(super) name: String,
    pub(super) expr: String,
    pub(super) noise_variance: f64,
    #[serde(default)]
    pub(super) unit: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSampling {
    pub(super) tau: f64,
    #[serde(default = "default_time_unit")]
    pub(super) time_unit: String,
    #[serde(default = "default_substeps")]
    pub(super) substeps: usize,
    #[serde(default = "default_chip_substeps")]
    pub(super) chip_substeps: usize,
}

fn default_chip_substeps() -> usize {
    1
}

fn default_time_unit() -> String {
    "s".into()
}

fn default_substeps() -> usize {
    10
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawLearning {
    pub(super) samples: usize,
    pub(super) seed: u64,
    pub(super) grid: BTreeMap<String, RawAxis>,
    #[serde(default)]
    pub(super) inputs: BTreeMap<String, RawInputProfile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawAxis {
    pub(super) min: Option<f64>,
    pub(super) max: Option<f64>,
    pub(super) points: Option<usize>,
    pub(super) value: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawInputProfile {
    pub(super) min: f64,
    pub(super) max: f64,
    pub(super) hold: usize,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawValidation {
    pub(super) trajectories: usize,
    pub(super) samples: usize,
    pub(super) seed: u64,
}

/// `[tuning]`: every field defaults from `[validation]` (the seed to another one).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawTuning {
    pub(super) trajectories: Option<usize>,
    pub(super) samples: Option<usize>,
    pub(super) seed: Option<u64>,
    pub(super) start_up: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMap {
    pub(super) horizon: RawChoice<usize>,
    pub(super) nm: RawChoice<usize>,
    pub(super) beta: RawChoice<f64>,
    pub(super) epsilon: f64,
    #[serde(default)]
    pub(super) normalisation: Normalisation,
    #[serde(default = "default_grid")]
    pub(super) monotonicity_grid: usize,
    #[serde(default)]
    pub(super) taps: Option<RawChoice<usize>>,
}

fn default_grid() -> usize {
    201
}
