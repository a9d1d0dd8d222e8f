//! The simulated runs besides the learning grid: `[validation]`, `[tuning]` (defaulting from it, with
//! a seed of its own) and `[scenario]`, each long enough to hold a window.

use std::collections::BTreeMap;

use super::limits;
use super::raw::*;
use super::validate::Validator;
use super::*;

impl Validator {
    /// One finite value per state, from the table at `field`.
    pub(super) fn state_values(
        &self,
        field: &str,
        raw: &BTreeMap<String, f64>,
        model: &Model,
    ) -> Result<Vec<f64>, SpecError> {
        self.keys_among(
            field,
            raw.keys(),
            &model.states,
            "a state",
            "give one initial value per state",
        )?;
        model
            .states
            .iter()
            .map(|state| match raw.get(state) {
                Some(v) if v.is_finite() => Ok(*v),
                Some(v) => Err(self.err(
                    format!("{field}.{state}"),
                    format!("{v} is not finite"),
                    "give a finite initial value",
                )),
                None => Err(self.err(
                    format!("{field}.{state}"),
                    format!("no initial value for `{state}`"),
                    format!("add `{state} = …` to `{field}`"),
                )),
            })
            .collect()
    }

    /// `[scenario]` or `[[scenario]]`: each scenario checked, named (a single `[scenario]` may leave
    /// its name out: `scenario`), the names distinct.
    pub(super) fn scenarios(
        &self,
        raw: &RawScenarios,
        model: &Model,
        horizon: usize,
    ) -> Result<Vec<Scenario>, SpecError> {
        let sections = raw.sections();
        if sections.is_empty() || sections.len() > limits::MAX_SCENARIOS {
            return Err(self.err(
                "scenario",
                format!("{} scenarios", sections.len()),
                format!(
                    "give 1 to {} `[[scenario]]` tables, or leave them out",
                    limits::MAX_SCENARIOS
                ),
            ));
        }
        let many = sections.len() > 1;
        let mut scenarios: Vec<Scenario> = Vec::new();
        for (section, raw) in sections {
            let scenario = self.scenario(&section, raw, model, horizon, many)?;
            if scenarios.iter().any(|s| s.name == scenario.name) {
                return Err(self.err(
                    format!("{section}.name"),
                    format!("a scenario is already named `{}`", scenario.name),
                    "give every scenario a name of its own",
                ));
            }
            scenarios.push(scenario);
        }
        Ok(scenarios)
    }

    /// One scenario in section `section`; `many`: it is one of several, so it needs a name.
    fn scenario(
        &self,
        section: &str,
        raw: &RawScenario,
        model: &Model,
        horizon: usize,
        many: bool,
    ) -> Result<Scenario, SpecError> {
        let name = match &raw.name {
            Some(name) => {
                self.identifier(&format!("{section}.name"), name)?;
                name.clone()
            }
            None if many => {
                return Err(self.err(
                    format!("{section}.name"),
                    "one of several scenarios has no name",
                    "give each `[[scenario]]` a `name` (e.g. \"start_up\"): the report's tables and figures say it",
                ))
            }
            None => "scenario".to_owned(),
        };
        let x0 = self.state_values(&format!("{section}.x0"), &raw.x0, model)?;
        let observer_x0 = raw
            .observer_x0
            .as_ref()
            .map(|values| self.state_values(&format!("{section}.observer_x0"), values, model))
            .transpose()?;
        let samples = format!("{section}.samples");
        self.at_most(&samples, raw.samples, limits::MAX_RUN_SAMPLES)?;
        if raw.samples < horizon {
            return Err(self.err(
                &samples,
                format!("{} samples hold no window of N = {horizon}", raw.samples),
                format!("set `{samples}` ≥ `map.horizon`"),
            ));
        }
        Ok(Scenario {
            name,
            x0,
            observer_x0,
            samples: raw.samples,
            seed: raw.seed,
        })
    }

    /// `[tuning]`, each field defaulting from `[validation]`; the seed must differ from every other.
    pub(super) fn tuning(
        &self,
        raw: Option<&RawTuning>,
        validation: &Validation,
        learning: &Learning,
        scenarios: Option<&RawScenarios>,
        horizon: usize,
    ) -> Result<Validation, SpecError> {
        let mut others = vec![learning.seed, validation.seed];
        others.extend(scenarios.iter().flat_map(|s| s.sections()).map(|(_, s)| s.seed));
        let taken = |seed: u64| others.contains(&seed);
        let seed = match raw.and_then(|t| t.seed) {
            Some(seed) if taken(seed) => {
                return Err(self.err(
                    "tuning.seed",
                    format!("seed {seed} is also the learning, validation or scenario seed: the tuning runs would not be new data"),
                    "choose another seed, or leave it out (a free one is derived from `validation.seed`)",
                ))
            }
            Some(seed) => seed,
            None => (1..).map(|k| validation.seed.wrapping_add(1000 * k)).find(|s| !taken(*s)).expect("a few seeds cannot take them all"),
        };
        let raw = RawValidation {
            trajectories: raw.and_then(|t| t.trajectories).unwrap_or(validation.trajectories),
            samples: raw.and_then(|t| t.samples).unwrap_or(validation.samples),
            seed,
        };
        self.runs("tuning", &raw, horizon)
    }

    /// `tuning.start_up` (in the spec's time unit) in samples after the first estimate: at least one,
    /// and within a tuning run's estimates.
    pub(super) fn start_up(
        &self,
        raw: Option<&RawTuning>,
        tau: f64,
        tuning: &Validation,
        horizon: usize,
    ) -> Result<Option<usize>, SpecError> {
        let Some(time) = raw.and_then(|t| t.start_up) else {
            return Ok(None);
        };
        let estimates = tuning.samples + 1 - horizon;
        let samples = (time / tau).round();
        if !(samples >= 1.0 && samples <= estimates as f64) {
            return Err(self.err(
                "tuning.start_up",
                format!("a start-up of {time} is {samples} samples of {tau}; a tuning run holds {estimates} estimates"),
                format!(
                    "set `tuning.start_up` between {tau} and {} (the sample period times the estimates of a run), or leave it out (the box filters' settling time is used)",
                    tau * estimates as f64
                ),
            ));
        }
        Ok(Some(samples as usize))
    }

    /// The random runs of section `section` (`validation` or `tuning`).
    pub(super) fn runs(&self, section: &str, raw: &RawValidation, horizon: usize) -> Result<Validation, SpecError> {
        if raw.trajectories == 0 {
            return Err(self.err(
                format!("{section}.trajectories"),
                format!("no {section} run"),
                format!("set `{section}.trajectories` to 1 or more (50 or more is sensible)"),
            ));
        }
        self.at_most(
            &format!("{section}.trajectories"),
            raw.trajectories,
            limits::MAX_TRAJECTORIES,
        )?;
        self.at_most(&format!("{section}.samples"), raw.samples, limits::MAX_RUN_SAMPLES)?;
        if raw.samples < horizon {
            return Err(self.err(
                format!("{section}.samples"),
                format!("runs of {} samples hold no window of N = {horizon}", raw.samples),
                format!("set `{section}.samples` ≥ `map.horizon`"),
            ));
        }
        Ok(Validation {
            trajectories: raw.trajectories,
            samples: raw.samples,
            seed: raw.seed,
        })
    }
}
