//! `[scenario]` and `[[scenario]]` as TOML spells them: one table, or several (each named).

use std::collections::BTreeMap;

use serde::Deserialize;

/// `[scenario]` (one table) or `[[scenario]]` (several, each named).
pub(super) enum RawScenarios {
    One(RawScenario),
    Many(Vec<RawScenario>),
}

impl RawScenarios {
    /// Each scenario with the spec's name of its section: `scenario`, or `scenario[i]`.
    pub(super) fn sections(&self) -> Vec<(String, &RawScenario)> {
        match self {
            RawScenarios::One(one) => vec![("scenario".to_owned(), one)],
            RawScenarios::Many(many) => many
                .iter()
                .enumerate()
                .map(|(i, s)| (format!("scenario[{i}]"), s))
                .collect(),
        }
    }
}

/// By hand, so that a mistake inside a scenario keeps its own message (an untagged enum would say
/// only that neither form matched).
impl<'de> Deserialize<'de> for RawScenarios {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl<'de> serde::de::Visitor<'de> for Visitor {
            type Value = RawScenarios;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a `[scenario]` table or `[[scenario]]` tables")
            }

            fn visit_map<A: serde::de::MapAccess<'de>>(self, map: A) -> Result<RawScenarios, A::Error> {
                RawScenario::deserialize(serde::de::value::MapAccessDeserializer::new(map)).map(RawScenarios::One)
            }

            fn visit_seq<A: serde::de::SeqAccess<'de>>(self, seq: A) -> Result<RawScenarios, A::Error> {
                Vec::<RawScenario>::deserialize(serde::de::value::SeqAccessDeserializer::new(seq))
                    .map(RawScenarios::Many)
            }
        }
        deserializer.deserialize_any(Visitor)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawScenario {
    pub(super) name: Option<String>,
    pub(super) x0: BTreeMap<String, f64>,
    pub(super) observer_x0: Option<BTreeMap<String, f64>>,
    pub(super) samples: usize,
    pub(super) seed: u64,
}
