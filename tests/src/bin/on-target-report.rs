//! Measures every generated observer, and every design's extended Kalman filter beside it, on the
//! emulated Cortex-M4F, rewrites the table in the README between `<!-- on-target:begin -->` and
//! `<!-- on-target:end -->`, and records each design's figures beside its report
//! (`target/designs/<design>/on_target.json`, and `report.json`'s `observers[].on_target`):
//!
//! ```sh
//! cargo run -p integration-tests --bin on-target-report
//! ```

use std::process::ExitCode;

use host::report::on_target::{Measured, OnTarget};
use integration_tests::on_target;
use integration_tests::workspace_root;

fn main() -> ExitCode {
    match run() {
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
    let measured = &all.designs;
    let filters = on_target::measure_ekf().map_err(|e| e.to_string())?;
    let mut table = String::from(
        "| design | targets | N | segments per target | instructions per push + estimate; EKF: push + targets (min / median / max) | first estimate | dot-product floor | VDIV + VSQRT per sample (max) | stack bytes | flash bytes | RAM bytes | max \\|target − host\\| |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for (name, design) in measured {
        let spec = integration_tests::shipped_specs()
            .into_iter()
            .find_map(|p| host::spec::load(&p).ok().filter(|d| &d.name == name))
            .ok_or_else(|| format!("no shipped spec for {name}"))?;
        let result = integration_tests::build(&spec);
        let largest = on_target::compare_with_library(name, design)?;
        let steady = design.steady_instructions();
        let (min, median, max) = on_target::spread(&steady);
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
        table += &format!(
            "| `{name}` | {} | {} | {} | {min} / {median} / {max} | {} | {} | {} | {} | {} | {} | {largest:.1e} |\n",
            targets.join(", "),
            spec.map.horizon,
            segments.join(", "),
            design.first_estimate_instructions().unwrap_or(0),
            2 * n_z * targets.len(),
            design.divisions.iter().max().unwrap_or(&0),
            design.stack_bytes,
            design.flash_bytes,
            design.observer_bytes + design.static_ram_bytes as usize,
        );
        // The design's extended Kalman filter: `push` + `targets` per sample, over the accepted
        // samples (a refused one only predicts); compared with the same filter in f64 on the host.
        let filter = filters.get(name).ok_or_else(|| format!("no EKF measured for {name}"))?;
        let largest = on_target::compare_ekf_with_f64(name, filter)?;
        let (min, median, max) = on_target::spread(&filter.accepted_instructions());
        let source = std::fs::read_to_string(workspace_root().join("generated/src").join(format!("{name}.rs")))
            .map_err(|e| e.to_string())?;
        let (_, map_median, map_max) = on_target::spread(&steady);
        let measured = Measured {
            source_sha256: host::report::on_target::source_hash(&source),
            observers: [
                (
                    "map".to_owned(),
                    OnTarget {
                        instructions_median: map_median,
                        instructions_max: map_max,
                        divisions: design.divisions.iter().copied().max().unwrap_or(0),
                        flash_bytes: design.flash_bytes,
                        ram_bytes: design.observer_bytes as u64 + design.static_ram_bytes,
                        stack_bytes: design.stack_bytes as u64,
                    },
                ),
                (
                    "ekf".to_owned(),
                    OnTarget {
                        instructions_median: median,
                        instructions_max: max,
                        divisions: filter.divisions.iter().copied().max().unwrap_or(0),
                        flash_bytes: filter.flash_bytes,
                        ram_bytes: filter.filter_bytes as u64 + filter.static_ram_bytes,
                        stack_bytes: filter.stack_bytes as u64,
                    },
                ),
            ]
            .into(),
        };
        // Beside the design's report, which `gen` wrote there (and fills in again while the source
        // is the one measured).
        host::report::on_target::record(&workspace_root().join("target/designs").join(name), &measured)
            .map_err(|e| format!("{name}: cannot record the on-target figures: {e}"))?;
        table += &format!(
            "| `{name}` EKF | {} | — | — | {min} / {median} / {max} | — | — | {} | {} | {} | {} | {largest:.1e} |\n",
            targets.join(", "),
            filter.divisions.iter().max().unwrap_or(&0),
            filter.stack_bytes,
            filter.flash_bytes,
            filter.filter_bytes + filter.static_ram_bytes as usize,
        );
    }
    for (family, flash) in &all.family_flash_bytes {
        table += &format!("| family `{family}` | (its members') | | | | | | | | {flash} | | |\n");
    }
    let readme_path = workspace_root().join("README.md");
    let readme = std::fs::read_to_string(&readme_path).map_err(|e| e.to_string())?;
    let (begin, end) = ("<!-- on-target:begin -->\n", "<!-- on-target:end -->");
    let (Some(start), Some(stop)) = (readme.find(begin), readme.find(end)) else {
        return Err("README.md has no on-target markers".into());
    };
    let updated = format!("{}{begin}{table}{}", &readme[..start], &readme[stop..]);
    host::output::write_if_changed(&readme_path, &updated).map_err(|e| e.to_string())?;
    Ok(table)
}
