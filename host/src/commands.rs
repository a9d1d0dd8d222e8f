//! The `simulate` and `estimate` jobs as library functions (the command line only parses arguments
//! and prints): one run of a design as CSV, and the library estimate over a recorded CSV file.
//! Nothing is written unless the whole job succeeded.

use std::path::{Path, PathBuf};

use indicatif::ProgressBar;
use rand::SeedableRng;

use crate::recording::{self, RecordingError, StreamError};
use crate::spec::{limits, Design, ObserverKind, SpecError};
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
    let scenario = design.scenario.as_ref();
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

/// Fits `design` and writes the estimates of its observer `kind` over the recorded file `input` to
/// `output` (see [`recording`] for the columns): the map streams row by row; an observer the map
/// starts (`corrected`, `ekf`, or the kind `gen` chose, `auto`) tunes its constants on the tuning runs
/// as `gen` does and runs through the host mirror of the chip's `firmware::Started`, in `f64`.
pub fn estimate(
    design: &Design,
    input: &Path,
    output: &Path,
    kind: ObserverKind,
    progress: &ProgressBar,
) -> Result<(), CommandError> {
    refuse_overwrite(output, &[input, &design.file])?;
    // A device or pipe may never end: only a regular file has a size to read.
    if input.exists() && !std::fs::metadata(input).is_ok_and(|m| m.is_file()) {
        return Err(CommandError::NotAFile { path: input.to_owned() });
    }
    let mut rows = recording::RowReader::open(design, input)?;
    // A started observer needs every state as a target: say so before fitting anything.
    if let (ObserverKind::Corrected | ObserverKind::Ekf, Err(why)) =
        (kind, crate::observers::corrected::state_targets(design))
    {
        return Err(crate::observers::recorded::RecordedError::Unavailable {
            design: design.name.clone(),
            kind: if kind == ObserverKind::Ekf { "ekf" } else { "corrected" },
            why,
        }
        .into());
    }
    let (design, _) = crate::search::settle(design.clone(), progress)?;
    let design = &design;
    let result = fit::run(design, progress)?;
    let maps: Vec<_> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
    let io = |source| CommandError::Io {
        path: output.to_owned(),
        source,
    };
    if kind != ObserverKind::Map {
        let code = crate::generate::model_code(design)?;
        progress.set_message(format!("{}: tuning the observers", design.name));
        let comparison = crate::observers::compare(design, &result, &code)?;
        let chosen = if kind == ObserverKind::Auto {
            comparison.chosen.0
        } else {
            kind
        };
        if chosen != ObserverKind::Map {
            let all = recording::read(design, input)?;
            let estimates = crate::observers::recorded::estimate(design, &result, &code, &comparison, chosen, &all)?;
            let names: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
            return output::write_atomically(output, recording::estimates_csv(&names, &estimates).as_bytes())
                .map_err(io);
        }
    }
    // Row by row: memory does not grow with the recording; the output appears only when complete.
    output::write_atomically_with(output, |out| {
        recording::estimate_streaming(&maps, design.map.horizon, &mut rows, out)
    })
    .map_err(|e| match e {
        StreamError::Recording(e) => CommandError::Recording(e),
        StreamError::Io(source) => io(source),
    })
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
