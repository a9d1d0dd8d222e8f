//! A straight-line program: expression trees lowered to one list of operations in which every
//! operand comes before its use and every distinct subexpression is computed once (hash-consing).
//!
//! The host evaluates it (in `f64` to tune and judge the EKF, in `f32` to predict the chip's bits) and
//! [`crate::emit::model`] writes it out as Rust, one `let` per operation in the same order, so that
//! both compute the same IEEE operations on the same operands. Integer powers 2 to 4 become products
//! (`powf` costs hundreds of instructions on the chip); every other function is `firmware::emitted::Maths`'s.

pub mod builder;

pub use builder::{Builder, LowerError, Names};

use firmware::emitted::Maths;
use firmware::Scalar;

use crate::spec::ast::Binary;

/// A value the program reads: the spec's names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Leaf {
    /// `model.parameters`, by index.
    Parameter(usize),
    /// A state, by index.
    State(usize),
    /// An input, by index.
    Input(usize),
    /// An entry of a filter's covariance, by index in its upper triangle ([`crate::plant::kalman`]).
    Covariance(usize),
    /// A measured output, by index ([`crate::plant::kalman`]).
    Measurement(usize),
    /// The map's estimate of a state, by state index ([`crate::observers::kind::corrected::program`]).
    Map(usize),
    /// The start-up blend of a state, by state index ([`crate::observers::kind::corrected::program`]).
    Blend(usize),
}

/// One operation; operands are indices of earlier operations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    /// A number (rounded to `f32` for the chip).
    Number(f64),
    /// A name.
    Leaf(Leaf),
    /// `-a`.
    Negate(usize),
    /// `a op b`.
    Binary(Binary, usize, usize),
    /// `f(a)`, `f` one of the expression language's functions (`log` is `ln`).
    Call(&'static str, usize),
    /// `a`, or `b` where `a` is below it or NaN: a state projected onto its lower bound
    /// (`firmware::emitted::at_least`, a select).
    AtLeast(usize, usize),
    /// `a`, or `b` where `a` is above it (`firmware::emitted::at_most`, a select).
    AtMost(usize, usize),
}

/// Operations and the indices of the results, in the order the caller asked for them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Program {
    /// The operations, each after its operands.
    pub ops: Vec<Op>,
    /// Which operations are the results.
    pub results: Vec<usize>,
}

impl Program {
    /// Drops the operations no result needs, keeping the order of the others.
    pub fn prune(&mut self) {
        let mut needed = vec![false; self.ops.len()];
        for &r in &self.results {
            needed[r] = true;
        }
        for i in (0..self.ops.len()).rev() {
            if needed[i] {
                match self.ops[i] {
                    Op::Negate(a) | Op::Call(_, a) => needed[a] = true,
                    Op::Binary(_, a, b) | Op::AtLeast(a, b) | Op::AtMost(a, b) => {
                        needed[a] = true;
                        needed[b] = true;
                    }
                    Op::Number(_) | Op::Leaf(_) => {}
                }
            }
        }
        let mut renumbered = vec![usize::MAX; self.ops.len()];
        let mut ops = Vec::new();
        for (i, op) in self.ops.iter().enumerate() {
            if needed[i] {
                let op = match *op {
                    Op::Negate(a) => Op::Negate(renumbered[a]),
                    Op::Call(f, a) => Op::Call(f, renumbered[a]),
                    Op::Binary(b, x, y) => Op::Binary(b, renumbered[x], renumbered[y]),
                    Op::AtLeast(x, y) => Op::AtLeast(renumbered[x], renumbered[y]),
                    Op::AtMost(x, y) => Op::AtMost(renumbered[x], renumbered[y]),
                    other => other,
                };
                renumbered[i] = ops.len();
                ops.push(op);
            }
        }
        self.ops = ops;
        for r in &mut self.results {
            *r = renumbered[*r];
        }
    }

    /// Evaluates every operation into `values` (one per operation) and returns the results: in `T`
    /// exactly as the emitted code computes them (numbers and parameters rounded to `f32` for `f32`).
    pub fn eval<T: Scalar + Maths>(
        &self,
        parameters: &[(String, f64)],
        x: &[T],
        u: &[T],
        values: &mut Vec<T>,
    ) -> Vec<T> {
        self.eval_with(parameters, values, |leaf| match leaf {
            Leaf::State(i) => x[i],
            Leaf::Input(i) => u[i],
            _ => T::literal(f32::NAN, f64::NAN), // a model's program reads no other leaf
        })
    }

    /// [`Program::eval`] with the values of states, inputs, covariance and measurements given by
    /// `leaf` (parameters are the program's constants).
    pub fn eval_with<T: Scalar + Maths>(
        &self,
        parameters: &[(String, f64)],
        values: &mut Vec<T>,
        leaf: impl Fn(Leaf) -> T,
    ) -> Vec<T> {
        values.clear();
        for op in &self.ops {
            let value = match *op {
                Op::Number(v) => T::literal(v as f32, v),
                Op::Leaf(Leaf::Parameter(i)) => T::literal(parameters[i].1 as f32, parameters[i].1),
                Op::Leaf(other) => leaf(other),
                Op::Negate(a) => -values[a],
                Op::Binary(op, a, b) => op.apply(values[a], values[b]),
                Op::Call(f, a) => crate::spec::ast::call(f, values[a]),
                Op::AtLeast(a, b) => firmware::emitted::at_least(values[a], values[b]),
                Op::AtMost(a, b) => firmware::emitted::at_most(values[a], values[b]),
            };
            values.push(value);
        }
        self.results.iter().map(|&r| values[r]).collect()
    }
    /// [`Program::eval`] in `f64` at `count` points at once, one operation for every point before the
    /// next (the interpreter's dispatch paid once per operation, not once per point: the particle
    /// filter's propagation): `states[i][p]` is state `i` of point `p`, the inputs are shared, and
    /// `results[r][p]` receives result `r` at point `p`; a parameter listed in `varying` (its index,
    /// then its value at every point) takes those values instead of its own. Each point's values are
    /// bit for bit [`Program::eval`]'s with those parameters.
    pub fn eval_many(
        &self,
        parameters: &[(String, f64)],
        varying: &[(usize, &[f64])],
        states: &[Vec<f64>],
        u: &[f64],
        values: &mut Vec<f64>,
        results: &mut [Vec<f64>],
    ) {
        let count = states.first().map_or(0, Vec::len);
        values.clear();
        values.resize(self.ops.len() * count, 0.0);
        for (i, op) in self.ops.iter().enumerate() {
            let (done, rest) = values.split_at_mut(i * count);
            let out = &mut rest[..count];
            let column = |a: usize| &done[a * count..(a + 1) * count];
            match *op {
                Op::Number(v) => out.fill(v),
                Op::Leaf(Leaf::Parameter(k)) => match varying.iter().find(|(i, _)| *i == k) {
                    Some((_, values)) => out.copy_from_slice(values),
                    None => out.fill(parameters[k].1),
                },
                Op::Leaf(Leaf::State(k)) => out.copy_from_slice(&states[k]),
                Op::Leaf(Leaf::Input(k)) => out.fill(u[k]),
                Op::Leaf(_) => out.fill(f64::NAN), // a model's program reads no other leaf
                Op::Negate(a) => out.iter_mut().zip(column(a)).for_each(|(o, &a)| *o = -a),
                Op::Binary(binary, a, b) => {
                    for ((o, &a), &b) in out.iter_mut().zip(column(a)).zip(column(b)) {
                        *o = binary.apply(a, b);
                    }
                }
                Op::Call(f, a) => out
                    .iter_mut()
                    .zip(column(a))
                    .for_each(|(o, &a)| *o = crate::spec::ast::call(f, a)),
                Op::AtLeast(a, b) => {
                    for ((o, &a), &b) in out.iter_mut().zip(column(a)).zip(column(b)) {
                        *o = firmware::emitted::at_least(a, b);
                    }
                }
                Op::AtMost(a, b) => {
                    for ((o, &a), &b) in out.iter_mut().zip(column(a)).zip(column(b)) {
                        *o = firmware::emitted::at_most(a, b);
                    }
                }
            }
        }
        for (out, &r) in results.iter_mut().zip(&self.results) {
            out.clear();
            out.extend_from_slice(&values[r * count..(r + 1) * count]);
        }
    }

    /// The program of the first `results` results only, pruned (e.g. `f` without its Jacobian).
    #[must_use]
    pub fn first_results(&self, results: usize) -> Program {
        let mut program = self.clone();
        program.results.truncate(results);
        program.prune();
        program
    }
}
