//! The report of a design: `report.json` (everything, machine-readable), `report.md` (one table a
//! person reads) and the one-screen summary `gen` prints.

pub mod plots;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::fit::evaluate::Evaluation;
use crate::fit::identify::Diagnostics;
use crate::fit::maps::FittedMap;
use crate::fit::DesignResult;
use crate::output::write_atomically;
use crate::spec::{Design, MapSettings};

/// `report.json`.
#[derive(Serialize)]
pub struct Report<'a> {
    /// Design name.
    pub design: &'a str,
    /// What it is.
    pub description: &'a str,
    /// The spec file.
    pub spec: String,
    /// Version of the tool that wrote it.
    pub tool_version: &'static str,
    /// Sample period.
    pub tau: f64,
    /// Map settings.
    pub map: &'a MapSettings,
    /// `n_z`.
    pub regressor_len: usize,
    /// Learning set.
    pub learning: SetSummary,
    /// Validation set.
    pub validation: SetSummary,
    /// One entry per target.
    pub targets: Vec<TargetReport<'a>>,
}

/// Size of a data set.
#[derive(Serialize)]
pub struct SetSummary {
    /// Simulated runs.
    pub runs: usize,
    /// Windows (`n_E` for the learning set).
    pub windows: usize,
    /// Seed.
    pub seed: u64,
}

/// One target's figures.
#[derive(Serialize)]
pub struct TargetReport<'a> {
    /// Name.
    pub name: &'a str,
    /// `g(x)`.
    pub expr: &'a str,
    /// RMSE of the map on the learning windows.
    pub rmse_learning: f64,
    /// RMSE of the map on the validation windows.
    pub rmse_validation: f64,
    /// Largest error on the validation windows (empirical `ε_x`).
    pub max_error_validation: f64,
    /// Fraction of validation windows where `Γ⁻¹` saturated.
    pub saturated_fraction_validation: f64,
    /// The linear floor on the same windows.
    pub linear: LinearReport,
    /// `rmse_validation / linear.rmse_validation` (below 1: the map beats the floor).
    pub ratio_to_linear_validation: f64,
    /// How the QP went.
    pub qp: &'a Diagnostics,
    /// The fitted map.
    pub fitted: &'a FittedMap,
}

/// The linear floor's figures.
#[derive(Serialize)]
pub struct LinearReport {
    /// RMSE on the learning windows.
    pub rmse_learning: f64,
    /// RMSE on the validation windows.
    pub rmse_validation: f64,
    /// Largest error on the validation windows.
    pub max_error_validation: f64,
}

/// Assembles the report of a run.
pub fn report<'a>(design: &'a Design, result: &'a DesignResult) -> Report<'a> {
    let summary = |set: &crate::data::DataSet, seed| SetSummary {
        runs: set.runs.len(),
        windows: set.window_count(),
        seed,
    };
    Report {
        design: &design.name,
        description: &design.description,
        spec: design.file.display().to_string(),
        tool_version: env!("CARGO_PKG_VERSION"),
        tau: design.tau,
        map: &design.map,
        regressor_len: result.learning.regressor_len(),
        learning: summary(&result.learning, design.learning.seed),
        validation: summary(&result.validation, design.validation.seed),
        targets: result
            .targets
            .iter()
            .map(|t| {
                let (learning, validation): (&Evaluation, &Evaluation) = (&t.learning, &t.validation);
                TargetReport {
                    name: &design.targets[t.index].name,
                    expr: design.targets[t.index].expr.text(),
                    rmse_learning: learning.map.rmse,
                    rmse_validation: validation.map.rmse,
                    max_error_validation: validation.map.max_error,
                    saturated_fraction_validation: validation.saturated_fraction,
                    linear: LinearReport {
                        rmse_learning: learning.linear.rmse,
                        rmse_validation: validation.linear.rmse,
                        max_error_validation: validation.linear.max_error,
                    },
                    ratio_to_linear_validation: validation.map.rmse / validation.linear.rmse,
                    qp: &t.fit.diagnostics,
                    fitted: &t.fit.map,
                }
            })
            .collect(),
    }
}

/// The table shared by `report.md` and the terminal summary.
pub fn table(report: &Report<'_>) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "| target | RMSE learning | RMSE validation | max error validation | linear RMSE validation | ratio | saturated | QP status | iterations | active / constraints | collapsed | Γ⁻¹ segments | proven table error |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for t in &report.targets {
        let _ = writeln!(
            s,
            "| {} | {:.4} | {:.4} | {:.4} | {:.4} | {:.3} | {:.1} % | {:?} | {} | {} / {} | {} | {} | {} |",
            t.name,
            t.rmse_learning,
            t.rmse_validation,
            t.max_error_validation,
            t.linear.rmse_validation,
            t.ratio_to_linear_validation,
            100.0 * t.saturated_fraction_validation,
            t.qp.status,
            t.qp.iterations,
            t.qp.active_constraints,
            t.qp.constraints,
            if t.qp.collapsed { "yes" } else { "no" },
            t.fitted
                .table
                .as_ref()
                .map_or("none (not emittable)".to_owned(), |t| format!(
                    "{} {}",
                    t.segments.len(),
                    t.knots_kind()
                )),
            t.fitted
                .table
                .as_ref()
                .map_or("—".to_owned(), |t| format!("{:.1e}", t.proven_bound))
        );
    }
    s
}

/// `report.md`.
pub fn markdown(report: &Report<'_>) -> String {
    let mut s = format!("# {}\n\n{}\n\n", report.design, report.description);
    let m = report.map;
    let _ = writeln!(
        s,
        "Spec `{}`. τ = {}, N = {}, n_m = {}, β = {}, ε = {}, normalisation `{:?}`, n_z = {}. \
         Learning: {} runs, n_E = {} windows. Validation: {} fresh runs, {} windows.\n",
        report.spec,
        report.tau,
        m.horizon,
        m.nm,
        m.beta,
        m.epsilon,
        m.normalisation,
        report.regressor_len,
        report.learning.runs,
        report.learning.windows,
        report.validation.runs,
        report.validation.windows
    );
    s.push_str(&table(report));
    s.push_str(
        "\n*ratio*: validation RMSE of the map over that of the plain linear least-squares map `Lᵀ Z + c` on the same data \
         (below 1: the nonlinear map beats the floor). *max error validation* is the paper's empirical ε_x. \
         *saturated*: windows where Γ⁻¹ clamped the estimate to the learning range. *collapsed*: Γ is a straight \
         line (≥ 90 % of the monotonicity constraints active). *Γ⁻¹ segments*: the table the chip evaluates instead of \
         inverting Γ; *proven table error*: its proven largest distance to the exact Γ⁻¹ (target units, at most 1e-4 of \
         the learning range); every estimate in this report uses that table, as the chip does. Full figures and the fitted coefficients: `report.json`.\n\n\
         Figures (PNG and SVG): `measurements` (the scenario's measured outputs and their noise, paper Fig. 1/5), \
         `identification` (identified against true on the learning windows, and dΓ/dr, Fig. 2 left/Fig. 3), \
         `estimation` (the observer along the scenario, Fig. 2 right/Fig. 4).\n",
    );
    s
}

/// The report as its two files' texts: `report.json` and `report.md`.
pub fn texts(report: &Report<'_>) -> (String, String) {
    let json = serde_json::to_string_pretty(report).expect("the report serialises: plain numbers and strings") + "\n";
    (json, markdown(report))
}

/// Writes `report.json` and `report.md` (from [`texts`]) into `folder`; returns their paths.
pub fn write_texts((json, markdown): &(String, String), folder: &Path) -> std::io::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(folder)?;
    let paths = vec![folder.join("report.json"), folder.join("report.md")];
    write_atomically(&paths[0], json.as_bytes())?;
    write_atomically(&paths[1], markdown.as_bytes())?;
    Ok(paths)
}
