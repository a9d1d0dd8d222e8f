//! The command line: [`args`] says what it accepts, this module runs each subcommand and says what
//! happened in words (errors: [`message`]).

pub mod args;
mod gen;

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};

use crate::{commands, fit, generate, spec};
use args::{Command, DesignChoice, EstimateArgs, PlotArgs, PrecisionArg, SearchArgs, SimulateArgs};

/// Runs a parsed command line.
pub fn run(command: Command) -> anyhow::Result<()> {
    match command {
        Command::Gen(args) => gen::run(args),
        Command::Estimate(args) => estimate(args),
        Command::Plot(args) => plot(args),
        Command::Simulate(args) => simulate(args),
        Command::Search(args) => search(args),
    }
}

impl DesignChoice {
    fn load(&self) -> anyhow::Result<spec::Design> {
        if let Some(path) = &self.spec {
            return Ok(spec::load(path)?);
        }
        Ok(generate::shipped_design(self.design.as_deref().unwrap_or_default())?)
    }
}

/// The error and its causes, each said once: the tool's errors already quote their cause (an OS error
/// printed twice read `Not a directory (os error 20): Not a directory (os error 20)`).
pub fn message(error: &anyhow::Error) -> String {
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

/// `search`: the spec's candidates, or with `--auto` every default one; prints the front.
fn search(SearchArgs { design: choice, auto }: SearchArgs) -> anyhow::Result<()> {
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
    let outcome = crate::search::run(&design, &search, &bar)?;
    bar.finish_and_clear();
    print!("{}", crate::search::summary(&design, &outcome));
    Ok(())
}

/// `plot`: the design is optional (names and units); the figure is written only when everything read.
fn plot(args: PlotArgs) -> anyhow::Result<()> {
    let choice = DesignChoice {
        design: args.design,
        spec: args.spec,
    };
    let design = match (&choice.design, &choice.spec) {
        (None, None) => None,
        _ => Some(choice.load()?),
    };
    let files = crate::report::recorded::plot(&args.input, &args.estimates, design.as_ref(), args.out.as_deref())?;
    for file in files {
        println!("{}", file.display());
    }
    Ok(())
}

/// `simulate`.
fn simulate(args: SimulateArgs) -> anyhow::Result<()> {
    let design = args.design.load()?;
    let run = commands::Simulation {
        x0: args.x0,
        samples: args.samples,
        seed: args.seed,
    };
    commands::simulate(&design, &run, &args.output)?;
    Ok(())
}

/// `estimate`: by the saved design when there is one, else fitted for this call (it says which).
fn estimate(args: EstimateArgs) -> anyhow::Result<()> {
    let design = args.design.load()?;
    let kind = args.kind;
    let bar = progress_bar(&design);
    let how = commands::Estimation {
        kind,
        precision: match args.precision {
            PrecisionArg::F64 => crate::recording::Precision::F64,
            PrecisionArg::F32 => crate::recording::Precision::F32,
        },
        tables: args.tables.as_deref(),
    };
    let provenance = commands::estimate(&design, &args.input, &args.output, how, &bar)?;
    bar.finish_and_clear();
    match provenance {
        commands::Provenance::Saved(path) => eprintln!("estimate: by the design saved in {}", path.display()),
        commands::Provenance::Fitted => {
            eprintln!("estimate: no saved design for this spec (`gen` saves one), so it was fitted for this call")
        }
    }
    Ok(())
}
