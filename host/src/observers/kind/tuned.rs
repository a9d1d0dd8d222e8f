//! What tuning gave the kinds a design has, keyed by the kind: [`Tuned`] (the constants and how they
//! were chosen, which the report shows) and [`TunedConstants`] (the constants alone: what the saved
//! tables hold, `estimate` runs on and the emitters write). One line per kind in [`kinds!`] declares
//! both, so that no other place lists what each kind keeps.

use std::collections::BTreeMap;
use std::fmt;

use serde::de::{self, DeserializeSeed, MapAccess, Visitor};
use serde::ser::SerializeMap;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::corrected::run as corrected;
use crate::observers::ekf;
use crate::observers::kind::corrected::program::CorrectionConstants;
use crate::observers::kind::ekf_restart::run::RestartConstants;
use crate::observers::kind::mhe::run::{ChipConstants, ChipTuned};
use crate::plant::kalman::EkfConstants;
use crate::spec::ObserverKind;

/// The EKF started by the map at `k = N − 1` as tuned (`ekf_map`), sharing the box EKF's `Q` and `R`.
#[derive(Clone, Debug)]
pub struct Started {
    /// `P(N−1)` diagonal: `factor` times the map's mean squared error per state on the tuning runs.
    pub p0: Vec<f64>,
    /// The factor, chosen on the tuning runs ([`ekf::tune_started`]).
    pub factor: f64,
    /// Each state's target.
    pub state_targets: Vec<usize>,
}

/// The map-started EKF's own constants (`ekf_map`): `P(N−1)`'s diagonal and each state's target; it
/// runs on the box EKF's `Q` and `R`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StartedConstants {
    /// `P(N−1)` diagonal.
    pub p0: Vec<f64>,
    /// Each state's target.
    pub state_targets: Vec<usize>,
}

/// Declares, for each kind with constants of its own (`Kind(tuning type => constants type, accessor)`),
/// the variant of [`Tuned`] and of [`KindConstants`], and the accessor of [`TunedConstants`] named after
/// the kind.
macro_rules! kinds {
    ($($kind:ident($tuned:ty => $constants:ty, $accessor:ident, |$t:ident| $of:expr);)*) => {
        /// What tuning one kind gave: its constants and how they were chosen.
        #[derive(Clone, Debug)]
        pub enum Tuned {
            $(
                #[doc = concat!("`", stringify!($accessor), "`.")]
                $kind($tuned),
            )*
        }

        /// The constants one kind runs on, as the saved tables hold them.
        #[derive(Clone, Debug, PartialEq)]
        pub enum KindConstants {
            $(
                #[doc = concat!("`", stringify!($accessor), "`.")]
                $kind($constants),
            )*
        }

        impl Tuned {
            /// Its kind.
            pub fn kind(&self) -> ObserverKind {
                match self {
                    $(Tuned::$kind(_) => ObserverKind::$kind,)*
                }
            }

            /// The constants it chose.
            pub fn constants(&self) -> KindConstants {
                match self {
                    $(Tuned::$kind($t) => KindConstants::$kind($of),)*
                }
            }
        }

        impl KindConstants {
            /// Its kind.
            pub fn kind(&self) -> ObserverKind {
                match self {
                    $(KindConstants::$kind(_) => ObserverKind::$kind,)*
                }
            }
        }

        impl Serialize for KindConstants {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                match self {
                    $(KindConstants::$kind(c) => c.serialize(serializer),)*
                }
            }
        }

        impl<'de> DeserializeSeed<'de> for ConstantsOf {
            type Value = KindConstants;
            fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<KindConstants, D::Error> {
                match self.0 {
                    $(ObserverKind::$kind => Ok(KindConstants::$kind(<$constants>::deserialize(deserializer)?)),)*
                    other => Err(de::Error::custom(format!("kind `{}` has no constants of its own", other.name()))),
                }
            }
        }

        impl TunedConstants {
            $(
                #[doc = concat!("The constants of `", stringify!($accessor), "`, when the design has it.")]
                pub fn $accessor(&self) -> Option<&$constants> {
                    match self.0.get(&ObserverKind::$kind) {
                        Some(KindConstants::$kind(c)) => Some(c),
                        _ => None,
                    }
                }
            )*
        }

        impl TunedKinds {
            $(
                #[doc = concat!("How `", stringify!($accessor), "` was tuned, when the design has it.")]
                pub fn $accessor(&self) -> Option<&$tuned> {
                    match self.0.get(&ObserverKind::$kind) {
                        Some(Tuned::$kind(t)) => Some(t),
                        _ => None,
                    }
                }
            )*
        }
    };
}

kinds! {
    EkfBox(ekf::Tuned => EkfConstants, ekf_box, |t| t.constants.clone());
    UkfBox(ekf::Tuned => EkfConstants, ukf_box, |t| t.constants.clone());
    Corrected(corrected::Tuned => CorrectionConstants, corrected, |t| t.constants.clone());
    EkfMap(Started => StartedConstants, ekf_map, |t| StartedConstants {
        p0: t.p0.clone(),
        state_targets: t.state_targets.clone(),
    });
    EkfRestart(RestartConstants => RestartConstants, ekf_restart, |t| t.clone());
    Mhe(ChipTuned => ChipConstants, mhe, |t| t.constants.clone());
}

impl KindConstants {
    /// A Kalman filter's constants, when this kind's constants are one filter's (the box filters).
    pub fn filter(&self) -> Option<&EkfConstants> {
        match self {
            KindConstants::EkfBox(c) | KindConstants::UkfBox(c) => Some(c),
            _ => None,
        }
    }
}

/// Reads the constants of the kind it holds.
struct ConstantsOf(ObserverKind);

/// Every kind's [`Tuned`], keyed by the kind (the kinds tuned so far, on the bench).
#[derive(Clone, Debug, Default)]
pub struct TunedKinds(BTreeMap<ObserverKind, Tuned>);

impl TunedKinds {
    /// How the Kalman filter of kind `kind` was tuned (a kind whose constants are a filter's,
    /// [`KindConstants::filter`]), when the design has it.
    pub fn filter(&self, kind: ObserverKind) -> Option<&ekf::Tuned> {
        match self.0.get(&kind)? {
            Tuned::EkfBox(t) | Tuned::UkfBox(t) => Some(t),
            _ => None,
        }
    }

    /// Records what tuning gave a kind (replacing what it gave before).
    pub fn insert(&mut self, tuned: Tuned) {
        self.0.insert(tuned.kind(), tuned);
    }

    /// The constants of every kind tuned.
    pub fn constants(&self) -> TunedConstants {
        TunedConstants(self.0.iter().map(|(&kind, t)| (kind, t.constants())).collect())
    }
}

/// Every kind's [`KindConstants`], keyed by the kind; in JSON an object from each kind's name
/// ([`ObserverKind::name`]) to its constants.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TunedConstants(BTreeMap<ObserverKind, KindConstants>);

impl TunedConstants {
    /// Whether `kind` has constants here.
    pub fn has(&self, kind: ObserverKind) -> bool {
        self.0.contains_key(&kind)
    }

    /// The constants of `kind`'s Kalman filter ([`KindConstants::filter`]), when it has them.
    pub fn filter(&self, kind: ObserverKind) -> Option<&EkfConstants> {
        self.0.get(&kind)?.filter()
    }

    /// The constants of `kind`, to edit (a test breaking saved tables on purpose).
    pub fn get_mut(&mut self, kind: ObserverKind) -> Option<&mut KindConstants> {
        self.0.get_mut(&kind)
    }

    /// Every kind's constants, in the order of [`ObserverKind`].
    pub fn iter(&self) -> impl Iterator<Item = &KindConstants> {
        self.0.values()
    }
}

impl Serialize for TunedConstants {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (kind, constants) in &self.0 {
            map.serialize_entry(kind, constants)?;
        }
        map.end()
    }
}

impl<'de> Deserialize<'de> for TunedConstants {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Kinds;
        impl<'de> Visitor<'de> for Kinds {
            type Value = TunedConstants;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an object from observer kinds to their constants")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<TunedConstants, A::Error> {
                let mut kinds = BTreeMap::new();
                while let Some(kind) = map.next_key::<ObserverKind>()? {
                    let constants = map.next_value_seed(ConstantsOf(kind))?;
                    if kinds.insert(kind, constants).is_some() {
                        return Err(de::Error::custom(format!("kind `{}` appears twice", kind.name())));
                    }
                }
                Ok(TunedConstants(kinds))
            }
        }
        deserializer.deserialize_map(Kinds)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn restart(threshold: f64) -> KindConstants {
        KindConstants::EkfRestart(RestartConstants {
            threshold,
            variances: vec![0.25, 4.0],
        })
    }

    #[test]
    fn constants_are_an_object_keyed_by_kind_name_and_read_back_as_written() {
        let started = StartedConstants {
            p0: vec![1.0, 2.0],
            state_targets: vec![1, 0],
        };
        let constants = TunedConstants(BTreeMap::from([
            (ObserverKind::EkfMap, KindConstants::EkfMap(started.clone())),
            (ObserverKind::EkfRestart, restart(8.0)),
        ]));
        let text = serde_json::to_string(&constants).unwrap();
        // Written by hand from the two structs' fields, in `ObserverKind`'s order.
        assert_eq!(
            text,
            r#"{"ekf_map":{"p0":[1.0,2.0],"state_targets":[1,0]},"ekf_restart":{"threshold":8.0,"variances":[0.25,4.0]}}"#
        );
        let back: TunedConstants = serde_json::from_str(&text).unwrap();
        assert_eq!(back, constants);
        assert_eq!(back.ekf_map(), Some(&started));
        assert!(back.ekf_box().is_none() && back.has(ObserverKind::EkfRestart) && !back.has(ObserverKind::Mhe));
    }

    #[test]
    fn a_kind_without_constants_or_named_twice_is_refused() {
        let map = serde_json::from_str::<TunedConstants>(r#"{"map":{}}"#).unwrap_err();
        assert!(
            map.to_string().contains("kind `map` has no constants of its own"),
            "{map}"
        );
        let twice =
            r#"{"ekf_restart":{"threshold":1.0,"variances":[]},"ekf_restart":{"threshold":2.0,"variances":[]}}"#;
        let twice = serde_json::from_str::<TunedConstants>(twice).unwrap_err();
        assert!(twice.to_string().contains("appears twice"), "{twice}");
        // A kind's constants are read as that kind's type: a restart's fields are not an EKF's.
        let wrong = serde_json::from_str::<TunedConstants>(r#"{"ekf_box":{"threshold":1.0,"variances":[]}}"#);
        assert!(wrong.is_err());
    }
}
