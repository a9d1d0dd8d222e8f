//! The `gen` job as one library function, which the command line, the tests and a design search call:
//! every spec through the pipeline (spec → data → fit → emit → report), then `generated/src/lib.rs`.
//!
//! All or nothing: every spec is loaded and the names and families of the resulting generated set are
//! checked before any fit; every design is then fitted, emitted (f32 against f64 on every validation
//! window) and reported in memory; only when all succeeded are the reports, figures, observer files and
//! `lib.rs` written. A failure touches no file and names the spec that failed.

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
    /// `--runtime-path` is not the folder of the `firmware` crate.
    #[error("{}: --runtime-path: {why}\n  fix: pass the folder of the `firmware` runtime crate (the checkout's firmware/), or --runtime-version <version>", path.display())]
    Runtime {
        /// The path given.
        path: PathBuf,
        /// What is wrong.
        why: String,
    },
    /// `gen --spec` would replace a file it did not write (see [`crate::standalone::owned`]).
    #[error(transparent)]
    NotOurs(#[from] crate::standalone::owned::NotOurs),
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
    /// cbindgen could not write the C header of a standalone crate's C library.
    #[error("{}: cbindgen could not write the C header: {message}", path.display())]
    Header {
        /// The C library's source it read.
        path: PathBuf,
        /// cbindgen's message.
        message: String,
    },
    /// A file or folder could not be listed, created or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// `--out` (or a design's folder in it) is a file.
    #[error("{}: is a file, not a folder: `gen --spec` writes a crate into the folder --out names\n  fix: choose a folder for --out (a new or empty one)", path.display())]
    NotAFolder {
        /// The file.
        path: PathBuf,
    },
    /// No checkout around the current folder (needed for the defaults: shipped specs, `generated/`).
    #[error("{}: not inside a checkout (no folder upward holds host/specs/ and generated/Cargo.toml); run from the checkout, or give the paths (--spec FILE instead of --design; for gen also --reports and --generated)", from.display())]
    NoWorkspace {
        /// Where the search started.
        from: PathBuf,
    },
    /// No shipped spec names the design asked for.
    #[error("unknown design `{name}`; the shipped designs are: {known}{broken} (or pass --spec FILE)")]
    UnknownDesign {
        /// The name asked for.
        name: String,
        /// The shipped designs that loaded.
        known: String,
        /// The shipped specs that did not load, if any.
        broken: String,
    },
    /// Two specs of one run name the same design.
    #[error("{} and {}: both specs name the design `{name}`: rename one", first.display(), second.display())]
    DuplicateName {
        /// The design name.
        name: String,
        /// One spec.
        first: PathBuf,
        /// The other.
        second: PathBuf,
    },
    /// `--strict`: some designs fail quality gates (each was reported); nothing was written.
    #[error("{designs} fail(s) the quality gates above (--strict); nothing was written: change the spec as each warning says, or run without --strict")]
    Gates {
        /// The designs, comma separated.
        designs: String,
    },
    /// Some designs failed (each was reported); nothing was written.
    #[error("{failed} of {total} design(s) failed; nothing was written")]
    Failed {
        /// Designs that failed.
        failed: usize,
        /// Designs asked for.
        total: usize,
    },
}

/// The checkout `gen` works in: the nearest folder, from the current one upward, that holds
/// `host/specs/` and `generated/Cargo.toml`. Found at run time, so that a copied or moved checkout
/// writes into itself, never into the one the binary was built in.
pub fn workspace_root() -> Result<PathBuf, GenerateError> {
    let here = std::env::current_dir().map_err(|source| GenerateError::Io {
        path: PathBuf::from("."),
        source,
    })?;
    here.ancestors()
        .find(|dir| dir.join("host/specs").is_dir() && dir.join("generated/Cargo.toml").is_file())
        .map(Path::to_owned)
        .ok_or(GenerateError::NoWorkspace { from: here })
}

/// Every spec shipped in `host/specs/` of the [`workspace_root`], sorted: what `gen` runs by default.
pub fn shipped_specs() -> Result<Vec<PathBuf>, GenerateError> {
    let folder = workspace_root()?.join("host/specs");
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

/// The shipped design named `name`. A broken spec of another design does not stand in the way; a
/// broken spec whose file is `<name>.toml` gives its own error; otherwise the error lists the designs
/// found and the specs that did not load.
pub fn shipped_design(name: &str) -> Result<Design, GenerateError> {
    let (mut known, mut broken) = (Vec::new(), Vec::new());
    for path in shipped_specs()? {
        match spec::load(&path) {
            Ok(design) if design.name == name => return Ok(design),
            Ok(design) => known.push(design.name),
            Err(e) if path.file_stem().is_some_and(|stem| stem == name) => return Err(e.into()),
            Err(_) => broken.push(path.display().to_string()),
        }
    }
    Err(GenerateError::UnknownDesign {
        name: name.to_owned(),
        known: known.join(", "),
        broken: if broken.is_empty() {
            String::new()
        } else {
            format!(" ({} did not load)", broken.join(", "))
        },
    })
}

/// One design fitted and emitted, in memory.
pub struct Emitted {
    /// The design.
    pub design: Design,
    /// Its data, fits and evaluation.
    pub result: DesignResult,
    /// Its observers compared (the map and the EKF).
    pub comparison: crate::observers::Comparison,
    /// The text of `generated/src/<design>.rs`.
    pub source: String,
    /// The design search, when the spec asks for one ([`crate::search`]); `design.map` holds its choice.
    pub search: Option<crate::search::Outcome>,
    /// Validation accuracy against the taps kept, when the spec prunes `L` ([`crate::search::sparsity`]).
    pub taps: Option<Vec<crate::search::sparsity::Row>>,
}

/// Searches (when the spec asks), fits and emits `design`, loaded from `spec` (nothing is written):
/// as a module of the `generated` crate, or with `standalone = Some(crate name)` as the module of a
/// crate of its own.
pub fn emit_design(
    design: Design,
    spec: &Path,
    standalone: Option<&str>,
    progress: &ProgressBar,
) -> Result<Emitted, GenerateError> {
    // What the spec's observer kind rules out is refused before the search and the fit.
    crate::observers::check_before_fit(&design, &model_code(&design)?)?;
    let (design, search) = crate::search::settle(design, progress)?;
    if search.is_some() {
        progress.set_length(fit::steps(&design));
        progress.set_position(0);
    }
    let result = fit::run(&design, progress)?;
    let taps =
        crate::search::sparsity::accuracy_vs_taps(&design, &result.learning, &result.validation).map_err(|e| {
            design.error(
                "map.taps",
                format!("a pruned fit failed: {e}"),
                "offer fewer counts in `map.taps`, or leave it out",
            )
        })?;
    // Relative to the checkout when there is one, so that the text does not depend on where it lives.
    let spec_path = match workspace_root() {
        Ok(workspace) => emit::portable_spec_path(spec, &workspace),
        Err(_) => spec.display().to_string(),
    };
    let placement = match standalone {
        None => emit::Placement::Generated { spec: &spec_path },
        Some(crate_name) => emit::Placement::Standalone {
            crate_name,
            source: &spec_path,
        },
    };
    let (comparison, source) = design_source(&design, &result, &placement, spec, progress)?;
    Ok(Emitted {
        design,
        result,
        comparison,
        source,
        search,
        taps,
    })
}

/// The design's model written as programs, or an error naming the spec field that cannot be.
pub fn model_code(design: &Design) -> Result<crate::plant::ModelCode, SpecError> {
    crate::plant::ModelCode::new(design).map_err(|e| {
        design.error(
            e.field,
            format!("the model cannot be written as Rust for the chip: {}", e.construct),
            "rewrite the expression as the message says",
        )
    })
}

/// The observers of a fitted design compared (the EKF tuned on new runs), and the text of its
/// `generated/src/<design>.rs`: maps, model and EKF.
pub fn design_source(
    design: &Design,
    result: &DesignResult,
    placement: &emit::Placement<'_>,
    spec: &Path,
    progress: &ProgressBar,
) -> Result<(crate::observers::Comparison, String), GenerateError> {
    let code = model_code(design)?;
    progress.set_message(format!("{}: tuning the EKF", design.name));
    let comparison = crate::observers::compare(design, result, &code)?;
    let emit_error = |source| GenerateError::Emit {
        file: spec.to_owned(),
        design: design.name.clone(),
        source,
    };
    let state_targets = crate::observers::corrected::state_targets(design).ok();
    let instructions: Vec<(&'static str, f64)> =
        comparison.observers.iter().map(|o| (o.kind, o.instructions)).collect();
    let observers = emit::model::Observers {
        ekf: comparison.ekf.as_ref().map(|t| &t.constants),
        started: comparison
            .started
            .as_ref()
            .map(|s| (s.p0.as_slice(), s.state_targets.as_slice())),
        restart: comparison.restart.as_ref(),
        corrected: comparison
            .corrected
            .as_ref()
            .ok()
            .map(|t| &t.constants)
            .zip(state_targets.as_deref()),
        kind: comparison.chosen.0,
        instructions: &instructions,
        tables_sha256: &crate::tables::Tables::new(design, result, Some(&comparison)).tables_sha256,
    };
    let source = emit::design_file(design, result, placement, &code, &observers).map_err(emit_error)?;
    Ok((comparison, source))
}

/// The text of `generated/src/lib.rs` declaring the design files `present` (sorted here) and the
/// families among them: those of `designs` (this run's, whose files it writes) as their specs say, and
/// those of the other files present in `sources` as the files declare (`FAMILY`), so that regenerating
/// one member of a family keeps the others.
pub fn lib_source(designs: &[Design], sources: &Path, present: &[String]) -> Result<String, GenerateError> {
    let mut present = present.to_vec();
    present.sort();
    let mut members = Vec::new();
    for design in designs {
        let member = emit::Member::of(design).map_err(|source| emit::FamilyError::Value {
            file: design.file.clone(),
            source,
        })?;
        members.extend(member);
    }
    for name in &present {
        if designs.iter().any(|d| &d.name == name) {
            continue;
        }
        let file = sources.join(format!("{name}.rs"));
        let source = std::fs::read_to_string(&file).map_err(|source| GenerateError::Io {
            path: file.clone(),
            source,
        })?;
        members.extend(emit::Member::declared(name, &source, &file));
    }
    let families = emit::families(&members, &present)?;
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
    /// The design's name.
    pub name: String,
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

/// Runs `gen` on `specs`: every design, then `lib.rs` declaring every design file present afterwards
/// with their families ([`lib_source`]). `progress` gives each design its progress bar
/// and `done` hears of each design as it ends (before anything is written). Writes nothing unless every
/// design succeeded, and with `strict` unless every design passes the quality gates
/// ([`reporting::gates`]).
pub fn run(
    specs: &[PathBuf],
    to: &Destinations,
    strict: bool,
    progress: impl Fn(&Design) -> ProgressBar,
    done: impl FnMut(&Path, Result<&Prepared, &GenerateError>),
) -> Result<Vec<Outcome>, GenerateError> {
    // 1. Every spec, the names and the families of the generated set afterwards: before any fit.
    let designs = load_specs(specs)?;
    let sources = to.generated.join("src");
    let mut present = present_designs(&sources)?;
    for (_, design) in &designs {
        if !present.contains(&design.name) {
            present.push(design.name.clone());
        }
    }
    // This run's designs as their specs say, the other files present as they declare.
    let this_run: Vec<Design> = designs.iter().map(|(_, d)| d.clone()).collect();
    let lib = lib_source(&this_run, &sources, &present)?;

    // 2. Fit, emit and report every design in memory.
    let prepared = prepare_all(designs, |_| None, |name| to.reports.join(name), strict, progress, done)?;

    // 3. Write.
    std::fs::create_dir_all(&sources).map_err(|source| GenerateError::Io {
        path: sources.clone(),
        source,
    })?;
    let mut outcomes = Vec::new();
    for (_, one) in prepared {
        outcomes.push(write(one, to)?);
    }
    let lib_path = sources.join("lib.rs");
    output::write_if_changed(&lib_path, &lib).map_err(|source| GenerateError::Io { path: lib_path, source })?;
    Ok(outcomes)
}

/// Every spec loaded and checked, refusing two designs of one name, before anything is fitted.
pub(crate) fn load_specs(specs: &[PathBuf]) -> Result<Vec<(PathBuf, Design)>, GenerateError> {
    let mut designs: Vec<(PathBuf, Design)> = Vec::new();
    for spec in specs {
        let design = spec::load(spec)?;
        if let Some((first, _)) = designs.iter().find(|(_, d)| d.name == design.name) {
            return Err(GenerateError::DuplicateName {
                name: design.name,
                first: first.clone(),
                second: spec.clone(),
            });
        }
        designs.push((spec.clone(), design));
    }
    Ok(designs)
}

/// Fits, emits and reports every design in memory ([`prepare`], the crate name from `standalone`,
/// the report folder from `folder`); `done` hears of each as it ends. Fails, before anything is
/// written, when one failed or, with `strict`, when one fails a quality gate.
pub(crate) fn prepare_all(
    designs: Vec<(PathBuf, Design)>,
    standalone: impl Fn(&Design) -> Option<String>,
    folder: impl Fn(&str) -> PathBuf,
    strict: bool,
    progress: impl Fn(&Design) -> ProgressBar,
    mut done: impl FnMut(&Path, Result<&Prepared, &GenerateError>),
) -> Result<Vec<(PathBuf, Prepared)>, GenerateError> {
    let total = designs.len();
    let mut prepared = Vec::new();
    let mut failed = 0;
    for (spec, design) in designs {
        let bar = progress(&design);
        let crate_name = standalone(&design);
        let one = prepare(design, &spec, crate_name.as_deref(), &folder, &bar);
        bar.finish_and_clear();
        match one {
            Ok(one) => {
                done(&spec, Ok(&one));
                prepared.push((spec, one));
            }
            Err(e) => {
                done(&spec, Err(&e));
                failed += 1;
            }
        }
    }
    if failed > 0 {
        return Err(GenerateError::Failed { failed, total });
    }
    let gated: Vec<&str> = prepared
        .iter()
        .filter(|(_, p)| !p.warnings.is_empty())
        .map(|(_, p)| p.emitted.design.name.as_str())
        .collect();
    if strict && !gated.is_empty() {
        return Err(GenerateError::Gates {
            designs: gated.join(", "),
        });
    }
    Ok(prepared)
}

/// The design files in `sources` (`<name>.rs` other than `lib.rs`), sorted; none if it does not exist.
fn present_designs(sources: &Path) -> Result<Vec<String>, GenerateError> {
    let entries = match std::fs::read_dir(sources) {
        Ok(entries) => entries,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(source) => {
            return Err(GenerateError::Io {
                path: sources.to_owned(),
                source,
            })
        }
    };
    let mut names: Vec<String> = entries
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|f| f.strip_suffix(".rs").map(str::to_owned))
        .filter(|f| !spec::RESERVED_MODULES.contains(&f.as_str()))
        .collect();
    names.sort();
    Ok(names)
}

/// One design fitted, emitted and reported, not yet written.
pub struct Prepared {
    /// The design, its fit and its observer source.
    pub emitted: Emitted,
    /// The report's JSON and Markdown.
    pub report: (String, String),
    /// The report's table (Markdown).
    pub table: String,
    /// Learning windows (`n_E`).
    pub learning_windows: usize,
    /// Validation windows.
    pub validation_windows: usize,
    /// Where its report goes.
    pub folder: PathBuf,
    /// The quality gates it fails ([`reporting::gates`]): `gen` warns, `gen --strict` refuses.
    pub warnings: Vec<reporting::gates::Gate>,
}

/// Fits, emits and reports one design in memory; its report goes to `folder(name)`.
pub(crate) fn prepare(
    design: Design,
    spec: &Path,
    standalone: Option<&str>,
    folder: impl Fn(&str) -> PathBuf,
    bar: &ProgressBar,
) -> Result<Prepared, GenerateError> {
    let emitted = emit_design(design, spec, standalone, bar)?;
    let folder = folder(&emitted.design.name);
    let mut report = reporting::report(&emitted.design, &emitted.result, &emitted.comparison);
    report.search = emitted.search.as_ref();
    report.taps = emitted.taps.as_deref();
    let measured = reporting::on_target::recorded(&folder, &emitted.source);
    for observer in &mut report.observers {
        observer.on_target = measured.get(observer.kind).cloned();
    }
    Ok(Prepared {
        warnings: reporting::gates::check(&emitted.design, &emitted.result, &emitted.comparison),
        report: reporting::texts(&report),
        table: format!("{}\n{}", reporting::table(&report), reporting::observers_table(&report)),
        learning_windows: report.learning.windows,
        validation_windows: report.validation.windows,
        folder,
        emitted,
    })
}

/// Writes a prepared design's report (JSON, Markdown), its tables ([`crate::tables`]) and figures
/// into its folder.
pub(crate) fn write_report(one: &Prepared) -> Result<(Vec<PathBuf>, Vec<PathBuf>), GenerateError> {
    let folder = &one.folder;
    let mut report_files = reporting::write_texts(&one.report, folder).map_err(|source| GenerateError::Io {
        path: folder.clone(),
        source,
    })?;
    // The design as data, for `estimate` to run without fitting again.
    let tables = folder.join(crate::tables::FILE);
    output::write_if_changed(&tables, &crate::tables::Tables::of(&one.emitted).to_json()).map_err(|source| {
        GenerateError::Io {
            path: tables.clone(),
            source,
        }
    })?;
    report_files.push(tables);
    let Emitted {
        design,
        result,
        comparison,
        search,
        ..
    } = &one.emitted;
    let mut figures = plots::draw(design, result, comparison, folder)?;
    if let Some(search) = search {
        figures.extend(plots::draw_search(design, search, folder)?);
    }
    Ok((report_files, figures))
}

/// Writes one prepared design: its report, figures and observer file (last).
fn write(one: Prepared, to: &Destinations) -> Result<Outcome, GenerateError> {
    let (report_files, figures) = write_report(&one)?;
    let (folder, design, source) = (one.folder, one.emitted.design, one.emitted.source);
    let observer = to.generated.join("src").join(format!("{}.rs", design.name));
    let changed = output::write_if_changed(&observer, &source).map_err(|source| GenerateError::Io {
        path: observer.clone(),
        source,
    })?;
    Ok(Outcome {
        name: design.name,
        folder,
        report_files,
        figures,
        observer,
        changed,
    })
}
