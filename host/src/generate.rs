//! The `gen` job as one library function, which the command line, the tests and a design search call:
//! every spec through the pipeline (spec → data → fit → emit → report), then `generated/src/lib.rs`.
//!
//! A design's observer file is written only when its fit, its emission checks (f32 against f64 on
//! every validation window) and its report and figures all succeeded: a failing design leaves its
//! previous file in place and the others still run. `lib.rs` then declares every design file present.

use std::path::{Path, PathBuf};

use indicatif::ProgressBar;

use crate::emit::{self, EmitError, FamilyError};
use crate::fit::{self, DesignResult};
use crate::output;
use crate::report::plots::{self, PlotError};
use crate::report::{self as reporting};
use crate::spec::{self, Design, SpecError};

/// Why `gen` failed for a design, or as a whole.
#[derive(Debug, thiserror::Error)]
pub enum GenerateError {
    /// The spec is invalid, or its data or fit failed (the message names the spec field to change).
    #[error(transparent)]
    Spec(#[from] SpecError),
    /// The fitted design cannot be emitted.
    #[error("{}: cannot emit design `{design}`: {source}", file.display())]
    Emit {
        /// The spec.
        file: PathBuf,
        /// The design.
        design: String,
        /// Why.
        source: EmitError,
    },
    /// The family modules of `lib.rs` cannot be emitted.
    #[error(transparent)]
    Family(#[from] FamilyError),
    /// A figure could not be drawn or written.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A file or folder could not be listed, created or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Some designs failed (each was reported); nothing was written for them.
    #[error("{failed} of {total} design(s) failed; nothing was written for them")]
    Failed {
        /// Designs that failed.
        failed: usize,
        /// Designs asked for.
        total: usize,
    },
}

/// The workspace the host belongs to (generated paths are written relative to it).
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("host/ lives in the workspace")
        .to_owned()
}

/// Every spec shipped in `host/specs/`, sorted: what `gen` runs by default.
pub fn shipped_specs() -> Result<Vec<PathBuf>, GenerateError> {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("specs");
    let entries = std::fs::read_dir(&folder).map_err(|source| GenerateError::Io {
        path: folder.clone(),
        source,
    })?;
    let mut specs: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    specs.sort();
    Ok(specs)
}

/// One design fitted and emitted, in memory.
pub struct Emitted {
    /// The design.
    pub design: Design,
    /// Its data, fits and evaluation.
    pub result: DesignResult,
    /// The text of `generated/src/<design>.rs`.
    pub source: String,
}

/// Fits and emits `design`, loaded from `spec` (nothing is written).
pub fn emit_design(design: Design, spec: &Path, progress: &ProgressBar) -> Result<Emitted, GenerateError> {
    let result = fit::run(&design, progress)?;
    let source =
        emit::design_file(&design, &result, &emit::portable_spec_path(spec, &workspace_root())).map_err(|source| {
            GenerateError::Emit {
                file: spec.to_owned(),
                design: design.name.clone(),
                source,
            }
        })?;
    Ok(Emitted { design, result, source })
}

/// The text of `generated/src/lib.rs` declaring the design files `present` (sorted here) and the
/// families among them, whose members' specs are found in `specs`.
pub fn lib_source(specs: &[PathBuf], present: &[String]) -> Result<String, GenerateError> {
    let mut present = present.to_vec();
    present.sort();
    let mut known: Vec<Design> = Vec::new();
    for path in specs {
        if let Ok(design) = spec::load(path) {
            if !known.iter().any(|d| d.name == design.name) {
                known.push(design);
            }
        }
    }
    let families = emit::families(&known, &present)?;
    emit::lib_file(&present, &families).map_err(|source| GenerateError::Emit {
        file: PathBuf::from("generated/src/lib.rs"),
        design: "lib".to_owned(),
        source,
    })
}

/// Where `gen` writes.
#[derive(Clone, Debug)]
pub struct Destinations {
    /// Reports and figures, one sub-folder per design.
    pub reports: PathBuf,
    /// The `generated` crate.
    pub generated: PathBuf,
}

/// What `gen` wrote for one design.
pub struct Outcome {
    /// The design.
    pub design: Design,
    /// Learning windows (`n_E`).
    pub learning_windows: usize,
    /// Validation windows.
    pub validation_windows: usize,
    /// The report's table (Markdown).
    pub table: String,
    /// The design's report folder.
    pub folder: PathBuf,
    /// The report files (JSON, Markdown).
    pub report_files: Vec<PathBuf>,
    /// The figures.
    pub figures: Vec<PathBuf>,
    /// The observer file.
    pub observer: PathBuf,
    /// Whether the observer file changed.
    pub changed: bool,
}

/// Runs `gen` on `specs` (and declares in `lib.rs` every design file present afterwards, with the
/// families of `specs` and of the shipped specs). `progress` gives each design its progress bar and
/// `done` hears of each design as it ends. Fails if any design failed.
pub fn run(
    specs: &[PathBuf],
    to: &Destinations,
    progress: impl Fn(&Design) -> ProgressBar,
    mut done: impl FnMut(&Path, Result<&Outcome, &GenerateError>),
) -> Result<(), GenerateError> {
    let sources = to.generated.join("src");
    std::fs::create_dir_all(&sources).map_err(|source| GenerateError::Io {
        path: sources.clone(),
        source,
    })?;
    let mut failed = 0;
    for spec in specs {
        match one_design(spec, to, &progress) {
            Ok(outcome) => done(spec, Ok(&outcome)),
            Err(e) => {
                done(spec, Err(&e));
                failed += 1;
            }
        }
    }
    let present: Vec<String> = std::fs::read_dir(&sources)
        .map_err(|source| GenerateError::Io {
            path: sources.clone(),
            source,
        })?
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|f| f.strip_suffix(".rs").map(str::to_owned))
        .filter(|f| f != "lib")
        .collect();
    let all_specs: Vec<PathBuf> = specs.iter().cloned().chain(shipped_specs()?).collect();
    let lib = lib_source(&all_specs, &present)?;
    let lib_path = sources.join("lib.rs");
    output::write_if_changed(&lib_path, &lib).map_err(|source| GenerateError::Io { path: lib_path, source })?;
    if failed > 0 {
        return Err(GenerateError::Failed {
            failed,
            total: specs.len(),
        });
    }
    Ok(())
}

/// Fits, emits and reports one design; writes its observer file last.
fn one_design(
    spec: &Path,
    to: &Destinations,
    progress: &impl Fn(&Design) -> ProgressBar,
) -> Result<Outcome, GenerateError> {
    let design = spec::load(spec)?;
    let bar = progress(&design);
    let emitted = emit_design(design, spec, &bar);
    bar.finish_and_clear();
    let Emitted { design, result, source } = emitted?;
    let report = reporting::report(&design, &result);
    let folder = to.reports.join(&design.name);
    let report_files = reporting::write(&report, &folder).map_err(|source| GenerateError::Io {
        path: folder.clone(),
        source,
    })?;
    let figures = plots::draw(&design, &result, &folder)?;
    let observer = to.generated.join("src").join(format!("{}.rs", design.name));
    let changed = output::write_if_changed(&observer, &source).map_err(|source| GenerateError::Io {
        path: observer.clone(),
        source,
    })?;
    Ok(Outcome {
        learning_windows: report.learning.windows,
        validation_windows: report.validation.windows,
        table: reporting::table(&report),
        folder,
        report_files,
        figures,
        observer,
        changed,
        design,
    })
}
