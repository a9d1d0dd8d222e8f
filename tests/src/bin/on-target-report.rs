//! Measures every observer of every generated design on the emulated Cortex-M4F (the map, the
//! observers the map starts and the EKF from the box centre, whichever the design has) and the map
//! and the EKF on the emulated Cortex-M0, rewrites the table in `docs/chip.md` between
//! `<!-- on-target:begin -->` and `<!-- on-target:end -->` (the Cortex-M0's between
//! `<!-- m0-on-target:begin -->` and `<!-- m0-on-target:end -->`, and the C build of every observer,
//! `generated/c/`, between `<!-- c-on-target:begin -->` and `<!-- c-on-target:end -->`), and
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

use std::path::PathBuf;
use std::process::ExitCode;

use integration_tests::on_target;
use integration_tests::{chip_table, workspace_root};

const USAGE: &str = "usage: on-target-report [--crate DIR]

Measures the observers on the emulated Cortex-M4F (QEMU mps2-an386) and Cortex-M0 (QEMU microbit)
and records the figures:
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
    on_target::same_alone(&program, &all.m4f)?;
    let (table, recorded) = chip_table::project_table(&all.m4f)?;
    // Beside each design's report, which `gen` wrote there (and fills in again while the source is
    // the one measured).
    for (name, measured) in &recorded {
        host::report::on_target::record(&workspace_root().join("target/designs").join(name), measured)
            .map_err(|e| format!("{name}: cannot record the on-target figures: {e}"))?;
    }
    // The project's page of on-target figures, between its markers.
    let path = workspace_root().join(chip_table::PAGE);
    let page = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let page = chip_table::with_table(&page, &table)?;
    // The Cortex-M0's, beside the Cortex-M4F's medians as the page now gives them.
    let m0_table = chip_table::m0_table(&all.m0, &|name, kind| chip_table::rust_median(&page, name, kind))?;
    let page = chip_table::with_m0_table(&page, &m0_table)?;
    // The C build of every observer beside the Rust one, in the same page.
    let scratch = workspace_root().join("target/on-target-c");
    std::fs::create_dir_all(&scratch).map_err(|e| format!("{}: {e}", scratch.display()))?;
    let runs =
        on_target::run_shipped_on_board(&workspace_root().join("generated/c"), &scratch).map_err(|e| e.to_string())?;
    let c_table = on_target::c_table(&runs, &|name, kind| chip_table::rust_median(&page, name, kind))?;
    let page = chip_table::with_c_table(&page, &c_table)?;
    host::output::write_if_changed(&path, &page).map_err(|e| e.to_string())?;
    Ok(format!("{table}\n{m0_table}\n{c_table}"))
}
