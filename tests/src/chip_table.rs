//! The project's table of on-target figures (`docs/chip.md`, between its markers): built from the
//! measurements, written by `on-target-report`, and compared by the on-target test with what it
//! measures, so that the page never shows figures the chip no longer gives.

use std::collections::BTreeMap;

use host::report::on_target::Measured;

use crate::on_target::{self, Figures, Kind, Measurements, ObserverKind};

/// The page that holds the table, relative to the workspace.
pub const PAGE: &str = "docs/chip.md";

/// Where the table starts and ends in [`PAGE`].
const MARKERS: (&str, &str) = ("<!-- on-target:begin -->\n", "<!-- on-target:end -->");

/// The table (Markdown) of every shipped design's observers in `all` (on the Cortex-M4F), and each
/// design's figures to record beside its report.
pub fn project_table(all: &Measurements) -> Result<(String, Vec<(String, Measured)>), String> {
    let clock = all.board.clock_mhz();
    let mut recorded = Vec::new();
    let mut table = format!(
        "| design | observer | targets | N | segments per target | instructions per sample, steady (min / median / max) | start-up: samples, max instructions | estimated cycles, steady (median / max) | µs per sample at {clock:.0} MHz (median) | first estimate | dot-product floor | VDIV + VSQRT per sample (max) | stack bytes | flash bytes | RAM bytes | max \\|target − host f64\\| |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
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
            let largest = largest_difference(name, kind, observer)?;
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
            Kind::Of(ObserverKind::EkfBox),
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
            let (_, cycles, cycles_max) = on_target::spread(&row.cycles.steady);
            let time = all.board.microseconds(cycles);
            let observer = format!("`{}`", kind.api());
            let chosen = if chosen == Some(kind) { " = `observer()`" } else { "" };
            let (horizon, segments, floor) = match kind {
                Kind::Of(ObserverKind::Map) => (
                    spec.map.horizon.to_string(),
                    segments.join(", "),
                    (2 * n_z * targets.len()).to_string(),
                ),
                // The filters from the box centre (a kind whose constants are one filter's) read no window.
                Kind::Of(k) if host::observers::kind::of(k).filter_code.is_some() => {
                    ("—".to_owned(), "—".to_owned(), "—".to_owned())
                }
                _ => (spec.map.horizon.to_string(), "—".to_owned(), "—".to_owned()),
            };
            table += &format!(
                "| `{name}` | {observer}{chosen} | {} | {horizon} | {segments} | {min} / {median} / {max} | {}, {} | {cycles} / {cycles_max} | {time:.2} | {} | {floor} | {} | {} | {} | {} | {} |\n",
                targets.join(", "),
                row.phases.start_up_samples,
                row.phases.start_up_max,
                row.phases.first_estimate,
                row.divisions,
                row.stack_bytes,
                row.flash_bytes,
                row.ram_bytes,
                largest_shown(row.largest),
            );
        }

        let source = std::fs::read_to_string(crate::workspace_root().join("generated/src").join(format!("{name}.rs")))
            .map_err(|e| e.to_string())?;
        let measured = Measured {
            source_sha256: host::report::on_target::source_hash(&source),
            observers: rows
                .iter()
                .map(|(kind, row)| (kind.name().to_owned(), row.on_target()))
                .collect(),
        };
        recorded.push((name.to_owned(), measured));
    }
    for (family, flash) in &all.family_flash_bytes {
        table += &format!("| family `{family}` | (its members' maps) | | | | | | | | | | | | {flash} | | |\n");
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
    let row = page
        .lines()
        .find(|l| l.starts_with(&format!("| `{name}` | `{}`", kind.api())))?;
    row.split(" | ").nth(5)?.split(" / ").nth(1)?.trim().parse().ok()
}

/// The largest `|chip − host f64|` of design `name`'s observer of `kind`: the map against the host
/// library, the others against the host's f64 mirror; NaN for the integer observer, whose only
/// truth is the host's run of the same integer code (bit for bit, checked by the on-target test).
fn largest_difference(name: &str, kind: Kind, observer: &on_target::ObserverMeasurement) -> Result<f64, String> {
    match kind {
        Kind::Of(ObserverKind::Map) => on_target::compare_with_library(name, observer),
        Kind::Fixed => Ok(f64::NAN),
        Kind::Of(ObserverKind::UkfBox) => on_target::compare_ukf_with_f64(name, observer),
        _ => on_target::compare_started_with_f64(name, observer),
    }
}

/// A largest difference as the tables show it (`—` where there is no f64 truth).
fn largest_shown(largest: f64) -> String {
    if largest.is_nan() {
        "— (bits of the host's `i32` run)".to_owned()
    } else {
        format!("{largest:.1e}")
    }
}

/// Where the Cortex-M0 table starts and ends in [`PAGE`].
const M0_MARKERS: (&str, &str) = ("<!-- m0-on-target:begin -->\n", "<!-- m0-on-target:end -->");

/// The Cortex-M0 table (Markdown) of every shipped design's observers in `all` (the map and the
/// EKF from the box centre in software floating point, the integer observer where a design has
/// one), each beside its median instructions on the Cortex-M4F (`m4f_median`: from the Cortex-M4F
/// table, [`rust_median`]).
pub fn m0_table(all: &Measurements, m4f_median: &dyn Fn(&str, Kind) -> Option<u64>) -> Result<String, String> {
    let clock = all.board.clock_mhz();
    let mut table = format!(
        "| design | observer | instructions per sample, steady (min / median / max) | start-up: samples, max instructions | estimated Cortex-M0+ cycles, steady (median / max) | µs per sample at {clock:.0} MHz (median) | Cortex-M4F instructions (median) | stack bytes | flash bytes | RAM bytes |\n|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for name in on_target::design_names() {
        let mut rows: BTreeMap<Kind, (Figures, Option<u64>)> = BTreeMap::new();
        let median = |figures: &Figures| on_target::spread(&figures.phases.steady).1;
        for (&kind, observer) in all.observers.get(name).into_iter().flatten() {
            // Bit for bit the host's f32 run (the on-target test checks it), as the Cortex-M4F's are:
            // its distance to f64 is the Cortex-M4F row's.
            let figures = Figures::of_observer(observer, f64::NAN)
                .map_err(|e| format!("{name} {} on the Cortex-M0: {e}", kind.api()))?;
            rows.insert(kind, (figures, m4f_median(name, kind)));
        }
        let filter = all
            .filters
            .get(name)
            .ok_or_else(|| format!("no EKF measured on the Cortex-M0 for {name}"))?;
        let figures =
            Figures::of_filter(filter, f64::NAN).map_err(|e| format!("{name} ekf() on the Cortex-M0: {e}"))?;
        rows.insert(
            Kind::Of(ObserverKind::EkfBox),
            (figures, m4f_median(name, Kind::Of(ObserverKind::EkfBox))),
        );
        let expected = on_target::m0_kinds(name);
        if !rows.keys().copied().eq(expected.iter().copied()) {
            return Err(format!(
                "{name}: measured {:?} on the Cortex-M0, the design has {expected:?}",
                rows.keys().collect::<Vec<_>>()
            ));
        }
        for (&kind, (row, on_m4f)) in &rows {
            let (min, _, max) = on_target::spread(&row.phases.steady);
            let (_, cycles, cycles_max) = on_target::spread(&row.cycles.steady);
            table += &format!(
                "| `{name}` | `{}` | {min} / {} / {max} | {}, {} | {cycles} / {cycles_max} | {:.2} | {} | {} | {} | {} |\n",
                kind.api(),
                median(row),
                row.phases.start_up_samples,
                row.phases.start_up_max,
                all.board.microseconds(cycles),
                on_m4f.map_or("—".to_owned(), |n| n.to_string()),
                row.stack_bytes,
                row.flash_bytes,
                row.ram_bytes,
            );
        }
    }
    Ok(table)
}

/// `page` with the Cortex-M0 table ([`m0_table`]) between its markers.
pub fn with_m0_table(page: &str, table: &str) -> Result<String, String> {
    let (begin, end) = M0_MARKERS;
    let (Some(start), Some(stop)) = (page.find(begin), page.find(end)) else {
        return Err(format!("{PAGE} has no Cortex-M0 on-target markers"));
    };
    Ok(format!("{}{begin}{table}{}", &page[..start], &page[stop..]))
}
