//! `gen`: fits designs into the project's `generated/` crate or as standalone crates, and says in a
//! few lines per design what came out (the tables stay in each report.md; `--verbose` prints them).

use std::path::PathBuf;

use super::args::GenArgs;
use crate::generate;

/// `gen`: without `--spec` (or with `--generated`) into a `generated` crate, else standalone crates.
pub fn run(args: GenArgs) -> anyhow::Result<()> {
    let GenArgs {
        specs,
        out,
        runtime_path,
        runtime_version,
        reports,
        generated,
        strict,
        force,
        verbose,
    } = args;
    if specs.is_empty() || generated.is_some() {
        into_generated(specs, reports, generated, strict, verbose)
    } else {
        standalone(&specs, out, runtime_path, runtime_version, strict, force, verbose)
    }
}

/// One progress bar per design on a terminal, drawn together: designs are prepared in parallel.
#[derive(Default)]
struct Bars(indicatif::MultiProgress);

impl Bars {
    /// A bar for `design` (hidden without a terminal).
    fn add(&self, design: &crate::spec::Design) -> indicatif::ProgressBar {
        let bar = super::progress_bar(design);
        if bar.is_hidden() {
            bar
        } else {
            self.0.add(bar)
        }
    }
}

/// Every spec through the library's job, a summary per design as it ends, then what was written
/// (nothing, if any design failed).
fn into_generated(
    specs: Vec<PathBuf>,
    reports: Option<PathBuf>,
    generated: Option<PathBuf>,
    strict: bool,
    verbose: bool,
) -> anyhow::Result<()> {
    let specs = if specs.is_empty() {
        generate::shipped_specs()?
    } else {
        specs
    };
    // The checkout is found from the current folder, at run time; only needed for the defaults.
    let in_checkout = |folder: &str| generate::workspace_root().map(|root| root.join(folder));
    let to = generate::Destinations {
        reports: match reports {
            Some(folder) => folder,
            None => in_checkout("target/designs")?,
        },
        generated: match generated {
            Some(folder) => folder,
            None => in_checkout("generated")?,
        },
    };
    eprintln!(
        "gen: {} spec(s); observers into {}, reports into {}",
        specs.len(),
        to.generated.display(),
        to.reports.display()
    );
    let bars = Bars::default();
    let outcomes = generate::run(
        &specs,
        &to,
        strict,
        |design| bars.add(design),
        |spec, prepared| match prepared {
            Ok(prepared) => print_summary(prepared, verbose),
            Err(error) => eprintln!("error: {}", super::of_spec(spec, error)),
        },
    )?;
    for outcome in &outcomes {
        println!(
            "{}: {} ({})",
            outcome.name,
            outcome.observer.display(),
            if outcome.changed { "updated" } else { "unchanged" },
        );
    }
    Ok(())
}

/// `gen --spec`: every spec as a standalone crate.
fn standalone(
    specs: &[PathBuf],
    out: Option<PathBuf>,
    runtime_path: Option<PathBuf>,
    runtime_version: Option<String>,
    strict: bool,
    force: bool,
    verbose: bool,
) -> anyhow::Result<()> {
    use crate::standalone::{Destination, Runtime};
    let checkout = generate::workspace_root();
    let runtime = match (runtime_path, runtime_version) {
        (_, Some(version)) => Runtime::Version(version),
        (Some(path), None) => Runtime::Path(std::path::absolute(&path)?),
        // In the checkout its firmware/; elsewhere the runtime the tool carries, written into the crate.
        (None, None) => match &checkout {
            Ok(root) => Runtime::Path(root.join("firmware")),
            Err(_) => Runtime::Embedded,
        },
    };
    let per_design = out.is_none() || specs.len() > 1;
    let out = match out {
        Some(out) => out,
        None => match &checkout {
            Ok(root) => root.join("target").join("observers"),
            Err(_) => PathBuf::from("observers"),
        },
    };
    let to = Destination {
        out: std::path::absolute(&out)?,
        per_design,
        runtime,
        force,
    };
    eprintln!(
        "gen: {} spec(s) as standalone crates in {}",
        specs.len(),
        to.out.display()
    );
    // A crate is replaced by a new folder (standalone::publish): a shell inside the old one would not see it.
    let inside = crate::standalone::publish::holds_current_directory(&to.out);
    let bars = Bars::default();
    let outcomes = crate::standalone::run(
        specs,
        &to,
        strict,
        |design| bars.add(design),
        |spec, prepared| match prepared {
            Ok(prepared) => print_summary(prepared, verbose),
            Err(error) => eprintln!("error: {}", super::of_spec(spec, error)),
        },
    )?;
    for outcome in &outcomes {
        println!(
            "{}: crate {} (cargo build --release --target thumbv7em-none-eabihf there)",
            outcome.name,
            outcome.folder.display(),
        );
        if let Some(why) = &outcome.in_place {
            eprintln!(
                "note: {}: {why}: the crate was written file by file (each file whole; a run killed while \
                 moving them can leave files of two runs, which the next gen replaces)",
                outcome.folder.display()
            );
        }
    }
    // A crate written file by file keeps its folder: a shell inside it sees the new files.
    if inside && outcomes.iter().any(|o| o.in_place.is_none()) {
        eprintln!(
            "note: the crate folder was replaced whole; a shell inside it still sees the old one until it changes directory (cd \"$PWD\")"
        );
    }
    Ok(())
}

/// What a user sees of one design once fitted: what it estimates, the observer `gen` chose with its
/// validation RMSE and predicted cost (the map's beside it), any warning, and where the full report
/// is. With `verbose`, the report's tables too.
fn print_summary(prepared: &generate::Prepared, verbose: bool) {
    let design = &prepared.emitted.design;
    let comparison = &prepared.emitted.comparison;
    let targets: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
    println!(
        "{}: {}",
        design.name,
        design.description.lines().next().unwrap_or_default()
    );
    let figures = |kind: &str| comparison.observers.iter().find(|o| o.kind == kind);
    let rmse = |kind: &str| {
        figures(kind).map_or(String::new(), |o| {
            targets
                .iter()
                .zip(&o.targets)
                .map(|(t, f)| format!("{t} {:.4}", f.rmse_validation))
                .collect::<Vec<_>>()
                .join(", ")
        })
    };
    let chosen = comparison.chosen.0.name();
    let chosen = if chosen == "auto" { "map" } else { chosen };
    let instructions = figures(chosen).map_or(0.0, |o| o.instructions);
    println!(
        "  observer: {chosen} (N = {}), ~{instructions:.0} instructions per sample; validation RMSE {}",
        design.map.horizon,
        rmse(chosen)
    );
    if chosen != "map" {
        println!("  the map alone: validation RMSE {}", rmse("map"));
    }
    for sentence in prepared.verdict.split("\n\n").map(str::trim).filter(|s| !s.is_empty()) {
        println!("  {sentence}");
    }
    for warning in &prepared.warnings {
        println!("  warning: {warning}");
    }
    println!("  report: {}", prepared.folder.join("report.md").display());
    if verbose {
        println!(
            "  n_E = {} learning windows, {} validation windows, N = {}, n_m = {}, β = {}, normalisation {:?}\n",
            prepared.learning_windows,
            prepared.validation_windows,
            design.map.horizon,
            design.map.nm,
            design.map.beta,
            design.map.normalisation
        );
        if let Some(search) = &prepared.emitted.search {
            print!("{}", crate::search::summary(design, search));
        }
        println!("{}", prepared.table);
    }
}
