//! The shape of `report.json`: every figure of a design, machine-readable, as serialised (a figure
//! that is not finite, where a filter diverged, as `null`).

use serde::Serialize;

use super::on_target;
use crate::fit::identify::Diagnostics;
use crate::fit::maps::FittedMap;
use crate::spec::MapSettings;

mod floor;
pub use floor::{BeatenReport, FloorReport, ParticlesReport};

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
    /// Its unit.
    pub time_unit: &'a str,
    /// Samples per validation run (a drift window).
    pub validation_samples: usize,
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
    /// Tuning runs (what the EKF's constants were chosen on; never reported as accuracy).
    pub tuning: SetSummary,
    /// Every set of runs, and which figures are computed on it.
    pub runs: Vec<super::runs::RunSet>,
    /// Every observer on the same data: the map, then the EKF.
    pub observers: Vec<ObserverReport>,
    /// Each filter the spec fixes constants of, beside the same filter tuned in every constant.
    pub fixed_filters: Vec<FixedFilterReport>,
    /// The host-only references: the on-line moving-horizon estimate and the particle floor.
    pub references: Vec<ReferenceReport>,
    /// How the EKF was tuned, when the host could run one.
    pub ekf_tuning: Option<EkfTuning>,
    /// How the moving-horizon observer on the chip (`mhe`) was tuned, when the host could run one.
    pub mhe_tuning: Option<ChipReport>,
    /// The box EKF started at the scenario's `observer_x0`: that start, its scenario RMSE per target.
    pub ekf_from_observer_x0: Option<(Vec<f64>, Vec<f64>)>,
    /// The helper maps (`fit::helpers`): per state that no target is, its validation RMSE.
    pub helpers: Vec<(String, f64)>,
    /// How the model-corrected map was tuned, or why the design has none.
    pub corrected_tuning: CorrectedTuning,
    /// What the design's `observer()` is, and why.
    pub observer: (crate::spec::ObserverKind, String),
    /// Every kind's tuning score, term by term.
    pub tuning_score: super::tuning_score::TuningScore,
    /// The chip's model against the learning simulation's.
    pub chip_model: ChipModel,
    /// The quality gates the design fails ([`gates`](super::gates)), one sentence each; empty when it passes them all.
    pub quality_gates: Vec<String>,
    /// The plants of the `rmse_mismatch` figures, when parameters are uncertain.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mismatch: Option<MismatchReport>,
    /// The spec's scenarios, with the box filters from each one's observer start.
    pub scenarios: Vec<super::scenarios::ScenarioReport>,
    /// The design search, when the spec asks for one (every candidate, the front, the choice).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub search: Option<&'a crate::search::Outcome>,
    /// Validation accuracy against the taps of `L` kept, when the spec prunes it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub taps: Option<&'a [crate::search::sparsity::Row]>,
    /// The map in integers, when the spec asks for it (`[chip] arithmetic = "fixed"`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fixed_point: Option<super::fixed_point::FixedPointReport>,
}

/// One observer's figures.
#[derive(Serialize)]
pub struct ObserverReport {
    /// Its kind's name ([`crate::spec::ObserverKind::name`]).
    pub kind: &'static str,
    /// Instructions per steady sample on the Cortex-M4F as the cost model predicts them
    /// ([`crate::search::cost`]; measured: `on_target`).
    pub predicted_instructions: f64,
    /// Per target name.
    pub targets: std::collections::BTreeMap<String, FiguresReport>,
    /// Its lost and restarted runs per set ([`crate::observers::lost`]): `{lost, runs, restarted,
    /// most_restarts, floor_lost}`, `null` for a set the design lacks or the observer is not run on.
    pub lost: crate::observers::lost::LostRuns,
    /// Measured on the emulated Cortex-M4F by `cargo run -p integration-tests --bin on-target-report`
    /// ([`on_target`]); `null` until the generated source written is measured.
    pub on_target: Option<on_target::OnTarget>,
}

/// [`crate::observers::Figures`] as serialised (NaN, where a filter diverged, as `null`).
#[derive(Serialize)]
pub struct FiguresReport {
    /// RMSE over the validation windows.
    pub rmse_validation: Option<f64>,
    /// Largest |error| there.
    pub max_error_validation: Option<f64>,
    /// The 95th percentile over validation runs of each run's RMSE (the tail the pooled RMSE hides).
    pub p95_validation: Option<f64>,
    /// RMSE over the scenario's windows (every observer from where it starts on the chip).
    pub rmse_scenario: Option<f64>,
    /// RMSE over the scenario's first 2 time units after the map's first estimate.
    pub rmse_transient: Option<f64>,
    /// Per scenario of the spec, in its order: RMSE over its windows, and over its transient.
    pub scenarios: Vec<(Option<f64>, Option<f64>)>,
    /// RMSE over the scenario's noise draws (`data::scenario_draws`), when there is a scenario
    /// (`null` where a filter diverged).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rmse_scenario_draws: Option<Option<f64>>,
    /// The 95th percentile over those draws of each draw's RMSE.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub p95_scenario_draws: Option<Option<f64>>,
    /// RMSE over the tuning runs.
    pub rmse_tuning: Option<f64>,
    /// The 95th percentile over tuning runs of each run's RMSE.
    pub p95_tuning: Option<f64>,
    /// RMSE over the mismatch runs (every corner of the uncertain parameters' box; [`MismatchReport`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rmse_mismatch: Option<f64>,
    /// The same per corner, in the order of [`MismatchReport::corners`].
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub rmse_corners: Vec<Option<f64>>,
    /// RMSE over the mismatch runs replayed on the nominal plant (with uncertain parameters, whose
    /// `rmse_validation` is over plants drawn in the box).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rmse_nominal: Option<f64>,
    /// Drift over long runs on the nominal plant ([`crate::observers::Drift`]).
    pub drift: DriftReport,
    /// The same on the plant at the last corner of the uncertain parameters' box.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drift_mismatch: Option<DriftReport>,
}

/// [`crate::observers::Drift`] as serialised.
#[derive(Serialize)]
pub struct DriftReport {
    /// RMSE over the first window after the start-up.
    pub rmse_first: Option<f64>,
    /// RMSE over the last window of the long runs.
    pub rmse_last: Option<f64>,
}

/// What the mismatch figures are measured on.
#[derive(Serialize)]
pub struct MismatchReport {
    /// How the plants were chosen.
    pub plants: &'static str,
    /// The uncertain parameters.
    pub parameters: Vec<String>,
    /// Every corner, the parameters in that order.
    pub corners: Vec<Vec<f64>>,
    /// Runs per corner.
    pub runs_per_corner: usize,
    /// The nominal values (the model's), in the same order.
    pub nominal: Vec<f64>,
}

/// See [`MismatchReport::plants`].
pub const MISMATCH_PLANTS: &str = "the corners of the box of the uncertain parameters (not drawn): at each, the \
     validation set's number of runs from its own seed, the same initial states, inputs and noise at every corner";

/// The EKF's tuning ([`crate::observers::ekf`]).
#[derive(Serialize)]
pub struct EkfTuning {
    /// `log10(Q_ii / s_i²)` per state (`s_i`: the state's spread over the learning runs).
    pub log_q: Vec<f64>,
    /// `log10(P(0)_ii / s_i²)` per state.
    pub log_p0: Vec<f64>,
    /// The score on the tuning runs at the choice ([`crate::observers::score`]).
    pub cost: f64,
    /// The score at the best point of the isotropic grid the search started from.
    pub grid_cost: f64,
    /// Score evaluations (grid and Nelder–Mead).
    pub evaluations: u64,
    /// The tuning runs it was chosen on (those from random starts).
    pub runs: usize,
    /// The map-started EKF's start covariance over the map's mean squared error per state.
    pub started_factor: Option<f64>,
    /// `diag(Q)` (the spec's `Q`, full, is in `fixed_filters`).
    pub q_diagonal: Vec<f64>,
    /// `diag(P(0))`.
    pub p0_diagonal: Vec<f64>,
    /// `x̂(0)` (centre of the state box, or the spec's).
    pub x0: Vec<f64>,
    /// The constants the spec fixes (`[observer.ekf]`): `"x0"`, `"q"`, `"p0"`.
    pub fixed: Vec<&'static str>,
    /// Its χ² watch (`firmware::watch`), the threshold chosen on the tuning runs (`null`: not watched);
    /// the UKF's is in `design.json` and its design file.
    pub watch: crate::plant::kalman::Watch,
}

/// The model-corrected map's tuning ([`crate::observers::kind::corrected::run`]).
#[derive(Serialize)]
#[serde(untagged)]
pub enum CorrectedTuning {
    /// Tuned.
    Tuned {
        /// `G` per state, after the start-up.
        g: Vec<f64>,
        /// `K`, states × outputs, row by row.
        k: Vec<f64>,
        /// `K₀`: the start-up gain, falling to `K` on the blend's schedule.
        k_start: Vec<f64>,
        /// `T`: the start-up blend's time constant, in estimates.
        schedule: f64,
        /// `J`: estimates that take the start-up blend.
        start_up: usize,
        /// Each state's clamp (its map's range), lower ends.
        lower: Vec<f64>,
        /// Upper ends.
        upper: Vec<f64>,
        /// Mean normalised RMSE on the tuning runs at the choice.
        cost: f64,
        /// The same at the best of the search's starts.
        start_cost: f64,
        /// Criterion evaluations (Nelder–Mead, every start).
        evaluations: u64,
        /// The best criterion with `G` free, and with `G = 0` (no map after the start-up).
        cost_with_and_without_map: (f64, f64),
    },
    /// Not available.
    Unavailable {
        /// Why.
        unavailable: String,
    },
}

/// The chip's model against the simulation's.
#[derive(Serialize)]
pub struct ChipModel {
    /// RK4 steps per sample on the chip.
    pub chip_substeps: usize,
    /// RK4 steps per sample of the learning simulation.
    pub simulation_substeps: usize,
    /// Per state, the largest one-sample difference over the validation states over its spread.
    pub max_step_difference_relative: Vec<f64>,
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

/// One reference as `report.json` holds it.
#[derive(Serialize)]
pub struct ReferenceReport {
    /// `mhe_host`, `mhe_host_prior` or `floor`.
    pub name: &'static str,
    /// What it is.
    pub what: &'static str,
    /// Per target name.
    pub targets: std::collections::BTreeMap<String, ReferenceFigures>,
    /// The moving-horizon estimate's solver, for `mhe_host` and `mhe_host_prior`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub solver: Option<SolverReport>,
    /// Its lost runs per set as an observer's (`null` on the tuning and long runs: not run there).
    pub lost: crate::observers::lost::LostRuns,
    /// The particle filter's count and its check, for `floor`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub particles: Option<ParticlesReport>,
    /// Whether the particle filter is a floor for this design, for `floor`: when it is not, the
    /// report places no observer against it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub floor: Option<FloorReport>,
}

/// A reference's figures on one target (`null` where not finite). Not on the tuning or long runs.
#[derive(Serialize)]
pub struct ReferenceFigures {
    /// RMSE over the validation windows.
    pub rmse_validation: Option<f64>,
    /// The 95th percentile over validation runs of each run's RMSE.
    pub p95_validation: Option<f64>,
    /// Largest |error| over the validation windows.
    pub max_error_validation: Option<f64>,
    /// RMSE over the scenario's windows.
    pub rmse_scenario: Option<f64>,
    /// RMSE over the scenario's noise draws, and their p95, when there is a scenario.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scenario_draws: Option<(Option<f64>, Option<f64>)>,
    /// RMSE over the mismatch runs, when parameters are uncertain.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rmse_mismatch: Option<f64>,
}

/// What the moving-horizon estimate took on the host.
#[derive(Serialize)]
pub struct SolverReport {
    /// The prior's weight and its tuning score, when it has one.
    pub prior: Option<(f64, f64)>,
    /// Windows solved.
    pub windows: usize,
    /// Mean seconds per window on the host (one thread; runs in parallel). Like the QP's
    /// `solve_time_s`, it differs from run to run, so `report.md` does not show it: its text is the
    /// same every run.
    pub mean_time_s: f64,
    /// Largest seconds for one window.
    pub max_time_s: f64,
    /// Mean Levenberg–Marquardt iterations per window (a run's first window: summed over its starts).
    pub mean_iterations: f64,
    /// The starts of a run's first window.
    pub starts: usize,
}

/// The chip's moving-horizon observer's constants and how they were chosen.
#[derive(Serialize)]
pub struct ChipReport {
    /// Its constants.
    pub constants: crate::observers::kind::mhe::run::ChipConstants,
    /// The prior's weight `p`, tuned with the converged estimate on the tuning runs.
    pub prior_weight: f64,
    /// Its tuning score at each Gauss–Newton step count tried.
    pub scores: Vec<(usize, f64)>,
    /// The converged MHE's with the same prior.
    pub converged_score: f64,
}

/// One filter the spec fixes constants of.
#[derive(Serialize)]
pub struct FixedFilterReport {
    /// Its kind: its row among the observers is the spec's filter.
    pub kind: &'static str,
    /// The spec's section (`observer.ekf`).
    pub section: &'static str,
    /// The constants the spec fixes: `"x0"`, `"q"`, `"p0"`.
    pub fixed: Vec<&'static str>,
    /// The spec's filter's constants (the fixed ones and those tuned around them).
    pub spec: FilterConstants,
    /// The same filter's constants with every one tuned.
    pub all_tuned: FilterConstants,
    /// The filter with every constant tuned, judged on the same data as the spec's.
    pub all_tuned_figures: ObserverReport,
}

/// A filter's constants and its score on the tuning runs.
#[derive(Serialize)]
pub struct FilterConstants {
    /// `x̂(0)`.
    pub x0: Vec<f64>,
    /// `Q`, per sampling period.
    pub q: crate::plant::Covariance,
    /// `P(0)`.
    pub p0: crate::plant::Covariance,
    /// The [score](crate::observers::score) on the tuning runs from random starts.
    pub score: f64,
}
