//! `[model.units]` and `[model.bounds]`: the unit of each state and input, and the range a state may
//! not leave (with the learning box inside it).

use std::collections::BTreeMap;

use super::validate::Validator;
use super::*;

impl Validator {
    /// `[model.units]`: a unit for each state or input named (outputs and targets have their own
    /// `unit` field), "" for the others.
    pub(super) fn units(
        &self,
        raw: &BTreeMap<String, String>,
        model: &Model,
    ) -> Result<(Vec<String>, Vec<String>), SpecError> {
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
    pub(super) fn bounds(
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

    /// Every start the spec gives inside `[model.bounds]`: a scenario's `x0` (the plant cannot start
    /// where it cannot be) and `observer_x0`, and a filter's fixed `x0` (every kind that carries the
    /// model projects its estimate onto the bounds, so a start outside is one no estimate can be).
    pub(super) fn starts_within_bounds(
        &self,
        model: &Model,
        bounds: &[super::Bounds],
        scenarios: &[super::Scenario],
        filters: &super::FixedFilters,
    ) -> Result<(), SpecError> {
        for start in super::starts::starts(filters, scenarios) {
            for ((name, bound), &value) in model.states.iter().zip(bounds).zip(start.values) {
                if value < bound.lower() || value > bound.upper() {
                    let side = |v: Option<f64>| v.map_or("unbounded".to_owned(), |v| v.to_string());
                    return Err(self.err(
                        start.field,
                        format!(
                            "`{name}` = {value} is outside its bounds (`model.bounds.{name}`: min {}, max {})",
                            side(bound.min),
                            side(bound.max)
                        ),
                        format!("start `{name}` within its bounds, or widen `model.bounds.{name}` if the plant can be there"),
                    ));
                }
            }
        }
        Ok(())
    }
}
