//! Field-by-field validation of a parsed spec: every problem becomes a [`SpecError`] naming the field
//! and the fix. The model and the learning grid are checked in [`super::validate_model`].

use std::collections::BTreeMap;

use super::limits;
use super::raw::*;
use super::*;

/// Characters a unit may not hold: markup of Markdown tables, HTML, SVG and code spans.
const LABEL_MARKUP: &str = "<>&|`\\\"";

pub(super) struct Validator {
    pub(super) file: String,
    pub(super) path: PathBuf,
}

impl Validator {
    pub(super) fn err(
        &self,
        field: impl Into<String>,
        problem: impl Into<String>,
        fix: impl Into<String>,
    ) -> SpecError {
        SpecError {
            file: self.file.clone(),
            field: field.into(),
            problem: problem.into(),
            fix: fix.into(),
        }
    }

    /// A unit: a short label on one line. Units reach doc comments, the C header, the report's
    /// Markdown tables and the figures' SVG; each of those escapes what it must, and nothing of more
    /// than one line or [`MAX_LABEL`] characters is a unit.
    pub(super) fn label(&self, field: impl Into<String>, text: &str) -> Result<(), SpecError> {
        if text.chars().any(char::is_control) || text.chars().count() > MAX_LABEL {
            return Err(self.err(
                field,
                "a unit is a short label on one line",
                format!("write it in at most {MAX_LABEL} characters, without line breaks or control characters (e.g. \"cm\", \"m/s^2\")"),
            ));
        }
        // A unit is shown as it is written in Markdown tables, HTML, SVG (XML) and code comments: none
        // of their markup characters may appear in it.
        if let Some(c) = text.chars().find(|c| LABEL_MARKUP.contains(*c)) {
            return Err(self.err(
                field,
                format!("a unit may not hold `{c}`: the reports' tables, HTML and figures would read it as markup"),
                "write it without < > & | ` \\ \" (e.g. \"g/(L h)\", \"m·s\", \"deg C\")",
            ));
        }
        Ok(())
    }

    pub(super) fn identifier(&self, field: &str, name: &str) -> Result<(), SpecError> {
        let mut chars = name.chars();
        let valid = matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
            && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
        if RESERVED_NAMES.contains(&name) || RESERVED_PREFIXES.iter().any(|p| name.starts_with(p)) {
            return Err(self.err(
                field,
                format!(
                    "`{name}` is reserved: it names a column of the CSV files `simulate`, `estimate` and `plot` use"
                ),
                format!(
                    "rename it (reserved: {}, and names starting with {})",
                    RESERVED_NAMES.join(", "),
                    RESERVED_PREFIXES.join(" or ")
                ),
            ));
        }
        if crate::spec::expr::is_operator_name(name) {
            return Err(self.err(
                field,
                format!("`{name}` is a function or constant of the expression language: expressions would read it as that, not as this name"),
                "rename it (e.g. `E` → `E0`, `PI` → `p`, `exp` → `expo`)",
            ));
        }
        if valid {
            Ok(())
        } else {
            Err(self.err(
                field,
                format!("`{name}` is not a valid name"),
                "use letters, digits and `_`, starting with a letter",
            ))
        }
    }

    /// Every key of the table `section` must be one of `names` (`kind`: "a state", "an input"); `fix`
    /// says what the table holds, and the names are listed after it.
    pub(super) fn keys_among<'k>(
        &self,
        section: &str,
        keys: impl IntoIterator<Item = &'k String>,
        names: &[String],
        kind: &str,
        fix: &str,
    ) -> Result<(), SpecError> {
        match keys.into_iter().find(|key| !names.contains(key)) {
            Some(key) => Err(self.err(
                format!("{section}.{key}"),
                format!("`{key}` is not {kind}"),
                format!("{fix} ({})", names.join(", ")),
            )),
            None => Ok(()),
        }
    }

    pub(super) fn positive(&self, field: &str, value: f64, what: &str) -> Result<f64, SpecError> {
        if value.is_finite() && value > 0.0 {
            Ok(value)
        } else {
            Err(self.err(
                field,
                format!("{what} must be a finite number > 0, got {}", readable(value)),
                format!("set `{field}` to a positive value"),
            ))
        }
    }

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
        let learning = self.learning(&raw.learning, &model, map.horizon)?;
        let validation = self.runs("validation", &raw.validation, map.horizon)?;
        let tuning = self.tuning(
            raw.tuning.as_ref(),
            &validation,
            &learning,
            raw.scenario.as_ref(),
            map.horizon,
        )?;
        if raw.sampling.chip_substeps == 0 {
            return Err(self.err(
                "sampling.chip_substeps",
                "the model on the chip needs at least one RK4 step per sample",
                "set `sampling.chip_substeps` to 1 or more (1 is the default)",
            ));
        }
        self.at_most("sampling.chip_substeps", raw.sampling.chip_substeps, 64)?;
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
        let scenario = raw
            .scenario
            .as_ref()
            .map(|s| self.scenario(s, &model, map.horizon))
            .transpose()?;
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
            chip_substeps: raw.sampling.chip_substeps,
            map,
            search,
            max_candidates: self.max_candidates(raw.search.as_ref())?,
            budget,
            targets,
            scenario,
            family,
            observer: raw.observer.map(|o| o.kind).unwrap_or_default(),
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

    /// One finite value per state, from the table at `field`.
    fn state_values(&self, field: &str, raw: &BTreeMap<String, f64>, model: &Model) -> Result<Vec<f64>, SpecError> {
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

    fn scenario(&self, raw: &RawScenario, model: &Model, horizon: usize) -> Result<Scenario, SpecError> {
        let x0 = self.state_values("scenario.x0", &raw.x0, model)?;
        let observer_x0 = raw
            .observer_x0
            .as_ref()
            .map(|values| self.state_values("scenario.observer_x0", values, model))
            .transpose()?;
        self.at_most("scenario.samples", raw.samples, limits::MAX_RUN_SAMPLES)?;
        if raw.samples < horizon {
            return Err(self.err(
                "scenario.samples",
                format!("{} samples hold no window of N = {horizon}", raw.samples),
                "set `scenario.samples` ≥ `map.horizon`",
            ));
        }
        Ok(Scenario {
            x0,
            observer_x0,
            samples: raw.samples,
            seed: raw.seed,
        })
    }

    /// `[map]`: one value of each field, or the search's candidates.
    fn map(&self, raw: &RawMap) -> Result<(MapSettings, Option<Search>), SpecError> {
        let horizons = self.choices("map.horizon", &raw.horizon, || Search::AUTO_HORIZONS.collect())?;
        let nms = self.choices("map.nm", &raw.nm, || Search::AUTO_NMS.to_vec())?;
        let betas = self.choices("map.beta", &raw.beta, || Search::AUTO_BETAS.to_vec())?;
        for &horizon in &horizons {
            if horizon == 0 {
                return Err(self.err(
                    "map.horizon",
                    "the horizon N must be at least 1",
                    "set `map.horizon` to the number of past measurements to use (the paper uses 10 and 3), or \"auto\"",
                ));
            }
            self.at_most("map.horizon", horizon, limits::MAX_HORIZON)?;
        }
        for &nm in &nms {
            self.at_most("map.nm", nm, limits::MAX_NM)?;
            if nm == 0 {
                return Err(self.err(
                    "map.nm",
                    "n_m must be at least 1",
                    "set `map.nm` (the paper uses 5), or \"auto\"",
                ));
            }
        }
        for &beta in &betas {
            self.positive("map.beta", beta, "β")?;
        }
        self.at_most(
            "map.monotonicity_grid",
            raw.monotonicity_grid,
            limits::MAX_MONOTONICITY_GRID,
        )?;
        let largest = |values: &[f64]| values.iter().copied().fold(f64::MIN, f64::max);
        let (nm_max, beta_max) = (*nms.iter().max().expect("checked non-empty"), largest(&betas));
        if beta_max * (nm_max as f64 - 1.0) > 30.0 {
            return Err(self.err(
                "map.beta",
                format!(
                    "β·(n_m - 1) = {} (β = {beta_max}, n_m = {nm_max}) makes basis odds ratios reach e^{:.0}: the basis degenerates to steps",
                    beta_max * (nm_max as f64 - 1.0),
                    beta_max * (nm_max as f64 - 1.0)
                ),
                "keep β·(n_m - 1) ≤ 30 for every candidate (β of 0.5 to 3 is usual)",
            ));
        }
        let taps = match &raw.taps {
            None => Taps::All,
            Some(RawChoice::Auto) => Taps::Auto,
            Some(choice) => {
                let counts = self.choices("map.taps", choice, Vec::new)?;
                if counts.contains(&0) {
                    return Err(self.err(
                        "map.taps",
                        "a map needs at least one tap",
                        "set `map.taps` to the number of non-zero gains to keep per target (≥ 1), a list of them, or \"auto\"; leave it out to keep every gain",
                    ));
                }
                Taps::Counts(counts)
            }
        };
        let (horizon, nm, beta) = (*horizons.iter().max().expect("checked non-empty"), nms[0], betas[0]);
        let fixed_taps = match &taps {
            Taps::All => Some(None),
            Taps::Counts(counts) if counts.len() == 1 => Some(Some(counts[0])),
            _ => None,
        };
        let search =
            (horizons.len() > 1 || nms.len() > 1 || betas.len() > 1 || fixed_taps.is_none()).then_some(Search {
                horizons,
                nms,
                betas,
                taps,
            });
        let epsilon = self.positive("map.epsilon", raw.epsilon, "ε")?;
        if !(1e-12..=1e12).contains(&epsilon) {
            return Err(self.err(
                "map.epsilon",
                format!("ε = {} is outside [1e-12, 1e12]: the QP loses its scale", readable(epsilon)),
                "set `map.epsilon` near the spread of the target times 1e-2 (0.01 is usual; with `intercept` the map does not depend on it)",
            ));
        }
        if raw.monotonicity_grid < 3 {
            return Err(self.err(
                "map.monotonicity_grid",
                format!(
                    "{} points cannot constrain the slope of Γ on [0, 1]",
                    raw.monotonicity_grid
                ),
                "use 201 or more points",
            ));
        }
        let settings = MapSettings {
            horizon,
            nm,
            beta,
            epsilon,
            normalisation: raw.normalisation,
            monotonicity_grid: raw.monotonicity_grid,
            taps: fixed_taps.flatten(),
        };
        Ok((settings, search))
    }

    /// `[search] max_candidates`: a whole number ≥ 1, or the default.
    fn max_candidates(&self, raw: Option<&RawSearch>) -> Result<usize, SpecError> {
        let default = crate::search::DEFAULT_MAX_CANDIDATES;
        let fix =
            format!("set `search.max_candidates` to a whole number ≥ 1 (the default is {default}), or leave it out");
        match raw.and_then(|r| r.max_candidates.as_ref()) {
            None => Ok(default),
            Some(toml::Value::Integer(n)) => match usize::try_from(*n) {
                Ok(n) if n >= 1 => Ok(n),
                _ => Err(self.err(
                    "search.max_candidates",
                    format!("{n} allows no candidate: a search fits at least one"),
                    fix,
                )),
            },
            Some(other) => Err(self.err(
                "search.max_candidates",
                format!("`{other}` is not a whole number of candidates"),
                fix,
            )),
        }
    }

    /// The candidates of one `[map]` field: its value, its list (sorted, without repeats) or `auto`'s.
    fn choices<T: Copy + PartialOrd>(
        &self,
        field: &str,
        raw: &RawChoice<T>,
        auto: impl FnOnce() -> Vec<T>,
    ) -> Result<Vec<T>, SpecError> {
        let mut values = match raw {
            RawChoice::One(v) => vec![*v],
            RawChoice::List(values) => values.clone(),
            RawChoice::Auto => auto(),
        };
        if values.is_empty() {
            return Err(self.err(
                field,
                "an empty list of candidates",
                format!("give `{field}` one value, a list of candidates, or \"auto\""),
            ));
        }
        values.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
        values.dedup_by(|a, b| a == b);
        Ok(values)
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

    /// `[tuning]`, each field defaulting from `[validation]`; the seed must differ from every other.
    fn tuning(
        &self,
        raw: Option<&RawTuning>,
        validation: &Validation,
        learning: &Learning,
        scenario: Option<&RawScenario>,
        horizon: usize,
    ) -> Result<Validation, SpecError> {
        let others = [Some(learning.seed), Some(validation.seed), scenario.map(|s| s.seed)];
        let taken = |seed: u64| others.contains(&Some(seed));
        let seed = match raw.and_then(|t| t.seed) {
            Some(seed) if taken(seed) => {
                return Err(self.err(
                    "tuning.seed",
                    format!("seed {seed} is also the learning, validation or scenario seed: the tuning runs would not be new data"),
                    "choose another seed, or leave it out (a free one is derived from `validation.seed`)",
                ))
            }
            Some(seed) => seed,
            None => (1..).map(|k| validation.seed.wrapping_add(1000 * k)).find(|s| !taken(*s)).expect("three seeds cannot take them all"),
        };
        let raw = RawValidation {
            trajectories: raw.and_then(|t| t.trajectories).unwrap_or(validation.trajectories),
            samples: raw.and_then(|t| t.samples).unwrap_or(validation.samples),
            seed,
        };
        self.runs("tuning", &raw, horizon)
    }

    /// The random runs of section `section` (`validation` or `tuning`).
    fn runs(&self, section: &str, raw: &RawValidation, horizon: usize) -> Result<Validation, SpecError> {
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

    /// `[model.units]`: a unit for each state or input named (outputs and targets have their own
    /// `unit` field), "" for the others.
    fn units(&self, raw: &BTreeMap<String, String>, model: &Model) -> Result<(Vec<String>, Vec<String>), SpecError> {
        for (name, unit) in raw {
            let field = format!("model.units.{name}");
            if !model.states.contains(name) && !model.inputs.contains(name) {
                let own_field = model.outputs.iter().any(|o| &o.name == name);
                return Err(self.err(
                    field,
                    format!("`{name}` is not a state or an input"),
                    if own_field {
                        format!("an output's unit is its `unit` field: set `unit = \"{unit}\"` in the `[[model.outputs]]` table of `{name}`")
                    } else {
                        format!(
                            "name a state or an input ({})",
                            model.states.iter().chain(&model.inputs).cloned().collect::<Vec<_>>().join(", ")
                        )
                    },
                ));
            }
            self.label(field, unit)?;
        }
        let unit_of = |name: &String| raw.get(name).cloned().unwrap_or_default();
        Ok((
            model.states.iter().map(unit_of).collect(),
            model.inputs.iter().map(unit_of).collect(),
        ))
    }

    /// `[model.bounds]`: each state named must be a state, with `min`, `max` or both, finite, `min`
    /// below `max`, and the learning box inside (the model's own trajectories start there).
    fn bounds(
        &self,
        raw: &BTreeMap<String, super::raw::RawBounds>,
        model: &Model,
        learning: &Learning,
    ) -> Result<Vec<super::Bounds>, SpecError> {
        let mut bounds = vec![super::Bounds::default(); model.states.len()];
        for (name, b) in raw {
            let field = format!("model.bounds.{name}");
            let Some(i) = model.states.iter().position(|s| s == name) else {
                return Err(self.err(
                    field,
                    format!("`{name}` is not a state: bounds are on states"),
                    format!("name a state ({})", model.states.join(", ")),
                ));
            };
            if b.min.is_none() && b.max.is_none() {
                return Err(self.err(
                    field,
                    "neither `min` nor `max` is given",
                    format!("give one side or both, e.g. `{name} = {{ min = 0.0 }}`, or remove the line"),
                ));
            }
            for (side, value) in [("min", b.min), ("max", b.max)] {
                if value.is_some_and(|v| !v.is_finite()) {
                    return Err(self.err(
                        format!("{field}.{side}"),
                        "a bound must be a finite number",
                        format!("leave `{side}` out for a state unbounded on that side"),
                    ));
                }
            }
            if let (Some(min), Some(max)) = (b.min, b.max) {
                if min >= max {
                    return Err(self.err(
                        field,
                        format!("`min` = {min} is not below `max` = {max}"),
                        "give `min` < `max` (a state that cannot move is a parameter, not a state)",
                    ));
                }
            }
            let (low, high) = match learning.axes[i] {
                Axis::Range { min, max, .. } => (min, max),
                Axis::Fixed(value) => (value, value),
            };
            let (lower, upper) = (b.min.unwrap_or(f64::NEG_INFINITY), b.max.unwrap_or(f64::INFINITY));
            if low < lower || high > upper {
                return Err(self.err(
                    field,
                    format!("the learning box of `{name}` ({low} to {high}, `learning.grid.{name}`) is not inside the bounds"),
                    "widen the bounds to the physically possible values, or shrink the learning grid into them",
                ));
            }
            bounds[i] = super::Bounds { min: b.min, max: b.max };
        }
        Ok(bounds)
    }

    fn targets(&self, raw: &[RawNamedExpr], model: &Model) -> Result<Vec<Target>, SpecError> {
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
            targets.push(Target {
                name: t.name.clone(),
                unit: t.unit.clone(),
                expr,
            });
        }
        Ok(targets)
    }
}
