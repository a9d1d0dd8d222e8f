//! What the comparison of a design's observers yields: each observer's figures per target, the
//! plants it is judged on, the tuned constants of every kind. Kept apart from how they are computed
//! ([`super::compare`]) and how a kind is chosen from them ([`super::choice`]), since the report, the
//! tables and the emitter read these structs alone.

use super::lost::{LostRuns, LostWhich};
use crate::data::Rows;
use crate::spec::ObserverKind;

/// Errors of one observer on one target.
#[derive(Clone, Debug, PartialEq)]
pub struct Figures {
    /// RMSE over the validation windows.
    pub rmse_validation: f64,
    /// Largest |error| over the validation windows.
    pub max_error_validation: f64,
    /// The 95th percentile over validation runs of each run's RMSE ([`score::percentile_95`](super::score::percentile_95)).
    pub p95_validation: f64,
    /// RMSE over the scenario's windows.
    pub rmse_scenario: f64,
    /// RMSE over the scenario's first [`TRANSIENT_TIME`] time units after the map's first estimate.
    pub rmse_transient: f64,
    /// Per scenario of the spec, in its order (the first is `rmse_scenario`'s): the RMSE over its
    /// windows and over its transient, every observer as the chip starts it.
    pub scenarios: Vec<(f64, f64)>,
    /// RMSE over the windows of the scenario's noise draws (`data::scenario_draws`), and the 95th
    /// percentile over draws of each draw's RMSE; `None` without a scenario.
    pub scenario_draws: Option<(f64, f64)>,
    /// RMSE over the tuning runs' windows.
    pub rmse_tuning: f64,
    /// The 95th percentile over tuning runs of each run's RMSE.
    pub p95_tuning: f64,
    /// RMSE over the mismatch runs' windows: the validation runs replayed on plants at every corner of
    /// the box of the uncertain parameters (`data::uncertain::mismatch_set`); `None` when every
    /// parameter is known.
    pub rmse_mismatch: Option<f64>,
    /// The same per corner, in the order of [`MismatchRuns::corners`](crate::data::MismatchRuns::corners).
    pub rmse_corners: Vec<f64>,
    /// RMSE over the mismatch runs replayed on the nominal plant (the model's values), when
    /// parameters are uncertain (`rmse_validation` is then over plants drawn in the box).
    pub rmse_nominal: Option<f64>,
    /// Drift over long runs on the nominal plant ([`Drift`]).
    pub drift: Drift,
    /// The same on the plant at the last corner ([`MismatchRuns::scenario`](crate::data::MismatchRuns::scenario)'s plant).
    pub drift_mismatch: Option<Drift>,
}

/// Whether an observer drifts: its RMSE over the first and the last window of
/// [`Drift::WINDOWS`] after the start-up (`START_UP_HORIZONS · N` estimates after the first, for every
/// kind), on long runs from their own seed (`data::uncertain::long_set`). A window is as long as a
/// validation run (`validation.samples`): 10 s and 60 s on Example 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drift {
    /// RMSE over the first window after the start-up.
    pub first: f64,
    /// RMSE over the last window.
    pub last: f64,
}

impl Drift {
    /// Windows after the start-up in a long run.
    pub const WINDOWS: usize = 6;

    /// Samples of a long run of `design`: the map's first window, the start-up and [`Drift::WINDOWS`]
    /// windows.
    pub fn long_samples(design: &crate::spec::Design) -> usize {
        let horizon = design.map.horizon;
        horizon - 1
            + super::kind::corrected::run::START_UP_HORIZONS * horizon
            + Drift::WINDOWS * design.validation.samples
    }
}

/// Length of the transient judged, in the spec's time unit, from the first window.
pub const TRANSIENT_TIME: f64 = 2.0;

/// One observer's figures, per target in spec order, and its estimates along the scenarios.
#[derive(Clone, Debug)]
pub struct ObserverFigures {
    /// Its kind's [`ObserverKind::name`] (a reference's own name for a reference).
    pub kind: &'static str,
    /// Predicted instructions per sample on the chip in steady state ([`crate::search::cost`]).
    pub instructions: f64,
    /// Per target.
    pub targets: Vec<Figures>,
    /// The score's terms on the tuning runs, one per regime ([`super::score::regimes`]): what `auto`
    /// chooses on; empty for a reference (not run on the tuning runs).
    pub tuning_terms: Vec<super::score::Term>,
    /// Its estimates on the tuning runs, run by run (empty for a reference): kept so that the terms
    /// can be taken again once the start-up is settled ([`super::kind::Bench::settle_start_up`]).
    pub tuning_estimates: Vec<Rows>,
    /// Its estimate of every target at every sample of the scenario (NaN before its first).
    pub scenario: Rows,
    /// The same along [`MismatchRuns::scenario`](crate::data::MismatchRuns::scenario), when parameters are uncertain.
    pub mismatch_scenario: Option<Rows>,
    /// Its lost runs on each set ([`super::lost`]).
    pub lost: LostRuns,
    /// Which runs it lost on the sets the floor is run on (to count those the floor lost too).
    pub lost_which: LostWhich,
}

/// A filter started at a scenario's `observer_x0` (the observer's start the scenario names) instead
/// of its own start: its figures on that scenario.
#[derive(Clone, Debug)]
pub struct FromObserverStart {
    /// The filter's kind (one whose `[observer.<filter>]` section this is).
    pub kind: &'static str,
    /// The scenario (index in the spec's order).
    pub scenario: usize,
    /// Per target: the RMSE over the scenario's windows and over its transient.
    pub targets: Vec<(f64, f64)>,
}

/// A filter the spec fixes constants of (`[observer.<filter>]`), tuned instead in
/// every constant by the same search on the same runs: what the report shows beside the spec's.
#[derive(Clone, Debug)]
pub struct Beside {
    /// The filter with every constant tuned.
    pub tuned: super::ekf::Tuned,
    /// Its figures (`kind`: the filter's kind, whose row in the comparison is the spec's filter).
    pub figures: ObserverFigures,
}

/// The comparison of a design's observers.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// The map first, then the EKF when the host could run one.
    pub observers: Vec<ObserverFigures>,
    /// The host-only references: the on-line moving-horizon estimate and the particle floor
    /// (`observers::references`); empty when the model is beyond the host's sizes.
    pub references: Vec<Reference>,
    /// What tuning gave each kind the design has, keyed by the kind.
    pub tuned: super::kind::TunedKinds,
    /// Why the design cannot have a kind, where its tuning says why.
    pub unavailable: std::collections::BTreeMap<ObserverKind, String>,
    /// Each filter the spec fixes constants of, with every constant tuned instead.
    pub beside: Vec<Beside>,
    /// The box filters from each scenario's `observer_x0`, where it gives one.
    pub from_observer_start: Vec<FromObserverStart>,
    /// What `observer()` is, and why.
    pub chosen: (ObserverKind, String),
    /// What the tuning runs were scored with: every kind's tuning and `auto` (the regimes the
    /// report's score table shows).
    pub scoring: super::score::Scoring,
    /// Largest one-sample difference between the chip's model (`chip_substeps`) and the learning
    /// simulation's (`substeps`) over the validation states, per state, relative to its spread.
    pub chip_model_error: Vec<f64>,
}

/// One reference's figures and what it took.
#[derive(Clone, Debug)]
pub struct Reference {
    /// What it is, in a phrase.
    pub what: &'static str,
    /// Its figures (`kind`: `mhe_host`, `mhe_host_prior` or `floor`; no instruction count; tuning and drift NaN).
    pub figures: ObserverFigures,
    /// What it took.
    pub cost: Cost,
}

/// What a reference took.
#[derive(Clone, Debug)]
pub enum Cost {
    /// The moving-horizon estimate.
    Solver {
        /// The prior's weight, tuned on the tuning runs, and the tuning score there; `None` without a prior.
        prior: Option<(f64, f64)>,
        /// Windows solved (every set it is judged on).
        windows: usize,
        /// Mean and largest seconds per window on the host (one thread's time, runs in parallel).
        mean_seconds: f64,
        /// See `mean_seconds`.
        max_seconds: f64,
        /// Mean iterations per window (a run's first window: summed over its starts).
        mean_iterations: f64,
        /// The starts of a run's first window ([`super::kind::mhe::run::starts`]).
        starts: usize,
    },
    /// The particle filter.
    Particles {
        /// Particles.
        count: usize,
        /// Validation RMSE per target at each count tried, doubling from the first count (`references::FIRST_PARTICLES`).
        checked: Vec<(usize, Vec<f64>)>,
        /// Whether doubling `count` moved no target's RMSE by more than `references::CONVERGED_WITHIN`;
        /// when not (at the cap), the floor is not one on this design and the report says so.
        converged: bool,
    },
}
