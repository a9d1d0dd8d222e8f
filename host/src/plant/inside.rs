//! Jacobians that stay finite on the declared bounds: where a model's slope is infinite on a bound
//! (`sqrt(h)` at `h = 0`), the Jacobian is evaluated with the state moved inside it.

use super::program::{self, Builder, Names, Program};
use crate::spec::Design;

/// How far inside its bounds a state is moved where a Jacobian is evaluated, as a fraction of its
/// learning range (see the module docs).
pub const JACOBIAN_INSIDE: f64 = 1e-3;

/// Each state's interval for the Jacobians of `program` (values, then their Jacobian row by row):
/// where some Jacobian entry is not finite with the state on a bound (checked at the learning box's
/// centre and corners for the other states, the inputs at their ranges' ends and centre), that bound
/// moved inward by [`JACOBIAN_INSIDE`] times the state's learning range (of the bound's size where
/// the range is a point); `None` where the slope is finite on the bound or there is none.
fn jacobian_points(design: &Design, program: &Program) -> Vec<(Option<f64>, Option<f64>)> {
    let axes = &design.learning.axes;
    let span = |axis: &crate::spec::Axis| match *axis {
        crate::spec::Axis::Range { min, max, .. } => (min, max),
        crate::spec::Axis::Fixed(value) => (value, value),
    };
    let n = axes.len();
    // The centre, then every corner (2ⁿ, n ≤ 10), of the states; each input's ends and centre.
    let corners = if n <= 10 { 1usize << n } else { 0 };
    let points: Vec<Vec<f64>> = std::iter::once(axes.iter().map(|a| 0.5 * (span(a).0 + span(a).1)).collect())
        .chain((0..corners).map(|c| {
            axes.iter()
                .enumerate()
                .map(|(i, a)| if c >> i & 1 == 0 { span(a).0 } else { span(a).1 })
                .collect()
        }))
        .collect();
    let inputs: Vec<Vec<f64>> = [0.0, 0.5, 1.0]
        .iter()
        .map(|w| {
            design
                .learning
                .inputs
                .iter()
                .map(|p| p.min + w * (p.max - p.min))
                .collect()
        })
        .collect();
    let parameters = &design.model.parameters;
    let mut scratch = Vec::new();
    let values = program.results.len() / (n + 1);
    let mut infinite_slope = |i: usize, bound: f64| {
        points.iter().any(|point| {
            let mut x = point.clone();
            x[i] = bound;
            inputs.iter().any(|u| {
                let all = program.eval::<f64>(parameters, &x, u, &mut scratch);
                all[values..].iter().any(|v| !v.is_finite())
            })
        })
    };
    design
        .state_bounds
        .iter()
        .zip(axes)
        .enumerate()
        .map(|(i, (bounds, axis))| {
            let (min, max) = span(axis);
            let width = max - min;
            let step = |bound: f64| JACOBIAN_INSIDE * if width > 0.0 { width } else { bound.abs().max(1.0) };
            let low = bounds.min.filter(|&b| infinite_slope(i, b)).map(|b| b + step(b));
            let high = bounds.max.filter(|&b| infinite_slope(i, b)).map(|b| b - step(b));
            (low, high)
        })
        .collect()
}

/// `program` (values, then their Jacobian row by row) with the Jacobian evaluated at the state moved
/// inside `inside` (a select per moved side), the values at the state itself.
///
/// A model may have an unbounded slope at a point its bounds allow (`sqrt(h)` at `h = 0`, `ln(c)`
/// at 0): a filter projected onto the bound would read an infinite slope there and refuse every
/// sample after. Inside by a thousandth of the learning range, the slope is finite and the chip and
/// the host agree on it (they run this program); away from the bound nothing changes, bit for bit
/// (the select passes the state through), and a model whose slopes are finite on its bounds is left
/// as it is.
pub(super) fn jacobian_inside(design: &Design, program: Program, names: Names<'_>) -> Program {
    let inside = jacobian_points(design, &program);
    if inside.iter().all(|&(low, high)| low.is_none() && high.is_none()) {
        return program;
    }
    let states = inside.len();
    let values = program.results.len() / (states + 1);
    let mut b = Builder::new(names);
    let x: Vec<usize> = (0..states).map(|i| b.leaf(program::Leaf::State(i))).collect();
    let at_state = b.inline(&program, &x);
    let moved: Vec<usize> = x
        .iter()
        .zip(&inside)
        .map(|(&xi, &(low, high))| {
            let mut m = xi;
            if let Some(low) = low {
                let low = b.number(low);
                m = b.at_least(m, low);
            }
            if let Some(high) = high {
                let high = b.number(high);
                m = b.at_most(m, high);
            }
            m
        })
        .collect();
    let at_moved = b.inline(&program, &moved);
    for &r in at_state[..values].iter().chain(&at_moved[values..]) {
        b.result(r);
    }
    let mut out = b.finish();
    out.prune();
    out
}
