//! The model as the chip will run it: the spec's expressions lowered to straight-line programs
//! ([`program`]) for `f(x, u)` with `∂f/∂x`, `h(x, u)` with `∂h/∂x`, and the targets `r(x, u)`.
//!
//! # Derivatives through definitions
//!
//! A definition `d = D(x, d₁, …)` is computed once and its total derivative carried forward:
//!
//! ```text
//! dD/dx_j = ∂D/∂x_j + Σ_m ∂D/∂d_m · dd_m/dx_j
//! ```
//!
//! each partial taken symbolically on the tree ([`crate::spec::ast::Node::derivative`]), so the
//! Jacobians never inline a definition into every expression that uses it. What no result needs is
//! dropped ([`Program::prune`]).
//!
//! The host evaluates these programs through [`Compiled`], which implements the firmware's
//! [`firmware::Model`]: the EKF the report measures is the firmware's own code, in `f64`.

pub mod coordinates;
pub mod covariance;
pub mod discretisation;
mod inside;
pub mod kalman;
pub mod program;

use firmware::emitted::Maths;
use firmware::Scalar;

use crate::spec::ast::{self, Node};
use crate::spec::Design;
pub use coordinates::Coordinates;
pub use covariance::Covariance;
use inside::jacobian_inside;
pub use inside::JACOBIAN_INSIDE;
pub use program::{Builder, LowerError, Names, Op, Program};

/// Most operations of one program: beyond this the emitted function would be too large to be what a
/// user wants on a microcontroller (and to compile quickly).
pub const MAX_OPS: usize = 20_000;

/// The model's programs.
#[derive(Clone, Debug)]
pub struct ModelCode {
    /// `f` (one per state), then `∂f_i/∂x_j` row by row.
    pub derivative: Program,
    /// `h` (one per output), then `∂h_i/∂x_j` row by row.
    pub output: Program,
    /// `r`, one per target.
    pub targets: Program,
    /// The parameters, as the programs' [`program::Leaf::Parameter`] indices read them.
    pub parameters: Vec<(String, f64)>,
    /// States, outputs, inputs, targets.
    pub dimensions: Dimensions,
    /// Each state's physical bounds (`[model.bounds]`), which the filters project their state onto,
    /// in the programs' coordinates.
    pub bounds: Vec<crate::spec::Bounds>,
    /// The coordinates the programs read and give ([`coordinates`]): the plant's, or a filter's.
    pub coordinates: Coordinates,
    /// The log coordinates of the design's states bounded below ([`Coordinates::logarithmic`]),
    /// which the filters that carry them take ([`ModelCode::logarithmic`]).
    pub log_coordinates: Coordinates,
}

/// How many of each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Dimensions {
    /// States.
    pub states: usize,
    /// Outputs.
    pub outputs: usize,
    /// Inputs.
    pub inputs: usize,
    /// Targets.
    pub targets: usize,
}

/// A model the translator cannot write as Rust: the spec field and the construct.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("`{field}`: {construct}")]
pub struct ModelCodeError {
    /// The spec field.
    pub field: String,
    /// What cannot be emitted, and why.
    pub construct: String,
}

/// A tree of the spec, with the field it came from.
struct Tree {
    field: String,
    node: Node,
}

fn parse(field: String, text: &str) -> Result<Tree, ModelCodeError> {
    let node = ast::parse(text).map_err(|e| ModelCodeError {
        field: field.clone(),
        construct: format!("the translator cannot read {e}"),
    })?;
    if !ast::reads_as_exmex(text, &node) {
        return Err(ModelCodeError {
            field,
            construct: format!("`{text}` is evaluated by exmex (the simulation) in another order than its operator priorities say (it folds operations between numbers first); add parentheses around the operands of `atan2`, `min`, `max` or write them as calls, e.g. `max(a, 1 + 2)`"),
        });
    }
    check_numbers(&field, &node)?;
    Ok(Tree { field, node })
}

/// Every number of `node` must be an `f32` the chip can hold: finite, and not flushed to zero.
fn check_numbers(field: &str, node: &Node) -> Result<(), ModelCodeError> {
    match node {
        Node::Number(v) => representable(*v).map_err(|problem| ModelCodeError {
            field: field.to_owned(),
            construct: format!("the number {v} {problem}"),
        }),
        Node::Variable(_) => Ok(()),
        Node::Negate(a) | Node::Call(_, a) => check_numbers(field, a),
        Node::Binary(_, a, b) => check_numbers(field, a).and_then(|()| check_numbers(field, b)),
    }
}

/// Whether `v` survives rounding to `f32`.
fn representable(v: f64) -> Result<(), &'static str> {
    let single = v as f32;
    if !single.is_finite() {
        Err("is not finite in f32 (the chip's precision)")
    } else if v != 0.0 && (single == 0.0 || single.is_subnormal()) {
        Err("underflows in f32 (the chip's precision)")
    } else {
        Ok(())
    }
}

/// The name bound to `dd/dx_j` of definition `name` (not an identifier: it cannot clash).
fn total_name(name: &str, j: usize) -> String {
    format!("d {name} / d x{j}")
}

impl ModelCode {
    /// Lowers the design's model and targets; refuses what cannot be emitted, naming the field.
    pub fn new(design: &Design) -> Result<Self, ModelCodeError> {
        let model = &design.model;
        let names = || Names {
            parameters: &model.parameters,
            states: &model.states,
            inputs: &model.inputs,
        };
        for (state, bounds) in model.states.iter().zip(&design.state_bounds) {
            for (side, value) in [("min", bounds.min), ("max", bounds.max)] {
                if let Some(value) = value {
                    representable(value).map_err(|problem| ModelCodeError {
                        field: format!("model.bounds.{state}.{side}"),
                        construct: format!("the bound {value} {problem}"),
                    })?;
                }
            }
        }
        for (name, value) in &model.parameters {
            representable(*value).map_err(|problem| ModelCodeError {
                field: format!("model.parameters.{name}"),
                construct: format!("the value {value} {problem}"),
            })?;
        }
        let definitions = model
            .definitions
            .iter()
            .enumerate()
            .map(|(i, d)| {
                Ok((
                    d.name.clone(),
                    parse(format!("model.definitions[{i}].expr"), d.expr.text())?,
                ))
            })
            .collect::<Result<Vec<_>, ModelCodeError>>()?;
        let derivatives = model
            .states
            .iter()
            .zip(&model.derivatives)
            .map(|(s, e)| parse(format!("model.derivatives.{s}"), e.text()))
            .collect::<Result<Vec<_>, _>>()?;
        let outputs = model
            .outputs
            .iter()
            .enumerate()
            .map(|(i, o)| parse(format!("model.outputs[{i}].expr"), o.expr.text()))
            .collect::<Result<Vec<_>, _>>()?;
        let targets = design
            .targets
            .iter()
            .enumerate()
            .map(|(i, t)| parse(format!("targets[{i}].expr"), t.expr.text()))
            .collect::<Result<Vec<_>, _>>()?;

        let states = model.states.len();
        let with_jacobian = |trees: &[Tree], what: &str| -> Result<Program, ModelCodeError> {
            let mut builder = Builder::new(names());
            bind_definitions(&mut builder, &definitions, &model.states)?;
            let mut rows = Vec::new();
            for tree in trees {
                let value = lower(&mut builder, tree, &tree.node)?;
                builder.result(value);
                let mut row = Vec::new();
                for (j, state) in model.states.iter().enumerate() {
                    row.push(lower(
                        &mut builder,
                        tree,
                        &total_derivative(&tree.node, state, j, &definitions),
                    )?);
                }
                rows.push(row);
            }
            for op in rows.into_iter().flatten() {
                builder.result(op);
            }
            finish(builder, what)
        };
        let derivative = jacobian_inside(design, with_jacobian(&derivatives, "model.derivatives")?, names());
        let output = jacobian_inside(design, with_jacobian(&outputs, "model.outputs")?, names());
        let mut builder = Builder::new(names());
        bind_definitions(&mut builder, &definitions, &[])?;
        for tree in &targets {
            let value = lower(&mut builder, tree, &tree.node)?;
            builder.result(value);
        }
        let targets = finish(builder, "targets")?;
        Ok(ModelCode {
            derivative,
            output,
            targets,
            parameters: model.parameters.clone(),
            dimensions: Dimensions {
                states,
                outputs: model.outputs.len(),
                inputs: model.inputs.len(),
                targets: design.targets.len(),
            },
            bounds: design.state_bounds.clone(),
            coordinates: Coordinates::plant(states),
            log_coordinates: Coordinates::logarithmic(design),
        })
    }

    /// The model in its log coordinates ([`ModelCode::log_coordinates`]; itself when it has none or
    /// is in them already).
    pub fn logarithmic(&self) -> ModelCode {
        self.in_coordinates(&self.log_coordinates)
    }

    /// `f(x, u)` and `∂f/∂x` (row-major) in `T`, as the emitted code computes them.
    pub fn derivative<T: Scalar + Maths>(&self, x: &[T], u: &[T], scratch: &mut Vec<T>) -> (Vec<T>, Vec<T>) {
        let mut values = self.derivative.eval(&self.parameters, x, u, scratch);
        let jacobian = values.split_off(self.dimensions.states);
        (values, jacobian)
    }

    /// `h(x, u)` and `∂h/∂x` (row-major) in `T`.
    pub fn output<T: Scalar + Maths>(&self, x: &[T], u: &[T], scratch: &mut Vec<T>) -> (Vec<T>, Vec<T>) {
        let mut values = self.output.eval(&self.parameters, x, u, scratch);
        let jacobian = values.split_off(self.dimensions.outputs);
        (values, jacobian)
    }

    /// The targets `r(x, u)` in `T`.
    pub fn targets<T: Scalar + Maths>(&self, x: &[T], u: &[T], scratch: &mut Vec<T>) -> Vec<T> {
        self.targets.eval(&self.parameters, x, u, scratch)
    }
}

/// A [`ModelCode`] as the firmware's [`firmware::Model`], evaluated by the host's interpreter of its
/// programs, for any dimensions matching the code's (inputs beyond the model's are ignored, so that
/// one filter type can serve models with fewer inputs).
pub struct Compiled<'a, T> {
    code: &'a ModelCode,
    scratch: std::cell::RefCell<Vec<T>>,
}

impl<'a, T> Compiled<'a, T> {
    /// The model of `code`.
    pub fn new(code: &'a ModelCode) -> Self {
        Compiled {
            code,
            scratch: std::cell::RefCell::new(Vec::new()),
        }
    }
}

impl<T: Scalar + Maths, const NX: usize, const NY: usize, const NU: usize> firmware::Model<T, NX, NY, NU>
    for Compiled<'_, T>
{
    fn derivative(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NX], [[T; NX]; NX]) {
        let (f, jacobian) = self.code.derivative(x, u, &mut self.scratch.borrow_mut());
        (array(&f), std::array::from_fn(|i| array(&jacobian[i * NX..])))
    }

    fn output(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NY], [[T; NX]; NY]) {
        let (h, jacobian) = self.code.output(x, u, &mut self.scratch.borrow_mut());
        (array(&h), std::array::from_fn(|i| array(&jacobian[i * NX..])))
    }
}

/// The first `N` values.
fn array<T: Copy, const N: usize>(values: &[T]) -> [T; N] {
    std::array::from_fn(|i| values[i])
}

/// Lowers every definition's value, and its total derivative in each of `states`.
fn bind_definitions(
    builder: &mut Builder<'_>,
    definitions: &[(String, Tree)],
    states: &[String],
) -> Result<(), ModelCodeError> {
    for (k, (name, tree)) in definitions.iter().enumerate() {
        let value = lower(builder, tree, &tree.node)?;
        builder.bind(name.clone(), value);
        for (j, state) in states.iter().enumerate() {
            let total = total_derivative(&tree.node, state, j, &definitions[..k]);
            let op = lower(builder, tree, &total)?;
            builder.bind(total_name(name, j), op);
        }
    }
    Ok(())
}

/// `d node / d x_j` where `node` may read `definitions` (each bound with its total derivative).
fn total_derivative(node: &Node, state: &str, j: usize, definitions: &[(String, Tree)]) -> Node {
    let mut total = node.derivative(state);
    for (name, _) in definitions {
        let partial = node.derivative(name);
        total = ast::add(total, ast::mul(partial, Node::Variable(total_name(name, j))));
    }
    total
}

fn lower(builder: &mut Builder<'_>, tree: &Tree, node: &Node) -> Result<usize, ModelCodeError> {
    builder.lower(node).map_err(|e| ModelCodeError {
        field: tree.field.clone(),
        construct: e.to_string(),
    })
}

/// The pruned program, its folded numbers checked and its size bounded.
fn finish(builder: Builder<'_>, what: &str) -> Result<Program, ModelCodeError> {
    let mut program = builder.finish();
    program.prune();
    for op in &program.ops {
        if let Op::Number(v) = op {
            representable(*v).map_err(|problem| ModelCodeError {
                field: what.to_owned(),
                construct: format!("a derivative folds to the number {v}, which {problem}"),
            })?;
        }
    }
    if program.ops.len() > MAX_OPS {
        return Err(ModelCodeError {
            field: what.to_owned(),
            construct: format!(
                "the values and Jacobians take {} operations, more than {MAX_OPS}: simplify the expressions or introduce definitions for repeated parts",
                program.ops.len()
            ),
        });
    }
    Ok(program)
}

#[cfg(test)]
mod tests;
