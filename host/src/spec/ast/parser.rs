//! Reading an expression's text into its tree, by exmex's priorities (see the module above), and the
//! check that exmex reads the text the same way.

use super::{Binary, Node, FUNCTIONS};

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
