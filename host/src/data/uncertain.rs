//! Runs on a plant whose parameters are not the model's nominal values: the draws that make the
//! learning, validation and tuning runs cover the declared parameter ranges, and the mismatch set,
//! which replays the validation runs at every corner of the parameter box.
//!
//! The observers are built and emitted on the nominal model; only the simulated plant moves. A design
//! whose parameters are all known draws nothing here, so its data are bit for bit those of a tool
//! without ranges (the generated files do not change).

use rand::RngExt;
use rand_chacha::ChaCha8Rng;

use super::{cartesian, random_runs, DataSet};
use crate::spec::model::Model;
use crate::spec::{Design, SpecError};

/// The plant of one learning, validation or tuning run: the model with each uncertain parameter drawn
/// uniformly in its `[min, max]` from `rng`, in the order of `Model::uncertain`; `None`, drawing
/// nothing, when every parameter is known.
///
/// Where the draws fall in a run's use of the generator: first. A random run (validation, tuning)
/// draws its parameters, then its initial state, inputs and noise; a grid run (learning) its
/// parameters, then its inputs and noise.
pub fn draw_plant(model: &Model, rng: &mut ChaCha8Rng) -> Option<Model> {
    if model.uncertain.is_empty() {
        return None;
    }
    let mut values = model.parameter_values();
    for u in &model.uncertain {
        values[u.index] = rng.random_range(u.min..=u.max);
    }
    Some(model.with_parameters(&values))
}

/// Every corner of the box of the uncertain parameters, each as their values in the order of
/// `Model::uncertain` (what [`corner_set`] takes): `2^p` corners for `p` uncertain parameters,
/// counted in binary with the first parameter varying slowest, so the first corner is every
/// parameter at its `min` and the last every parameter at its `max`. None when nothing is uncertain.
pub fn corners(model: &Model) -> Vec<Vec<f64>> {
    if model.uncertain.is_empty() {
        return Vec::new();
    }
    let sides: Vec<Vec<f64>> = model.uncertain.iter().map(|u| vec![u.min, u.max]).collect();
    cartesian(&sides)
}

/// The seed of the mismatch runs: the first of `validation.seed + 1000 k`, `k = 1, 2, …` (wrapping),
/// that is none of the learning, validation, tuning and scenario seeds. With `[tuning]`'s default
/// seed (`validation.seed + 1000`) that is `validation.seed + 2000`. Its own seed, so that the mismatch
/// runs start from other states, with other inputs and noise, than any run the maps or the observers
/// were fitted, tuned or judged on.
pub fn mismatch_seed(design: &Design) -> u64 {
    free_seed(design, 0)
}

/// The `index`-th (from 0) of the seeds `validation.seed + 1000 k`, `k = 1, 2, …` (wrapping), that is
/// none of the learning, validation, tuning and scenario seeds: 0 is [`mismatch_seed`], 1 the long
/// runs' ([`long_set`]).
pub fn free_seed(design: &Design, index: usize) -> u64 {
    let taken = [
        Some(design.learning.seed),
        Some(design.validation.seed),
        Some(design.tuning.seed),
        design.scenario().map(|s| s.seed),
    ];
    (1..)
        .map(|k: u64| design.validation.seed.wrapping_add(1000 * k))
        .filter(|seed| !taken.contains(&Some(*seed)))
        .nth(index)
        .expect("four seeds cannot take them all")
}

/// Long runs, to see whether an observer drifts: `validation.trajectories` runs of `samples` samples
/// from random states in the box, from their own seed ([`free_seed`] 1), on the plant with the
/// uncertain parameters at `values` (in the order of `Model::uncertain`), or on the nominal model
/// when `values` is `None`. Nothing is drawn for the parameters.
pub fn long_set(design: &Design, values: Option<&[f64]>, samples: usize) -> Result<DataSet, SpecError> {
    let plant = match values {
        Some(values) => design
            .model
            .with_parameters(&design.model.values_with_uncertain(values)),
        None => design.model.clone(),
    };
    let settings = crate::spec::Validation {
        seed: free_seed(design, 1),
        samples,
        ..design.validation
    };
    random_runs(design, &settings, "long", Some(&plant))
}

/// The nominal values of the uncertain parameters, in the order of `Model::uncertain`.
pub fn nominal(model: &Model) -> Vec<f64> {
    let values = model.parameter_values();
    model.uncertain.iter().map(|u| values[u.index]).collect()
}

/// The runs of the mismatch set at one point of the parameter box: the uncertain parameters at
/// `values` (in the order of `Model::uncertain`; usually a corner from [`corners`], but any values are
/// simulated), the others nominal. As the validation set (`validation.trajectories` runs of
/// `validation.samples`, initial states uniform in the box, the same inputs profiles and noise) but
/// from [`mismatch_seed`], and with nothing drawn for the parameters: every point gets the same
/// initial states, inputs and noise, so that two points differ only by their plant. Each run records
/// all its parameters in `Run::parameters`.
///
/// The all-max corner, for a report's "on a plant with a = 4.4, b = 1.1", is `corners(..).last()`.
///
/// # Panics
/// When `values` does not hold one value per uncertain parameter.
pub fn corner_set(design: &Design, values: &[f64]) -> Result<DataSet, SpecError> {
    let plant = design
        .model
        .with_parameters(&design.model.values_with_uncertain(values));
    let settings = crate::spec::Validation {
        seed: mismatch_seed(design),
        ..design.validation
    };
    random_runs(design, &settings, "mismatch", Some(&plant))
}

/// The mismatch set: [`corner_set`] at every corner of the parameter box, in the order of
/// [`corners`], concatenated (run `i` is at corner `i / validation.trajectories`, which its
/// `Run::parameters` also records). `None` when every parameter is known. The spec refuses more than
/// `spec::limits::MAX_UNCERTAIN` uncertain parameters, which bounds the set at 256 times the validation
/// set (`spec::limits::check_budget` counts it).
pub fn mismatch_set(design: &Design) -> Result<Option<DataSet>, SpecError> {
    let corners = corners(&design.model);
    if corners.is_empty() {
        return Ok(None);
    }
    let mut runs = Vec::with_capacity(corners.len() * design.validation.trajectories);
    for corner in &corners {
        runs.extend(corner_set(design, corner)?.runs);
    }
    Ok(Some(DataSet {
        runs,
        horizon: design.map.horizon,
    }))
}

#[cfg(test)]
mod tests;
