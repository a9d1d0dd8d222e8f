//! Model expressions: text parsed by `exmex`, bound once to slots of an environment vector.
//!
//! Every expression of a model (derivatives, outputs, helper definitions, targets) is evaluated on
//! one environment `[parameters…, states…, inputs…, definitions…]`. Binding a variable name to its slot
//! happens at compile time, so an unknown name is an error before any simulation, and evaluation is a
//! gather plus an `exmex` call.

use exmex::prelude::*;

/// Why an expression could not be compiled.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ExprError {
    /// The text is not a valid expression.
    #[error("cannot parse `{text}`: {message}")]
    Syntax {
        /// The expression text.
        text: String,
        /// What the parser said.
        message: String,
    },
    /// The expression names a variable that is not in scope.
    #[error("`{text}` uses `{name}`, which is not defined here (known: {known})")]
    UnknownVariable {
        /// The expression text.
        text: String,
        /// The unknown name.
        name: String,
        /// The names in scope, comma separated.
        known: String,
    },
}

/// A compiled expression.
#[derive(Clone, Debug)]
pub struct Expression {
    text: String,
    flat: FlatEx<f64>,
    /// `slots[i]` is the environment index of the `i`-th variable in `exmex`'s (alphabetical) order.
    slots: Vec<usize>,
}

impl Expression {
    /// Parses `text` and binds each of its variables to its index in `scope`.
    pub fn compile(text: &str, scope: &[&str]) -> Result<Self, ExprError> {
        let flat = FlatEx::<f64>::parse(text)
            .map_err(|e| ExprError::Syntax { text: text.to_owned(), message: e.to_string() })?;
        let slots = flat
            .var_names()
            .iter()
            .map(|name| {
                scope.iter().position(|s| s == name).ok_or_else(|| ExprError::UnknownVariable {
                    text: text.to_owned(),
                    name: name.clone(),
                    known: scope.join(", "),
                })
            })
            .collect::<Result<_, _>>()?;
        Ok(Expression { text: text.to_owned(), flat, slots })
    }

    /// The source text.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Environment indices this expression reads.
    pub fn slots(&self) -> &[usize] {
        &self.slots
    }

    /// Evaluates on an environment; an evaluation failure gives NaN, which callers treat as any other
    /// non-finite value.
    pub fn eval(&self, environment: &[f64]) -> f64 {
        let mut values = [0.0; 16];
        if self.slots.len() <= values.len() {
            for (value, &slot) in values.iter_mut().zip(&self.slots) {
                *value = environment[slot];
            }
            self.flat.eval(&values[..self.slots.len()]).unwrap_or(f64::NAN)
        } else {
            let values: Vec<f64> = self.slots.iter().map(|&slot| environment[slot]).collect();
            self.flat.eval(&values).unwrap_or(f64::NAN)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binds_variables_by_name_not_by_position() {
        let e = Expression::compile("b - 2*a + c^2", &["c", "a", "b"]).unwrap();
        assert_eq!(e.eval(&[3.0, 1.0, 10.0]), 10.0 - 2.0 + 9.0);
    }

    #[test]
    fn unknown_names_and_bad_syntax_are_errors() {
        assert!(matches!(
            Expression::compile("x1 + x3", &["x1", "x2"]),
            Err(ExprError::UnknownVariable { name, .. }) if name == "x3"
        ));
        assert!(matches!(Expression::compile("x1 + * (", &["x1"]), Err(ExprError::Syntax { .. })));
    }

    #[test]
    fn exp_of_minus_infinity_is_its_limit() {
        // exp(-kp/P) at P = 0 must be 0, not NaN (E. coli model).
        let e = Expression::compile("exp(-kp/P)", &["kp", "P"]).unwrap();
        assert_eq!(e.eval(&[0.5, 0.0]), 0.0);
    }
}
