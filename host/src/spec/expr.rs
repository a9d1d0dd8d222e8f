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
    /// A unary minus applied to a power, which `exmex` reads against mathematical convention.
    #[error("`{text}`: `-{operand}^…` is read by exmex as `(-{operand})^…`, not `-({operand}^…)`")]
    AmbiguousMinus {
        /// The expression text.
        text: String,
        /// The operand the minus applies to.
        operand: String,
    },
    /// The expression is longer than [`MAX_EXPRESSION_CHARS`].
    #[error("an expression of {length} characters is longer than the limit of {MAX_EXPRESSION_CHARS}")]
    TooLong {
        /// Its length in characters.
        length: usize,
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

impl ExprError {
    /// What to change in the expression.
    pub fn fix(&self) -> String {
        match self {
            ExprError::Syntax { .. } => "write it in exmex syntax: + - * / ^, parentheses, exp, ln, sqrt, sin, cos, abs, … (decimal numbers, no 1e-3 notation: use a parameter)".into(),
            ExprError::AmbiguousMinus { operand, .. } => format!("write `-({operand}^…)` or `0 - {operand}^…` if that is meant, `(-{operand})^…` otherwise"),
            ExprError::TooLong { .. } => "split it into `[[model.definitions]]`, each evaluated once per step".into(),
            ExprError::UnknownVariable { name, .. } => format!("declare `{name}`, or use only the states, inputs, parameters and earlier definitions in scope"),
        }
    }
}

/// The longest expression accepted. exmex's evaluation time grows faster than linearly with the
/// length of one expression (measured: 1 000 evaluations of an n-term sum take 8 ms at n = 1 000,
/// 78 ms at 4 000 and 247 ms at 8 000), while many short definitions cost their total length: a
/// model that needs more is split into definitions.
pub const MAX_EXPRESSION_CHARS: usize = 4_000;

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
        let length = text.chars().count();
        if length > MAX_EXPRESSION_CHARS {
            return Err(ExprError::TooLong { length });
        }
        reject_minus_before_power(text)?;
        let flat = FlatEx::<f64>::parse(text).map_err(|e| ExprError::Syntax {
            text: text.to_owned(),
            message: e.to_string(),
        })?;
        let slots = flat
            .var_names()
            .iter()
            .map(|name| {
                scope
                    .iter()
                    .position(|s| s == name)
                    .ok_or_else(|| ExprError::UnknownVariable {
                        text: text.to_owned(),
                        name: name.clone(),
                        known: scope.join(", "),
                    })
            })
            .collect::<Result<_, _>>()?;
        Ok(Expression {
            text: text.to_owned(),
            flat,
            slots,
        })
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

#[derive(Clone, Copy, PartialEq, Debug)]
enum Token<'a> {
    Operand(&'a str),
    Operator(char),
    Open,
    Close,
    Comma,
}

/// Splits an expression into operands (names, numbers), operators and parentheses.
fn tokens(text: &str) -> Vec<Token<'_>> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i] as char;
        let start = i;
        i += 1;
        match c {
            c if c.is_whitespace() => {}
            '(' => out.push(Token::Open),
            ')' => out.push(Token::Close),
            ',' => out.push(Token::Comma),
            c if c.is_ascii_alphabetic() || c == '_' => {
                while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                    i += 1;
                }
                out.push(Token::Operand(&text[start..i]));
            }
            c if c.is_ascii_digit() || c == '.' => {
                while i < bytes.len() {
                    let d = bytes[i];
                    let exponent_sign = (d == b'-' || d == b'+') && matches!(bytes[i - 1], b'e' | b'E');
                    if d.is_ascii_digit() || d == b'.' || d == b'e' || d == b'E' || exponent_sign {
                        i += 1;
                    } else {
                        break;
                    }
                }
                out.push(Token::Operand(&text[start..i]));
            }
            c => out.push(Token::Operator(c)),
        }
    }
    out
}

/// Whether `name` is a function or constant of the expression language (`sin`, `exp`, `E`, `PI`,
/// `TAU`, …, as `exmex`'s own operator table lists them): a state, input, parameter or definition of
/// that name would be read as the operator, silently.
pub fn is_operator_name(name: &str) -> bool {
    <exmex::FloatOpsFactory<f64> as exmex::MakeOperators<f64>>::make()
        .iter()
        .any(|op| op.repr() == name)
}

/// Refuses `-x^2`, `-(a+b)^2`, `-sin(x)^2`: exmex binds a unary minus tighter than `^`, so these
/// would silently mean `(-x)^2`. `-(x^2)` and `0 - x^2` say what is meant.
fn reject_minus_before_power(text: &str) -> Result<(), ExprError> {
    let tokens = tokens(text);
    for (i, token) in tokens.iter().enumerate() {
        let unary = *token == Token::Operator('-')
            && match i.checked_sub(1).map(|p| tokens[p]) {
                None | Some(Token::Open | Token::Comma) => true,
                Some(Token::Operator(op)) => op != '^',
                _ => false,
            };
        if !unary {
            continue;
        }
        // The operand: a name or number, a call `f(…)`, or a group `(…)`.
        let mut j = i + 1;
        let first = j;
        if let Some(Token::Operand(_)) = tokens.get(j) {
            j += 1;
        }
        if tokens.get(j) == Some(&Token::Open) && (j == first || matches!(tokens.get(first), Some(Token::Operand(_)))) {
            let mut depth = 0;
            while let Some(t) = tokens.get(j) {
                match t {
                    Token::Open => depth += 1,
                    Token::Close => depth -= 1,
                    _ => {}
                }
                j += 1;
                if depth == 0 {
                    break;
                }
            }
        }
        if j > first && tokens.get(j) == Some(&Token::Operator('^')) {
            let operand = match tokens[first] {
                Token::Operand(name) => name.to_owned(),
                _ => "(…)".to_owned(),
            };
            return Err(ExprError::AmbiguousMinus {
                text: text.to_owned(),
                operand,
            });
        }
    }
    Ok(())
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
        assert!(matches!(
            Expression::compile("x1 + * (", &["x1"]),
            Err(ExprError::Syntax { .. })
        ));
    }

    #[test]
    fn minus_before_a_power_is_refused_where_exmex_would_misread_it() {
        for text in ["-x^2", "1 + -x^2", "2*-x^2", "-(x+1)^2", "-sin(x)^2", "(-x^3)"] {
            assert!(
                matches!(Expression::compile(text, &["x"]), Err(ExprError::AmbiguousMinus { .. })),
                "{text}"
            );
        }
        // What exmex reads as meant, checked by value at x = 3.
        for (text, value) in [
            ("-(x^2)", -9.0),
            ("0 - x^2", -9.0),
            ("1 - x^2", -8.0),
            ("x^-2", 1.0 / 9.0),
            ("-x", -3.0),
            ("0.2*x^2", 1.8),
            ("-x*2", -6.0),
        ] {
            let e = Expression::compile(text, &["x"]).unwrap();
            assert!((e.eval(&[3.0]) - value).abs() < 1e-12, "{text}: {}", e.eval(&[3.0]));
        }
    }

    #[test]
    fn exp_of_minus_infinity_is_its_limit() {
        // exp(-kp/P) at P = 0 must be 0, not NaN (E. coli model).
        let e = Expression::compile("exp(-kp/P)", &["kp", "P"]).unwrap();
        assert_eq!(e.eval(&[0.5, 0.0]), 0.0);
    }
}
