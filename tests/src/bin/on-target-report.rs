//! Measures every observer of every generated design on the emulated Cortex-M4F (the map, the
//! observers the map starts and the EKF from the box centre, whichever the design has), rewrites
//! the table in `docs/chip.md` between `<!-- on-target:begin -->` and `<!-- on-target:end -->`, and
//! records each design's figures beside its report (`target/designs/<design>/on_target.json`, and
//! `report.json`'s `observers[].on_target`, and the section of `report.md` that shows them):
//!
//! ```sh
//! cargo run -p integration-tests --bin on-target-report
//! ```
//!
//! With `--crate DIR`, the same for the standalone crate `mho gen --spec` wrote in `DIR` (see
//! `integration_tests::on_target::standalone`): its figures go beside its report (`DIR/report/`) and
//! into its `README.md`, never into the project's docs.
//!
//! The map and the observers it starts run one after the other in one program per design; before
//! anything is written, each of them is also built and run alone, and its counts must be the same.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::ExitCode;

use host::report::on_target::Measured;
use integration_tests::on_target::{self, Figures, Kind};
use integration_tests::workspace_root;

const USAGE: &str = "usage: on-target-report [--crate DIR]

Measures the observers on the emulated Cortex-M4F (QEMU mps2-an386) and records the figures:
  (no argument)   every shipped design: beside its report (target/designs/<name>/) and in docs/chip.md
  --crate DIR     the standalone crate `mho gen --spec FILE --out DIR` wrote: in DIR/report/ and DIR/README.md
";

fn main() -> ExitCode {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let result = match arguments.iter().map(String::as_str).collect::<Vec<_>>().as_slice() {
        [] => run(),
        ["--crate", folder] => on_target::standalone::measure_crate(&PathBuf::from(folder)),
        ["-h" | "--help"] => {
            print!("{USAGE}");
            return ExitCode::SUCCESS;
        }
        _ => Err(format!("unexpected arguments {arguments:?}\n\n{USAGE}")),
    };
    match result {
        Ok(table) => {
            print!("{table}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<String, String> {
    let all = on_target::measure().map_err(|e| e.to_string())?;
    let program = on_target::Program::project();
    on_target::same_alone(&program, &all)?;
    let mut table = String::from(
        "| design | observer | targets | N | segments per target | instructions per sample, steady (min / median / max) | start-up: samples, max instructions | first estimate | dot-product floor | VDIV + VSQRT per sample (max) | stack bytes | flash bytes | RAM bytes | max \\|target − host f64\\| |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for name in on_target::design_names() {
        let spec = integration_tests::shipped_specs()
            .into_iter()
            .find_map(|p| host::spec::load(&p).ok().filter(|d| d.name == name))
            .map(integration_tests::settled)
            .ok_or_else(|| format!("no shipped spec for {name}"))?;
        let result = integration_tests::build(&spec);
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
            };
            let chosen = if chosen == Some(kind) { " = `observer()`" } else { "" };
            let (horizon, segments, floor) = match kind {
                Kind::Map => (
                    spec.map.horizon.to_string(),
                    segments.join(", "),
                    (2 * n_z * targets.len()).to_string(),
                ),
                Kind::Corrected | Kind::StartedEkf | Kind::RestartedEkf => {
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

        let source = std::fs::read_to_string(workspace_root().join("generated/src").join(format!("{name}.rs")))
            .map_err(|e| e.to_string())?;
        let measured = Measured {
            source_sha256: host::report::on_target::source_hash(&source),
            observers: rows
                .iter()
                .map(|(kind, row)| (kind.report_name().to_owned(), row.on_target()))
                .collect(),
        };
        // Beside the design's report, which `gen` wrote there (and fills in again while the source
        // is the one measured).
        host::report::on_target::record(&workspace_root().join("target/designs").join(name), &measured)
            .map_err(|e| format!("{name}: cannot record the on-target figures: {e}"))?;
    }
    for (family, flash) in &all.family_flash_bytes {
        table += &format!("| family `{family}` | (its members' maps) | | | | | | | | | | {flash} | | |\n");
    }
    // The project's page of on-target figures, between its markers.
    let chip_path = workspace_root().join("docs/chip.md");
    let chip = std::fs::read_to_string(&chip_path).map_err(|e| format!("{}: {e}", chip_path.display()))?;
    let (begin, end) = ("<!-- on-target:begin -->\n", "<!-- on-target:end -->");
    let (Some(start), Some(stop)) = (chip.find(begin), chip.find(end)) else {
        return Err("docs/chip.md has no on-target markers".into());
    };
    let updated = format!("{}{begin}{table}{}", &chip[..start], &chip[stop..]);
    host::output::write_if_changed(&chip_path, &updated).map_err(|e| e.to_string())?;
    Ok(table)
}
