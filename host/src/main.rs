//! `host`: the command line of the design-time tool.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use rand::SeedableRng;

use host::{data, emit, output, pipeline, plots, recording, report, spec};

/// Off-line moving-horizon observer design: simulate, fit r = Γ⁻¹(Lᵀ Z), validate, report, emit Rust.
#[derive(Parser)]
#[command(version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Trains every design, writes its report and its generated observer (all shipped specs by default).
    Gen {
        /// A design spec (TOML); repeat for several. Default: every spec in host/specs/.
        #[arg(long = "spec", value_name = "FILE")]
        specs: Vec<PathBuf>,
        /// Folder for reports (one sub-folder per design).
        #[arg(long, value_name = "DIR", default_value_os_t = workspace_root().join("target").join("designs"))]
        reports: PathBuf,
        /// The `generated` crate to write the observers into.
        #[arg(long, value_name = "DIR", default_value_os_t = workspace_root().join("generated"))]
        generated: PathBuf,
    },
    /// Simulates one run of a design (its `[scenario]` unless overridden) and writes it as CSV.
    Simulate {
        #[command(flatten)]
        design: DesignChoice,
        /// Initial state, comma separated in state order (default: the spec's scenario).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        x0: Option<Vec<f64>>,
        /// Samples (default: the spec's scenario).
        #[arg(long)]
        samples: Option<usize>,
        /// Seed of the noise and inputs (default: the spec's scenario).
        #[arg(long)]
        seed: Option<u64>,
        /// CSV file to write (time, states, outputs, inputs).
        #[arg(long, value_name = "FILE")]
        output: PathBuf,
    },
    /// Estimates the targets of a design over recorded measurements (the library maps, in f64).
    Estimate {
        #[command(flatten)]
        design: DesignChoice,
        /// CSV with a header, one row per sample; columns named after the outputs and inputs.
        #[arg(long, value_name = "FILE")]
        input: PathBuf,
        /// CSV to write: one column per target, then `saturated`.
        #[arg(long, value_name = "FILE")]
        output: PathBuf,
    },
}

/// Which design: a shipped one by name, or any spec file.
#[derive(Args)]
#[group(required = true, multiple = false)]
struct DesignChoice {
    /// Name of a design shipped in host/specs/.
    #[arg(long)]
    design: Option<String>,
    /// A design spec file.
    #[arg(long, value_name = "FILE")]
    spec: Option<PathBuf>,
}

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("host/ lives in the workspace")
        .to_owned()
}

fn shipped_specs() -> Result<Vec<PathBuf>, String> {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("specs");
    let entries = std::fs::read_dir(&folder).map_err(|e| format!("cannot list {}: {e}", folder.display()))?;
    let mut specs: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    specs.sort();
    Ok(specs)
}

impl DesignChoice {
    fn load(&self) -> Result<spec::Design, String> {
        if let Some(path) = &self.spec {
            return spec::load(path).map_err(|e| e.to_string());
        }
        let name = self.design.as_deref().unwrap_or_default();
        let mut known = Vec::new();
        for path in shipped_specs()? {
            let design = spec::load(&path).map_err(|e| e.to_string())?;
            if design.name == name {
                return Ok(design);
            }
            known.push(design.name);
        }
        Err(format!(
            "unknown design `{name}`; the shipped designs are: {} (or pass --spec FILE)",
            known.join(", ")
        ))
    }
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Gen {
            specs,
            reports,
            generated,
        } => gen(specs, &reports, &generated),
        Command::Simulate {
            design,
            x0,
            samples,
            seed,
            output,
        } => simulate(&design, x0, samples, seed, &output),
        Command::Estimate { design, input, output } => estimate(&design, &input, &output),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn progress_bar(design: &spec::Design) -> ProgressBar {
    if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(pipeline::steps(design));
        bar.set_style(ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed} {msg}").expect("valid template"));
        bar
    } else {
        ProgressBar::hidden()
    }
}

fn gen(specs: Vec<PathBuf>, reports: &Path, generated: &Path) -> Result<(), String> {
    let specs = if specs.is_empty() { shipped_specs()? } else { specs };
    let sources = generated.join("src");
    std::fs::create_dir_all(&sources).map_err(|e| format!("cannot create {}: {e}", sources.display()))?;
    let mut failures = 0;
    for path in &specs {
        if let Err(message) = gen_one(path, reports, generated) {
            eprintln!("error: {message}");
            failures += 1;
        }
    }
    // lib.rs declares every design file present, old ones included: nothing written before is lost.
    let mut designs: Vec<String> = std::fs::read_dir(&sources)
        .map_err(|e| format!("cannot list {}: {e}", sources.display()))?
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|f| f.strip_suffix(".rs").map(str::to_owned))
        .filter(|f| f != "lib")
        .collect();
    designs.sort();
    // Families are known from the specs: the shipped ones and those given here (which take precedence).
    let mut known: Vec<spec::Design> = Vec::new();
    for path in specs.iter().chain(&shipped_specs()?) {
        if let Ok(design) = spec::load(path) {
            if !known.iter().any(|d| d.name == design.name) {
                known.push(design);
            }
        }
    }
    let families = emit::families(&known, &designs)?;
    let lib = emit::lib_file(&designs, &families).map_err(|e| e.to_string())?;
    output::write_if_changed(&sources.join("lib.rs"), &lib).map_err(|e| format!("{}: {e}", sources.display()))?;
    if failures > 0 {
        return Err(format!(
            "{failures} of {} design(s) failed; nothing was written for them",
            specs.len()
        ));
    }
    Ok(())
}

fn gen_one(path: &Path, reports: &Path, generated: &Path) -> Result<(), String> {
    let design = spec::load(path).map_err(|e| e.to_string())?;
    let progress = progress_bar(&design);
    let result = pipeline::run(&design, &progress).map_err(|e| e.to_string())?;
    progress.finish_and_clear();
    let source = emit::design_file(&design, &result, &emit::portable_spec_path(path, &workspace_root()))
        .map_err(|e| format!("{}: cannot emit design `{}`: {e}", path.display(), design.name))?;
    let report = report::report(&design, &result);
    let folder = reports.join(&design.name);
    let written =
        report::write(&report, &folder).map_err(|e| format!("{}: cannot write the report: {e}", folder.display()))?;
    let figures = plots::draw(&design, &result, &folder).map_err(|e| format!("cannot draw the figures: {e}"))?;
    let target = generated.join("src").join(format!("{}.rs", design.name));
    let changed = output::write_if_changed(&target, &source).map_err(|e| format!("{}: {e}", target.display()))?;
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
    println!(
        "\n  report: {}\n  figures: {} files in {}\n  observer: {} ({})\n",
        written[1].display(),
        figures.len(),
        folder.display(),
        target.display(),
        if changed { "updated" } else { "unchanged" }
    );
    Ok(())
}

fn simulate(
    choice: &DesignChoice,
    x0: Option<Vec<f64>>,
    samples: Option<usize>,
    seed: Option<u64>,
    output: &Path,
) -> Result<(), String> {
    let design = choice.load()?;
    let scenario = design.scenario.clone();
    let missing = |what: &str| format!("design `{}` has no `[scenario]`: give --{what}", design.name);
    let x0 = x0
        .or_else(|| scenario.as_ref().map(|s| s.x0.clone()))
        .ok_or_else(|| missing("x0"))?;
    if x0.len() != design.model.states.len() {
        return Err(format!(
            "--x0 has {} values; the states are {}",
            x0.len(),
            design.model.states.join(", ")
        ));
    }
    let samples = samples
        .or(scenario.as_ref().map(|s| s.samples))
        .ok_or_else(|| missing("samples"))?;
    let seed = seed
        .or(scenario.as_ref().map(|s| s.seed))
        .ok_or_else(|| missing("seed"))?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let run = data::simulate_run(&design, &x0, samples, &mut rng, "scenario").map_err(|e| e.to_string())?;
    output::write_atomically(output, recording::run_csv(&design, &run).as_bytes())
        .map_err(|e| format!("{}: {e}", output.display()))
}

fn estimate(choice: &DesignChoice, input: &Path, output: &Path) -> Result<(), String> {
    let design = choice.load()?;
    let rows = recording::read(&design, input).map_err(|e| e.to_string())?;
    let result = pipeline::run(&design, &progress_bar(&design)).map_err(|e| e.to_string())?;
    let maps: Vec<_> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
    let estimates = recording::estimate(&maps, design.map.horizon, &rows);
    let names: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
    output::write_atomically(output, recording::estimates_csv(&names, &estimates).as_bytes())
        .map_err(|e| format!("{}: {e}", output.display()))
}
