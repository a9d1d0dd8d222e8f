//! What the emitters of a design's files know of its observers: the tuned constants of every kind it
//! has, which kind `observer()` is, and what the file records beside them; every kind's part of the
//! Rust and the C reads it (`crate::observers::kind::Kind::rust`, `Kind::c`).

use crate::observers::kind::corrected::program::CorrectionConstants;
use crate::observers::kind::ekf_restart::run::RestartConstants;
use crate::observers::kind::mhe::run::ChipConstants;
use crate::observers::kind::tuned::TunedConstants;
use crate::plant::kalman::EkfConstants;
use crate::spec::ObserverKind;

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
    pub fn mhe(&self) -> Option<&'a ChipConstants> {
        self.constants.mhe()
    }
}
