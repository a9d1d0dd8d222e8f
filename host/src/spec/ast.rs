//! The tree of a spec expression, parsed here because exmex keeps its own tree private: what the model
//! is written out as Rust from, and differentiated on. It reads the text exactly as exmex does, which
//! the tests check by evaluating both on random points:
//!
//! * binary operators by exmex's priorities, highest first, equal ones left to right:
//!   `^` (4) > `/` (3) > `*` (2) > binary `-` (1) > `+`, `atan2`, `min`, `max` (0), so `a * b / c` is
//!   `a * (b / c)` and `a + b - c` is `a + (b - c)`;
//! * a unary `-` or `+` binds tighter than any binary operator (`-x^2` is `(-x)^2`, which the
//!   validator refuses as ambiguous);
//! * `f(…)` applies one of exmex's unary functions; `PI`, `π`, `E`, `e`, `TAU`, `τ` are constants;
//!   numbers are decimals without exponent.

use std::fmt;

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

    /// Applies the operator.
    pub fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            Binary::Add => a + b,
            Binary::Sub => a - b,
            Binary::Mul => a * b,
            Binary::Div => a / b,
            Binary::Pow => a.powf(b),
            Binary::Atan2 => a.atan2(b),
            Binary::Min => a.min(b),
            Binary::Max => a.max(b),
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

/// `f(a)` for a name of [`FUNCTIONS`].
pub fn call(function: &str, a: f64) -> f64 {
    match function {
        "abs" => a.abs(),
        "signum" => a.signum(),
        "sin" => a.sin(),
        "cos" => a.cos(),
        "tan" => a.tan(),
        "asin" => a.asin(),
        "acos" => a.acos(),
        "atan" => a.atan(),
        "sinh" => a.sinh(),
        "cosh" => a.cosh(),
        "tanh" => a.tanh(),
        "asinh" => a.asinh(),
        "acosh" => a.acosh(),
        "atanh" => a.atanh(),
        "floor" => a.floor(),
        "round" => a.round(),
        "ceil" => a.ceil(),
        "trunc" => a.trunc(),
        "fract" => a.fract(),
        "exp" => a.exp(),
        "sqrt" => a.sqrt(),
        "cbrt" => a.cbrt(),
        "ln" | "log" => a.ln(),
        "log2" => a.log2(),
        "log10" => a.log10(),
        _ => f64::NAN,
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
