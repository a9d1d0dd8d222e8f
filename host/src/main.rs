//! `host`: the command line of the design-time tool.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};

use host::{commands, fit, generate, spec};

/// Off-line moving-horizon observer design: simulate, fit r = Γ⁻¹(Lᵀ Z), validate, report, emit Rust.
#[derive(Parser)]
#[command(version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Trains designs and writes their observers and reports. Without --spec: every shipped spec into
    /// the project's generated/ crate. With --spec: each design as a standalone crate (--out).
    Gen {
        /// A design spec (TOML); repeat for several. Each becomes a standalone crate, unless
        /// --generated names a `generated` crate to add it to.
        #[arg(long = "spec", value_name = "FILE")]
        specs: Vec<PathBuf>,
        /// With --spec: the crate's folder (several specs: one sub-folder per design). Default:
        /// target/observers/<name>/ of the checkout.
        #[arg(long, value_name = "DIR", conflicts_with = "generated")]
        out: Option<PathBuf>,
        /// With --spec: the `firmware` runtime the crate depends on, by path. Default: the checkout's
        /// firmware/.
        #[arg(long, value_name = "DIR", conflicts_with = "runtime_version")]
        runtime_path: Option<PathBuf>,
        /// With --spec: the `firmware` runtime by version requirement (for a registry that has it).
        #[arg(long, value_name = "VERSION")]
        runtime_version: Option<String>,
        /// Folder for reports, one sub-folder per design. Default: target/designs/ of the checkout
        /// (a standalone crate keeps its report in its report/ folder).
        #[arg(long, value_name = "DIR")]
        reports: Option<PathBuf>,
        /// The `generated` crate to write the observers into. Default (without --spec): generated/ of
        /// the checkout.
        #[arg(long, value_name = "DIR")]
        generated: Option<PathBuf>,
        /// Refuse (write nothing) when a design fails a quality gate, instead of warning.
        #[arg(long)]
        strict: bool,
        /// With --spec: replace files in the crate's folder that `gen` did not write (or that were
        /// changed since); without it such a file stops the run, named, before anything is fitted.
        #[arg(long, requires = "specs")]
        force: bool,
    },
    /// Runs a design's search over N, n_m and β (the spec's candidates, or with --auto the default
    /// ones) and prints the trade-off front; writes nothing.
    Search {
        #[command(flatten)]
        design: DesignChoice,
        /// Search every `[map]` field over its default candidates, whatever the spec gives.
        #[arg(long)]
        auto: bool,
    },
    /// Plots a recorded run and its estimates (what `estimate` wrote for it) as PNG and SVG: every
    /// target's estimate against its truth column when the input has one (`truth_<target>` or the
    /// target's name), refused samples and saturated estimates marked, then the outputs and inputs.
    Plot {
        /// The recorded run (CSV with a header), as given to `estimate`.
        #[arg(long, value_name = "FILE")]
        input: PathBuf,
        /// The estimates `estimate` wrote for it.
        #[arg(long, value_name = "FILE")]
        estimates: PathBuf,
        /// A shipped design, for its names and units: a panel per output and input. Without a design
        /// the input's other numeric columns share one panel.
        #[arg(long, conflicts_with = "spec")]
        design: Option<String>,
        /// A design spec file, instead of --design.
        #[arg(long, value_name = "FILE")]
        spec: Option<PathBuf>,
        /// Writes PREFIX.png and PREFIX.svg. Default: the estimates' path without its extension.
        #[arg(long, value_name = "PREFIX")]
        out: Option<PathBuf>,
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
    /// Estimates the targets of a design over recorded measurements with its observer.
    Estimate {
        #[command(flatten)]
        design: DesignChoice,
        /// CSV with a header, one row per sample; columns named after the outputs and inputs.
        #[arg(long, value_name = "FILE")]
        input: PathBuf,
        /// CSV to write: `time`, `run` (when the input has one), `status`, one column per target, then
        /// `saturated_<target>` per target (-1, 0, 1).
        #[arg(long, value_name = "FILE")]
        output: PathBuf,
        /// The observer: `auto` (default) is the design's `observer()`, the kind `gen` chose; `map`,
        /// `corrected`, `ekf_map` (the EKF started by the map), `ekf_box` (from the box centre) or
        /// `ekf_restart` (from the box centre, restarted by the map) ask for one.
        #[arg(long, value_enum, default_value = "auto")]
        kind: KindArg,
        /// The fitted design `gen` saved (design.json in its report folder). Default: the checkout's
        /// target/designs/<name>/ or target/observers/<name>/report/ when they hold this spec's; else
        /// the design is fitted for this call.
        #[arg(long, value_name = "FILE")]
        tables: Option<PathBuf>,
        /// `f64` (default): the host library, the reference the tables are certified against. `f32`:
        /// the firmware's code on the emitted tables, bit for bit what the chip computes.
        #[arg(long, value_enum, default_value = "f64")]
        precision: PrecisionArg,
    },
}

/// `--precision`.
#[derive(Clone, Copy, clap::ValueEnum)]
enum PrecisionArg {
    F64,
    F32,
}

/// `--kind`.
#[derive(Clone, Copy, clap::ValueEnum)]
enum KindArg {
    Auto,
    Map,
    Corrected,
    /// The EKF started by the map.
    #[value(name = "ekf_map")]
    EkfMap,
    /// The EKF from the centre of the state box.
    #[value(name = "ekf_box")]
    EkfBox,
    /// The EKF from the centre of the state box, restarted from the map when they disagree.
    #[value(name = "ekf_restart")]
    EkfRestart,
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

impl DesignChoice {
    fn load(&self) -> anyhow::Result<spec::Design> {
        if let Some(path) = &self.spec {
            return Ok(spec::load(path)?);
        }
        Ok(generate::shipped_design(self.design.as_deref().unwrap_or_default())?)
    }
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Gen {
            specs,
            out,
            runtime_path,
            runtime_version,
            reports,
            generated,
            strict,
            force,
        } => {
            if specs.is_empty() || generated.is_some() {
                gen(specs, reports, generated, strict)
            } else {
                gen_standalone(&specs, out, runtime_path, runtime_version, strict, force)
            }
        }
        Command::Search { design, auto } => search(&design, auto),
        Command::Plot {
            input,
            estimates,
            design,
            spec,
            out,
        } => plot(&input, &estimates, DesignChoice { design, spec }, out.as_deref()),
        Command::Simulate {
            design,
            x0,
            samples,
            seed,
            output,
        } => simulate(&design, x0, samples, seed, &output),
        Command::Estimate {
            design,
            input,
            output,
            kind,
            tables,
            precision,
        } => estimate(&design, &input, &output, kind, tables.as_deref(), precision),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {}", message(&error));
            ExitCode::FAILURE
        }
    }
}

/// The error and its causes, each said once: the tool's errors already quote their cause (an OS error
/// printed twice read `Not a directory (os error 20): Not a directory (os error 20)`).
fn message(error: &anyhow::Error) -> String {
    let mut text = error.to_string();
    for cause in error.chain().skip(1) {
        let cause = cause.to_string();
        if !text.contains(&cause) {
            text = format!("{text}: {cause}");
        }
    }
    text
}

/// A design's error, named by its spec unless the error names it already.
fn of_spec(spec: &std::path::Path, error: &generate::GenerateError) -> String {
    let (spec, error) = (spec.display().to_string(), error.to_string());
    if error.contains(&spec) {
        error
    } else {
        format!("{spec}: {error}")
    }
}

fn progress_bar(design: &spec::Design) -> ProgressBar {
    if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(fit::steps(design));
        bar.set_style(ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed} {msg}").expect("valid template"));
        bar
    } else {
        ProgressBar::hidden()
    }
}

/// `gen`: every spec through the library's job, a summary per design as it ends, then what was written
/// (nothing, if any design failed).
fn gen(specs: Vec<PathBuf>, reports: Option<PathBuf>, generated: Option<PathBuf>, strict: bool) -> anyhow::Result<()> {
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
    let outcomes = generate::run(&specs, &to, strict, progress_bar, |spec, prepared| match prepared {
        Ok(prepared) => print_summary(prepared),
        Err(error) => eprintln!("error: {}", of_spec(spec, error)),
    })?;
    for outcome in &outcomes {
        println!(
            "{}:\n  report: {}\n  figures: {} files in {}\n  observer: {} ({})",
            outcome.name,
            outcome.report_files[1].display(),
            outcome.figures.len(),
            outcome.folder.display(),
            outcome.observer.display(),
            if outcome.changed { "updated" } else { "unchanged" }
        );
    }
    Ok(())
}

/// `gen --spec`: every spec as a standalone crate.
fn gen_standalone(
    specs: &[PathBuf],
    out: Option<PathBuf>,
    runtime_path: Option<PathBuf>,
    runtime_version: Option<String>,
    strict: bool,
    force: bool,
) -> anyhow::Result<()> {
    use host::standalone::{Destination, Runtime};
    let checkout = generate::workspace_root();
    let runtime = match (runtime_path, runtime_version) {
        (_, Some(version)) => Runtime::Version(version),
        (Some(path), None) => Runtime::Path(std::path::absolute(&path)?),
        (None, None) => match &checkout {
            Ok(root) => Runtime::Path(root.join("firmware")),
            Err(_) => anyhow::bail!(
                "outside the tool's checkout the crate needs the `firmware` runtime\n  fix: pass --runtime-path <firmware crate folder> or --runtime-version <version>"
            ),
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
    let inside = host::standalone::publish::holds_current_directory(&to.out);
    let outcomes = host::standalone::run(specs, &to, strict, progress_bar, |spec, prepared| match prepared {
        Ok(prepared) => print_summary(prepared),
        Err(error) => eprintln!("error: {}", of_spec(spec, error)),
    })?;
    for outcome in &outcomes {
        println!(
            "{}:\n  crate: {} (cargo build --release --target thumbv7em-none-eabihf there)\n  report: {}\n  figures: {} files",
            outcome.name,
            outcome.folder.display(),
            outcome.report_files[1].display(),
            outcome.figures.len(),
        );
    }
    if inside {
        eprintln!(
            "note: the crate folder was replaced whole; a shell inside it still sees the old one until it changes directory (cd \"$PWD\")"
        );
    }
    Ok(())
}

/// What a user sees of one design once fitted: its settings and the report's table.
fn print_summary(prepared: &generate::Prepared) {
    let design = &prepared.emitted.design;
    println!(
        "{} — {}\n  n_E = {} learning windows, {} validation windows, N = {}, n_m = {}, β = {}, normalisation {:?}\n",
        design.name,
        design.description,
        prepared.learning_windows,
        prepared.validation_windows,
        design.map.horizon,
        design.map.nm,
        design.map.beta,
        design.map.normalisation
    );
    if let Some(search) = &prepared.emitted.search {
        print!("{}", host::search::summary(design, search));
    }
    println!("{}", prepared.table);
    for warning in &prepared.warnings {
        eprintln!("warning: {}: {warning}", design.name);
    }
}

fn search(choice: &DesignChoice, auto: bool) -> anyhow::Result<()> {
    let mut design = choice.load()?;
    if auto {
        design.search = Some(spec::Search::every_default());
    }
    let Some(search) = design.search.clone() else {
        anyhow::bail!(
            "{}: `map`: the spec fixes N, n_m and β, so there is nothing to search\n  fix: set `horizon`, `nm` or `beta` to \"auto\" or a list of candidates, or pass --auto",
            design.file.display()
        );
    };
    let bar = progress_bar(&design);
    let outcome = host::search::run(&design, &search, &bar)?;
    bar.finish_and_clear();
    print!("{}", host::search::summary(&design, &outcome));
    Ok(())
}

/// `plot`: the design is optional (names and units); the figure is written only when everything read.
fn plot(input: &Path, estimates: &Path, choice: DesignChoice, out: Option<&Path>) -> anyhow::Result<()> {
    let design = match (&choice.design, &choice.spec) {
        (None, None) => None,
        _ => Some(choice.load()?),
    };
    let files = host::report::recorded::plot(input, estimates, design.as_ref(), out)?;
    for file in files {
        println!("{}", file.display());
    }
    Ok(())
}

fn simulate(
    choice: &DesignChoice,
    x0: Option<Vec<f64>>,
    samples: Option<usize>,
    seed: Option<u64>,
    output: &Path,
) -> anyhow::Result<()> {
    let design = choice.load()?;
    commands::simulate(&design, &commands::Simulation { x0, samples, seed }, output)?;
    Ok(())
}

fn estimate(
    choice: &DesignChoice,
    input: &Path,
    output: &Path,
    kind: KindArg,
    tables: Option<&Path>,
    precision: PrecisionArg,
) -> anyhow::Result<()> {
    let design = choice.load()?;
    let kind = match kind {
        KindArg::Auto => spec::ObserverKind::Auto,
        KindArg::Map => spec::ObserverKind::Map,
        KindArg::Corrected => spec::ObserverKind::Corrected,
        KindArg::EkfMap => spec::ObserverKind::EkfMap,
        KindArg::EkfBox => spec::ObserverKind::EkfBox,
        KindArg::EkfRestart => spec::ObserverKind::EkfRestart,
    };
    let bar = progress_bar(&design);
    let how = commands::Estimation {
        kind,
        precision: match precision {
            PrecisionArg::F64 => host::recording::Precision::F64,
            PrecisionArg::F32 => host::recording::Precision::F32,
        },
        tables,
    };
    let provenance = commands::estimate(&design, input, output, how, &bar)?;
    bar.finish_and_clear();
    match provenance {
        commands::Provenance::Saved(path) => eprintln!("estimate: by the design saved in {}", path.display()),
        commands::Provenance::Fitted => {
            eprintln!("estimate: no saved design for this spec (`gen` saves one), so it was fitted for this call")
        }
    }
    Ok(())
}
