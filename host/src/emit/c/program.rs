//! A straight-line program ([`crate::plant::Program`]) as a C function: one `const float` per
//! operation, in the program's order, each the IEEE operation the Rust file's `let` computes (so that
//! with `-ffp-contract=off` both give the same bits). A function of the model is `<math.h>`'s of the
//! same name as the firmware's `libm` call (`expf` for `Maths::exp`): exact for the correctly rounded
//! ones (`sqrtf`, `fabsf`, `floorf`, …), within an ulp or so for the others, whose C library differs
//! from Rust's `libm`.

use std::fmt::Write;

use super::text::float;
use crate::emit::EmitError;
use crate::plant::program::Leaf;
use crate::plant::{ModelCode, Op, Program};
use crate::spec::ast::Binary;

/// The `<math.h>` function a model function is (its `firmware::Maths` name: `libm`'s `<name>f`), or
/// the helper of the C file ([`helpers`]) for the two that C does not have.
fn c_function(name: &str) -> String {
    match name {
        "abs" => "fabsf".to_owned(),
        // libm's own algorithm, written out (see `helpers`), as `exp` below.
        "ln" => "libm_logf".to_owned(),
        // libm's own algorithm, written out (see `helpers`): C libraries' `expf` differ in the last bit.
        "exp" => "libm_expf".to_owned(),
        "signum" | "fract" => name.to_owned(),
        other => format!("{other}f"),
    }
}

/// The C expression of operation `op` (operands by their locals `t<index>`).
fn operation(op: &Op, code: &ModelCode, what: &str) -> Result<String, EmitError> {
    let t = |i: usize| format!("t{i}");
    Ok(match *op {
        Op::Number(v) => float(&format!("{what}: a number of the model"), v)?,
        Op::Leaf(Leaf::Parameter(i)) => {
            let (name, value) = &code.parameters[i];
            format!("{} /* {name} */", float(&format!("model.parameters.{name}"), *value)?)
        }
        Op::Leaf(Leaf::State(i)) => format!("x[{i}]"),
        Op::Leaf(Leaf::Input(i)) => format!("u[{i}]"),
        Op::Leaf(Leaf::Covariance(k)) => format!("p[{k}]"),
        Op::Leaf(Leaf::Measurement(i)) => format!("y[{i}]"),
        Op::Leaf(Leaf::Map(i)) => format!("f[{i}]"),
        Op::Leaf(Leaf::Blend(i)) => format!("g[{i}]"),
        Op::Negate(a) => format!("-{}", t(a)),
        Op::Binary(b, x, y) => {
            let (x, y) = (t(x), t(y));
            match b {
                Binary::Add => format!("{x} + {y}"),
                Binary::Sub => format!("{x} - {y}"),
                Binary::Mul => format!("{x} * {y}"),
                Binary::Div => format!("{x} / {y}"),
                Binary::Pow => format!("powf({x}, {y})"),
                Binary::Atan2 => format!("atan2f({x}, {y})"),
                Binary::Min => format!("fminf({x}, {y})"),
                Binary::Max => format!("fmaxf({x}, {y})"),
            }
        }
        Op::Call(f, a) => {
            format!("{}({})", c_function(f), t(a))
        }
        // `firmware::bounds::at_least` and `at_most`, by the same selects.
        Op::AtLeast(a, b) => format!("select_float(!({0} >= {1}), {1}, {0})", t(a), t(b)),
        Op::AtMost(a, b) => format!("select_float({0} > {1}, {1}, {0})", t(a), t(b)),
    })
}

/// The parameter of a program's function that a leaf reads (`x`, `u`, …); none for a parameter of
/// the model, which is a number.
fn reads(leaf: &Leaf) -> Option<&'static str> {
    match leaf {
        Leaf::Parameter(_) => None,
        Leaf::State(_) => Some("x"),
        Leaf::Input(_) => Some("u"),
        Leaf::Covariance(_) => Some("p"),
        Leaf::Measurement(_) => Some("y"),
        Leaf::Map(_) => Some("f"),
        Leaf::Blend(_) => Some("g"),
    }
}

/// Whether any of `programs` calls a function of `<math.h>`.
pub(crate) fn needs_math(programs: &[&Program]) -> bool {
    programs.iter().any(|p| {
        p.ops.iter().any(|op| {
            matches!(
                op,
                Op::Call(..) | Op::Binary(Binary::Pow | Binary::Atan2 | Binary::Min | Binary::Max, ..)
            )
        })
    })
}

/// Whether any of `programs` calls the function `name` (`signum`, `exp`, …).
pub(crate) fn calls(programs: &[&Program], name: &str) -> bool {
    programs
        .iter()
        .any(|p| p.ops.iter().any(|op| matches!(op, Op::Call(f, _) if *f == name)))
}

/// `static void <name>(const float *<param>, …, float *out)` computing `program`: its operations
/// that some result needs, in order, then `out[i]` = result `i`. Every parameter is `const float *`
/// (`(void)` where no operation reads it).
pub(crate) fn function(
    name: &str,
    doc: &str,
    params: &[&str],
    program: &Program,
    code: &ModelCode,
) -> Result<String, EmitError> {
    let mut needed = vec![false; program.ops.len()];
    for &r in &program.results {
        needed[r] = true;
    }
    for i in (0..program.ops.len()).rev() {
        if !needed[i] {
            continue;
        }
        match program.ops[i] {
            Op::Negate(a) | Op::Call(_, a) => needed[a] = true,
            Op::Binary(_, a, b) | Op::AtLeast(a, b) | Op::AtMost(a, b) => {
                needed[a] = true;
                needed[b] = true;
            }
            Op::Number(_) | Op::Leaf(_) => {}
        }
    }
    let signature: Vec<String> = params.iter().map(|p| format!("const float *{p}")).collect();
    let mut text = format!(
        "/* {doc} */\nstatic void {name}({}, float *out) {{\n",
        signature.join(", ")
    );
    // A parameter no needed operation reads is cast to void (an unused parameter is a warning).
    for (k, p) in params.iter().enumerate() {
        let read = program.ops.iter().enumerate().any(|(i, op)| {
            needed[i]
                && match op {
                    Op::Leaf(leaf) => reads(leaf) == Some(params[k]),
                    _ => false,
                }
        });
        if !read {
            writeln!(text, "    (void){p};").expect("write to a String");
        }
    }
    for (i, op) in program.ops.iter().enumerate() {
        if needed[i] {
            writeln!(text, "    const float t{i} = {};", operation(op, code, name)?).expect("write to a String");
        }
    }
    for (k, &r) in program.results.iter().enumerate() {
        writeln!(text, "    out[{k}] = t{r};").expect("write to a String");
    }
    text.push_str("}\n\n");
    Ok(text)
}
