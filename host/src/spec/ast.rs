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

use std::fmt;

use firmware::{Maths, Scalar};

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

/// Why a text has no tree.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("`{text}`: {problem} at character {at}")]
pub struct ParseError {
    /// The expression.
    pub text: String,
    /// What was expected.
    pub problem: String,
    /// Where (0-based character index).
    pub at: usize,
}

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Number(f64),
    Name(String),
    Operator(String),
    Open,
    Close,
    Comma,
}

fn tokens(text: &str) -> Result<Vec<(Token, usize)>, ParseError> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    let error = |problem: &str, at: usize| ParseError {
        text: text.to_owned(),
        problem: problem.to_owned(),
        at,
    };
    while i < chars.len() {
        let c = chars[i];
        let start = i;
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() || c == '.' {
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            let literal: String = chars[start..i].iter().collect();
            let value = literal.parse().map_err(|_| error("not a number", start))?;
            out.push((Token::Number(value), start));
        } else if c.is_alphabetic() || c == '_' {
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push((Token::Name(chars[start..i].iter().collect()), start));
        } else if "+-*/^".contains(c) {
            out.push((Token::Operator(c.to_string()), start));
            i += 1;
        } else if c == '(' {
            out.push((Token::Open, start));
            i += 1;
        } else if c == ')' {
            out.push((Token::Close, start));
            i += 1;
        } else if c == ',' {
            out.push((Token::Comma, start));
            i += 1;
        } else {
            return Err(error(&format!("unexpected `{c}`"), start));
        }
    }
    Ok(out)
}

/// Parses `text` into a tree.
pub fn parse(text: &str) -> Result<Node, ParseError> {
    let tokens = tokens(text)?;
    let mut parser = Parser { text, tokens, next: 0 };
    let node = parser.expression(0)?;
    match parser.tokens.get(parser.next) {
        None => Ok(node),
        Some((_, at)) => Err(parser.error("an operator", *at)),
    }
}

struct Parser<'a> {
    text: &'a str,
    tokens: Vec<(Token, usize)>,
    next: usize,
}

impl Parser<'_> {
    fn error(&self, expected: &str, at: usize) -> ParseError {
        ParseError {
            text: self.text.to_owned(),
            problem: format!("expected {expected}"),
            at,
        }
    }

    fn end(&self) -> usize {
        self.text.chars().count()
    }

    /// Binary operators of priority at least `floor`, left to right among equals.
    fn expression(&mut self, floor: u8) -> Result<Node, ParseError> {
        let mut left = self.operand()?;
        loop {
            let operator = match self.tokens.get(self.next) {
                Some((Token::Operator(s) | Token::Name(s), _)) => Binary::parse(s),
                _ => None,
            };
            let Some((operator, priority)) = operator else { break };
            if priority < floor {
                break;
            }
            self.next += 1;
            let right = self.expression(priority + 1)?;
            left = Node::Binary(operator, Box::new(left), Box::new(right));
        }
        Ok(left)
    }

    /// A number, a name, a call or a group, after any unary signs.
    fn operand(&mut self) -> Result<Node, ParseError> {
        let Some((token, at)) = self.tokens.get(self.next).cloned() else {
            return Err(self.error("an operand", self.end()));
        };
        self.next += 1;
        match token {
            Token::Operator(s) if s == "-" => Ok(Node::Negate(Box::new(self.operand()?))),
            Token::Operator(s) if s == "+" => self.operand(),
            Token::Number(value) => Ok(Node::Number(value)),
            Token::Open => {
                let inner = self.expression(0)?;
                self.close()?;
                Ok(inner)
            }
            Token::Name(name) if Binary::parse(&name).is_some() => {
                // `atan2(a, b)`, `min(a, b)`, `max(a, b)`: the binary operator written as a call.
                let (operator, _) = Binary::parse(&name).expect("checked by the guard");
                if !matches!(self.tokens.get(self.next), Some((Token::Open, _))) {
                    return Err(self.error(&format!("`(` after `{name}`"), at));
                }
                self.next += 1;
                let a = self.expression(0)?;
                match self.tokens.get(self.next) {
                    Some((Token::Comma, _)) => self.next += 1,
                    Some((_, at)) => return Err(self.error("`,`", *at)),
                    None => return Err(self.error("`,`", self.end())),
                }
                let b = self.expression(0)?;
                self.close()?;
                Ok(Node::Binary(operator, Box::new(a), Box::new(b)))
            }
            Token::Name(name) => {
                if let Some(&function) = FUNCTIONS.iter().find(|f| **f == name) {
                    if matches!(self.tokens.get(self.next), Some((Token::Open, _))) {
                        self.next += 1;
                        let argument = self.expression(0)?;
                        self.close()?;
                        return Ok(Node::Call(function, Box::new(argument)));
                    }
                    return Err(self.error(&format!("`(` after `{name}`"), at));
                }
                Ok(match name.as_str() {
                    "PI" | "π" => Node::Number(std::f64::consts::PI),
                    "E" | "e" => Node::Number(std::f64::consts::E),
                    "TAU" | "τ" => Node::Number(std::f64::consts::TAU),
                    _ => Node::Variable(name),
                })
            }
            _ => Err(self.error("an operand", at)),
        }
    }

    fn close(&mut self) -> Result<(), ParseError> {
        match self.tokens.get(self.next) {
            Some((Token::Close, _)) => {
                self.next += 1;
                Ok(())
            }
            Some((_, at)) => Err(self.error("`)`", *at)),
            None => Err(self.error("`)`", self.end())),
        }
    }
}

/// Whether exmex evaluates `text` as `node` does, at three sets of values of its variables (NaN for
/// NaN): false for texts where exmex's folding of numbers departs from its own priorities.
pub fn reads_as_exmex(text: &str, node: &Node) -> bool {
    use exmex::prelude::*;
    let Ok(flat) = exmex::FlatEx::<f64>::parse(text) else {
        return false;
    };
    let names = flat.var_names().to_vec();
    (0..3).all(|set| {
        let value = |i: usize| 0.37 + 0.61 * ((i * 7 + set * 3) % 11) as f64;
        let values: Vec<f64> = (0..names.len()).map(value).collect();
        let theirs = flat.eval(&values).unwrap_or(f64::NAN);
        let ours = node.eval(&|n: &str| names.iter().position(|m| m == n).map_or(f64::NAN, value));
        (ours - theirs).abs() <= 1e-9 * (1.0 + theirs.abs()) || (ours.is_nan() && theirs.is_nan()) || ours == theirs
    })
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

impl Node {
    /// `∂self/∂variable`, by the rules of calculus on the tree (folding `0` and `1` as it goes). Where
    /// a function has no derivative (the steps of `floor`, `round`, `ceil`, `trunc`, `signum`; the kinks
    /// of `abs`, `min`, `max`), the derivative of the piece the point lies on is used.
    pub fn derivative(&self, variable: &str) -> Node {
        use Binary::*;
        let d = |n: &Node| n.derivative(variable);
        match self {
            Node::Number(_) => num(0.0),
            Node::Variable(name) => num(if name == variable { 1.0 } else { 0.0 }),
            Node::Negate(a) => negate(d(a)),
            Node::Binary(op, a, b) => {
                let (a, b) = (a.as_ref().clone(), b.as_ref().clone());
                let (da, db) = (d(&a), d(&b));
                match op {
                    Add => add(da, db),
                    Sub => sub(da, db),
                    Mul => add(mul(da, b.clone()), mul(a.clone(), db)),
                    // (a/b)' = a'/b - a b'/b²
                    Div => sub(div(da, b.clone()), div(mul(a.clone(), db), mul(b.clone(), b))),
                    Pow if is_zero(&db) => {
                        // (a^b)' = b a^(b-1) a' for b constant in the variable
                        mul(mul(b.clone(), pow(a, sub(b, num(1.0)))), da)
                    }
                    // (a^b)' = a^b (b' ln a + b a'/a)
                    Pow => mul(
                        pow(a.clone(), b.clone()),
                        add(mul(db, call_node("ln", a.clone())), div(mul(b, da), a)),
                    ),
                    // atan2(a, b)' = (b a' - a b') / (a² + b²)
                    Atan2 => div(
                        sub(mul(b.clone(), da), mul(a.clone(), db)),
                        add(mul(a.clone(), a), mul(b.clone(), b)),
                    ),
                    Min => select(Min, a, b, da, db),
                    Max => select(Max, a, b, da, db),
                }
            }
            Node::Call(f, a) => {
                let a = a.as_ref().clone();
                let da = d(&a);
                if is_zero(&da) {
                    return num(0.0);
                }
                let outer = match *f {
                    "sin" => call_node("cos", a),
                    "cos" => negate(call_node("sin", a)),
                    "tan" => add(num(1.0), mul(call_node("tan", a.clone()), call_node("tan", a))),
                    "asin" => div(num(1.0), call_node("sqrt", sub(num(1.0), mul(a.clone(), a)))),
                    "acos" => negate(div(num(1.0), call_node("sqrt", sub(num(1.0), mul(a.clone(), a))))),
                    "atan" => div(num(1.0), add(num(1.0), mul(a.clone(), a))),
                    "sinh" => call_node("cosh", a),
                    "cosh" => call_node("sinh", a),
                    "tanh" => sub(num(1.0), mul(call_node("tanh", a.clone()), call_node("tanh", a))),
                    "asinh" => div(num(1.0), call_node("sqrt", add(mul(a.clone(), a), num(1.0)))),
                    "acosh" => div(num(1.0), call_node("sqrt", sub(mul(a.clone(), a), num(1.0)))),
                    "atanh" => div(num(1.0), sub(num(1.0), mul(a.clone(), a))),
                    "exp" => call_node("exp", a),
                    "sqrt" => div(num(0.5), call_node("sqrt", a)),
                    "cbrt" => div(
                        num(1.0),
                        mul(num(3.0), mul(call_node("cbrt", a.clone()), call_node("cbrt", a))),
                    ),
                    "ln" | "log" => div(num(1.0), a),
                    "log2" => div(num(std::f64::consts::LOG2_E), a),
                    "log10" => div(num(std::f64::consts::LOG10_E), a),
                    "abs" => call_node("signum", a),
                    "fract" => num(1.0),
                    _ => num(0.0), // floor, round, ceil, trunc, signum: piecewise constant
                };
                mul(outer, da)
            }
        }
    }
}

fn num(value: f64) -> Node {
    Node::Number(value)
}

fn is_zero(n: &Node) -> bool {
    *n == Node::Number(0.0)
}

fn is_one(n: &Node) -> bool {
    *n == Node::Number(1.0)
}

fn negate(a: Node) -> Node {
    match a {
        Node::Number(v) => num(-v),
        a => Node::Negate(Box::new(a)),
    }
}

/// Both operands numbers: the folded value.
fn folded(op: Binary, a: &Node, b: &Node) -> Option<Node> {
    match (a, b) {
        (Node::Number(x), Node::Number(y)) => Some(num(op.apply(*x, *y))),
        _ => None,
    }
}

/// `a + b`, folded where an operand is a number.
pub fn add(a: Node, b: Node) -> Node {
    if let Some(n) = folded(Binary::Add, &a, &b) {
        return n;
    }
    match (is_zero(&a), is_zero(&b)) {
        (true, _) => b,
        (_, true) => a,
        _ => Node::Binary(Binary::Add, Box::new(a), Box::new(b)),
    }
}

fn sub(a: Node, b: Node) -> Node {
    if let Some(n) = folded(Binary::Sub, &a, &b) {
        return n;
    }
    match (is_zero(&a), is_zero(&b)) {
        (_, true) => a,
        (true, _) => negate(b),
        _ => Node::Binary(Binary::Sub, Box::new(a), Box::new(b)),
    }
}

/// `a * b`, folded where an operand is a number.
pub fn mul(a: Node, b: Node) -> Node {
    if let Some(n) = folded(Binary::Mul, &a, &b) {
        n
    } else if is_zero(&a) || is_zero(&b) {
        num(0.0)
    } else if is_one(&a) {
        b
    } else if is_one(&b) {
        a
    } else {
        Node::Binary(Binary::Mul, Box::new(a), Box::new(b))
    }
}

fn div(a: Node, b: Node) -> Node {
    if let Some(n) = folded(Binary::Div, &a, &b) {
        n
    } else if is_zero(&a) {
        num(0.0)
    } else if is_one(&b) {
        a
    } else {
        Node::Binary(Binary::Div, Box::new(a), Box::new(b))
    }
}

fn pow(a: Node, b: Node) -> Node {
    if is_one(&b) {
        a
    } else {
        Node::Binary(Binary::Pow, Box::new(a), Box::new(b))
    }
}

fn call_node(function: &'static str, a: Node) -> Node {
    Node::Call(function, Box::new(a))
}

/// The derivative of `min(a, b)` or `max(a, b)`: that of the operand the operator picks, written
/// without a comparison node as `(da + db)/2 ± (da - db)/2 · signum(b - a)` (the mean of both where
/// `a = b`).
fn select(op: Binary, a: Node, b: Node, da: Node, db: Node) -> Node {
    let half_difference = match op {
        Binary::Min => sub(da.clone(), db.clone()),
        _ => sub(db.clone(), da.clone()),
    };
    add(
        mul(num(0.5), add(da, db)),
        mul(mul(num(0.5), half_difference), call_node("signum", sub(b, a))),
    )
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
