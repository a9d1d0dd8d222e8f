//! The builder of a [`Program`]: expression trees lowered in order, every distinct subexpression
//! computed once (hash-consing), and the folding arithmetic that composes programs (a filter's
//! sample). Kept apart from the program it builds, which the host evaluates and the emitter writes.

use std::collections::HashMap;

use crate::spec::ast::{Binary, Node};

use super::{Leaf, Op, Program};

/// The names a program's trees may use, each bound to a leaf or to an earlier operation.
pub struct Names<'a> {
    /// Parameter names and values.
    pub parameters: &'a [(String, f64)],
    /// State names.
    pub states: &'a [String],
    /// Input names.
    pub inputs: &'a [String],
}

/// Builds a [`Program`] from trees, sharing what they have in common.
pub struct Builder<'a> {
    names: Names<'a>,
    program: Program,
    /// Operations already present, keyed by their exact value (numbers by their bits).
    seen: HashMap<Key, usize>,
    /// Names bound to operations: definitions, and the derivative of a definition.
    bound: HashMap<String, usize>,
}

/// The identity of an operation, for sharing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Key {
    Number(u64),
    Leaf(Leaf),
    Negate(usize),
    Binary(u8, usize, usize),
    Call(&'static str, usize),
    AtLeast(usize, usize),
    AtMost(usize, usize),
}

/// A tree the builder cannot lower.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LowerError {
    /// A name that is neither a parameter, state, input nor bound definition.
    #[error("`{0}` is not a parameter, state, input or definition the model has")]
    UnknownName(String),
    /// A function the firmware does not provide.
    #[error("function `{0}` is not one the firmware provides")]
    UnknownFunction(String),
}

impl<'a> Builder<'a> {
    /// An empty program over `names`.
    pub fn new(names: Names<'a>) -> Self {
        Builder {
            names,
            program: Program::default(),
            seen: HashMap::new(),
            bound: HashMap::new(),
        }
    }

    /// Binds `name` to operation `op` (a definition's value, or a derivative of one).
    pub fn bind(&mut self, name: impl Into<String>, op: usize) {
        self.bound.insert(name.into(), op);
    }

    /// Appends `tree`'s operations (those not already present) and returns the index of its value.
    pub fn lower(&mut self, tree: &Node) -> Result<usize, LowerError> {
        Ok(match tree {
            Node::Number(v) => self.push(Op::Number(*v)),
            Node::Variable(name) => {
                if let Some(&op) = self.bound.get(name) {
                    op
                } else {
                    let leaf = self.leaf_named(name)?;
                    self.push(Op::Leaf(leaf))
                }
            }
            Node::Negate(a) => {
                let a = self.lower(a)?;
                self.push(Op::Negate(a))
            }
            Node::Binary(Binary::Pow, a, b) if matches!(**b, Node::Number(n) if n == 2.0 || n == 3.0 || n == 4.0) => {
                let a = self.lower(a)?;
                let square = self.push(Op::Binary(Binary::Mul, a, a));
                if **b == Node::Number(2.0) {
                    square
                } else if **b == Node::Number(3.0) {
                    self.push(Op::Binary(Binary::Mul, square, a))
                } else {
                    self.push(Op::Binary(Binary::Mul, square, square))
                }
            }
            Node::Binary(op, a, b) => {
                let (a, b) = (self.lower(a)?, self.lower(b)?);
                self.push(Op::Binary(*op, a, b))
            }
            Node::Call(f, a) => {
                let function = match *f {
                    "log" => "ln",
                    f if crate::spec::ast::FUNCTIONS.contains(&f) => f,
                    f => return Err(LowerError::UnknownFunction(f.to_owned())),
                };
                let a = self.lower(a)?;
                self.push(Op::Call(function, a))
            }
        })
    }

    /// Marks operation `op` as the next result.
    pub fn result(&mut self, op: usize) {
        self.program.results.push(op);
    }

    /// The program built.
    pub fn finish(self) -> Program {
        self.program
    }

    // Arithmetic on operations, for programs composed of others (a filter's sample). Each folds what
    // is known from the operands alone: an operation on numbers becomes a number, `0·a` becomes 0,
    // `1·a`, `a + 0`, `a - 0` and `a / 1` become `a`, so that the Jacobians' structural zeros and ones
    // cost nothing. (`0·a = 0` assumes `a` finite, which the filter checks of its results.)

    /// The number `v`.
    pub fn number(&mut self, v: f64) -> usize {
        self.push(Op::Number(v))
    }

    /// The leaf `leaf`.
    pub fn leaf(&mut self, leaf: Leaf) -> usize {
        self.push(Op::Leaf(leaf))
    }

    /// `-a`.
    pub fn negate(&mut self, a: usize) -> usize {
        match self.program.ops[a] {
            Op::Number(v) => self.number(-v),
            Op::Negate(b) => b,
            _ => self.push(Op::Negate(a)),
        }
    }

    /// `a op b`, folded where the operands decide it.
    pub fn binary(&mut self, op: Binary, a: usize, b: usize) -> usize {
        let (x, y) = (self.known(a), self.known(b));
        match (op, x, y) {
            (_, Some(x), Some(y)) => self.number(op.apply(x, y)),
            (Binary::Add, Some(0.0), _) => b,
            (Binary::Add | Binary::Sub, _, Some(0.0)) => a,
            (Binary::Sub, Some(0.0), _) => self.negate(b),
            (Binary::Mul, Some(0.0), _) | (Binary::Mul, _, Some(0.0)) => self.number(0.0),
            (Binary::Mul, Some(1.0), _) => b,
            (Binary::Mul | Binary::Div, _, Some(1.0)) => a,
            (Binary::Mul, Some(-1.0), _) => self.negate(b),
            (Binary::Mul | Binary::Div, _, Some(-1.0)) => self.negate(a),
            _ => self.push(Op::Binary(op, a, b)),
        }
    }

    /// `a op b` computed as written, in the program's precision, even on numbers (a constant the
    /// library computes in its own precision at construction; the compiler folds it in the emitted
    /// code, where it costs nothing).
    pub fn unfolded(&mut self, op: Binary, a: usize, b: usize) -> usize {
        self.push(Op::Binary(op, a, b))
    }

    /// `a + b`.
    pub fn add(&mut self, a: usize, b: usize) -> usize {
        self.binary(Binary::Add, a, b)
    }

    /// `a - b`.
    pub fn sub(&mut self, a: usize, b: usize) -> usize {
        self.binary(Binary::Sub, a, b)
    }

    /// `a · b`.
    pub fn mul(&mut self, a: usize, b: usize) -> usize {
        self.binary(Binary::Mul, a, b)
    }

    /// `f(a)`, `f` one of the expression language's functions (folded on a number).
    pub fn call(&mut self, f: &'static str, a: usize) -> usize {
        match self.known(a) {
            Some(v) => self.number(crate::spec::ast::call(f, v)),
            None => self.push(Op::Call(f, a)),
        }
    }

    /// `Σ aᵢ bᵢ` in order, starting from `start` (zero terms fold away).
    pub fn dot(&mut self, start: usize, a: &[usize], b: &[usize]) -> usize {
        a.iter().zip(b).fold(start, |sum, (&a, &b)| {
            let term = self.mul(a, b);
            self.add(sum, term)
        })
    }

    /// Appends `program`'s operations with its states read from `states` (its other leaves read as
    /// themselves), folding as it goes; returns its results.
    pub fn inline(&mut self, program: &Program, states: &[usize]) -> Vec<usize> {
        let mut map = Vec::with_capacity(program.ops.len());
        for op in &program.ops {
            let mapped = match *op {
                Op::Number(v) => self.number(v),
                Op::Leaf(Leaf::State(i)) => states[i],
                Op::Leaf(leaf) => self.leaf(leaf),
                Op::Negate(a) => self.negate(map[a]),
                Op::Binary(b, x, y) => self.binary(b, map[x], map[y]),
                Op::Call(f, a) => match self.known(map[a]) {
                    Some(v) => self.number(crate::spec::ast::call(f, v)),
                    None => self.push(Op::Call(f, map[a])),
                },
                Op::AtLeast(a, b) => self.push(Op::AtLeast(map[a], map[b])),
                Op::AtMost(a, b) => self.push(Op::AtMost(map[a], map[b])),
            };
            map.push(mapped);
        }
        program.results.iter().map(|&r| map[r]).collect()
    }

    /// `a`, or `low` where `a` is below it or NaN ([`firmware::emitted::at_least`]: a select).
    pub fn at_least(&mut self, a: usize, low: usize) -> usize {
        self.push(Op::AtLeast(a, low))
    }

    /// `a`, or `high` where `a` is above it ([`firmware::emitted::at_most`]: a select).
    pub fn at_most(&mut self, a: usize, high: usize) -> usize {
        self.push(Op::AtMost(a, high))
    }

    /// `states` projected onto `bounds` (a select per bounded side, nothing for an unbounded one).
    pub fn project(&mut self, states: &mut [usize], bounds: &[crate::spec::Bounds]) {
        for (x, b) in states.iter_mut().zip(bounds) {
            if let Some(min) = b.min {
                let low = self.number(min);
                *x = self.push(Op::AtLeast(*x, low));
            }
            if let Some(max) = b.max {
                let high = self.number(max);
                *x = self.push(Op::AtMost(*x, high));
            }
        }
    }

    /// The value of operation `op` when it is a number.
    fn known(&self, op: usize) -> Option<f64> {
        match self.program.ops[op] {
            Op::Number(v) => Some(v),
            _ => None,
        }
    }

    fn leaf_named(&self, name: &str) -> Result<Leaf, LowerError> {
        if let Some(i) = self.names.parameters.iter().position(|(n, _)| n == name) {
            Ok(Leaf::Parameter(i))
        } else if let Some(i) = self.names.states.iter().position(|n| n == name) {
            Ok(Leaf::State(i))
        } else if let Some(i) = self.names.inputs.iter().position(|n| n == name) {
            Ok(Leaf::Input(i))
        } else {
            Err(LowerError::UnknownName(name.to_owned()))
        }
    }

    fn push(&mut self, op: Op) -> usize {
        let key = match op {
            Op::Number(v) => Key::Number(v.to_bits()),
            Op::Leaf(leaf) => Key::Leaf(leaf),
            Op::Negate(a) => Key::Negate(a),
            Op::Binary(b, x, y) => Key::Binary(b as u8, x, y),
            Op::Call(f, a) => Key::Call(f, a),
            Op::AtLeast(a, b) => Key::AtLeast(a, b),
            Op::AtMost(a, b) => Key::AtMost(a, b),
        };
        *self.seen.entry(key).or_insert_with(|| {
            self.program.ops.push(op);
            self.program.ops.len() - 1
        })
    }
}
