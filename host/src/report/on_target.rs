//! The emulated chip's figures for a design's observers, as `report.json` carries them.
//!
//! `gen` cannot measure them (that needs the generated crate built for the target, and QEMU):
//! `cargo run -p integration-tests --bin on-target-report` measures every shipped design and writes
//! [`FILE`] beside its report, keyed by the SHA-256 of the generated source it measured, and fills
//! the report's `observers[].on_target`. `gen` fills them in again from that file while the
//! generated source it writes is the one measured; after a change they are `null` until measured.
//! A standalone crate (`gen --spec`) is measured the same way with `on-target-report -- --crate
//! DIR`, which records beside the crate's report.
//!
//! `report.md` shows the figures in a [`section`] between [`BEGIN`] and [`END`]: [`record`] rewrites
//! that section (and `report.html`) as `gen` would write it with the figures, so the report reads the
//! same whether the figures came before or after it.

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};

/// The file beside `report.json`.
pub const FILE: &str = "on_target.json";

/// The clock the section states a sample's time at, in MHz: a common Cortex-M4F top speed.
pub const CLOCK_MHZ: f64 = 80.0;

/// One observer's cost on the emulated Cortex-M4F, per sample.
///
/// The start-up is every sample of the recorded sequence up to and including the estimate that
/// ends it: the samples before the first estimate, the first estimate, and the estimates after it
/// that take a follower's start-up path (`Follower::START_UP`; none for the map and the EKF). The
/// steady state is every accepted sample after it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct OnTarget {
    /// Median instructions of a steady sample (`push` + estimate).
    pub instructions_median: u64,
    /// Largest instructions of a steady sample.
    pub instructions_max: u64,
    /// Median estimated cycles of a steady sample: each executed instruction's cycles by the core's
    /// published timing (zero wait states; `integration-tests`' `on_target/timing.rs`); `None` in
    /// figures recorded before cycles were estimated.
    #[serde(default)]
    pub cycles_median: Option<u64>,
    /// Largest estimated cycles of a steady sample; `None` as above.
    #[serde(default)]
    pub cycles_max: Option<u64>,
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
    /// Largest `|chip − host f64|` over the recorded sequence's estimates (target units): the
    /// chip's `f32` against the host library's `f64` on the same samples; `None` in figures
    /// recorded before it was.
    #[serde(default)]
    pub largest_difference: Option<f64>,
}

/// [`FILE`]: what was measured, and of which source.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Measured {
    /// SHA-256 of `generated/src/<design>.rs` as measured.
    pub source_sha256: String,
    /// By observer kind, as `report.json` names them (`"map"`, `"corrected"`, `"ekf_map"`,
    /// `"ekf_restart"`, `"ekf_box"`).
    pub observers: BTreeMap<String, OnTarget>,
}

/// SHA-256 of a generated source, in hex.
pub fn source_hash(source: &str) -> String {
    crate::output::sha256_hex(source.as_bytes())
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

/// Marks the start of the figures' [`section`] in `report.md` (and a crate's README).
pub const BEGIN: &str = "<!-- on-target:begin -->";
/// Marks its end.
pub const END: &str = "<!-- on-target:end -->";

/// The figures as `report.md` shows them, by kind (as [`Measured::observers`]), between [`BEGIN`]
/// and [`END`]; with none, how to measure them.
pub fn section(observers: &BTreeMap<String, OnTarget>) -> String {
    let mut s = format!("{BEGIN}\n");
    if observers.is_empty() {
        s.push_str(
            "Not measured for this generated source yet. From the checkout: `cargo run -p integration-tests --bin on-target-report` \
             (a standalone crate: `cargo run -p integration-tests --bin on-target-report -- --crate <its folder>`).\n",
        );
    } else {
        s.push_str(
            "On the emulated Cortex-M4F (QEMU `mps2-an386`), over the design's recorded sequence: instructions executed by `push` + `estimate` \
             per sample, the cycles they take by the Cortex-M4's published timing (zero wait states, a taken branch 3 cycles) and that time at 80 MHz, \
             the start-up up to the estimate that ends it, flash and RAM added to a program, \
             and the largest difference between the chip's `f32` estimates and the host library's `f64` ones.\n\n\
             | observer | instructions per sample, steady (median / max) | estimated cycles, steady (median / max) | µs per sample at 80 MHz (median) | start-up: samples, max instructions | VDIV + VSQRT per sample (max) | stack bytes | flash bytes | RAM bytes | max \\|chip − host f64\\| |\n\
             |---|---|---|---|---|---|---|---|---|---|\n",
        );
        for (kind, api) in crate::observers::kind::REGISTRY
            .iter()
            .map(|k| (k.kind.name(), k.measured_as))
        {
            let Some(o) = observers.get(kind) else { continue };
            let start_up = match (o.start_up_samples, o.start_up_instructions_max) {
                (Some(samples), Some(max)) => format!("{samples}, {max}"),
                _ => "not measured".to_owned(),
            };
            let largest = o
                .largest_difference
                .map_or("not measured".to_owned(), |d| format!("{d:.1e}"));
            let (cycles, time) = match (o.cycles_median, o.cycles_max) {
                (Some(median), Some(max)) => (format!("{median} / {max}"), format!("{:.2}", median as f64 / CLOCK_MHZ)),
                _ => ("not estimated".to_owned(), "—".to_owned()),
            };
            s.push_str(&format!(
                "| {api} | {} / {} | {cycles} | {time} | {start_up} | {} | {} | {} | {} | {largest} |\n",
                o.instructions_median, o.instructions_max, o.divisions, o.stack_bytes, o.flash_bytes, o.ram_bytes
            ));
        }
    }
    s.push_str(END);
    s.push('\n');
    s
}

/// `text` with its section (from [`BEGIN`] to the line of [`END`]) replaced by `section`; `None`
/// when it has no section.
pub fn splice(text: &str, section: &str) -> Option<String> {
    let start = text.find(BEGIN)?;
    let end = start + text[start..].find(END)? + END.len();
    let end = end + usize::from(text[end..].starts_with('\n'));
    Some(format!("{}{section}{}", &text[..start], &text[end..]))
}

/// Writes `measured` to `folder`'s [`FILE`], sets `observers[].on_target` of `folder`'s
/// `report.json` (when there is one) by kind, and rewrites the [`section`] of its `report.md` and
/// `report.html`.
pub fn record(folder: &Path, measured: &Measured) -> std::io::Result<()> {
    std::fs::create_dir_all(folder)?;
    let text = serde_json::to_string_pretty(measured).map_err(std::io::Error::other)?;
    crate::output::write_atomically(&folder.join(FILE), (text + "\n").as_bytes())?;
    let report = folder.join("report.json");
    if let Ok(text) = std::fs::read_to_string(&report) {
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
        crate::output::write_atomically(&report, (text + "\n").as_bytes())?;
    }
    let markdown = folder.join("report.md");
    if let Some(spliced) = std::fs::read_to_string(&markdown)
        .ok()
        .and_then(|text| splice(&text, &section(&measured.observers)))
    {
        super::write_markdown(folder, &spliced)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Measured {
        Measured {
            source_sha256: source_hash("fn a() {}"),
            observers: BTreeMap::from([(
                "ekf_box".to_owned(),
                OnTarget {
                    instructions_median: 241,
                    instructions_max: 241,
                    cycles_median: Some(400),
                    cycles_max: Some(404),
                    start_up_instructions_max: Some(336),
                    start_up_samples: Some(10),
                    divisions: 1,
                    flash_bytes: 900,
                    ram_bytes: 20,
                    stack_bytes: 200,
                    largest_difference: Some(3.5e-6),
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
            r#"{"observers": [{"kind": "map", "on_target": null}, {"kind": "ekf_box", "on_target": null}]}"#,
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
    fn the_section_is_replaced_and_nothing_else() {
        let before = format!("# r\n\ntext\n{}\nafter\n", section(&BTreeMap::new()));
        assert!(before.contains("Not measured"));
        let measured = section(&sample().observers);
        let after = splice(&before, &measured).unwrap();
        assert_eq!(after, format!("# r\n\ntext\n{measured}\nafter\n"));
        assert!(
            after.contains("| `ekf()` | 241 / 241 | 400 / 404 | 5.00 | 10, 336 | 1 | 200 | 900 | 20 | 3.5e-6 |"),
            "{after}"
        );
        assert_eq!(
            splice(&after, &measured).unwrap(),
            after,
            "splicing twice changes nothing"
        );
        assert_eq!(splice("# r\nno section\n", &measured), None);
    }

    #[test]
    fn recording_rewrites_the_section_of_report_md_and_html() {
        let dir = std::env::temp_dir().join(format!("on-target-md-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("report.md"),
            format!("# design\n\n{}", section(&BTreeMap::new())),
        )
        .unwrap();
        record(&dir, &sample()).unwrap();
        let markdown = std::fs::read_to_string(dir.join("report.md")).unwrap();
        assert_eq!(markdown, format!("# design\n\n{}", section(&sample().observers)));
        let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
        assert!(html.contains("3.5e-6") && !html.contains("Not measured"), "{html}");
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
        assert_eq!(figures["map"].cycles_median, None);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
