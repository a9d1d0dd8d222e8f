//! The `simulate` and `estimate` jobs as library functions (the command line only parses arguments
//! and prints): one run of a design as CSV, and the library estimate over a recorded CSV file.
//! Nothing is written unless the whole job succeeded.

use std::path::{Path, PathBuf};

use indicatif::ProgressBar;
use rand::SeedableRng;

use crate::recording::{self, EstimatesCsv, MapEvaluator, Precision, RecordingError, StreamError};
use crate::spec::{limits, Design, ObserverKind, SpecError};
use crate::tables::Tables;
use crate::{data, fit, output};

/// Why `simulate` or `estimate` did not run.
#[derive(Debug, thiserror::Error)]
pub enum CommandError {
    /// The spec is invalid, or its simulation or fit failed.
    #[error(transparent)]
    Spec(#[from] SpecError),
    /// The recorded file cannot be used.
    #[error(transparent)]
    Recording(#[from] RecordingError),
    /// The observer kind asked for does not exist for this design.
    #[error(transparent)]
    Kind(#[from] crate::observers::recorded::RecordedError),
    /// Saved tables could not be read.
    #[error(transparent)]
    Tables(#[from] crate::tables::TablesError),
    /// `--tables` names tables fitted from another spec (or by another version of the tool).
    #[error("{}: these tables were not fitted from {} as it is now (or by this version of the tool); run `gen` for it, or leave out --tables to fit for this call", path.display(), spec.display())]
    StaleTables {
        /// The tables.
        path: PathBuf,
        /// The spec.
        spec: PathBuf,
    },
    /// A value the design's `[scenario]` would give is missing.
    #[error("design `{design}` has no `[scenario]`: give --{option}")]
    NoScenario {
        /// The design.
        design: String,
        /// The command-line option to give instead.
        option: &'static str,
    },
    /// The initial state holds a NaN or an infinity (it used to be blamed on the spec's derivatives).
    #[error("--x0 {x0:?}: every initial value must be finite")]
    NonFiniteX0 {
        /// The values given.
        x0: Vec<f64>,
    },
    /// The initial state has the wrong length.
    #[error("--x0 has {given} values; the states are {states}")]
    StateCount {
        /// Values given.
        given: usize,
        /// The design's states.
        states: String,
    },
    /// `--samples` is above [`limits::MAX_RUN_SAMPLES`].
    #[error("--samples {samples} is above the limit of {limit} samples per run")]
    TooLong {
        /// Samples asked for.
        samples: usize,
        /// The limit.
        limit: usize,
    },
    /// The recorded input is not a regular file (a folder, a device such as /dev/zero, a pipe).
    #[error("{}: not a regular file; give a CSV file", path.display())]
    NotAFile {
        /// The input.
        path: PathBuf,
    },
    /// The output would replace one of the job's inputs, or is a folder.
    #[error("{}: {reason}; give another --output", path.display())]
    Output {
        /// The output path.
        path: PathBuf,
        /// Why it cannot be written.
        reason: String,
    },
    /// The output file could not be written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
}

/// What `simulate` runs: each `None` falls back on the design's `[scenario]`.
#[derive(Clone, Debug, Default)]
pub struct Simulation {
    /// Initial state, in state order.
    pub x0: Option<Vec<f64>>,
    /// Samples.
    pub samples: Option<usize>,
    /// Seed of the noise and inputs.
    pub seed: Option<u64>,
}

/// Simulates one run of `design` and writes it to `output` as CSV (time, states, outputs, inputs).
pub fn simulate(design: &Design, run: &Simulation, output: &Path) -> Result<(), CommandError> {
    let scenario = design.scenario();
    let missing = |option| CommandError::NoScenario {
        design: design.name.clone(),
        option,
    };
    let x0 = run
        .x0
        .clone()
        .or_else(|| scenario.map(|s| s.x0.clone()))
        .ok_or_else(|| missing("x0"))?;
    if x0.iter().any(|v| !v.is_finite()) {
        return Err(CommandError::NonFiniteX0 { x0 });
    }
    if x0.len() != design.model.states.len() {
        return Err(CommandError::StateCount {
            given: x0.len(),
            states: design.model.states.join(", "),
        });
    }
    let samples = run
        .samples
        .or(scenario.map(|s| s.samples))
        .ok_or_else(|| missing("samples"))?;
    if samples > limits::MAX_RUN_SAMPLES {
        return Err(CommandError::TooLong {
            samples,
            limit: limits::MAX_RUN_SAMPLES,
        });
    }
    let seed = run.seed.or(scenario.map(|s| s.seed)).ok_or_else(|| missing("seed"))?;
    refuse_overwrite(output, &[&design.file])?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let simulated = data::simulate_run(design, &x0, samples, &mut rng, "scenario")?;
    output::write_atomically_with(output, |out| recording::write_run_csv(design, &simulated, out)).map_err(|source| {
        CommandError::Io {
            path: output.to_owned(),
            source,
        }
    })
}

/// Where `estimate` took the fitted design from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Provenance {
    /// The tables `gen` saved ([`crate::tables`]): nothing was fitted.
    Saved(PathBuf),
    /// No saved tables for this spec: the design was fitted (and its observers tuned) for this call.
    Fitted,
}

/// The saved tables of `design`: `explicit` (which must be this spec's), or the first of the
/// checkout's report folders (`target/designs/<name>/`, `target/observers/<name>/report/`) whose
/// tables are this spec's and were written with the observer file that is there now
/// (`generated/src/<name>.rs`, the crate's `src/<name>.rs`).
fn saved_tables(design: &Design, explicit: Option<&Path>) -> Result<Option<(Tables, PathBuf)>, CommandError> {
    if let Some(path) = explicit {
        let tables = Tables::read(path)?.ok_or_else(|| CommandError::NotAFile { path: path.to_owned() })?;
        if !tables.belongs_to(design) {
            return Err(CommandError::StaleTables {
                path: path.to_owned(),
                spec: design.file.clone(),
            });
        }
        tables.check(design, path)?;
        // Beside the observer it was written with (a crate's `report/design.json` and
        // `src/<name>.rs`): that observer must carry these tables' hash.
        let beside = path
            .parent()
            .and_then(Path::parent)
            .map(|folder| folder.join("src").join(format!("{}.rs", design.name)));
        if let Some(observer) = beside {
            if let Ok(text) = std::fs::read_to_string(&observer) {
                if !tables.written_with(&text) {
                    return Err(crate::tables::TablesError::OtherObserver {
                        path: path.to_owned(),
                        observer,
                    }
                    .into());
                }
            }
        }
        return Ok(Some((tables, path.to_owned())));
    }
    let Ok(root) = crate::generate::workspace_root() else {
        return Ok(None);
    };
    let source = format!("{}.rs", design.name);
    let crate_folder = root.join("target/observers").join(&design.name);
    for (path, observer) in [
        (
            root.join("target/designs").join(&design.name).join(crate::tables::FILE),
            root.join("generated/src").join(&source),
        ),
        (
            crate_folder.join("report").join(crate::tables::FILE),
            crate_folder.join("src").join(&source),
        ),
    ] {
        if let Some(tables) = Tables::read(&path)? {
            if tables.belongs_to(design) && tables.matches_observer(&observer) {
                tables.check(design, &path)?;
                return Ok(Some((tables, path)));
            }
        }
    }
    Ok(None)
}

/// What `estimate` runs.
#[derive(Clone, Copy, Debug)]
pub struct Estimation<'a> {
    /// The observer (`Auto`: the one `gen` chose).
    pub kind: ObserverKind,
    /// Its arithmetic.
    pub precision: Precision,
    /// The saved tables to use (`None`: look for them in the checkout, else fit).
    pub tables: Option<&'a Path>,
}

/// Estimates the targets over the recorded measurements `input` into `output` (the format of
/// [`crate::recording`]) as `how` says, by the tables `gen` saved for this spec, or else by fitting
/// the design for this call.
pub fn estimate(
    design: &Design,
    input: &Path,
    output: &Path,
    how: Estimation<'_>,
    progress: &ProgressBar,
) -> Result<Provenance, CommandError> {
    let Estimation {
        kind,
        precision,
        tables,
    } = how;
    // The input, the spec and the saved design are read: none of them may be the output.
    let mut read = vec![input, design.file.as_path()];
    read.extend(tables);
    refuse_overwrite(output, &read)?;
    // A device or pipe may never end: only a regular file has a size to read.
    if !recording::regular_or_missing(input) {
        return Err(CommandError::NotAFile { path: input.to_owned() });
    }
    let mut rows = recording::RowReader::open(design, input)?;
    let (mut design, provenance, tables) = match saved_tables(design, tables)? {
        Some((tables, path)) => (design.clone(), Provenance::Saved(path), tables),
        None => {
            let (design, _, runs) = crate::generate::settle(design.clone(), progress)?;
            let result = fit::run(&design, runs, progress)?;
            let comparison = if kind == ObserverKind::Map {
                None
            } else {
                let code = crate::generate::model_code(&design)?;
                Some(crate::observers::compare(&design, &result, &code, progress)?)
            };
            let tables = Tables::new(&design, &result, comparison.as_ref());
            (design, Provenance::Fitted, tables)
        }
    };
    design.map.horizon = tables.horizon;
    let design = &design;
    let io = |source| CommandError::Io {
        path: output.to_owned(),
        source,
    };
    let chosen = if kind == ObserverKind::Auto {
        tables.chosen
    } else {
        kind
    };
    let names: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
    let csv = EstimatesCsv::new(&names, rows.has_runs(), design.tau);
    if chosen != ObserverKind::Map {
        // Row by row, as the map below: memory does not grow with the recording.
        let code = crate::generate::model_code(design)?;
        output::write_atomically_with(output, |out| -> Result<(), Streamed> {
            std::io::Write::write_all(out, csv.header().as_bytes())?;
            let mut k = 0;
            crate::observers::recorded::stream(
                design,
                &tables,
                &code,
                chosen,
                precision,
                || rows.next_row().map_err(Streamed::from),
                |row, estimate| {
                    std::io::Write::write_all(out, csv.line(k, row, &estimate).as_bytes())?;
                    k += 1;
                    Ok(())
                },
            )
        })
        .map_err(|e| match e {
            Streamed::Recording(e) => CommandError::Recording(e),
            Streamed::Observer(e) => CommandError::Kind(e),
            Streamed::Io(source) => io(source),
        })?;
        return Ok(provenance);
    }
    let maps = MapEvaluator::new(&tables.maps, precision).map_err(crate::observers::recorded::RecordedError::from)?;
    // Row by row: memory does not grow with the recording; the output appears only when complete.
    output::write_atomically_with(output, |out| {
        recording::estimate_streaming(&maps, tables.horizon, &csv, &mut rows, out)
    })
    .map_err(|e| match e {
        StreamError::Recording(e) => CommandError::Recording(e),
        StreamError::Io(source) => io(source),
    })?;
    Ok(provenance)
}

/// Why streaming an observer's estimates stopped.
#[derive(Debug, thiserror::Error)]
enum Streamed {
    #[error(transparent)]
    Recording(#[from] recording::RecordingError),
    #[error(transparent)]
    Observer(#[from] crate::observers::recorded::RecordedError),
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

/// Refuses an `output` that is a folder or the same file as one of `inputs` (compared as canonical
/// paths, so `./a.csv`, `a.csv` and a link to it are one file): writing it would destroy the input.
fn refuse_overwrite(output: &Path, inputs: &[&Path]) -> Result<(), CommandError> {
    let refuse = |reason: String| CommandError::Output {
        path: output.to_owned(),
        reason,
    };
    if output.is_dir() {
        return Err(refuse("is a folder".to_owned()));
    }
    let Ok(target) = output.canonicalize() else {
        return Ok(()); // does not exist yet: it cannot be an input
    };
    for input in inputs {
        if input.canonicalize().is_ok_and(|i| i == target) {
            return Err(refuse(format!(
                "is the input {}, which writing would destroy",
                input.display()
            )));
        }
    }
    Ok(())
}
