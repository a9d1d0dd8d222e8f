//! The emulated chip's figures for a design's observers, as `report.json` carries them.
//!
//! `gen` cannot measure them (that needs the generated crate built for the target, and QEMU):
//! `cargo run -p integration-tests --bin on-target-report` measures every shipped design and writes
//! [`FILE`] beside its report, keyed by the SHA-256 of the generated source it measured, and fills
//! the report's `observers[].on_target`. `gen` fills them in again from that file while the
//! generated source it writes is the one measured; after a change they are `null` until measured.

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};
use sha2::Digest;

/// The file beside `report.json`.
pub const FILE: &str = "on_target.json";

/// One observer's cost on the emulated Cortex-M4F, per sample.
///
/// The start-up is every sample of the recorded sequence up to and including the estimate that
/// ends it: the samples before the first estimate, the first estimate, and the estimates after it
/// that take a follower's start-up path (`Follower::START_UP`; none for the map and the EKF). The
/// steady state is every accepted sample after it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct OnTarget {
    /// Median instructions of a steady sample (`push` + estimate).
    pub instructions_median: u64,
    /// Largest instructions of a steady sample.
    pub instructions_max: u64,
    /// Largest instructions of a start-up sample; `None` in figures recorded before the start-up was
    /// measured.
    #[serde(default)]
    pub start_up_instructions_max: Option<u64>,
    /// Samples of the recorded sequence in the start-up; `None` as above.
    #[serde(default)]
    pub start_up_samples: Option<u64>,
    /// Largest number of `VDIV` and `VSQRT` in one sample.
    pub divisions: u64,
    /// Flash the observer adds to a program, in bytes.
    pub flash_bytes: u64,
    /// RAM: the observer's state and its static data, in bytes.
    pub ram_bytes: u64,
    /// Deepest stack use of one sample, in bytes.
    pub stack_bytes: u64,
}

/// [`FILE`]: what was measured, and of which source.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Measured {
    /// SHA-256 of `generated/src/<design>.rs` as measured.
    pub source_sha256: String,
    /// By observer kind, as `report.json` names them (`"map"`, `"corrected"`, `"ekf_started"`,
    /// `"ekf"`).
    pub observers: BTreeMap<String, OnTarget>,
}

/// SHA-256 of a generated source, in hex.
pub fn source_hash(source: &str) -> String {
    sha2::Sha256::digest(source.as_bytes())
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The figures in `folder`'s [`FILE`] when they were measured on `source`; none otherwise (no file,
/// an unreadable one, or another source).
pub fn recorded(folder: &Path, source: &str) -> BTreeMap<String, OnTarget> {
    std::fs::read_to_string(folder.join(FILE))
        .ok()
        .and_then(|text| serde_json::from_str::<Measured>(&text).ok())
        .filter(|m| m.source_sha256 == source_hash(source))
        .map(|m| m.observers)
        .unwrap_or_default()
}

/// Writes `measured` to `folder`'s [`FILE`] and sets `observers[].on_target` of `folder`'s
/// `report.json` (when there is one) by kind.
pub fn record(folder: &Path, measured: &Measured) -> std::io::Result<()> {
    std::fs::create_dir_all(folder)?;
    let text = serde_json::to_string_pretty(measured).map_err(std::io::Error::other)?;
    crate::output::write_atomically(&folder.join(FILE), (text + "\n").as_bytes())?;
    let report = folder.join("report.json");
    let Ok(text) = std::fs::read_to_string(&report) else {
        return Ok(());
    };
    let mut json: serde_json::Value = serde_json::from_str(&text).map_err(std::io::Error::other)?;
    if let Some(observers) = json.get_mut("observers").and_then(|o| o.as_array_mut()) {
        for observer in observers {
            let kind = observer
                .get("kind")
                .and_then(|k| k.as_str())
                .unwrap_or_default()
                .to_owned();
            let value = measured
                .observers
                .get(&kind)
                .map(serde_json::to_value)
                .transpose()
                .map_err(std::io::Error::other)?;
            observer["on_target"] = value.unwrap_or(serde_json::Value::Null);
        }
    }
    let text = serde_json::to_string_pretty(&json).map_err(std::io::Error::other)?;
    crate::output::write_atomically(&report, (text + "\n").as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Measured {
        Measured {
            source_sha256: source_hash("fn a() {}"),
            observers: BTreeMap::from([(
                "ekf".to_owned(),
                OnTarget {
                    instructions_median: 241,
                    instructions_max: 241,
                    start_up_instructions_max: Some(336),
                    start_up_samples: Some(10),
                    divisions: 1,
                    flash_bytes: 900,
                    ram_bytes: 20,
                    stack_bytes: 200,
                },
            )]),
        }
    }

    #[test]
    fn figures_come_back_only_for_the_source_measured() {
        let dir = std::env::temp_dir().join(format!("on-target-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("report.json"),
            r#"{"observers": [{"kind": "map", "on_target": null}, {"kind": "ekf", "on_target": null}]}"#,
        )
        .unwrap();
        record(&dir, &sample()).unwrap();
        assert_eq!(recorded(&dir, "fn a() {}"), sample().observers);
        assert!(recorded(&dir, "fn a() { }").is_empty(), "another source");
        let report: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
        assert_eq!(report["observers"][0]["on_target"], serde_json::Value::Null);
        assert_eq!(report["observers"][1]["on_target"]["instructions_median"], 241);
        assert_eq!(report["observers"][1]["on_target"]["start_up_instructions_max"], 336);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn figures_recorded_before_the_start_up_was_measured_still_read() {
        let dir = std::env::temp_dir().join(format!("on-target-old-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let old = format!(
            r#"{{"source_sha256": "{}", "observers": {{"map": {{"instructions_median": 126, "instructions_max": 126,
            "divisions": 0, "flash_bytes": 2428, "ram_bytes": 88, "stack_bytes": 48}}}}}}"#,
            source_hash("fn a() {}")
        );
        std::fs::write(dir.join(FILE), old).unwrap();
        let figures = recorded(&dir, "fn a() {}");
        assert_eq!(figures["map"].instructions_max, 126);
        assert_eq!(figures["map"].start_up_instructions_max, None);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
