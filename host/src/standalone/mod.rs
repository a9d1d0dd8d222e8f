//! A user's design as a crate of its own: what `gen --spec FILE [--out DIR]` writes, so that a spec
//! outside `host/specs/` never touches the project's `generated/` crate or its tests.
//!
//! ```text
//! <out>/Cargo.toml        its own [workspace]: it builds wherever it is copied; `firmware` by path or version
//! <out>/src/lib.rs        #![no_std]; the design module
//! <out>/src/<name>.rs     the design, as `gen` emits it for `generated/`
//! <out>/spec.toml         the spec it came from
//! <out>/README.md         how to use it, then the report (accuracy and cost tables) and its figures
//! <out>/report/           report.json, report.md and the figures (PNG and SVG)
//! <out>/c/                 the C library: a staticlib crate of extern "C" functions, include/<name>.h
//! ```
//!
//! The default `<out>` is `target/observers/<name>/` of the checkout. Like `gen`, nothing is written
//! unless every design fits (and, with `--strict`, passes the quality gates). Nothing the user wrote
//! is replaced: every file a crate gets is recorded in its `.gen-files` ([`owned`]), and a run that
//! would replace a file not recorded there (or changed since) is refused before anything is fitted,
//! unless `--force`. A crate is replaced whole where it can be ([`publish`]): written into a stage
//! beside it and swapped in with one rename, so that a run killed at any instant leaves the old crate
//! or the new one; in a folder that cannot be renamed (a mount point), file by file, each file whole.

pub mod c_library;
pub mod owned;
pub mod publish;
pub mod runtime;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use indicatif::ProgressBar;

use crate::emit::STANDALONE_SPEC;
use crate::generate::{load_specs, prepare_all, write_report, GenerateError, Outcome, Prepared};
use crate::output::write_if_changed;
use crate::spec::Design;

/// Where the crate finds the `firmware` runtime.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Runtime {
    /// The runtime the tool carries ([`runtime`]), written into the crate's `firmware/` folder: the
    /// default outside the checkout, so that the crate builds with nothing but the toolchain.
    Embedded,
    /// A path to the `firmware` crate (default: the checkout's `firmware/`, absolute).
    Path(PathBuf),
    /// A version requirement, for a registry that has `firmware`.
    Version(String),
}

impl Runtime {
    /// Checks a path runtime: a folder whose `Cargo.toml` is the `firmware` package (a crate that
    /// depends on anything else would fail to build, later and far from the cause).
    pub fn check(&self) -> Result<(), GenerateError> {
        let Runtime::Path(path) = self else {
            return Ok(());
        };
        let wrong = |why: String| GenerateError::Runtime {
            path: path.clone(),
            why,
        };
        let manifest = path.join("Cargo.toml");
        let text = std::fs::read_to_string(&manifest)
            .map_err(|e| wrong(format!("cannot read {}: {e}", manifest.display())))?;
        let table: toml::Table = text
            .parse()
            .map_err(|e| wrong(format!("{} is not a Cargo manifest: {e}", manifest.display())))?;
        let name = table
            .get("package")
            .and_then(|p| p.get("name"))
            .and_then(toml::Value::as_str);
        if name != Some("firmware") {
            return Err(wrong(format!(
                "{} is the package {}, not `firmware`",
                manifest.display(),
                name.map_or("of no name".to_owned(), |n| format!("`{n}`"))
            )));
        }
        Ok(())
    }

    /// The `[dependencies]` line.
    fn dependency(&self) -> String {
        match self {
            Runtime::Embedded => format!("firmware = {{ path = {:?} }}", runtime::FOLDER),
            Runtime::Path(path) => format!("firmware = {{ path = {:?} }}", path.to_string_lossy()),
            Runtime::Version(version) => format!("firmware = {version:?}"),
        }
    }
}

/// Where `gen --spec` writes.
#[derive(Clone, Debug)]
pub struct Destination {
    /// With one spec, the crate's folder; with several, the folder holding one crate per design.
    pub out: PathBuf,
    /// Whether `out` holds one crate per design (`out/<name>/`) rather than being the crate.
    pub per_design: bool,
    /// The runtime dependency.
    pub runtime: Runtime,
    /// Whether files `gen` did not write may be replaced (`--force`; see [`owned`]).
    pub force: bool,
}

/// The crate's package name for design `name`.
pub fn package_name(name: &str) -> String {
    format!("{}-observer", name.replace('_', "-"))
}

/// The crate's library name (what `use` names) for design `name`.
pub fn library_name(name: &str) -> String {
    format!("{name}_observer")
}

/// Fits every spec and writes each design as a standalone crate (see the module's documentation).
/// `progress` and `done` are as for [`crate::generate::run`].
pub fn run(
    specs: &[PathBuf],
    to: &Destination,
    strict: bool,
    progress: impl Fn(&Design) -> ProgressBar + Sync,
    done: impl FnMut(&Path, Result<&Prepared, &GenerateError>),
) -> Result<Vec<Outcome>, GenerateError> {
    let designs = load_specs(specs)?;
    let folder_of = |name: &str| {
        if to.per_design {
            to.out.join(name)
        } else {
            to.out.clone()
        }
    };
    // Before anything is fitted: the runtime the crates will depend on is the `firmware` crate, and
    // no crate may replace a file `gen` did not write.
    // Where each crate goes (links followed) and how it will be published there, also decided now.
    to.runtime.check()?;
    let mut plans = std::collections::BTreeMap::new();
    for (_, design) in &designs {
        let folder = folder_of(&design.name);
        for path in folder.ancestors().take_while(|p| p.starts_with(&to.out)) {
            if path.exists() && !path.is_dir() {
                return Err(GenerateError::NotAFolder { path: path.to_owned() });
            }
        }
        let plan = publish::plan(&folder)?;
        owned::check(plan.folder(), &design.name, &to.runtime, to.force)?;
        plans.insert(design.name.clone(), plan);
    }
    let prepared = prepare_all(
        designs,
        |design| Some(library_name(&design.name)),
        |name| folder_of(name).join("report"),
        strict,
        progress,
        done,
    )?;
    prepared
        .into_iter()
        .map(|(path, mut one)| {
            let plan = &plans[&one.emitted.design.name];
            let folder = plan.folder();
            let observer = folder.join("src").join(format!("{}.rs", one.emitted.design.name));
            let changed = std::fs::read_to_string(observer).ok().as_ref() != Some(&one.emitted.source);
            // Written whole into a stage, then swapped in or moved in file by file ([`publish`]).
            let outcome = plan.replace(|stage| {
                one.folder = stage.join(owned::REPORT);
                write(&one, &path, stage, &to.runtime, changed)
            })?;
            Ok(outcome.moved(folder, plan.publication()))
        })
        .collect()
}

impl Outcome {
    /// The outcome with its paths in the stage moved to the crate's `folder`, published as said.
    fn moved(self, folder: &Path, publication: &publish::Publication) -> Outcome {
        let stage = self.folder;
        let to = |path: PathBuf| path.strip_prefix(&stage).map_or(path.clone(), |p| folder.join(p));
        Outcome {
            name: self.name,
            folder: folder.to_owned(),
            report_files: self.report_files.into_iter().map(to).collect(),
            figures: self.figures.into_iter().map(to).collect(),
            observer: to(self.observer),
            changed: self.changed,
            in_place: match publication {
                publish::Publication::Swap => None,
                publish::Publication::InPlace { why } => Some(why.clone()),
            },
        }
    }
}

/// Writes one crate into `folder` (a fresh stage): its files, the report, and the list of them.
fn write(
    one: &Prepared,
    spec: &Path,
    folder: &Path,
    runtime: &Runtime,
    changed: bool,
) -> Result<Outcome, GenerateError> {
    let design = &one.emitted.design;
    let io = |path: &Path| {
        let path = path.to_owned();
        move |source| GenerateError::Io { path, source }
    };
    let (report_files, figures) = write_report(one)?;
    let sources = folder.join("src");
    std::fs::create_dir_all(&sources).map_err(io(&sources))?;
    let spec_text = std::fs::read_to_string(spec).map_err(io(spec))?;
    let files = [
        (folder.join("Cargo.toml"), manifest(design, runtime)),
        (folder.join(STANDALONE_SPEC), spec_text),
        (folder.join("README.md"), readme(one)),
        (sources.join("lib.rs"), library(design)),
    ];
    for (path, text) in &files {
        write_if_changed(path, text).map_err(io(path))?;
    }
    if runtime == &Runtime::Embedded {
        for (relative, text) in runtime::files() {
            let path = folder.join(relative);
            if let Some(parent) = path.parent() {
                std::fs::create_dir_all(parent).map_err(io(parent))?;
            }
            write_if_changed(&path, &text).map_err(io(&path))?;
        }
    }
    let c = folder.join(c_library::FOLDER);
    let c_sources = c.join("src");
    let include = c.join("include");
    for dir in [&c_sources, &include] {
        std::fs::create_dir_all(dir).map_err(io(dir))?;
    }
    let c_source = c_sources.join("lib.rs");
    for (path, text) in [
        (c.join("Cargo.toml"), c_library::manifest(design)),
        (c_source.clone(), c_library::source(design)),
    ] {
        write_if_changed(&path, &text).map_err(io(&path))?;
    }
    let header = c_library::header(design, &c_source).map_err(|e| GenerateError::Header {
        path: c_source.clone(),
        message: e.to_string(),
    })?;
    let header_path = include.join(format!("{}.h", design.name));
    write_if_changed(&header_path, &header).map_err(io(&header_path))?;
    let observer = sources.join(format!("{}.rs", design.name));
    write_if_changed(&observer, &one.emitted.source).map_err(io(&observer))?;
    // The observers as C99 source, the C route without a Rust toolchain.
    let c_source = folder.join(C_SOURCE_FOLDER);
    std::fs::create_dir_all(&c_source).map_err(io(&c_source))?;
    for (extension, text) in [("h", &one.emitted.c_source.header), ("c", &one.emitted.c_source.source)] {
        let path = c_source.join(format!("{}.{extension}", design.name));
        write_if_changed(&path, text).map_err(io(&path))?;
    }
    let mut written = owned::fixed_files(&design.name, runtime);
    written.extend(
        report_files
            .iter()
            .chain(&figures)
            .filter_map(|path| path.strip_prefix(folder).ok().map(Path::to_path_buf)),
    );
    let list = folder.join(owned::LIST);
    owned::Owned::default().record(folder, &written).map_err(io(&list))?;
    Ok(Outcome {
        name: design.name.clone(),
        folder: folder.to_owned(),
        report_files,
        figures,
        observer,
        changed,
        in_place: None,
    })
}

/// `Cargo.toml`.
fn manifest(design: &Design, runtime: &Runtime) -> String {
    format!(
        "# The `{name}` observer, emitted by `mho gen --spec` (mho {version}). Do not edit: regenerate.\n\
         {licence}\n\
         [package]\n\
         name = \"{package}\"\n\
         version = \"0.1.0\"\n\
         edition = \"2021\"\n\
         rust-version = \"1.95\"\n\
         description = {description:?}\n\
         license = \"MIT OR Apache-2.0\"\n\
         publish = false\n\
         \n\
         [lib]\n\
         name = \"{library}\"\n\
         \n\
         [dependencies]\n\
         {dependency}\n\
         \n\
         # A workspace of its own: the crate builds wherever it is copied, even inside another workspace.\n\
         [workspace]\n\
         \n\
         [profile.release]\n\
         opt-level = \"s\"\n\
         lto = true\n\
         codegen-units = 1\n",
        name = design.name,
        version = env!("CARGO_PKG_VERSION"),
        package = package_name(&design.name),
        library = library_name(&design.name),
        description = format!("Observer `{}`: {}", design.name, design.description),
        dependency = runtime.dependency(),
        licence = crate::emit::licence_comment("# "),
    )
}

/// `src/lib.rs`: the crate root over the design's module.
#[derive(askama::Template)]
#[template(path = "standalone/lib.rs", escape = "none")]
struct Library<'a> {
    name: &'a str,
    description: String,
    spec: &'static str,
    version: &'static str,
    licence: String,
}

/// `src/lib.rs`.
fn library(design: &Design) -> String {
    askama::Template::render(&Library {
        name: &design.name,
        description: crate::emit::doc_prose(&design.description),
        spec: STANDALONE_SPEC,
        version: env!("CARGO_PKG_VERSION"),
        licence: crate::emit::licence_comment("//! "),
    })
    .expect("plain fields render")
}

/// The crate's folder of the observers as C99 source (`<name>.h`, `<name>.c`, [`crate::emit::c`]).
pub const C_SOURCE_FOLDER: &str = "c-source";

/// `README.md`: how to build and use the crate, then the report with its figures.
fn readme(one: &Prepared) -> String {
    let design = &one.emitted.design;
    let (name, library) = (&design.name, library_name(&design.name));
    let mut text = format!(
        "# The `{name}` observer\n\n{}\n\nEmitted by `mho gen --spec` from [`{STANDALONE_SPEC}`]({STANDALONE_SPEC}) (mho {}). \
         Do not edit: change the spec and regenerate.\n\n{licence}\n\n\
         ## Build and use\n\n\
         ```sh\ncargo build --release --target thumbv7em-none-eabihf   # a Cortex-M4F; any target with a float unit works\n```\n\n\
         ```rust\n\
         let mut observer = {library}::{name}::observer(); // fixed memory, no allocation\n\
         let (y, u) = ([0.0; {library}::{name}::OUTPUTS], [0.0; {library}::{name}::INPUTS]);\n\
         observer.push(y, u).ok(); // every sample; a NaN or infinite one is refused (no new estimate)\n\
         if let Some(estimates) = observer.estimate() {{\n    \
         // one per target, in {library}::{name}::TARGET_NAMES order\n    \
         let _ = estimates[0].value;\n\
         }}\n\
         ```\n\n\
         ## From C: two routes\n\n\
         - **C source, no Rust toolchain** (`{C_SOURCE_FOLDER}/{name}.h`, `{name}.c`): add both files to your C build \
         (any C99 compiler: gcc, clang, IAR, Keil, a vendor IDE) and build them with `-ffp-contract=off` (or your \
         compiler's switch that forbids fused multiply-add), which gives the Rust observer's bits. Each kind is a \
         struct you allocate: `{name}_observer observer; {name}_observer_init(&observer);`, then \
         `{name}_observer_push(&observer, y, u)` every sample and `{name}_observer_estimate(&observer, values, flags)`; \
         `{name}_map`, `{name}_ekf_box`, … are the other kinds. Choose it unless something below applies.\n\
         - **The Rust static library** (`{c}/`): `cd {c} && cargo build --release --target thumbv7em-none-eabihf` \
         gives `lib{library}_c.a` and `{c}/include/{name}.h` (`{name}_init(storage, size)`, `{name}_push`, \
         `{name}_estimate` over storage of `STORAGE_SIZE` bytes, every call checking its arguments). Choose it when you \
         want exactly the code the Rust rows of the on-target figures measure, or calls that check the storage they \
         are given; it needs a Rust toolchain with your target, and your build links a Rust archive.\n\n",
        crate::emit::doc_prose(&design.description),
        env!("CARGO_PKG_VERSION"),
        c = c_library::FOLDER,
        licence = crate::emit::LICENCE.join(" "),
    );
    // The report, its first heading dropped (the README has its own), its figures (embedded by the
    // report, beside it in report/) linked from here.
    let report = crate::report::relocate_figures(&one.report.1, "report");
    let body = report.split_once('\n').map_or(report.as_str(), |(_, rest)| rest);
    let _ = write!(
        text,
        "## Report\n\nFrom `report/report.md` (also `report/report.html`); every figure is on validation runs unless it says otherwise.\n{body}"
    );
    text
}
