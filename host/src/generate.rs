//! The `gen` job as one library function, which the command line, the tests and a design search call:
//! every spec through the pipeline (spec → data → fit → emit → report), then `generated/src/lib.rs`.
//!
//! All or nothing: every spec is loaded and the names and families of the resulting generated set are
//! checked before any fit; every design is then fitted, emitted (f32 against f64 on every validation
//! window) and reported in memory; only when all succeeded are the reports, figures, observer files and
//! `lib.rs` written. A failure touches no file and names the spec that failed.

use std::path::{Path, PathBuf};

use indicatif::ProgressBar;

use crate::emit;
use crate::output;
use crate::report::plots;
use crate::report::{self as reporting};
use crate::spec::{self, Design};

mod design;
mod emitted;
mod error;
mod shipped;

pub use design::{design_source, emit_design, fixed_point, model_code, settle, simulate_and_fit};
pub use emitted::{Emitted, Fixed};
pub use error::{GenerateError, NotOurs};
pub use shipped::{shipped_design, shipped_specs, workspace_root};

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

/// The folder of the `generated` crate that holds every shipped design's C99 source (`<name>.h`,
/// `<name>.c`, [`crate::emit::c`]): C for firmware without a Rust toolchain.
pub const C_FOLDER: &str = "c";

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
    /// A crate published file by file rather than swapped in whole, and why
    /// ([`crate::standalone::publish`]); `None` for `generated/` and swapped crates.
    pub in_place: Option<String>,
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
    progress: impl Fn(&Design) -> ProgressBar + Sync,
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
        // Their C names must not clash either: one C program may link every design of a run.
        for (first, other) in &designs {
            if crate::emit::c::c_name_clash(&other.name, &design.name).is_some() {
                return Err(GenerateError::CNameClash {
                    first_name: other.name.clone(),
                    first: first.clone(),
                    second_name: design.name.clone(),
                    second: spec.clone(),
                });
            }
        }
        designs.push((spec.clone(), design));
    }
    Ok(designs)
}

/// Fits, emits and reports every design in memory ([`prepare`], the crate name from `standalone`,
/// the report folder from `folder`), designs in parallel on the machine's cores; `done` then hears of
/// each in the order given. Fails, before anything is written, when one failed or, with `strict`,
/// when one fails a quality gate.
pub(crate) fn prepare_all(
    designs: Vec<(PathBuf, Design)>,
    standalone: impl Fn(&Design) -> Option<String> + Sync,
    folder: impl Fn(&str) -> PathBuf + Sync,
    strict: bool,
    progress: impl Fn(&Design) -> ProgressBar + Sync,
    mut done: impl FnMut(&Path, Result<&Prepared, &GenerateError>),
) -> Result<Vec<(PathBuf, Prepared)>, GenerateError> {
    use rayon::prelude::*;
    let total = designs.len();
    let results: Vec<(PathBuf, Result<Prepared, GenerateError>)> = designs
        .into_par_iter()
        .map(|(spec, design)| {
            let bar = progress(&design);
            let crate_name = standalone(&design);
            let one = prepare(design, &spec, crate_name.as_deref(), &folder, &bar);
            bar.finish_and_clear();
            (spec, one)
        })
        .collect();
    let mut prepared = Vec::new();
    let mut failed = 0;
    for (spec, one) in results {
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
        .filter(|(_, p)| p.warnings.iter().any(reporting::gates::Gate::strict))
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
    /// Where the observers stand between the on-line MHE and the floor, in sentences
    /// ([`reporting::references::verdict`]).
    pub verdict: String,
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
    report.fixed_point = emitted
        .fixed
        .as_ref()
        .map(|fixed| reporting::fixed_point::of(&emitted.design, &emitted.result, fixed));
    let measured = reporting::on_target::recorded(&folder, &emitted.source);
    for observer in &mut report.observers {
        observer.on_target = measured.get(observer.kind).cloned();
    }
    Ok(Prepared {
        warnings: reporting::gates::check(&emitted.design, &emitted.result, &emitted.comparison),
        report: reporting::texts(&report),
        table: format!("{}\n{}", reporting::table(&report), reporting::observers_table(&report)),
        verdict: reporting::references::verdict(&report),
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
    output::write_if_changed(
        &tables,
        &crate::tables::Tables::of(
            &one.emitted.design,
            &one.emitted.result,
            &one.emitted.comparison,
            &one.emitted.source,
        )
        .to_json(),
    )
    .map_err(|source| GenerateError::Io {
        path: tables.clone(),
        source,
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
    // The C99 source first: the Rust file, written last, is what marks the design as generated.
    let c_folder = to.generated.join(C_FOLDER);
    std::fs::create_dir_all(&c_folder).map_err(|source| GenerateError::Io {
        path: c_folder.clone(),
        source,
    })?;
    for (extension, text) in [("h", &one.emitted.c_source.header), ("c", &one.emitted.c_source.source)] {
        let path = c_folder.join(format!("{}.{extension}", design.name));
        output::write_if_changed(&path, text).map_err(|source| GenerateError::Io { path, source })?;
    }
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
        in_place: None,
    })
}
