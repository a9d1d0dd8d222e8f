//! The model of a design written out as Rust: one `let` per operation of its straight-line programs
//! ([`crate::plant::Program`]), in their order, generic over the firmware's [`firmware::Scalar`] so
//! that the chip runs it in `f32` and the host's tests in `f64`; and the design's EKF over it.
//!
//! Every number is written once for both precisions (`T::literal(f32, f64)`, each rounded here), every
//! function is the firmware's `Maths::…` (libm), every name a local of the spec's name with a prefix
//! (`x_` states, `u_` inputs; parameters are constants of module `parameters`), so nothing of the
//! spec's text is pasted into code.
//!
//! One submodule per piece: `rust_text` (literals, lists, a program's `let`s), `plant` (the model and
//! the EKF), then one per model-based observer kind (`filter`, the frame of the EKF and of the UKF (`ukf`), `started`, `restarted`, `corrected`) and the
//! chip's moving-horizon estimator (`mhe`).

pub(crate) mod filter;
mod plant;
pub(crate) mod rust_text;
mod started;

use crate::emit::EmitError;
use crate::observers::kind::corrected::emit::corrector;
use crate::observers::kind::corrected::program::CorrectionConstants;
use crate::observers::kind::ekf_restart::emit::restarted;
use crate::observers::kind::ekf_restart::run::RestartConstants;
use crate::observers::kind::TunedConstants;
use crate::plant::kalman::{self, EkfConstants};
use crate::plant::ModelCode;
use crate::spec::{Design, ObserverKind};
use plant::model_and_ekf;
use rust_text::{list, literal};
use started::started_ekf;

/// The observers a design file carries besides its map, and which one `observer()` is.
#[derive(Clone, Copy, Debug)]
pub struct Observers<'a> {
    /// The tuned constants of every kind the design has, keyed by the kind.
    pub constants: &'a TunedConstants,
    /// Each state's target, when every state is one (the kinds the map starts or corrects).
    pub state_targets: Option<&'a [usize]>,
    /// `observer()`'s kind: `Map`, `Corrected` or `Ekf` (never `Auto`: chosen before).
    pub kind: ObserverKind,
    /// Every observer kind the design has and its predicted instructions per steady sample
    /// ([`crate::search::cost`]), in the report's order.
    pub instructions: &'a [(&'static str, f64)],
    /// SHA-256 of the tables saved with this file ([`crate::tables::Tables::content_sha256`]).
    pub tables_sha256: &'a str,
    /// The map in integers, when the spec asks for it (`[chip] arithmetic = "fixed"`).
    pub fixed: Option<&'a crate::fixed_point::FixedPoint>,
}

impl<'a> Observers<'a> {
    /// The EKF's constants (the peer, and the map-started EKF).
    pub fn ekf(&self) -> Option<&'a EkfConstants> {
        self.constants.ekf_box()
    }

    /// The UKF's constants (`ukf_box`), written beside the EKF.
    pub fn ukf(&self) -> Option<&'a EkfConstants> {
        self.constants.ukf_box()
    }

    /// The EKF started by the map: its `P(N−1)` diagonal and each state's target.
    pub fn started(&self) -> Option<(&'a [f64], &'a [usize])> {
        let started = self.constants.ekf_map()?;
        Some((&started.p0, &started.state_targets))
    }

    /// The box-started EKF's check against the map (with [`Self::ekf`] and [`Self::started`]).
    pub fn restart(&self) -> Option<&'a RestartConstants> {
        self.constants.ekf_restart()
    }

    /// The model-corrected map's constants and each state's target.
    pub fn corrected(&self) -> Option<(&'a CorrectionConstants, &'a [usize])> {
        self.constants.corrected().zip(self.state_targets)
    }

    /// The chip's moving-horizon observer's constants, when the host could run one.
    pub fn mhe(&self) -> Option<&'a crate::observers::kind::mhe::run::ChipConstants> {
        self.constants.mhe()
    }
}

/// The Rust source of the design's model (`parameters`, `Plant`, `targets`), its EKF (`ekf`), its
/// model-based followers of the map, and `Observer` / `observer()` of the chosen kind.
pub fn model_source(design: &Design, code: &ModelCode, observers: &Observers<'_>) -> Result<String, EmitError> {
    let mut text = model_and_ekf(design, code, observers.ekf())?;
    if let (Some(_), Some(constants)) = (observers.ekf(), observers.ukf()) {
        text.push_str(&crate::observers::kind::ukf_box::emit::ukf(design, code, constants)?);
    }
    if let Some((constants, state_targets)) = observers.corrected() {
        text.push_str(&corrector(design, code, constants, state_targets)?);
    }
    if let (Some(_), Some((p0, state_targets))) = (observers.ekf(), observers.started()) {
        let upper = kalman::diagonal_upper(p0);
        let entries = upper
            .iter()
            .enumerate()
            .map(|(i, v)| literal(&format!("map-started EKF P0[{i}]"), *v))
            .collect::<Result<Vec<_>, _>>()?;
        text.push_str(&started_ekf(
            &list(&entries),
            &format!("{p0:?}"),
            &format!("{state_targets:?}"),
        )?);
    }
    if let (Some(ekf), Some(_), Some(restart)) = (observers.ekf(), observers.started(), observers.restart()) {
        text.push_str(&restarted(ekf, restart)?);
    }
    if let Some(constants) = observers.mhe() {
        text.push_str(&crate::observers::kind::mhe::emit::mhe(constants)?);
    }
    let entry = crate::observers::kind::of(observers.kind);
    let (ty, kind) = (entry.observer_type, entry.kind.name());
    let what = format!("{} ([`{ty}`])", entry.what);
    text.push_str(&askama::Template::render(&KindText {
        kind,
        what: &what,
        ty,
        tables: observers.tables_sha256,
    })?);
    Ok(text)
}

/// `KIND`, `Observer` and `observer()` of the chosen kind (`ty`: its type), and `TABLES_SHA256`.
#[derive(askama::Template)]
#[template(path = "model/kind.rs", escape = "none")]
struct KindText<'a> {
    kind: &'a str,
    what: &'a str,
    ty: &'a str,
    tables: &'a str,
}
