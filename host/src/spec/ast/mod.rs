//! The tree of a spec expression, parsed here because exmex keeps its own tree private: what the model
//! is written out as Rust from, and differentiated on. It reads the text exactly as exmex does, which
//! the tests check by evaluating both on random points:
//!
//! * binary operators by exmex's priorities, highest first, equal ones left to right:
//!   `^` (4) > `/` (3) > `*` (2) > binary `-` (1) > `+`, `atan2`, `min`, `max` (0), so `a * b / c` is
//!   `a * (b / c)` and `a + b - c` is `a + (b - c)`. (exmex folds operations between numbers before
//!   the others, which breaks its left-to-right order at priority 0: it reads `a max 1 + 2` as
//!   `a max 3`. The translator finds such texts by evaluating both readings, and refuses them.)
//! * a unary `-` or `+` binds tighter than any binary operator (`-x^2` is `(-x)^2`, which the
//!   validator refuses as ambiguous);
//! * `atan2(a, b)`, `min(a, b)`, `max(a, b)` are the binary operators written as calls (an operand);
//! * `f(…)` applies one of exmex's unary functions; `PI`, `π`, `E`, `e`, `TAU`, `τ` are constants;
//!   numbers are decimals without exponent.
//!
//! The tree and its evaluation are here; reading a text into it in `parser`, its derivative in
//! `derivative`.

mod derivative;
mod parser;

use std::fmt;

use firmware::emitted::Maths;
use firmware::Scalar;

pub use derivative::{add, mul};
pub use parser::{parse, reads_as_exmex, ParseError};

/// A binary operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Binary {
    /// `+`.
    Add,
    /// `-`.
    Sub,
    /// `*`.
    Mul,
    /// `/`.
    Div,
    /// `^`.
    Pow,
    /// `atan2`.
    Atan2,
    /// `min`.
    Min,
    /// `max`.
    Max,
}

impl Binary {
    /// The operator spelt `text`, with exmex's priority.
    fn parse(text: &str) -> Option<(Binary, u8)> {
        Some(match text {
            "^" => (Binary::Pow, 4),
            "/" => (Binary::Div, 3),
            "*" => (Binary::Mul, 2),
            "-" => (Binary::Sub, 1),
            "+" => (Binary::Add, 0),
            "atan2" => (Binary::Atan2, 0),
            "min" => (Binary::Min, 0),
            "max" => (Binary::Max, 0),
            _ => return None,
        })
    }

    /// Applies the operator (the non-arithmetic ones by the firmware's `libm`-backed [`Maths`]: what
    /// the emitted code calls).
    pub fn apply<T: Scalar + Maths>(self, a: T, b: T) -> T {
        match self {
            Binary::Add => a + b,
            Binary::Sub => a - b,
            Binary::Mul => a * b,
            Binary::Div => a / b,
            Binary::Pow => Maths::powf(a, b),
            Binary::Atan2 => Maths::atan2(a, b),
            Binary::Min => Maths::min(a, b),
            Binary::Max => Maths::max(a, b),
        }
    }
}

/// The unary functions of the expression language (exmex's list).
pub const FUNCTIONS: &[&str] = &[
    "abs", "signum", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh",
    "floor", "round", "ceil", "trunc", "fract", "exp", "sqrt", "cbrt", "ln", "log2", "log10", "log",
];

/// One node of an expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// A number written in the text, or a named constant.
    Number(f64),
    /// A name of the scope.
    Variable(String),
    /// `-a`.
    Negate(Box<Node>),
    /// `a ∘ b`.
    Binary(Binary, Box<Node>, Box<Node>),
    /// `f(a)` with `f` one of [`FUNCTIONS`].
    Call(&'static str, Box<Node>),
}

impl Node {
    /// The value with the variables looked up by `value_of`.
    pub fn eval(&self, value_of: &impl Fn(&str) -> f64) -> f64 {
        match self {
            Node::Number(v) => *v,
            Node::Variable(name) => value_of(name),
            Node::Negate(a) => -a.eval(value_of),
            Node::Binary(op, a, b) => op.apply(a.eval(value_of), b.eval(value_of)),
            Node::Call(f, a) => call(f, a.eval(value_of)),
        }
    }
}

/// `f(a)` for a name of [`FUNCTIONS`] (`ln` and `log` both the natural logarithm), by the firmware's
/// `libm`-backed [`Maths`]; NaN for any other name.
pub fn call<T: Scalar + Maths>(function: &str, a: T) -> T {
    match function {
        "abs" => Maths::abs(a),
        "signum" => Maths::signum(a),
        "sin" => Maths::sin(a),
        "cos" => Maths::cos(a),
        "tan" => Maths::tan(a),
        "asin" => Maths::asin(a),
        "acos" => Maths::acos(a),
        "atan" => Maths::atan(a),
        "sinh" => Maths::sinh(a),
        "cosh" => Maths::cosh(a),
        "tanh" => Maths::tanh(a),
        "asinh" => Maths::asinh(a),
        "acosh" => Maths::acosh(a),
        "atanh" => Maths::atanh(a),
        "floor" => Maths::floor(a),
        "round" => Maths::round(a),
        "ceil" => Maths::ceil(a),
        "trunc" => Maths::trunc(a),
        "fract" => Maths::fract(a),
        "exp" => Maths::exp(a),
        "sqrt" => Maths::sqrt(a),
        "cbrt" => Maths::cbrt(a),
        "ln" | "log" => Maths::ln(a),
        "log2" => Maths::log2(a),
        "log10" => Maths::log10(a),
        _ => T::literal(f32::NAN, f64::NAN),
    }
}

impl fmt::Display for Node {
    /// Fully parenthesised, for messages and tests.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Node::Number(v) => write!(f, "{v:?}"),
            Node::Variable(name) => f.write_str(name),
            Node::Negate(a) => write!(f, "(-{a})"),
            Node::Binary(op, a, b) => write!(f, "({a} {op:?} {b})"),
            Node::Call(name, a) => write!(f, "{name}({a})"),
        }
    }
}

#[cfg(test)]
mod tests;
