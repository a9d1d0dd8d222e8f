//! The command line's words: subcommands and their options, as `--help` shows them (one example each).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use crate::spec::ObserverKind;

/// Off-line moving-horizon observers for microcontrollers: from a TOML spec of a plant, fits the
/// map r = Γ⁻¹(Lᵀ Z) of the last N samples, compares it with model-based observers, and writes a
/// no_std Rust crate (and a C library) for the chip.
#[derive(Parser)]
#[command(
    name = "mho",
    version,
    after_help = "Example: mho gen --spec my_plant.toml --out my-observer\nIn the checkout, `cargo run -p host --` runs it; `cargo install --path host` installs it."
)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Subcommand)]
pub enum Command {
    /// Fits designs and writes their observers and reports (the main job)
    Gen(GenArgs),
    /// Estimates a design's targets over a recording (CSV), as the chip would
    Estimate(EstimateArgs),
    /// Plots a recording and its estimates (PNG and SVG)
    Plot(PlotArgs),
    /// Simulates one run of a design and writes it as CSV
    Simulate(SimulateArgs),
    /// Searches a design's N, n_m and β and prints the trade-off front; writes nothing
    Search(SearchArgs),
}

/// `gen`.
#[derive(Args)]
#[command(
    long_about = "Fits designs and writes their observers and reports. Without --spec: every shipped spec into the \
                  project's generated/ crate. With --spec: each design as a standalone crate (--out), replaced whole.",
    after_help = "Example: mho gen --spec my_plant.toml --out my-observer"
)]
pub struct GenArgs {
    /// A design spec (TOML); repeat for several. Each becomes a standalone crate, unless
    /// --generated names a `generated` crate to add it to.
    #[arg(long = "spec", value_name = "FILE")]
    pub specs: Vec<PathBuf>,
    /// With --spec: the crate's folder (several specs: one sub-folder per design). Default:
    /// `target/observers/<name>/` of the checkout.
    #[arg(long, value_name = "DIR", conflicts_with = "generated")]
    pub out: Option<PathBuf>,
    /// With --spec: the `firmware` runtime the crate depends on, by path. Default: the checkout's
    /// firmware/; outside a checkout, the runtime mho carries, written into the crate's firmware/.
    #[arg(long, value_name = "DIR", conflicts_with = "runtime_version")]
    pub runtime_path: Option<PathBuf>,
    /// With --spec: the `firmware` runtime by version requirement (for a registry that has it).
    #[arg(long, value_name = "VERSION")]
    pub runtime_version: Option<String>,
    /// Folder for reports, one sub-folder per design. Default: target/designs/ of the checkout
    /// (a standalone crate keeps its report in its report/ folder).
    #[arg(long, value_name = "DIR")]
    pub reports: Option<PathBuf>,
    /// The `generated` crate to write the observers into. Default (without --spec): generated/ of
    /// the checkout.
    #[arg(long, value_name = "DIR")]
    pub generated: Option<PathBuf>,
    /// Refuse (write nothing) when a design fails a quality gate, instead of warning.
    #[arg(long)]
    pub strict: bool,
    /// With --spec: replace files in the crate's folder that `gen` did not write (or that were
    /// changed since); without it such a file stops the run, named, before anything is fitted.
    #[arg(long, requires = "specs")]
    pub force: bool,
    /// Print every design's tables (as in its report.md), not only its summary.
    #[arg(long)]
    pub verbose: bool,
}

/// `search`.
#[derive(Args)]
#[command(after_help = "Example: mho search --design vanderpol --auto")]
pub struct SearchArgs {
    /// The design.
    #[command(flatten)]
    pub design: DesignChoice,
    /// Search every `[map]` field over its default candidates, whatever the spec gives.
    #[arg(long)]
    pub auto: bool,
}

/// `plot`.
#[derive(Args)]
#[command(
    long_about = "Plots a recorded run and its estimates (what `estimate` wrote for it) as PNG and SVG: every \
                  target's estimate against its truth column when the input has one (`truth_<target>` or the \
                  target's name), refused samples and saturated estimates marked, then the outputs and inputs.",
    after_help = "Example: mho plot --spec my_plant.toml --input run.csv --estimates estimates.csv"
)]
pub struct PlotArgs {
    /// The recorded run (CSV with a header), as given to `estimate`.
    #[arg(long, value_name = "FILE")]
    pub input: PathBuf,
    /// The estimates `estimate` wrote for it.
    #[arg(long, value_name = "FILE")]
    pub estimates: PathBuf,
    /// A shipped design, for its names and units: a panel per output and input. Without a design
    /// the input's other numeric columns share one panel.
    #[arg(long, conflicts_with = "spec")]
    pub design: Option<String>,
    /// A design spec file, instead of --design.
    #[arg(long, value_name = "FILE")]
    pub spec: Option<PathBuf>,
    /// Writes PREFIX.png and PREFIX.svg. Default: the estimates' path without its extension.
    #[arg(long, value_name = "PREFIX")]
    pub out: Option<PathBuf>,
}

/// `simulate`.
#[derive(Args)]
#[command(after_help = "Example: mho simulate --spec my_plant.toml --samples 1000 --output run.csv")]
pub struct SimulateArgs {
    /// The design.
    #[command(flatten)]
    pub design: DesignChoice,
    /// Initial state, comma separated in state order (default: the spec's scenario).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub x0: Option<Vec<f64>>,
    /// Samples (default: the spec's scenario).
    #[arg(long)]
    pub samples: Option<usize>,
    /// Seed of the noise and inputs (default: the spec's scenario).
    #[arg(long)]
    pub seed: Option<u64>,
    /// CSV file to write (time, states, outputs, inputs).
    #[arg(long, value_name = "FILE")]
    pub output: PathBuf,
}

/// `estimate`.
#[derive(Args)]
#[command(
    after_help = "Example: mho estimate --spec my_plant.toml --input run.csv --output estimates.csv --precision f32"
)]
pub struct EstimateArgs {
    /// The design.
    #[command(flatten)]
    pub design: DesignChoice,
    /// CSV with a header, one row per sample; columns named after the outputs and inputs.
    #[arg(long, value_name = "FILE")]
    pub input: PathBuf,
    /// CSV to write: `time`, `run` (when the input has one), `status`, one column per target, then
    /// `saturated_<target>` per target (-1, 0, 1).
    #[arg(long, value_name = "FILE")]
    pub output: PathBuf,
    /// The observer: `auto` (default) is the design's `observer()`, the kind `gen` chose; any other
    /// of the kinds listed asks for that one.
    #[arg(long, default_value = "auto", value_parser = kind_parser())]
    pub kind: ObserverKind,
    /// The fitted design `gen` saved (design.json in its report folder). Default: the checkout's
    /// `target/designs/<name>/` or `target/observers/<name>/report/` when they hold this spec's; else
    /// the design is fitted for this call.
    #[arg(long, value_name = "FILE")]
    pub tables: Option<PathBuf>,
    /// `f64` (default): the host library, the reference the tables are certified against. `f32`:
    /// the firmware's code on the emitted tables, bit for bit what the chip computes.
    #[arg(long, value_enum, default_value = "f64")]
    pub precision: PrecisionArg,
}

/// `--precision`.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum PrecisionArg {
    /// The host library in f64.
    F64,
    /// The firmware's code on the emitted f32 tables.
    F32,
}

/// `--kind`: `auto` or a kind of the registry ([`crate::observers::kind::REGISTRY`]).
fn kind_parser() -> impl clap::builder::TypedValueParser<Value = ObserverKind> {
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    let kinds = crate::observers::kind::REGISTRY
        .iter()
        .map(|k| PossibleValue::new(k.kind.name()).help(k.what));
    let values = std::iter::once(PossibleValue::new("auto").help("the kind `gen` chose")).chain(kinds);
    PossibleValuesParser::new(values)
        .map(|name| crate::observers::kind::named(&name).map_or(ObserverKind::Auto, |k| k.kind))
}

/// Which design: a shipped one by name, or any spec file.
#[derive(Args)]
#[group(required = true, multiple = false)]
pub struct DesignChoice {
    /// Name of a design shipped in host/specs/.
    #[arg(long)]
    pub design: Option<String>,
    /// A design spec file.
    #[arg(long, value_name = "FILE")]
    pub spec: Option<PathBuf>,
}
