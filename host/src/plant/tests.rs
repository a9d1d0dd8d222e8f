//! The programs against the spec's own evaluation (exmex) and against central differences of it.

use std::path::Path;

use super::*;

/// A model that uses every construct the translator handles: definitions reading definitions,
/// functions, powers (integer and not), atan2, min and max, parameters and an input.
const SPEC: &str = r#"
name = "constructs"
[model]
states = ["a", "b", "c"]
inputs = ["v"]
[model.parameters]
k = 0.7
w = 1.3
[[model.definitions]]
name = "g"
expr = "k*a/(1 + b^2)"
[[model.definitions]]
name = "s"
expr = "sin(g)*exp(-c) + sqrt(abs(b) + 1)"
[model.derivatives]
a = "g*s - w*b + v"
b = "atan2(a, 2 + c^2) + max(a, b) - tanh(s)"
c = "(1 + a^2)^0.5 - c^3/10 + min(g, v) + ln(2 + cos(b))"
[[model.outputs]]
name = "y1"
expr = "s*a + log10(3 + c^4)"
noise_variance = 0.1
[[model.outputs]]
name = "y2"
expr = "cbrt(b) + asinh(g)"
noise_variance = 0.1
[sampling]
tau = 0.1
substeps = 1
[learning]
samples = 20
seed = 1
grid.a = { min = -1.0, max = 1.0, points = 2 }
grid.b = { min = -1.0, max = 1.0, points = 2 }
grid.c = { min = 0.0, max = 1.0, points = 2 }
inputs.v = { min = -1.0, max = 1.0, hold = 5 }
[validation]
trajectories = 2
samples = 20
seed = 2
[map]
horizon = 3
nm = 2
beta = 1.0
epsilon = 0.01
[[targets]]
name = "sa"
expr = "s*a"
[[targets]]
name = "c"
expr = "c"
"#;

pub(super) fn design() -> Design {
    crate::spec::parse(Path::new("constructs.toml"), SPEC).unwrap()
}

/// Deterministic points: states in [-2, 2]³ (c ≥ 0 keeps ln's argument positive), input in [-1, 1].
pub(super) fn points() -> impl Iterator<Item = ([f64; 3], [f64; 1])> {
    // From k = 1: at k = 0, g = v = 0 is the kink of `min(g, v)`.
    (1..=500).map(|k| {
        let k = k as f64;
        (
            [
                2.0 * (k * 0.731).sin(),
                2.0 * (k * 0.377).cos(),
                1.5 + (k * 0.913).sin(),
            ],
            [(k * 0.191).sin()],
        )
    })
}

#[test]
fn values_match_the_specs_own_evaluation_to_rounding() {
    let design = design();
    let code = ModelCode::new(&design).unwrap();
    let mut environment = Vec::new();
    let mut scratch = Vec::new();
    let mut worst = 0.0_f64;
    for (x, u) in points() {
        let mut f = [0.0; 3];
        design.model.derivative(&x, &u, &mut environment, &mut f);
        let mut h = [0.0; 2];
        design.model.outputs(&x, &u, &mut environment, &mut h);
        let targets: Vec<f64> = design.targets.iter().map(|t| t.expr.eval(&environment)).collect();
        let (ours_f, _) = code.derivative(&x, &u, &mut scratch);
        let (ours_h, _) = code.output(&x, &u, &mut scratch);
        let ours_r = code.targets(&x, &u, &mut scratch);
        for (a, b) in f
            .iter()
            .chain(&h)
            .chain(&targets)
            .zip(ours_f.iter().chain(&ours_h).chain(&ours_r))
        {
            worst = worst.max((a - b).abs() / (1.0 + a.abs()));
        }
    }
    // The same operations but for x^n as products and libm's functions for the platform's: a few ulps.
    assert!(worst < 1e-14, "worst relative difference {worst:e}");
}

#[test]
fn jacobians_match_central_differences_of_the_specs_evaluation() {
    let design = design();
    let code = ModelCode::new(&design).unwrap();
    let mut environment = Vec::new();
    let mut scratch = Vec::new();
    let mut worst = 0.0_f64;
    let delta = 1e-6;
    for (x, u) in points() {
        let (_, df) = code.derivative(&x, &u, &mut scratch);
        let (_, dh) = code.output(&x, &u, &mut scratch);
        for j in 0..3 {
            let (mut up, mut down) = (x, x);
            up[j] += delta;
            down[j] -= delta;
            let (mut f_up, mut f_down, mut h_up, mut h_down) = ([0.0; 3], [0.0; 3], [0.0; 2], [0.0; 2]);
            design.model.derivative(&up, &u, &mut environment, &mut f_up);
            design.model.derivative(&down, &u, &mut environment, &mut f_down);
            design.model.outputs(&up, &u, &mut environment, &mut h_up);
            design.model.outputs(&down, &u, &mut environment, &mut h_down);
            for i in 0..3 {
                let difference = (f_up[i] - f_down[i]) / (2.0 * delta);
                worst = worst.max((difference - df[i * 3 + j]).abs() / (1.0 + difference.abs()));
            }
            for i in 0..2 {
                let difference = (h_up[i] - h_down[i]) / (2.0 * delta);
                worst = worst.max((difference - dh[i * 3 + j]).abs() / (1.0 + difference.abs()));
            }
        }
    }
    // Central differences: O(δ²) truncation and O(ε/δ) rounding, about 1e-9 here. A dropped chain
    // term through a definition is O(1).
    assert!(worst < 1e-7, "worst relative difference {worst:e}");
}

#[test]
fn shared_subexpressions_are_computed_once() {
    let code = ModelCode::new(&design()).unwrap();
    for program in [&code.derivative, &code.output, &code.targets] {
        for (i, a) in program.ops.iter().enumerate() {
            assert!(!program.ops[..i].contains(a), "operation {a:?} appears twice");
        }
    }
}

#[test]
fn what_cannot_be_emitted_is_refused_with_its_field() {
    let text = SPEC.replace("w = 1.3", "w = 1e39");
    let design = crate::spec::parse(Path::new("constructs.toml"), &text).unwrap();
    let error = ModelCode::new(&design).unwrap_err();
    assert_eq!(error.field, "model.parameters.w");
    assert!(error.construct.contains("not finite in f32"), "{error}");

    let text = SPEC.replace("c^3/10", "c^3/10000000000000000000000000000000000000000000000");
    let design = crate::spec::parse(Path::new("constructs.toml"), &text).unwrap();
    let error = ModelCode::new(&design).unwrap_err();
    assert_eq!(error.field, "model.derivatives.c");

    // exmex folds `1 + 2` first here, against its left-to-right order: the simulation's reading
    // differs from the tree's, so the model is refused rather than emitted wrong.
    let text = SPEC.replace("ln(2 + cos(b))", "(ln(2 + cos(b)) max 1 + 2)");
    let design = crate::spec::parse(Path::new("constructs.toml"), &text).unwrap();
    let error = ModelCode::new(&design).unwrap_err();
    assert_eq!(error.field, "model.derivatives.c");
    assert!(error.construct.contains("add parentheses"), "{error}");
}

#[test]
fn many_points_at_once_are_bit_for_bit_one_at_a_time() {
    let design = design();
    let code = ModelCode::new(&design).unwrap();
    let f = code.derivative.first_results(3);
    assert!(f.ops.len() < code.derivative.ops.len(), "nothing pruned");
    let points: Vec<([f64; 3], [f64; 1])> = points().collect();
    let u = [0.3];
    let states: Vec<Vec<f64>> = (0..3).map(|i| points.iter().map(|(x, _)| x[i]).collect()).collect();
    for program in [&f, &code.output, &code.targets] {
        let mut results = vec![Vec::new(); program.results.len()];
        // `w` (index 1) varies from point to point.
        let w: Vec<f64> = (0..points.len()).map(|p| 1.0 + 0.01 * p as f64).collect();
        program.eval_many(&code.parameters, &[(1, &w)], &states, &u, &mut Vec::new(), &mut results);
        for (p, (x, _)) in points.iter().enumerate() {
            let mut parameters = code.parameters.clone();
            assert_eq!(parameters[1].0, "w");
            parameters[1].1 = w[p];
            let one = program.eval(&parameters, x, &u, &mut Vec::new());
            for (r, value) in one.iter().enumerate() {
                assert_eq!(results[r][p].to_bits(), value.to_bits(), "point {p}, result {r}");
            }
        }
    }
}

/// A tank draining through an orifice, `dh/dt = u − c √h`, bounded at 0 and learnt on `h ∈ [0, 4]`.
const TANK: &str = r#"
name = "tank"
[model]
states = ["h"]
inputs = ["u"]
[model.bounds]
h = { min = 0.0 }
[model.parameters]
c = 0.5
[model.derivatives]
h = "u - c*sqrt(h)"
[[model.outputs]]
name = "y"
expr = "sqrt(h)"
noise_variance = 0.01
[sampling]
tau = 0.1
substeps = 1
[learning]
samples = 20
seed = 1
grid.h = { min = 0.0, max = 4.0, points = 2 }
inputs.u = { min = 0.0, max = 1.0, hold = 5 }
[validation]
trajectories = 2
samples = 20
seed = 2
[map]
horizon = 3
nm = 2
beta = 1.0
epsilon = 0.01
[[targets]]
name = "h"
expr = "h"
"#;

#[test]
fn jacobians_are_finite_at_a_bound_where_the_slope_is_not() {
    let design = crate::spec::parse(Path::new("tank.toml"), TANK).unwrap();
    let code = ModelCode::new(&design).unwrap();
    let mut scratch = Vec::new();
    // The closed forms: d(u − c√h)/dh = −c / (2√h), d√h/dh = 1 / (2√h), at h moved inside the bound
    // by a thousandth of the learning range [0, 4].
    let inside = JACOBIAN_INSIDE * 4.0;
    for (h, at) in [(0.0, inside), (-1.0, inside), (inside / 2.0, inside), (2.25, 2.25)] {
        let (f, jacobian) = code.derivative(&[h], &[0.3], &mut scratch);
        let (y, dy) = code.output(&[h], &[0.3], &mut scratch);
        // The values are the model's at the state itself (√ of a negative level is NaN, as written).
        assert_eq!(f[0].to_bits(), (0.3 - 0.5 * h.sqrt()).to_bits(), "f at h = {h}");
        assert_eq!(y[0].to_bits(), h.sqrt().to_bits(), "h(x) at h = {h}");
        let slope = 1.0 / (2.0 * at.sqrt());
        assert!(
            (jacobian[0] + 0.5 * slope).abs() <= 1e-12 * slope,
            "∂f/∂h at h = {h}: {}",
            jacobian[0]
        );
        assert!((dy[0] - slope).abs() <= 1e-12 * slope, "∂h/∂h at h = {h}: {}", dy[0]);
    }
}

#[test]
fn a_model_with_finite_slopes_on_its_bounds_is_left_as_it_is() {
    let linear = TANK
        .replace("c*sqrt(h)", "c*h")
        .replace("expr = \"sqrt(h)\"", "expr = \"h\"");
    let unbounded = linear.replace("h = { min = 0.0 }", "");
    let code = |text: &str| ModelCode::new(&crate::spec::parse(Path::new("tank.toml"), text).unwrap()).unwrap();
    let (bounded, free) = (code(&linear), code(&unbounded));
    assert_eq!(bounded.derivative.ops, free.derivative.ops);
    assert_eq!(bounded.output.ops, free.output.ops);
    // The tank's own square root is moved: its program differs from the unbounded one's.
    let sqrt_free = code(&TANK.replace("h = { min = 0.0 }", ""));
    assert_ne!(code(TANK).derivative.ops, sqrt_free.derivative.ops);
}
