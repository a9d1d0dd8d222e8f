//! Every run a design is fitted, tuned and judged on, simulated once into one value ([`Runs`]) that
//! every stage receives: the design search and the fit read the learning and tuning runs, the
//! observers are tuned on the tuning runs and judged on the others, the report names the set behind
//! each figure. Each set has its own seed, so no figure is ever computed on runs a constant was
//! chosen on.

use super::{
    learning_set, scenario_draws, scenario_run, scenario_runs, tuning_set, uncertain, validation_set, DataSet, Run,
};
use crate::spec::{Design, SpecError};

/// A design's runs, one field per set (see each for what it is used for).
#[derive(Clone, Debug)]
pub struct Runs {
    /// The learning grid ([`learning_set`]): the maps are fitted on it, and only on it.
    pub learning: DataSet,
    /// The validation runs ([`validation_set`]): every `validation` figure.
    pub validation: DataSet,
    /// The tuning runs ([`tuning_set`]): every tuned constant, the design search's score and `auto`'s.
    pub tuning: DataSet,
    /// The scenario: the spec's `[scenario]` ([`scenario_run`]), else the first validation run; the
    /// `scenario` and `transient` figures and the estimation figure.
    pub scenario: Run,
    /// Every scenario's run ([`scenario_runs`]), in spec order (the first is [`Runs::scenario`]'s):
    /// the per-scenario figures.
    pub scenarios: Vec<Run>,
    /// The scenario's noise draws ([`scenario_draws`]); `None` without a `[scenario]`.
    pub scenario_draws: Option<DataSet>,
    /// Long runs on the nominal plant ([`uncertain::long_set`]): the drift figures.
    pub long: DataSet,
    /// The plants of the uncertain parameters; `None` when every parameter is known.
    pub mismatch: Option<MismatchRuns>,
}

/// The runs on the plants of the uncertain parameters' box: the mismatch figures.
#[derive(Clone, Debug)]
pub struct MismatchRuns {
    /// Every corner of the box ([`uncertain::corners`]), parameters in the order of `Model::uncertain`.
    pub corners: Vec<Vec<f64>>,
    /// The nominal values of the uncertain parameters ([`uncertain::nominal`]).
    pub nominal: Vec<f64>,
    /// The validation settings replayed at every corner ([`uncertain::mismatch_set`]).
    pub corners_set: DataSet,
    /// The same initial states, inputs and noise on the nominal plant ([`uncertain::corner_set`]).
    pub nominal_set: DataSet,
    /// Long runs on the plant at the last corner: the drift under mismatch.
    pub long: DataSet,
    /// The scenario on the plant at the last corner (without a `[scenario]`, the first run there).
    pub scenario: Run,
}

impl Runs {
    /// Simulates every set of `design`, long runs of `long_samples` samples.
    pub fn simulate(design: &Design, long_samples: usize) -> Result<Self, SpecError> {
        Self::complete(design, learning_set(design)?, tuning_set(design)?, long_samples)
    }

    /// Every set of `design` from its learning and tuning runs, simulated already (for the design
    /// search, whose choice of `N` does not change them: they are cut anew at `design.map.horizon`).
    pub fn complete(
        design: &Design,
        mut learning: DataSet,
        mut tuning: DataSet,
        long_samples: usize,
    ) -> Result<Self, SpecError> {
        let horizon = design.map.horizon;
        learning.horizon = horizon;
        tuning.horizon = horizon;
        let validation = validation_set(design)?;
        let scenario = scenario(design, &validation)?;
        Ok(Runs {
            learning,
            tuning,
            scenario,
            validation,
            scenarios: scenario_runs(design)?,
            scenario_draws: scenario_draws(design)?,
            long: uncertain::long_set(design, None, long_samples)?,
            mismatch: MismatchRuns::simulate(design, long_samples)?,
        })
    }
}

/// The scenario of [`Runs::scenario`]: the spec's `[scenario]`, else the first run of `validation`,
/// the design's validation set.
pub fn scenario(design: &Design, validation: &DataSet) -> Result<Run, SpecError> {
    Ok(match scenario_run(design, &design.model, "scenario")? {
        Some(run) => run,
        None => validation.runs[0].clone(),
    })
}

impl MismatchRuns {
    /// The mismatch runs of `design`, `None` when every parameter is known.
    fn simulate(design: &Design, long_samples: usize) -> Result<Option<Self>, SpecError> {
        let Some(corners_set) = uncertain::mismatch_set(design)? else {
            return Ok(None);
        };
        let corners = uncertain::corners(&design.model);
        let last = corners.last().expect("a mismatch set has corners").clone();
        let plant = design.model.with_parameters(&design.model.values_with_uncertain(&last));
        let scenario = match scenario_run(design, &plant, "mismatch scenario")? {
            Some(run) => run,
            None => corners_set.runs[corners_set.runs.len() - design.validation.trajectories].clone(),
        };
        let nominal = uncertain::nominal(&design.model);
        Ok(Some(MismatchRuns {
            nominal_set: uncertain::corner_set(design, &nominal)?,
            long: uncertain::long_set(design, Some(&last), long_samples)?,
            corners_set,
            scenario,
            nominal,
            corners,
        }))
    }
}
