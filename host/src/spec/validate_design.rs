//! The whole spec into a [`Design`]: each section checked (here or in the other `validate_*`
//! modules), then the design's size against the budget of [`super::limits`]; and the sections that
//! belong to the design as a whole (`[family]`, `[[targets]]`, `[budget]`).

use super::limits;
use super::raw::*;
use super::validate::Validator;
use super::*;

impl Validator {
    pub(super) fn design(&self, raw: RawSpec) -> Result<Design, SpecError> {
        let name_ok = is_module_name(&raw.name);
        if !name_ok {
            return Err(self.err(
                "name",
                format!("`{}` is not a lower-case identifier, or is reserved", raw.name),
                "use lower-case letters, digits and `_`, starting with a letter, not a Rust keyword nor `lib` (it names a module in generated/)",
            ));
        }
        let model = self.model(&raw.model)?;
        let tau = self.positive("sampling.tau", raw.sampling.tau, "the sample period τ")?;
        // The chip holds τ in f32: checked here, before anything is fitted, not when it is emitted.
        if (tau as f32).is_subnormal() || tau as f32 == 0.0 || !(tau as f32).is_finite() {
            return Err(self.err(
                "sampling.tau",
                format!(
                    "the sample period τ = {tau:e} is outside the normal f32 range ({:e} to {:e}): the chip would see 0, ∞ or a value without precision",
                    f32::MIN_POSITIVE,
                    f32::MAX
                ),
                "rescale it: change `sampling.time_unit` (e.g. from s to µs) and every rate with it",
            ));
        }
        if raw.sampling.substeps == 0 {
            return Err(self.err(
                "sampling.substeps",
                "RK4 needs at least one step per sample",
                "set `sampling.substeps` to 1 or more (10 is usual)",
            ));
        }
        self.at_most("sampling.substeps", raw.sampling.substeps, limits::MAX_SUBSTEPS)?;
        let (map, search) = self.map(&raw.map)?;
        let budget = self.budget(raw.budget.as_ref())?;
        let fixed = self.chip(raw.chip.as_ref(), &model)?;
        let learning = self.learning(&raw.learning, &model, map.horizon)?;
        let validation = self.runs("validation", &raw.validation, map.horizon)?;
        let tuning = self.tuning(
            raw.tuning.as_ref(),
            &validation,
            &learning,
            raw.scenario.as_ref(),
            map.horizon,
        )?;
        let start_up = self.start_up(raw.tuning.as_ref(), tau, &tuning, map.horizon)?;
        if raw.sampling.chip_substeps == 0 {
            return Err(self.err(
                "sampling.chip_substeps",
                "the model on the chip needs at least one RK4 step per sample",
                "set `sampling.chip_substeps` to 1 or more (1 is the default)",
            ));
        }
        self.at_most(
            "sampling.chip_substeps",
            raw.sampling.chip_substeps,
            super::MAX_CHIP_SUBSTEPS,
        )?;
        self.label("sampling.time_unit", &raw.sampling.time_unit)?;
        // The description is prose of any length; line breaks and tabs are kept (doc comments make
        // them spaces), other control characters are not text.
        if raw
            .description
            .chars()
            .any(|c| c.is_control() && c != '\n' && c != '\t')
        {
            return Err(self.err(
                "description",
                "it holds a control character",
                "write the description as plain text (line breaks and tabs are fine)",
            ));
        }
        let targets = self.targets(&raw.targets, &model)?;
        let (state_units, input_units) = self.units(&raw.model.units, &model)?;
        let state_bounds = self.bounds(&raw.model.bounds, &model, &learning)?;
        let family = raw
            .family
            .as_ref()
            .map(|f| self.family(f, &model, &raw.name))
            .transpose()?;
        let scenarios = match &raw.scenario {
            Some(s) => self.scenarios(s, &model, map.horizon)?,
            None => Vec::new(),
        };
        let mut filters = FixedFilters::default();
        if let Some(observer) = &raw.observer {
            for (section, fixed) in observer.filter_sections() {
                if fixed.is_some() {
                    filters.insert(section, self.fixed_filter(section, fixed, &model)?);
                }
            }
        }
        self.starts_within_bounds(&model, &state_bounds, &scenarios, &filters)?;
        let design = Design {
            file: self.path.clone(),
            name: raw.name,
            description: raw.description,
            model,
            tau,
            time_unit: raw.sampling.time_unit.clone(),
            state_units,
            input_units,
            state_bounds,
            substeps: raw.sampling.substeps,
            learning,
            validation,
            tuning,
            start_up,
            chip_substeps: raw.sampling.chip_substeps,
            map,
            search,
            max_candidates: self.max_candidates(raw.search.as_ref())?,
            budget,
            targets,
            scenarios,
            family,
            observer: raw.observer.as_ref().map(|o| o.kind).unwrap_or_default(),
            filters,
            fixed,
            spec_sha256: String::new(),
        };
        limits::check_budget(&design)?;
        if let Some(search) = &design.search {
            crate::search::check_size(&design, search)?;
        }
        Ok(design)
    }

    fn family(&self, raw: &RawFamily, model: &Model, design: &str) -> Result<Family, SpecError> {
        if !is_module_name(&raw.name) || raw.name == design {
            return Err(self.err(
                "family.name",
                format!("`{}` cannot name the family's module", raw.name),
                "use a lower-case identifier that is not a Rust keyword and differs from every design name",
            ));
        }
        let output = model.outputs.iter().position(|o| o.name == raw.output).ok_or_else(|| {
            let names: Vec<&str> = model.outputs.iter().map(|o| o.name.as_str()).collect();
            self.err(
                "family.output",
                format!("`{}` is not an output", raw.output),
                format!("name one of the outputs: {}", names.join(", ")),
            )
        })?;
        if !raw.value.is_finite() {
            return Err(self.err(
                "family.value",
                format!("{} is not finite", raw.value),
                "give this member's value of the output",
            ));
        }
        Ok(Family {
            name: raw.name.clone(),
            output,
            value: raw.value,
        })
    }

    fn targets(&self, raw: &[RawTarget], model: &Model) -> Result<Vec<Target>, SpecError> {
        if raw.is_empty() {
            return Err(self.err(
                "targets",
                "nothing to estimate",
                "add a `[[targets]]` table with `name` and `expr` (e.g. a state name)",
            ));
        }
        let scope = model.scope();
        let mut targets: Vec<Target> = Vec::new();
        for (i, t) in raw.iter().enumerate() {
            self.identifier(&format!("targets[{i}].name"), &t.name)?;
            if targets.iter().any(|other| other.name == t.name) {
                return Err(self.err(
                    format!("targets[{i}].name"),
                    format!("target `{}` is declared twice", t.name),
                    "give each target its own name",
                ));
            }
            self.label(format!("targets[{i}].unit"), &t.unit)?;
            let expr = Expression::compile(&t.expr, &scope)
                .map_err(|e| self.err(format!("targets[{i}].expr"), e.to_string(), e.fix()))?;
            let weight = t.weight.unwrap_or(1.0);
            if !(weight.is_finite() && weight >= 0.0) {
                return Err(self.err(
                    format!("targets[{i}].weight"),
                    format!(
                        "target `{}` has weight {weight}: a weight is a finite number ≥ 0",
                        t.name
                    ),
                    "give the target's share of the score (default 1; 0 to report it without choosing for it)",
                ));
            }
            targets.push(Target {
                name: t.name.clone(),
                unit: t.unit.clone(),
                expr,
                weight,
            });
        }
        if targets.iter().all(|t| t.weight == 0.0) {
            return Err(self.err(
                "targets[0].weight",
                "every target has weight 0: nothing would be chosen for any of them",
                "give at least one target a weight above 0 (leave `weight` out for 1)",
            ));
        }
        Ok(targets)
    }

    /// `[budget]`: each limit, when given, positive.
    fn budget(&self, raw: Option<&RawBudget>) -> Result<Budget, SpecError> {
        let Some(raw) = raw else {
            return Ok(Budget::default());
        };
        let whole = |field: &str, value: Option<u64>, what: &str| match value {
            Some(0) => Err(self.err(
                field,
                format!("a budget of 0 {what} leaves no observer"),
                format!("set `{field}` to the most the chip can spend, or leave it out"),
            )),
            _ => Ok(value),
        };
        Ok(Budget {
            instructions: whole("budget.instructions", raw.instructions, "instructions per sample")?,
            first_estimate: raw
                .first_estimate
                .map(|t| self.positive("budget.first_estimate", t, "the delay to the first estimate"))
                .transpose()?,
            flash: whole("budget.flash", raw.flash, "bytes")?,
        })
    }
}
