//! A fitted design saved as data (`design.json` beside its report): what `estimate` needs to run any
//! observer kind on recorded measurements without fitting, searching or tuning again. The maps are
//! the ones emitted (their certified tables included), the observers' constants the tuned ones.
//!
//! The file records the SHA-256 of the spec it came from and the settings the search chose: a
//! changed spec, or a file written by another version of the tool, is not used (`estimate` then fits
//! again and says so).

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::fit::maps::FittedMap;
use crate::fit::DesignResult;
use crate::generate::Emitted;
use crate::observers::restart::RestartConstants;
use crate::observers::Comparison;
use crate::plant::correction::CorrectionConstants;
use crate::plant::kalman::EkfConstants;
use crate::spec::{Design, ObserverKind};

/// The file's name in a report folder.
pub const FILE: &str = "design.json";

/// The saved design.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Tables {
    /// The tool's version that wrote it.
    pub version: String,
    /// SHA-256 of the spec text it was fitted from.
    pub spec_sha256: String,
    /// SHA-256 of the observer file emitted with it: tables beside a report are used only while that
    /// file is unchanged (a rebuilt tool that fits differently rewrites it).
    pub source_sha256: String,
    /// `N` (as the search chose it, when the spec searches).
    pub horizon: usize,
    /// `n_m`, `β` and the taps kept, for the record.
    pub nm: usize,
    /// `β`.
    pub beta: f64,
    /// Non-zero gains per target, when `L` is pruned.
    pub taps: Option<usize>,
    /// The kind `observer()` is.
    pub chosen: ObserverKind,
    /// Every target's map, in the spec's order.
    pub maps: Vec<FittedMap>,
    /// The model-corrected map's constants, when the design has one.
    pub corrected: Option<CorrectionConstants>,
    /// The EKF's constants, when the design has one.
    pub ekf: Option<EkfConstants>,
    /// The map-started EKF's `P(N−1)` diagonal and each state's target, when it has one.
    pub started: Option<(Vec<f64>, Vec<usize>)>,
    /// The restarted EKF's check (`ekf_restart`), when it has one (with `ekf` and `started`).
    pub restart: Option<RestartConstants>,
}

/// Why saved tables could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum TablesError {
    /// The file could not be read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The file is not a saved design.
    #[error("{}: not a saved design ({source}); delete it, or run `gen` again to rewrite it", path.display())]
    Format {
        /// The file.
        path: PathBuf,
        /// Why.
        source: serde_json::Error,
    },
}

impl Tables {
    /// What `emitted` is, as data.
    pub fn of(emitted: &Emitted) -> Self {
        let mut tables = Self::new(&emitted.design, &emitted.result, Some(&emitted.comparison));
        tables.source_sha256 = sha256(&emitted.source);
        tables
    }

    /// A fitted `design` (its map settled) as data: the maps of `result` and, when its observers were
    /// compared, their constants and the chosen kind (else the map alone). No observer file yet.
    pub fn new(design: &Design, result: &DesignResult, comparison: Option<&Comparison>) -> Self {
        Tables {
            version: env!("CARGO_PKG_VERSION").to_owned(),
            spec_sha256: design.spec_sha256.clone(),
            source_sha256: String::new(),
            horizon: design.map.horizon,
            nm: design.map.nm,
            beta: design.map.beta,
            taps: design.map.taps,
            chosen: comparison.map_or(ObserverKind::Map, |c| c.chosen.0),
            maps: result.targets.iter().map(|t| t.fit.map.clone()).collect(),
            corrected: comparison
                .and_then(|c| c.corrected.as_ref().ok())
                .map(|t| t.constants.clone()),
            ekf: comparison.and_then(|c| c.ekf.as_ref()).map(|t| t.constants.clone()),
            started: comparison
                .and_then(|c| c.started.as_ref())
                .map(|s| (s.p0.clone(), s.state_targets.clone())),
            restart: comparison.and_then(|c| c.restart.clone()),
        }
    }

    /// The JSON text.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("plain data serialises") + "\n"
    }

    /// Reads `path`: `None` when there is no such file.
    pub fn read(path: &Path) -> Result<Option<Self>, TablesError> {
        let text = match std::fs::read_to_string(path) {
            Ok(text) => text,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(source) => {
                return Err(TablesError::Io {
                    path: path.to_owned(),
                    source,
                })
            }
        };
        serde_json::from_str(&text)
            .map(Some)
            .map_err(|source| TablesError::Format {
                path: path.to_owned(),
                source,
            })
    }

    /// Whether these tables are `design`'s: the same spec text, read by this version of the tool.
    pub fn belongs_to(&self, design: &Design) -> bool {
        self.spec_sha256 == design.spec_sha256 && self.version == env!("CARGO_PKG_VERSION")
    }

    /// Whether `observer`, the emitted file these tables were written with, is unchanged.
    pub fn matches_observer(&self, observer: &Path) -> bool {
        std::fs::read_to_string(observer).is_ok_and(|text| sha256(&text) == self.source_sha256)
    }
}

/// Lower-case hex SHA-256 of `text`.
fn sha256(text: &str) -> String {
    use sha2::Digest;
    sha2::Sha256::digest(text.as_bytes())
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}
