//! The symbolic derivative of a tree, and the constructors that fold numbers as they build one (what
//! the model's Jacobians are made of).

use super::{Binary, Node};

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
/// `a = b`). Being a blend, it is NaN where the operand not picked has an infinite derivative (`max(1,
/// sqrt(x))` at `x = 0`); on a declared bound the filters take their Jacobians inside it
/// (`crate::plant::inside`), and elsewhere `sqrt(max(1, x))` says the same with a finite slope.
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
