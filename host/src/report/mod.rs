//! The report of a design: `report.json` (everything, machine-readable), `report.md` (one table a
//! person reads) and the one-screen summary `gen` prints.

mod assemble;
mod draw;
pub mod filters;
pub mod fixed_filters;
pub mod fixed_point;
pub mod gates;
pub mod html;
mod lost;
mod markdown;
pub mod on_target;
pub mod plots;
pub mod recorded;
pub mod references;
pub mod runs;
pub mod scenarios;
mod schema;
mod sensitivity;
mod tables;
pub mod tuning_score;

use std::path::{Path, PathBuf};

pub use assemble::report;
pub use markdown::{markdown, relocate_figures};
pub use schema::{
    ChipModel, CorrectedTuning, DriftReport, EkfTuning, FiguresReport, FilterConstants, FixedFilterReport,
    LinearReport, MismatchReport, ObserverReport, Report, SetSummary, TargetReport, MISMATCH_PLANTS,
};
pub use tables::{observers_table, search_table, table, taps_table};

use crate::output::write_atomically;

/// The report as its two files' texts: `report.json` and `report.md`.
pub fn texts(report: &Report<'_>) -> (String, String) {
    let json = serde_json::to_string_pretty(report).expect("the report serialises: plain numbers and strings") + "\n";
    (json, markdown(report))
}

/// Writes `report.json`, `report.md` (from [`texts`]) and `report.html` (the Markdown for a browser,
/// [`html::page`]) into `folder`; returns their paths in that order.
pub fn write_texts((json, markdown): &(String, String), folder: &Path) -> std::io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(folder)?;
    let json_path = folder.join("report.json");
    write_atomically(&json_path, json.as_bytes())?;
    let mut paths = vec![json_path];
    paths.extend(write_markdown(folder, markdown)?);
    Ok(paths)
}

/// Writes `report.md` and `report.html` (the Markdown for a browser, [`html::page`], titled by its
/// first heading) into `folder`; returns their paths in that order.
pub fn write_markdown(folder: &Path, markdown: &str) -> std::io::Result<Vec<PathBuf>> {
    let paths = vec![folder.join("report.md"), folder.join("report.html")];
    let title = markdown
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("# "))
        .unwrap_or("report");
    write_atomically(&paths[0], markdown.as_bytes())?;
    write_atomically(&paths[1], html::page(title, markdown).as_bytes())?;
    Ok(paths)
}
