//! The project's table of on-target figures (`docs/chip.md`, between its markers): built from the
//! measurements, written by `on-target-report`, and compared by the on-target test with what it
//! measures, so that the page never shows figures the chip no longer gives.

use std::collections::BTreeMap;

use host::report::on_target::Measured;

use crate::on_target::{self, Figures, Kind, Measurements};

/// The page that holds the table, relative to the workspace.
pub const PAGE: &str = "docs/chip.md";

/// Where the table starts and ends in [`PAGE`].
const MARKERS: (&str, &str) = ("<!-- on-target:begin -->\n", "<!-- on-target:end -->");

/// The table (Markdown) of every shipped design's observers in `all`, and each design's figures to
/// record beside its report.
pub fn project_table(all: &Measurements) -> Result<(String, Vec<(String, Measured)>), String> {
    let mut recorded = Vec::new();
    let mut table = String::from(
        "| design | observer | targets | N | segments per target | instructions per sample, steady (min / median / max) | start-up: samples, max instructions | first estimate | dot-product floor | VDIV + VSQRT per sample (max) | stack bytes | flash bytes | RAM bytes | max \\|target − host f64\\| |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for name in on_target::design_names() {
        let spec = crate::shipped_specs()
            .into_iter()
            .find_map(|p| host::spec::load(&p).ok().filter(|d| d.name == name))
            .map(crate::settled)
            .ok_or_else(|| format!("no shipped spec for {name}"))?;
        let result = crate::build(&spec);
        let targets: Vec<&str> = spec.targets.iter().map(|t| t.name.as_str()).collect();
        let segments: Vec<String> = result
            .targets
            .iter()
            .map(|t| {
                t.fit.map.table.as_ref().map_or("none".to_owned(), |t| match t.starts {
                    None => t.segments.len().to_string(),
                    Some(_) => format!("{} searched", t.segments.len()),
                })
            })
            .collect();
        let n_z = spec.map.horizon * (spec.model.outputs.len() + spec.model.inputs.len());
        let chosen = on_target::chosen_kind(name);

        let mut rows: BTreeMap<Kind, Figures> = BTreeMap::new();
        for (&kind, observer) in all.observers.get(name).into_iter().flatten() {
            let largest = match kind {
                Kind::Map => on_target::compare_with_library(name, observer)?,
                _ => on_target::compare_started_with_f64(name, observer)?,
            };
            rows.insert(
                kind,
                Figures::of_observer(observer, largest).map_err(|e| format!("{name} {}: {e}", kind.api()))?,
            );
        }
        let filter = all
            .filters
            .get(name)
            .ok_or_else(|| format!("no EKF measured for {name}"))?;
        rows.insert(
            Kind::Ekf,
            Figures::of_filter(filter, on_target::compare_ekf_with_f64(name, filter)?)
                .map_err(|e| format!("{name} ekf(): {e}"))?,
        );
        let expected = on_target::kinds(name);
        if !rows.keys().copied().eq(expected.iter().copied()) {
            return Err(format!(
                "{name}: measured {:?}, the design has {expected:?}",
                rows.keys().collect::<Vec<_>>()
            ));
        }

        for (&kind, row) in &rows {
            let (min, median, max) = on_target::spread(&row.phases.steady);
            let observer = match kind {
                Kind::Map => "`map_observer()`",
                Kind::Corrected => "`CorrectedObserver`",
                Kind::StartedEkf => "`StartedEkfObserver`",
                Kind::RestartedEkf => "`RestartedEkfObserver`",
                Kind::Ekf => "`ekf()`",
                Kind::Mhe => "`MheObserver`",
            };
            let chosen = if chosen == Some(kind) { " = `observer()`" } else { "" };
            let (horizon, segments, floor) = match kind {
                Kind::Map => (
                    spec.map.horizon.to_string(),
                    segments.join(", "),
                    (2 * n_z * targets.len()).to_string(),
                ),
                Kind::Corrected | Kind::StartedEkf | Kind::RestartedEkf | Kind::Mhe => {
                    (spec.map.horizon.to_string(), "—".to_owned(), "—".to_owned())
                }
                Kind::Ekf => ("—".to_owned(), "—".to_owned(), "—".to_owned()),
            };
            table += &format!(
                "| `{name}` | {observer}{chosen} | {} | {horizon} | {segments} | {min} / {median} / {max} | {}, {} | {} | {floor} | {} | {} | {} | {} | {:.1e} |\n",
                targets.join(", "),
                row.phases.start_up_samples,
                row.phases.start_up_max,
                row.phases.first_estimate,
                row.divisions,
                row.stack_bytes,
                row.flash_bytes,
                row.ram_bytes,
                row.largest,
            );
        }

        let source = std::fs::read_to_string(crate::workspace_root().join("generated/src").join(format!("{name}.rs")))
            .map_err(|e| e.to_string())?;
        let measured = Measured {
            source_sha256: host::report::on_target::source_hash(&source),
            observers: rows
                .iter()
                .map(|(kind, row)| (kind.report_name().to_owned(), row.on_target()))
                .collect(),
        };
        recorded.push((name.to_owned(), measured));
    }
    for (family, flash) in &all.family_flash_bytes {
        table += &format!("| family `{family}` | (its members' maps) | | | | | | | | | | {flash} | | |\n");
    }
    Ok((table, recorded))
}

/// `page` with `table` between its markers.
pub fn with_table(page: &str, table: &str) -> Result<String, String> {
    let (begin, end) = MARKERS;
    let (Some(start), Some(stop)) = (page.find(begin), page.find(end)) else {
        return Err(format!("{PAGE} has no on-target markers"));
    };
    Ok(format!("{}{begin}{table}{}", &page[..start], &page[stop..]))
}

/// Where the C table starts and ends in [`PAGE`].
const C_MARKERS: (&str, &str) = ("<!-- c-on-target:begin -->\n", "<!-- c-on-target:end -->");

/// `page` with the C table (`on_target::c_table`) between its markers.
pub fn with_c_table(page: &str, table: &str) -> Result<String, String> {
    let (begin, end) = C_MARKERS;
    let (Some(start), Some(stop)) = (page.find(begin), page.find(end)) else {
        return Err(format!("{PAGE} has no C on-target markers"));
    };
    Ok(format!("{}{begin}{table}{}", &page[..start], &page[stop..]))
}

/// The C table as `page` shows it (between its markers).
pub fn c_table_of(page: &str) -> Option<&str> {
    let (begin, end) = C_MARKERS;
    let start = page.find(begin)? + begin.len();
    Some(&page[start..page.find(end)?])
}

/// The median instructions per steady sample of design `name`'s Rust observer of `kind`, as the
/// on-target table of `page` gives it.
pub fn rust_median(page: &str, name: &str, kind: Kind) -> Option<u64> {
    let observer = match kind {
        Kind::Map => "map_observer()",
        Kind::Ekf => "ekf()",
        Kind::Corrected => "CorrectedObserver",
        Kind::StartedEkf => "StartedEkfObserver",
        Kind::RestartedEkf => "RestartedEkfObserver",
        Kind::Mhe => "MheObserver",
    };
    let row = page
        .lines()
        .find(|l| l.starts_with(&format!("| `{name}` | `{observer}`")))?;
    row.split(" | ").nth(5)?.split(" / ").nth(1)?.trim().parse().ok()
}
