//! A user's standalone crate (`mho gen --spec FILE --out DIR`) on the emulated Cortex-M4F.
//!
//! The runners and probes of `tests/on-target/` link the crate in place of the project's
//! `generated` (both re-export the runtime as `generated::firmware`): a manifest of their own under
//! `target/on-target/crates/<name>/` names the crate's folder as the `generated` dependency. They run
//! the crate's own recorded sequence (`RECORDED_Y`, `RECORDED_U`), which the host rebuilds from the
//! spec (the design's scenario, [`host::emit::recorded_sequence`]) to check every sample: the map
//! and the observers it starts bit for bit against `estimate --precision f32` on the crate's saved
//! tables (`report/design.json`), every kind against the host's `f64` for the largest difference.
//! Only when all of that holds are the figures written, beside the crate's report and into the
//! [`section`](host::report::on_target::section) its `report.md` and `README.md` show.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use host::observers::recorded;
use host::recording::{EstimateRow, Precision, Row, Status};
use host::report::on_target::{self as figures, Measured, OnTarget};
use host::spec::{Design, ObserverKind};
use host::tables::Tables;

use super::{chip_flag, Board, EkfMeasurement, Figures, Kind, ObserverMeasurement, Program};
use crate::workspace_root;

/// A generated crate as the harness reads it.
pub struct Crate {
    /// Its folder.
    pub folder: PathBuf,
    /// Its package name (`Cargo.toml`).
    pub package: String,
    /// Its spec (`spec.toml`), with the map settings the tables were fitted with.
    pub design: Design,
    /// Its saved tables (`report/design.json`).
    pub tables: Tables,
}

impl Crate {
    /// Reads the crate in `folder`: its package name, spec and saved tables, which must be the
    /// spec's and written with the observer file that is there (else: regenerate it).
    pub fn load(folder: &Path) -> Result<Self, String> {
        let regenerate = "regenerate it with `cargo run -p host -- gen --spec <spec> --out <folder>`";
        let manifest = folder.join("Cargo.toml");
        let text = std::fs::read_to_string(&manifest).map_err(|e| {
            format!(
                "{}: {e}; --crate takes the folder of a crate `mho gen --spec` wrote",
                manifest.display()
            )
        })?;
        let table: toml::Table = text.parse().map_err(|e| format!("{}: {e}", manifest.display()))?;
        let package = table
            .get("package")
            .and_then(|p| p.get("name"))
            .and_then(toml::Value::as_str)
            .ok_or_else(|| format!("{}: no `package.name`", manifest.display()))?
            .to_owned();
        let mut design = host::spec::load(&folder.join("spec.toml")).map_err(|e| e.to_string())?;
        let path = folder.join("report").join(host::tables::FILE);
        let tables = Tables::read(&path)
            .map_err(|e| e.to_string())?
            .ok_or_else(|| format!("{}: missing; {regenerate}", path.display()))?;
        if !tables.belongs_to(&design) {
            return Err(format!(
                "{}: written from another spec or by another version of the tool; {regenerate}",
                path.display()
            ));
        }
        let source = folder.join("src").join(format!("{}.rs", design.name));
        if !tables.matches_observer(&source) {
            return Err(format!(
                "{}: not the observer file {} was written with; {regenerate}",
                source.display(),
                path.display()
            ));
        }
        design.map.horizon = tables.horizon;
        design.map.nm = tables.nm;
        design.map.beta = tables.beta;
        design.map.taps = tables.taps;
        Ok(Crate {
            folder: folder.to_owned(),
            package,
            design,
            tables,
        })
    }

    /// The kinds its design file has: those whose saved constants are all there.
    pub fn kinds(&self) -> Vec<Kind> {
        host::observers::kind::REGISTRY
            .iter()
            .filter(|entry| self.tables.missing(entry.kind).is_none())
            .map(|entry| Kind::Of(entry.kind))
            .collect()
    }

    /// The on-target program linking this crate: `tests/on-target/Cargo.toml` with the crate as its
    /// `generated` and absolute paths to the shared sources (its build script holds the memory
    /// layouts), written with the project's lock file into `target/on-target/crates/<name>/`; built into the project's
    /// `target/on-target/` (its dependencies are compiled once for every program).
    pub fn program(&self) -> Result<Program, String> {
        let source = workspace_root().join("tests/on-target");
        let runner = workspace_root().join("target/on-target/crates").join(&self.design.name);
        std::fs::create_dir_all(&runner).map_err(|e| format!("{}: {e}", runner.display()))?;
        let read = |file: &str| {
            std::fs::read_to_string(source.join(file)).map_err(|e| format!("{}: {e}", source.join(file).display()))
        };
        let mut manifest: toml::Table = read("Cargo.toml")?.parse().map_err(|e| format!("{e}"))?;
        let path = |p: PathBuf| toml::Value::String(p.display().to_string());
        let package = manifest
            .get_mut("package")
            .and_then(toml::Value::as_table_mut)
            .ok_or("tests/on-target/Cargo.toml: no [package]")?;
        package.insert("autobins".into(), toml::Value::Boolean(false));
        package.insert("build".into(), path(source.join("build.rs")));
        let bins = [
            ("on-target", "src/main.rs"),
            ("ekf", "src/bin/ekf.rs"),
            ("probe", "src/bin/probe.rs"),
        ]
        .map(|(name, file)| {
            toml::Value::Table(toml::Table::from_iter([
                ("name".to_owned(), toml::Value::String(name.into())),
                ("path".to_owned(), path(source.join(file))),
                ("test".to_owned(), toml::Value::Boolean(false)),
                ("bench".to_owned(), toml::Value::Boolean(false)),
            ]))
        });
        manifest.insert("bin".into(), toml::Value::Array(bins.into()));
        let dependencies = manifest
            .get_mut("dependencies")
            .and_then(toml::Value::as_table_mut)
            .ok_or("tests/on-target/Cargo.toml: no [dependencies]")?;
        dependencies.insert(
            "generated".into(),
            toml::Value::Table(toml::Table::from_iter([
                (
                    "path".to_owned(),
                    path(self.folder.canonicalize().map_err(|e| e.to_string())?),
                ),
                ("package".to_owned(), toml::Value::String(self.package.clone())),
            ])),
        );
        let write = |file: &str, text: &str| {
            std::fs::write(runner.join(file), text).map_err(|e| format!("{}: {e}", runner.join(file).display()))
        };
        write(
            "Cargo.toml",
            &format!(
                "# Written by the on-target harness for the crate at {}: tests/on-target's runners linking it.\n{manifest}",
                self.folder.display()
            ),
        )?;
        write("Cargo.lock", &read("Cargo.lock")?)?;
        let target_dir = workspace_root().join("target").join("on-target");
        Ok(Program {
            manifest: runner.join("Cargo.toml"),
            elves: runner,
            target_dir,
        })
    }
}

/// Measures the crate in `folder` on the emulated chip, checks every estimate against the host,
/// and records the figures beside its report and in its README; returns the README's section.
/// Nothing is written to the crate unless every check passes.
pub fn measure_crate(folder: &Path) -> Result<String, String> {
    let user = Crate::load(folder)?;
    let name = user.design.name.clone();
    let program = user.program()?;
    let kinds = user.kinds();
    let all = super::measure_designs(&program, Board::Mps2An386, &[(name.clone(), kinds.clone())], &[])
        .map_err(|e| e.to_string())?;
    super::same_alone(&program, &all)?;

    let code = host::generate::model_code(&user.design).map_err(|e| e.to_string())?;
    let validation = host::data::validation_set(&user.design).map_err(|e| e.to_string())?;
    let scenario = host::data::runs::scenario(&user.design, &validation).map_err(|e| e.to_string())?;
    let rows = host::emit::recorded_sequence(&scenario);

    let mut observers: BTreeMap<String, OnTarget> = BTreeMap::new();
    for (&kind, measured) in all.observers.get(&name).into_iter().flatten() {
        let largest = check_observer(&user, &code, &rows, kind, measured)?;
        let figures = Figures::of_observer(measured, largest).map_err(|e| format!("{name} {}: {e}", kind.api()))?;
        observers.insert(kind.name().to_owned(), figures.on_target());
    }
    if let Some(filter) = all.filters.get(&name) {
        let largest = check_filter(&user, &code, &rows, filter)?;
        let figures = Figures::of_filter(filter, largest).map_err(|e| format!("{name} ekf(): {e}"))?;
        observers.insert(Kind::Of(ObserverKind::EkfBox).name().to_owned(), figures.on_target());
    }
    let expected: BTreeSet<&str> = kinds.iter().map(|k| k.name()).collect();
    if !observers.keys().map(String::as_str).eq(expected.iter().copied()) {
        return Err(format!(
            "{name}: measured {:?}, the crate has {expected:?}",
            observers.keys().collect::<Vec<_>>()
        ));
    }

    let source_path = folder.join("src").join(format!("{name}.rs"));
    let source = std::fs::read_to_string(&source_path).map_err(|e| format!("{}: {e}", source_path.display()))?;
    let section = figures::section(&observers);
    let measured = Measured {
        source_sha256: figures::source_hash(&source),
        observers,
    };
    figures::record(&folder.join("report"), &measured)
        .map_err(|e| format!("{}: cannot record the figures: {e}", folder.join("report").display()))?;
    let readme_path = folder.join("README.md");
    let readme = std::fs::read_to_string(&readme_path).map_err(|e| format!("{}: {e}", readme_path.display()))?;
    let readme = figures::splice(&readme, &section).ok_or_else(|| {
        format!(
            "{}: no `{}` … `{}` section to fill; regenerate the crate",
            readme_path.display(),
            figures::BEGIN,
            figures::END
        )
    })?;
    host::output::write_if_changed(&readme_path, &readme).map_err(|e| format!("{}: {e}", readme_path.display()))?;
    // What this changed stays the tool's: `gen --spec` may replace it again.
    let changed: Vec<PathBuf> = [
        "README.md",
        "report/on_target.json",
        "report/report.json",
        "report/report.md",
        "report/report.html",
    ]
    .into_iter()
    .map(PathBuf::from)
    .filter(|relative| folder.join(relative).is_file())
    .collect();
    let list = folder.join(host::standalone::owned::LIST);
    host::standalone::owned::Owned::read(folder)
        .and_then(|owned| owned.record(folder, &changed))
        .map_err(|e| format!("{}: {e}", list.display()))?;
    Ok(section)
}

/// The host's estimates of `kind` over `rows` in `precision`, by the crate's tables.
fn host_rows(
    user: &Crate,
    code: &host::plant::ModelCode,
    rows: &[Row],
    kind: Kind,
    precision: Precision,
) -> Result<Vec<EstimateRow>, String> {
    let Kind::Of(kind) = kind else {
        return Err("a standalone crate's integer observer is not measured on the chip".to_owned());
    };
    recorded::estimate(&user.design, &user.tables, code, kind, precision, rows).map_err(|e| e.to_string())
}

/// Checks the chip's samples of `kind` against `estimate --precision f32` bit for bit (status,
/// value and saturation of every estimate); returns the largest `|chip − host f64|`.
fn check_observer(
    user: &Crate,
    code: &host::plant::ModelCode,
    rows: &[Row],
    kind: Kind,
    measured: &ObserverMeasurement,
) -> Result<f64, String> {
    let what = format!("{} {}", user.design.name, kind.api());
    let single = host_rows(user, code, rows, kind, Precision::F32)?;
    let double = host_rows(user, code, rows, kind, Precision::F64)?;
    if measured.samples.len() != rows.len() {
        return Err(format!(
            "{what}: {} samples on the chip, {} recorded",
            measured.samples.len(),
            rows.len()
        ));
    }
    let mut largest: f64 = 0.0;
    for (k, ((chip, host), reference)) in measured.samples.iter().zip(&single).zip(&double).enumerate() {
        let status = match (chip.accepted, &chip.estimates) {
            (false, _) => Status::Refused,
            (true, None) => Status::NoEstimateYet,
            (true, Some(_)) => Status::Ok,
        };
        if status != host.status {
            return Err(format!(
                "{what} sample {k}: {status:?} on the chip, {:?} by `estimate --precision f32`",
                host.status
            ));
        }
        let (Status::Ok, Some(estimates)) = (status, &chip.estimates) else {
            continue;
        };
        for (t, (&(bits, flag), &(value, saturation))) in estimates.iter().zip(&host.targets).enumerate() {
            let expected = ((value as f32).to_bits(), chip_flag(saturation));
            if (bits, flag) != expected {
                return Err(format!(
                    "{what} sample {k} target {t}: {} ({flag}) on the chip, {value} ({}) by `estimate --precision f32`",
                    f32::from_bits(bits),
                    expected.1
                ));
            }
            if let Some(&(exact, _)) = reference.targets.get(t) {
                largest = larger(largest, f32::from_bits(bits), exact)
                    .ok_or_else(|| format!("{what} sample {k} target {t}: {value} on the chip, {exact} in f64"))?;
            }
        }
    }
    Ok(largest)
}

/// Checks that the chip's EKF from the box centre refuses the samples the host's `f64` filter (same
/// constants, same start) refuses; returns the largest `|chip − host f64|` of its targets.
fn check_filter(
    user: &Crate,
    code: &host::plant::ModelCode,
    rows: &[Row],
    measured: &EkfMeasurement,
) -> Result<f64, String> {
    let what = format!("{} ekf()", user.design.name);
    let constants = user
        .tables
        .constants
        .ekf_box()
        .ok_or_else(|| format!("{what}: no EKF constants saved"))?;
    let width = |f: fn(&Row) -> &Vec<f64>| rows.first().map_or(0, |r| f(r).len());
    let mut run = host::data::Run {
        states: host::data::Rows::new(0),
        inputs: host::data::Rows::new(width(|r| &r.u)),
        measurements: host::data::Rows::new(width(|r| &r.y)),
        targets: host::data::Rows::new(user.design.targets.len()),
        parameters: Vec::new(),
    };
    for row in rows {
        run.inputs.push(&row.u);
        run.measurements.push(&row.y);
    }
    let host = host::observers::ekf::estimate_run(code, constants, &constants.x0, &run)
        .ok_or_else(|| format!("{what}: the host cannot run a filter of this size"))?;
    // The host's filter refuses a sample by giving NaN targets (`estimate_run`).
    let targets: Vec<Option<Vec<f64>>> = host
        .iter()
        .map(|row| row.iter().all(|v| !v.is_nan()).then(|| row.to_vec()))
        .collect();
    super::ekf_largest_difference(&what, measured, &targets)
}

/// `largest` or `|chip − exact|`, whichever is larger; `None` when either estimate is not finite
/// (a bounded observer never gives one).
fn larger(largest: f64, chip: f32, exact: f64) -> Option<f64> {
    let difference = (f64::from(chip) - exact).abs();
    difference.is_finite().then(|| largest.max(difference))
}
