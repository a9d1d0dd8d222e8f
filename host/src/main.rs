//! `host`: the command line of the design-time tool.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};

use host::{pipeline, report, spec};

/// Off-line moving-horizon observer design: simulate, fit r = Γ⁻¹(Lᵀ Z), validate, report.
#[derive(Parser)]
#[command(version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Trains the maps of every design and writes its report (all shipped specs by default).
    Gen {
        /// A design spec (TOML); repeat for several. Default: every spec in host/specs/.
        #[arg(long = "spec", value_name = "FILE")]
        specs: Vec<PathBuf>,
        /// Folder for reports (one sub-folder per design).
        #[arg(long, value_name = "DIR", default_value_os_t = default_report_folder())]
        reports: PathBuf,
    },
}

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("host/ lives in the workspace")
        .to_owned()
}

fn default_report_folder() -> PathBuf {
    workspace_root().join("target").join("designs")
}

fn shipped_specs() -> std::io::Result<Vec<PathBuf>> {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("specs");
    let mut specs: Vec<PathBuf> = std::fs::read_dir(folder)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    specs.sort();
    Ok(specs)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Gen { specs, reports } => gen(specs, &reports),
    }
}

fn gen(specs: Vec<PathBuf>, reports: &Path) -> ExitCode {
    let specs = if specs.is_empty() {
        match shipped_specs() {
            Ok(specs) => specs,
            Err(e) => {
                eprintln!("error: cannot list the shipped specs in host/specs: {e}");
                return ExitCode::FAILURE;
            }
        }
    } else {
        specs
    };
    let mut failures = 0;
    for path in &specs {
        if let Err(message) = gen_one(path, reports) {
            eprintln!("error: {message}");
            failures += 1;
        }
    }
    if failures > 0 {
        eprintln!(
            "{failures} of {} design(s) failed; nothing was written for them",
            specs.len()
        );
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

fn gen_one(path: &Path, reports: &Path) -> Result<(), String> {
    let design = spec::load(path).map_err(|e| e.to_string())?;
    let progress = if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(pipeline::steps(&design));
        bar.set_style(ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed} {msg}").expect("valid template"));
        bar
    } else {
        ProgressBar::hidden()
    };
    let result = pipeline::run(&design, &progress).map_err(|e| e.to_string())?;
    progress.finish_and_clear();
    let report = report::report(&design, &result);
    let folder = reports.join(&design.name);
    let written =
        report::write(&report, &folder).map_err(|e| format!("{}: cannot write the report: {e}", folder.display()))?;
    println!(
        "{} — {}\n  n_E = {} learning windows, {} validation windows, N = {}, n_m = {}, β = {}, normalisation {:?}\n",
        design.name,
        design.description,
        report.learning.windows,
        report.validation.windows,
        design.map.horizon,
        design.map.nm,
        design.map.beta,
        design.map.normalisation
    );
    print!("{}", report::table(&report));
    println!("\n  report: {}\n", written[1].display());
    Ok(())
}
