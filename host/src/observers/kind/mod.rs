//! What an observer kind is, in one place: one module per kind, each one [`Kind`] entry of
//! [`REGISTRY`]: its name as users type it (spec, `--kind`, the report's rows), what it needs of a
//! design, its cost model before the fit, how it is tuned on the tuning runs and judged on the others
//! ([`Bench`]), the type a design file gives it and how the figures draw it. The comparison
//! ([`super::compare`]), `auto` ([`super::choose`]), the check before the fit, the saved tables,
//! `estimate`, the emitter, the on-target section and the figures read the registry; adding a kind is
//! a module here, its entry in [`REGISTRY`] and its name in [`ObserverKind`] (plus its code on the chip).
//!
//! The registry's order is the order kinds are tuned in (a kind may read the constants of the kinds
//! before it: the EKF started or restarted by the map reuses the box EKF's `Q` and `R`) and the order
//! of the report's rows.

pub mod corrected;
mod ekf_box;
mod ekf_map;
pub mod ekf_restart;
mod map;
pub mod mhe;
pub mod ukf_bank;
pub mod ukf_box;

pub use bench::{map_estimates, Bench};
pub use tuned::{KindConstants, Started, StartedConstants, Tuned, TunedConstants, TunedKinds};

mod bench;
pub(crate) mod tuned;

use crate::emit::c::text::CPart;
use crate::emit::model::observers::Observers;
use crate::emit::EmitError;
use crate::plant::kalman::{EkfConstants, FilterCode};
use crate::plant::ModelCode;
use crate::recording::Precision;
use crate::spec::{Design, FixedFilter, ObserverKind};

use super::ObserverFigures;

/// One observer kind (see the module's documentation).
pub struct Kind {
    /// Its name ([`ObserverKind::name`]).
    pub kind: ObserverKind,
    /// What it is, in a phrase ("the model-corrected map"): the emitted docs, the report.
    pub what: &'static str,
    /// Its short name in the report's sentences ("UKF" in "the UKF's validation RMSE").
    pub short: &'static str,
    /// The type a design file gives it; `Observer` is this type when `observer()` is this kind.
    pub observer_type: &'static str,
    /// What the on-target harness measures of it (the report's on-target section).
    pub measured_as: &'static str,
    /// Its legend in the figures.
    pub legend: &'static str,
    /// Its colour in the figures (RGB).
    pub colour: (u8, u8, u8),
    /// Drawn as dots (else as a line).
    pub dots: bool,
    /// What it needs of the design besides the map.
    pub needs: Needs,
    /// Its predicted instructions per steady sample from the model alone, before any fit (the EKF
    /// kinds, whose tuned constants are non-zero literals whatever their values); `None` when the
    /// count needs the fit ([`crate::search::cost`]).
    pub cost_before_fit: Option<fn(&ModelCode, &EkfConstants) -> f64>,
    /// Why a design's tables may lack its own constants (empty for the map, which has none).
    pub missing_why: &'static str,
    /// The arithmetic its report figures are in: `F32`, the chip's, for the kinds whose f32 and f64
    /// runs part on a shipped design; `estimate --precision` in it gives the
    /// report's estimates to the bit.
    pub judged_in: Precision,
    /// Whether it counts the samples it refuses (`refused()` on the chip, the C struct's `refused`):
    /// the kinds over the filters' shared rules (`firmware::rules`).
    pub counts_refusals: bool,
    /// The spec's section of fixed filter constants it reads, if any.
    pub fixed: Option<FixedSection>,
    /// The filter program its constants build, when they are one Kalman filter's (the box
    /// filters): what the kinds that read its constants run on the host.
    pub filter_code: Option<fn(&ModelCode, &EkfConstants) -> FilterCode>,
    /// Its part of the design's Rust file, after the model and the EKF
    /// ([`crate::emit::model::model_source`]); `None` from the emitter when the design lacks it.
    pub rust: Option<Emitter<String>>,
    /// Its part of the design's C ([`crate::emit::c`]), likewise.
    pub c: Option<Emitter<CPart>>,
    /// Tunes it on the tuning runs and judges it on every set ([`Bench::judge`]), recording its
    /// constants in the bench for the kinds after it; `None` when the design cannot have it.
    pub tune: fn(&mut Bench<'_>) -> Option<ObserverFigures>,
}

/// Writes a kind's part of a design's emitted file from the design, its model's programs and the
/// tuned constants of every kind it has.
pub type Emitter<P> = fn(&Design, &ModelCode, &Observers<'_>) -> Result<Option<P>, EmitError>;

/// The spec's section of fixed constants a filter kind reads (`[observer.<filter>]`).
#[derive(Clone, Copy)]
pub struct FixedSection {
    /// Its name in the spec (`observer.ekf`).
    pub section: &'static str,
    /// Whether these constants fix the kind's own filter, rather than a `Q` it reuses (the
    /// map-started and restarted EKFs run on the box EKF's).
    pub own: bool,
}

impl FixedSection {
    /// The constants `design`'s spec fixes in this section.
    pub fn of<'d>(&self, design: &'d Design) -> &'d FixedFilter {
        design.filters.of(self.section)
    }
}

/// What a kind needs of a design besides the map.
#[derive(Clone, Copy, Debug)]
pub struct Needs {
    /// Every state as a target: the map starts, checks or corrects the model's state.
    pub state_targets: bool,
    /// A model the host can filter ([`super::ekf::supported`]).
    pub filter: bool,
    /// The kinds whose tuned constants it runs on ([`TunedConstants`]): its own, and those it
    /// reuses (the map-started EKF runs on the box EKF's `Q` and `R`).
    pub reads: &'static [ObserverKind],
}

/// Every kind, in the order they are tuned and reported.
pub const REGISTRY: [Kind; 7] = [
    map::KIND,
    ekf_box::KIND,
    ukf_box::KIND,
    corrected::KIND,
    ekf_map::KIND,
    ekf_restart::KIND,
    mhe::KIND,
];

/// The entry of `kind` (`Auto` is not a kind a design has: the map's).
pub fn of(kind: ObserverKind) -> &'static Kind {
    REGISTRY.iter().find(|k| k.kind == kind).unwrap_or(&REGISTRY[0])
}

/// The entry named `name` ([`ObserverKind::name`]), if any.
pub fn named(name: &str) -> Option<&'static Kind> {
    REGISTRY.iter().find(|k| k.kind.name() == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_but_auto_has_one_entry_and_the_map_comes_first() {
        // Every variant a spec may name, by its serde name; `auto` is a choice, not a kind.
        for name in [
            "map",
            "corrected",
            "ekf_map",
            "ekf_box",
            "ukf_box",
            "ekf_restart",
            "mhe",
        ] {
            let kind: ObserverKind = toml::Value::String(name.to_owned()).try_into().unwrap();
            assert_eq!(REGISTRY.iter().filter(|k| k.kind == kind).count(), 1, "{name}");
            assert_eq!(named(name).map(|k| k.kind), Some(kind));
        }
        assert_eq!(REGISTRY.len(), 7);
        assert!(named("auto").is_none());
        assert_eq!(
            REGISTRY[0].kind,
            ObserverKind::Map,
            "every other kind reads the map's estimates"
        );
        assert_eq!(of(ObserverKind::Auto).kind, ObserverKind::Map);
    }

    #[test]
    fn a_kinds_type_is_its_name_in_rust_spelling() {
        // One name per kind: `ekf_map` is `EkfMapObserver` in a design file, never another word.
        let camel = |name: &str| -> String {
            name.split('_')
                .map(|word| word[..1].to_uppercase() + &word[1..])
                .collect()
        };
        for entry in REGISTRY {
            assert_eq!(entry.observer_type, camel(entry.kind.name()) + "Observer");
        }
        assert_eq!(camel("ekf_restart"), "EkfRestart");
    }
}
