//! The model in log coordinates against the plant's by the chain rule, and its Jacobians against
//! central differences of its own values.

use std::path::Path;

use super::*;

/// A tank `h ≥ 0` (box centre 2: `c = 0.02`) driving an unbounded `v`, with an input.
const SPEC: &str = r#"
name = "tank_and_v"
[model]
states = ["h", "v"]
inputs = ["u"]
[model.bounds]
h = { min = 0.0 }
[model.parameters]
c = 0.5
[model.derivatives]
h = "u - c*sqrt(h) + 0.1*v"
v = "-h*v"
[[model.outputs]]
name = "y"
expr = "sqrt(h) + v"
noise_variance = 0.01
[sampling]
tau = 0.1
substeps = 1
[learning]
samples = 20
seed = 1
grid.h = { min = 0.0, max = 4.0, points = 2 }
grid.v = { min = -1.0, max = 1.0, points = 2 }
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
name = "hv"
expr = "h*v"
"#;

fn plant() -> ModelCode {
    ModelCode::new(&crate::spec::parse(Path::new("tank_and_v.toml"), SPEC).unwrap()).unwrap()
}

#[test]
fn only_a_state_bounded_below_is_carried_by_its_logarithm() {
    let code = plant();
    let log = code.log_coordinates.0[0].expect("h is bounded below");
    assert_eq!(
        (log.min, log.offset),
        (0.0, 0.02),
        "1 % of the box centre's distance to the bound"
    );
    assert_eq!(code.log_coordinates.0[1], None);
    let z = code.logarithmic();
    assert_eq!(z.bounds[0].min, Some(0.02f64.ln()));
    assert_eq!(z.bounds[1], code.bounds[1]);
    let coordinates = &z.coordinates;
    let x = coordinates.to_plant(&[0.02f64.ln(), 0.3]);
    assert!(
        (x[0] - 0.0).abs() < 1e-15 && x[1] == 0.3,
        "the bound in z is the bound in x: {x:?}"
    );
    let back = coordinates.to_filter(&coordinates.to_plant(&[0.7, -0.4]));
    assert!((back[0] - 0.7).abs() < 1e-15 && back[1] == -0.4);
    // Below the bound reads as on it.
    assert_eq!(coordinates.to_filter(&[-1.0, 0.0])[0], 0.02f64.ln());
}

#[test]
fn the_log_model_is_the_plants_by_the_chain_rule() {
    let code = plant();
    let z_code = code.logarithmic();
    let mut scratch = Vec::new();
    for (z, u) in [([0.3, -0.5], [0.2]), ([-2.0, 0.8], [0.9]), ([1.2, 0.0], [0.0])] {
        let x = z_code.coordinates.to_plant(&z);
        let s = x[0] + 0.02;
        let (f, _) = code.derivative::<f64>(&x, &u, &mut scratch);
        let (fz, _) = z_code.derivative::<f64>(&z, &u, &mut scratch);
        assert!(
            (fz[0] - f[0] / s).abs() < 1e-14 && fz[1] == f[1],
            "{fz:?} against {f:?}"
        );
        let (h, _) = code.output::<f64>(&x, &u, &mut scratch);
        let (hz, _) = z_code.output::<f64>(&z, &u, &mut scratch);
        assert!((hz[0] - h[0]).abs() < 1e-14);
        let (r, rz) = (
            code.targets::<f64>(&x, &u, &mut scratch),
            z_code.targets::<f64>(&z, &u, &mut scratch),
        );
        assert!((rz[0] - r[0]).abs() < 1e-14);
    }
}

#[test]
fn the_log_models_jacobians_are_its_values_slopes() {
    let z_code = plant().logarithmic();
    let mut scratch = Vec::new();
    let step = 1e-6;
    for (z, u) in [([0.3, -0.5], [0.2]), ([-2.0, 0.8], [0.9])] {
        let (_, jf) = z_code.derivative::<f64>(&z, &u, &mut scratch);
        let (_, jh) = z_code.output::<f64>(&z, &u, &mut scratch);
        for j in 0..2 {
            let (mut up, mut down) = (z, z);
            up[j] += step;
            down[j] -= step;
            let (fu, _) = z_code.derivative::<f64>(&up, &u, &mut scratch);
            let (fd, _) = z_code.derivative::<f64>(&down, &u, &mut scratch);
            for i in 0..2 {
                let difference = (fu[i] - fd[i]) / (2.0 * step);
                assert!(
                    (jf[i * 2 + j] - difference).abs() < 1e-6,
                    "∂ż{i}/∂z{j}: {} against {difference}",
                    jf[i * 2 + j]
                );
            }
            let (hu, _) = z_code.output::<f64>(&up, &u, &mut scratch);
            let (hd, _) = z_code.output::<f64>(&down, &u, &mut scratch);
            let difference = (hu[0] - hd[0]) / (2.0 * step);
            assert!(
                (jh[j] - difference).abs() < 1e-6,
                "∂h/∂z{j}: {} against {difference}",
                jh[j]
            );
        }
    }
}

#[test]
fn a_plant_covariance_maps_by_the_slopes_at_the_start() {
    let coordinates = plant().log_coordinates;
    let mapped = coordinates.covariance(&crate::plant::Covariance::Diagonal(vec![0.5, 0.3]), &[1.98, 0.0]);
    // dz/dx = 1 / (1.98 + 0.02) = 0.5 for h; v unchanged.
    assert_eq!(mapped, crate::plant::Covariance::Diagonal(vec![0.125, 0.3]));
}
