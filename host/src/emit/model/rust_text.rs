//! The pieces every written-out observer is made of: a number as `T::literal(f32, f64)`, lists and
//! rows of them, and a straight-line program as one `let` per operation ([`body`]).

use std::fmt::Write;

use crate::emit::{f32_literal, EmitError};
use crate::plant::program::Leaf;
use crate::plant::{ModelCode, Op, Program};
use crate::spec::ast::Binary;
use crate::spec::Design;

/// `T::literal(single, double)` for `value`, the `f32` checked as [`f32_literal`] checks it.
pub(crate) fn literal(what: &str, value: f64) -> Result<String, EmitError> {
    Ok(format!("T::literal({}, {value:?})", f32_literal(what, value)?))
}

/// The right-hand side of operation `op`.
fn operation(op: &Op, code: &ModelCode, names: &Names<'_>) -> Result<String, EmitError> {
    Ok(match *op {
        Op::Number(v) => literal("a number of the model", v)?,
        Op::Leaf(Leaf::Parameter(i)) => {
            format!("T::literal(parameters::{0}.0, parameters::{0}.1)", code.parameters[i].0)
        }
        Op::Leaf(Leaf::State(i)) => format!("x[{i}]"),
        Op::Leaf(Leaf::Input(i)) => format!("u[{i}]"),
        Op::Leaf(Leaf::Covariance(k)) => format!("p[{k}]"),
        Op::Leaf(Leaf::Measurement(i)) => format!("y[{i}]"),
        Op::Leaf(Leaf::Map(i)) => format!("f[{i}]"),
        // Read from the start-up table where used: no copy of the row.
        Op::Leaf(Leaf::Blend(i)) => format!("T::literal(g[{i}].0, g[{i}].1)"),
        Op::Negate(a) => format!("-{}", names.of(a)),
        Op::Binary(b, x, y) => {
            let (x, y) = (names.of(x), names.of(y));
            match b {
                Binary::Add => format!("{x} + {y}"),
                Binary::Sub => format!("{x} - {y}"),
                Binary::Mul => format!("{x} * {y}"),
                Binary::Div => format!("{x} / {y}"),
                Binary::Pow => format!("Maths::powf({x}, {y})"),
                Binary::Atan2 => format!("Maths::atan2({x}, {y})"),
                Binary::Min => format!("Maths::min({x}, {y})"),
                Binary::Max => format!("Maths::max({x}, {y})"),
            }
        }
        Op::Call(f, a) => format!("Maths::{f}({})", names.of(a)),
        Op::AtLeast(a, b) => format!("firmware::emitted::at_least({}, {})", names.of(a), names.of(b)),
        Op::AtMost(a, b) => format!("firmware::emitted::at_most({}, {})", names.of(a), names.of(b)),
    })
}

/// The local each operation is bound to: `x_<state>`, `u_<input>`, `p_<parameter>`, or `t<index>`.
struct Names<'a> {
    program: &'a Program,
    design: &'a Design,
}

impl Names<'_> {
    fn of(&self, op: usize) -> String {
        let model = &self.design.model;
        match self.program.ops[op] {
            Op::Leaf(Leaf::State(i)) => format!("x_{}", model.states[i]),
            Op::Leaf(Leaf::Input(i)) => format!("u_{}", model.inputs[i]),
            Op::Leaf(Leaf::Parameter(i)) => format!("p_{}", model.parameters[i].0),
            Op::Leaf(Leaf::Covariance(k)) => format!("cov{k}"),
            Op::Leaf(Leaf::Measurement(i)) => format!("y_{}", model.outputs[i].name),
            Op::Leaf(Leaf::Map(i)) => format!("f_{}", model.states[i]),
            Op::Leaf(Leaf::Blend(i)) if i < model.states.len() => format!("g_{}", model.states[i]),
            Op::Leaf(Leaf::Blend(i)) => format!("k{}", i - model.states.len()),
            _ => format!("t{op}"),
        }
    }
}

/// The body of a function computing `program`: its `let`s, then `result` (the results by name).
pub(crate) fn body(
    program: &Program,
    code: &ModelCode,
    design: &Design,
    indent: &str,
    result: impl Fn(&[String]) -> String,
) -> Result<String, EmitError> {
    let names = Names { program, design };
    let mut text = String::new();
    for (i, op) in program.ops.iter().enumerate() {
        writeln!(
            text,
            "{indent}let {}: T = {};",
            names.of(i),
            operation(op, code, &names)?
        )
        .expect("write to a String");
    }
    let results: Vec<String> = program.results.iter().map(|&r| names.of(r)).collect();
    writeln!(text, "{indent}{}", result(&results)).expect("write to a String");
    Ok(text)
}

/// `[a, b, …]`.
pub(crate) fn list(items: &[String]) -> String {
    format!("[{}]", items.join(", "))
}

/// `[a, b, …]` of `values` as `f32` literals (each checked as [`f32_literal`] checks it, named
/// `what[i]`).
pub(crate) fn f32_list(what: &str, values: &[f64]) -> Result<String, EmitError> {
    let entries = values
        .iter()
        .enumerate()
        .map(|(i, v)| f32_literal(&format!("{what}[{i}]"), *v))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(list(&entries))
}

/// `[[…], …]`: `items` in rows of `width`.
pub(crate) fn rows(items: &[String], width: usize) -> String {
    if width == 0 {
        return format!("[[]; {}]", items.len());
    }
    list(&items.chunks(width).map(list).collect::<Vec<_>>())
}
