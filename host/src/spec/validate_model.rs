//! Validation of the model (states, inputs, parameters, definitions, derivatives, outputs) and of the
//! learning grid.

use super::limits;
use super::raw::*;
use super::validate::Validator;
use super::*;

impl Validator {
    pub(super) fn model(&self, raw: &RawModel) -> Result<Model, SpecError> {
        if raw.states.is_empty() {
            return Err(self.err(
                "model.states",
                "the model has no state",
                "list the state names, e.g. `states = [\"x1\", \"x2\"]`",
            ));
        }
        if raw.outputs.is_empty() {
            return Err(self.err(
                "model.outputs",
                "the model has no measured output",
                "add a `[[model.outputs]]` table with `name`, `expr` and `noise_variance`",
            ));
        }
        let mut seen: Vec<(String, String)> = Vec::new();
        let mut declare = |field: String, name: &str| -> Result<(), SpecError> {
            self.identifier(&field, name)?;
            if let Some((_, first)) = seen.iter().find(|(n, _)| *n == name) {
                return Err(self.err(
                    field,
                    format!("`{name}` is already declared at `{first}`"),
                    "give every state, input, parameter, definition and output its own name",
                ));
            }
            seen.push((name.to_owned(), field));
            Ok(())
        };
        for (i, s) in raw.states.iter().enumerate() {
            declare(format!("model.states[{i}]"), s)?;
        }
        for (i, s) in raw.inputs.iter().enumerate() {
            declare(format!("model.inputs[{i}]"), s)?;
        }
        for (name, value) in &raw.parameters {
            declare(format!("model.parameters.{name}"), name)?;
            if !value.is_finite() {
                return Err(self.err(
                    format!("model.parameters.{name}"),
                    format!("value {value} is not finite"),
                    "give a finite number",
                ));
            }
        }
        for (i, d) in raw.definitions.iter().enumerate() {
            declare(format!("model.definitions[{i}].name"), &d.name)?;
        }
        for (i, o) in raw.outputs.iter().enumerate() {
            declare(format!("model.outputs[{i}].name"), &o.name)?;
            let field = format!("model.outputs[{i}].noise_variance");
            if !(o.noise_variance.is_finite() && o.noise_variance >= 0.0) {
                return Err(self.err(
                    field,
                    format!("a variance must be finite and ≥ 0, got {}", readable(o.noise_variance)),
                    "give the variance of the measurement noise (0 for none)",
                ));
            }
        }
        self.keys_among(
            "model.derivatives",
            raw.derivatives.keys(),
            &raw.states,
            "a state",
            "give one derivative per state of `model.states`",
        )?;
        let mut derivatives = Vec::new();
        for state in &raw.states {
            let text = raw.derivatives.get(state).ok_or_else(|| {
                self.err(
                    format!("model.derivatives.{state}"),
                    format!("no derivative for state `{state}`"),
                    format!("add `{state} = \"…\"` (dx/dt) under `[model.derivatives]`"),
                )
            })?;
            derivatives.push(text.clone());
        }
        let parameters: Vec<(String, f64)> = raw.parameters.iter().map(|(k, v)| (k.clone(), *v)).collect();
        let definitions: Vec<(String, String)> = raw
            .definitions
            .iter()
            .map(|d| (d.name.clone(), d.expr.clone()))
            .collect();
        let outputs: Vec<(String, String, f64, String)> = raw
            .outputs
            .iter()
            .map(|o| (o.name.clone(), o.expr.clone(), o.noise_variance, o.unit.clone()))
            .collect();
        Model::compile(&ModelText {
            states: &raw.states,
            inputs: &raw.inputs,
            parameters: &parameters,
            definitions: &definitions,
            derivatives: &derivatives,
            outputs: &outputs,
        })
        .map_err(|e| self.err(e.field, e.error.to_string(), e.error.fix()))
    }

    pub(super) fn learning(&self, raw: &RawLearning, model: &Model, horizon: usize) -> Result<Learning, SpecError> {
        self.at_most("learning.samples", raw.samples, limits::MAX_RUN_SAMPLES)?;
        if raw.samples <= horizon {
            return Err(self.err(
                "map.horizon",
                format!(
                    "N = {horizon} leaves no window in runs of N_s = {} samples (N must be < N_s)",
                    raw.samples
                ),
                "lower `map.horizon` or raise `learning.samples`",
            ));
        }
        self.keys_among(
            "learning.grid",
            raw.grid.keys(),
            &model.states,
            "a state",
            "give one axis per state",
        )?;
        let axes = model
            .states
            .iter()
            .map(|state| {
                let field = format!("learning.grid.{state}");
                let raw = raw.grid.get(state).ok_or_else(|| {
                    self.err(&field, format!("no axis for state `{state}`"), format!("add `grid.{state} = {{ min = …, max = …, points = … }}` (or `{{ value = … }}` to hold it fixed)"))
                })?;
                self.axis(&field, raw)
            })
            .collect::<Result<Vec<_>, _>>()?;
        self.keys_among(
            "learning.inputs",
            raw.inputs.keys(),
            &model.inputs,
            "an input",
            "give one profile per input of `model.inputs`",
        )?;
        let inputs = model
            .inputs
            .iter()
            .map(|input| {
                let field = format!("learning.inputs.{input}");
                let p = raw.inputs.get(input).ok_or_else(|| {
                    self.err(
                        &field,
                        format!("no profile for input `{input}`"),
                        format!("add `inputs.{input} = {{ min = …, max = …, hold = … }}` under `[learning]`"),
                    )
                })?;
                if !(p.min.is_finite() && p.max.is_finite() && p.min <= p.max && (p.max - p.min).is_finite()) {
                    // Name the bound to change: `min` only when it is the one that is not finite.
                    let bound = if p.min.is_finite() { "max" } else { "min" };
                    return Err(self.err(
                        format!("{field}.{bound}"),
                        format!(
                            "the range [{}, {}] is not a finite interval",
                            readable(p.min),
                            readable(p.max)
                        ),
                        "give finite bounds with min ≤ max",
                    ));
                }
                if p.hold == 0 {
                    return Err(self.err(
                        format!("{field}.hold"),
                        "an input value must be held at least one sample",
                        "set `hold` to 1 or more samples",
                    ));
                }
                Ok(InputProfile {
                    min: p.min,
                    max: p.max,
                    hold: p.hold,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Learning {
            samples: raw.samples,
            seed: raw.seed,
            axes,
            inputs,
        })
    }

    fn axis(&self, field: &str, raw: &RawAxis) -> Result<Axis, SpecError> {
        match (raw.min, raw.max, raw.points, raw.value) {
            (None, None, None, Some(value)) if value.is_finite() => Ok(Axis::Fixed(value)),
            (None, None, None, Some(value)) => Err(self.err(
                format!("{field}.value"),
                format!("{value} is not finite"),
                "give a finite value",
            )),
            (Some(min), Some(max), Some(points), None) => {
                if !(min.is_finite() && max.is_finite() && (max - min).is_finite()) {
                    let bound = if min.is_finite() { "max" } else { "min" };
                    return Err(self.err(
                        format!("{field}.{bound}"),
                        format!("the bounds [{}, {}] are not finite", readable(min), readable(max)),
                        "give finite bounds",
                    ));
                }
                if min > max {
                    return Err(self.err(
                        format!("{field}.max"),
                        format!("the box is inverted: min = {min} > max = {max}"),
                        "swap `min` and `max`",
                    ));
                }
                if min == max {
                    return Err(self.err(
                        format!("{field}.max"),
                        format!("the box is empty: min = max = {min}"),
                        "widen the interval, or hold the state fixed with `{ value = … }`",
                    ));
                }
                self.at_most(&format!("{field}.points"), points, limits::MAX_AXIS_POINTS)?;
                if points == 0 {
                    return Err(self.err(
                        format!("{field}.points"),
                        "a grid of 0 points has no initial state",
                        "set `points` to 2 or more",
                    ));
                }
                if points == 1 {
                    return Err(self.err(
                        format!("{field}.points"),
                        "one point cannot span [min, max]",
                        "set `points` to 2 or more, or hold the state fixed with `{ value = … }`",
                    ));
                }
                Ok(Axis::Range { min, max, points })
            }
            _ => Err(self.err(
                field,
                "an axis is either `{ min, max, points }` or `{ value }`",
                format!("write `{field} = {{ min = …, max = …, points = … }}` or `{{ value = … }}`"),
            )),
        }
    }
}
