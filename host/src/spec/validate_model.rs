//! Validation of the model (states, inputs, parameters, definitions, derivatives, outputs) and of the
//! learning grid.

use super::limits;
use super::model::Uncertain;
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
        let mut parameters: Vec<(String, f64)> = Vec::new();
        let mut uncertain = Vec::new();
        for (index, (name, raw)) in raw.parameters.iter().enumerate() {
            declare(format!("model.parameters.{name}"), name)?;
            let value = match raw {
                RawParameter::Known(value) => self.known_parameter(name, *value)?,
                RawParameter::Uncertain(range) => {
                    let (min, max) = self.parameter_range(name, range)?;
                    uncertain.push(Uncertain {
                        index,
                        name: name.clone(),
                        min,
                        max,
                    });
                    range.value
                }
            };
            parameters.push((name.clone(), value));
        }
        self.at_most_uncertain(&uncertain)?;
        for (i, d) in raw.definitions.iter().enumerate() {
            declare(format!("model.definitions[{i}].name"), &d.name)?;
        }
        for (i, o) in raw.outputs.iter().enumerate() {
            declare(format!("model.outputs[{i}].name"), &o.name)?;
            self.label(format!("model.outputs[{i}].unit"), &o.unit)?;
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
        let mut model = Model::compile(&ModelText {
            states: &raw.states,
            inputs: &raw.inputs,
            parameters: &parameters,
            definitions: &definitions,
            derivatives: &derivatives,
            outputs: &outputs,
        })
        .map_err(|e| self.err(e.field, e.error.to_string(), e.error.fix()))?;
        model.uncertain = uncertain;
        Ok(model)
    }

    fn known_parameter(&self, name: &str, value: f64) -> Result<f64, SpecError> {
        if value.is_finite() {
            Ok(value)
        } else {
            Err(self.err(
                format!("model.parameters.{name}"),
                format!("value {value} is not finite"),
                "give a finite number",
            ))
        }
    }

    /// `[min, max]` of an uncertain parameter: finite, `min < max`, the nominal value inside. Each
    /// error names the key to change (`model.parameters.a.max`), as for the bounds of an axis.
    fn parameter_range(&self, name: &str, raw: &RawRange) -> Result<(f64, f64), SpecError> {
        let field = format!("model.parameters.{name}");
        let (value, min, max) = (raw.value, raw.min, raw.max);
        if !(min.is_finite() && max.is_finite() && (max - min).is_finite()) {
            let bound = if min.is_finite() { "max" } else { "min" };
            return Err(self.err(
                format!("{field}.{bound}"),
                format!("the range [{}, {}] is not finite", readable(min), readable(max)),
                "give finite bounds of the values the plant's parameter may take",
            ));
        }
        if min > max {
            return Err(self.err(
                format!("{field}.max"),
                format!(
                    "the range is inverted: min = {} > max = {}",
                    readable(min),
                    readable(max)
                ),
                "swap `min` and `max`",
            ));
        }
        if min == max {
            return Err(self.err(
                format!("{field}.max"),
                format!("the range is empty: min = max = {}", readable(min)),
                format!(
                    "widen the range, or give a known parameter as a plain number: `{name} = {}`",
                    readable(value)
                ),
            ));
        }
        if !value.is_finite() {
            return Err(self.err(
                format!("{field}.value"),
                format!("the nominal value {value} is not finite"),
                "give the finite value the emitted model and the observers use",
            ));
        }
        if !(min..=max).contains(&value) {
            return Err(self.err(
                format!("{field}.value"),
                format!(
                    "the nominal value {} is outside the range [{}, {}]",
                    readable(value),
                    readable(min),
                    readable(max)
                ),
                "give a nominal value between `min` and `max`, or widen the range to hold it",
            ));
        }
        Ok((min, max))
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

#[cfg(test)]
mod tests {
    use std::path::Path;

    use crate::spec::model::Uncertain;

    /// A first-order lag whose gain and time constant may be given as numbers or with ranges.
    fn lag(parameters: &str) -> String {
        format!(
            r#"
            name = "lag"
            [model]
            states = ["x"]
            inputs = ["u"]
            derivatives.x = "(k*u - x)/T"
            outputs = [{{ name = "y", expr = "b*x", noise_variance = 0.01 }}]
            [model.parameters]
            {parameters}
            [sampling]
            tau = 0.1
            [learning]
            samples = 20
            seed = 1
            grid.x = {{ min = -1.0, max = 1.0, points = 3 }}
            inputs.u = {{ min = -1.0, max = 1.0, hold = 3 }}
            [validation]
            trajectories = 4
            samples = 20
            seed = 2
            [map]
            horizon = 3
            nm = 2
            beta = 1.0
            epsilon = 0.01
            [[targets]]
            name = "x"
            expr = "x"
        "#
        )
    }

    #[test]
    fn a_parameter_is_a_number_or_a_value_with_a_range() {
        let text = lag("k = { value = 2.0, min = 1.5, max = 2.5 }\nT = { value = 1, min = 0.5, max = 2 }\nb = 3");
        let design = crate::spec::parse(Path::new("lag.toml"), &text).unwrap();
        let model = &design.model;
        // Table order: upper case first. The nominal value stands in `parameters`, integers read as numbers.
        let names: Vec<&str> = model.parameters.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["T", "b", "k"]);
        assert_eq!(model.parameter_values(), [1.0, 3.0, 2.0]);
        assert_eq!(
            model.uncertain,
            [
                Uncertain {
                    index: 0,
                    name: "T".into(),
                    min: 0.5,
                    max: 2.0
                },
                Uncertain {
                    index: 2,
                    name: "k".into(),
                    min: 1.5,
                    max: 2.5
                },
            ]
        );
        // Plain numbers only: nothing is uncertain, as before ranges existed.
        let design = crate::spec::parse(Path::new("lag.toml"), &lag("k = 2.0\nT = 1\nb = 3.0")).unwrap();
        assert!(design.model.uncertain.is_empty());
        assert_eq!(design.model.parameter_values(), [1.0, 3.0, 2.0]);
        // The nominal value may sit on a bound.
        let text = lag("k = { value = 2.5, min = 1.5, max = 2.5 }\nT = 1.0\nb = 3.0");
        crate::spec::parse(Path::new("lag.toml"), &text).unwrap();
    }

    #[test]
    fn with_parameters_changes_the_plant_and_keeps_the_ranges() {
        let text = lag("k = { value = 2.0, min = 1.5, max = 2.5 }\nT = 1.0\nb = 3.0");
        let model = crate::spec::parse(Path::new("lag.toml"), &text).unwrap().model;
        let mut environment = Vec::new();
        let mut dx = [0.0];
        // ẋ = (k u - x)/T at x = 1, u = 1: (2 - 1)/1 nominally, (2.5 - 1)/4 with T = 4, k = 2.5.
        model.derivative(&[1.0], &[1.0], &mut environment, &mut dx);
        assert_eq!(dx, [1.0]);
        let other = model.with_parameters(&[4.0, 3.0, 2.5]);
        other.derivative(&[1.0], &[1.0], &mut environment, &mut dx);
        assert_eq!(dx, [0.375]);
        assert_eq!(other.uncertain, model.uncertain);
        assert_eq!(model.parameter_values(), [1.0, 3.0, 2.0], "the original is unchanged");
        assert_eq!(model.values_with_uncertain(&[1.75]), [1.0, 3.0, 1.75]);
    }

    #[test]
    #[should_panic(expected = "2 values for the 3 parameters")]
    fn with_parameters_wants_one_value_per_parameter() {
        let model = crate::spec::parse(Path::new("lag.toml"), &lag("k = 2.0\nT = 1.0\nb = 3.0"))
            .unwrap()
            .model;
        model.with_parameters(&[1.0, 2.0]);
    }

    /// The limit on uncertain parameters is [`limits::MAX_UNCERTAIN`]: 8 pass, 9 are refused.
    #[test]
    fn at_most_eight_parameters_have_a_range() {
        let ranges = |count: usize| -> String {
            (1..=count)
                .map(|i| format!("p{i} = {{ value = 1.0, min = 0.5, max = 1.5 }}\n"))
                .collect()
        };
        let text = lag(&format!("k = 2.0\nT = 1.0\nb = 3.0\n{}", ranges(8)));
        let design = crate::spec::parse(Path::new("lag.toml"), &text).unwrap();
        assert_eq!(design.model.uncertain.len(), 8);
        let text = lag(&format!("k = 2.0\nT = 1.0\nb = 3.0\n{}", ranges(9)));
        let error = crate::spec::parse(Path::new("lag.toml"), &text).unwrap_err();
        assert_eq!(error.field, "model.parameters.p9", "{error}");
        assert!(error.fix.contains("at most 8"), "{error}");
    }
}
