use nalgebra::{Matrix2, Vector2};

use super::*;
use crate::data::simulate::Integrator;
use crate::observers::kind::corrected::program::correction_code;

/// Example 1's model, a validation-like run of it, and a stand-in for the map's estimates (the true
/// state plus a known offset), so that each case has a closed-form answer.
fn fixture(spec: &str) -> (Design, ModelCode, Run, Rows) {
    let design = crate::spec::load(std::path::Path::new(spec)).unwrap();
    let code = ModelCode::new(&design).unwrap();
    let data = crate::data::validation_set(&design).unwrap();
    let run = data.runs[0].clone();
    let map: Rows = run.states.iter().map(|x| vec![x[0] + 0.1, x[1] - 0.2]).collect();
    (design, code, run, map)
}

fn setting<'a>(code: &'a ModelCode, targets: &'a [usize]) -> Setting<'a> {
    Setting {
        code,
        h: 0.1,
        substeps: 1,
        state_targets: targets,
        first: 9,
        lower: vec![-1e9; 2],
        upper: vec![1e9; 2],
    }
}

fn constants(setting: &Setting<'_>, g: f64, k: [f64; 2], schedule: f64) -> CorrectionConstants {
    CorrectionConstants {
        g: vec![g; 2],
        k: k.to_vec(),
        k_start: k.to_vec(),
        schedule,
        ..setting.constants(&[0.0; 7])
    }
}

fn run_with(setting: &Setting<'_>, constants: &CorrectionConstants, map: &Rows, run: &Run) -> Rows {
    estimate_rows(setting, &correction_code(setting.code, constants), constants, map, run).rows
}

#[test]
fn with_g_one_and_k_zero_it_is_the_map() {
    let (_, code, run, map) = fixture("specs/vanderpol.toml");
    let targets = [0, 1];
    let setting = setting(&code, &targets);
    let out = run_with(&setting, &constants(&setting, 1.0, [0.0, 0.0], 3.0), &map, &run);
    assert!(out[8].iter().all(|v| v.is_nan()), "no estimate before N samples");
    for k in 9..run.targets.len() {
        for i in 0..2 {
            // x̄ + 1 · (F − x̄) is F up to one rounding.
            assert!(
                (out[k][i] - map[k][i]).abs() <= 1e-15 * (1.0 + map[k][i].abs()),
                "k = {k}"
            );
        }
    }
}

#[test]
fn with_g_and_k_zero_it_is_the_model_from_the_maps_first_estimate() {
    // T tiny: the blend is G = 0 from the second estimate on, leaving the model's open-loop
    // prediction, which an independent integrator (the learning simulation's, 1 substep) gives.
    let (design, code, run, map) = fixture("specs/vanderpol.toml");
    let targets = [0, 1];
    let setting = setting(&code, &targets);
    let out = run_with(&setting, &constants(&setting, 0.0, [0.0, 0.0], 1e-300), &map, &run);
    let mut integrator = Integrator::new(&design.model, design.tau, 1);
    let mut x = map[9].to_vec();
    for k in 10..run.targets.len() {
        integrator.advance(&mut x, &run.inputs[k - 1]);
        let gap = (out[k][0] - x[0]).abs().max((out[k][1] - x[1]).abs());
        assert!(
            gap < 1e-9 * (1.0 + x[0].abs() + x[1].abs()),
            "k = {k}: {:?} vs {x:?}",
            &out[k]
        );
    }
}

#[test]
fn the_start_up_blend_follows_its_schedule_and_is_cut_to_g() {
    // With K = 0: x̂(j) = x̄ + g_j (F − x̄), g_j = G + (1 − G)/(1 + j/T) for j ≤ J, then G.
    let (design, code, run, map) = fixture("specs/vanderpol.toml");
    let targets = [0, 1];
    let setting = setting(&code, &targets);
    let (g, schedule) = (0.3, 2.5);
    let mut constants = constants(&setting, g, [0.0, 0.0], schedule);
    constants.start_up = 3;
    let out = run_with(&setting, &constants, &map, &run);
    let mut integrator = Integrator::new(&design.model, design.tau, 1);
    let mut x = map[9].to_vec();
    for j in 1..7 {
        let k = 9 + j;
        integrator.advance(&mut x, &run.inputs[k - 1]);
        let blend = if j <= 3 {
            g + (1.0 - g) / (1.0 + j as f64 / schedule)
        } else {
            g
        };
        for i in 0..2 {
            x[i] += blend * (map[k][i] - x[i]);
            assert!(
                (out[k][i] - x[i]).abs() < 1e-9,
                "j = {j}, state {i}: {} vs {}",
                out[k][i],
                x[i]
            );
        }
    }
}

/// `ẋ1 = x2, ẋ2 = −x1 − 0.5 x2, y = x1` (Example 1's spec otherwise), a validation run, and a map
/// biased by (0.3, −0.4).
fn linear() -> (ModelCode, Run, Rows) {
    let design = crate::spec::parse(
        std::path::Path::new("linear.toml"),
        &std::fs::read_to_string("specs/vanderpol.toml")
            .unwrap()
            .replace("x2 = \"4*x1 + (1 - x1^2)*x2\"", "x2 = \"-x1 - 0.5*x2\"")
            .replace("x1 = \"-x2\"", "x1 = \"x2\"")
            .replace("expr = \"x1 + x2\"", "expr = \"x1\""),
    )
    .unwrap();
    let code = ModelCode::new(&design).unwrap();
    let run = crate::data::validation_set(&design).unwrap().runs[0].clone();
    let map: Rows = run.states.iter().map(|x| vec![x[0] + 0.3, x[1] - 0.4]).collect();
    (code, run, map)
}

/// One RK4 step of the linear plant: exactly `A_d = Σₙ₌₀⁴ (hA)ⁿ / n!`.
fn linear_step() -> Matrix2<f64> {
    let ha = Matrix2::new(0.0, 1.0, -1.0, -0.5) * 0.1;
    Matrix2::identity() + ha + ha * ha / 2.0 + ha * ha * ha / 6.0 + ha * ha * ha * ha / 24.0
}

#[test]
fn a_linear_plant_with_g_zero_is_the_fixed_gain_observer_in_closed_form() {
    // ẋ = A x, y = C x: one RK4 step is exactly A_d = Σₙ₌₀⁴ (hA)ⁿ / n!, and with G = 0 after the
    // first estimate the observer is x̂(k) = (I − K C) A_d x̂(k−1) + K y(k).
    let (code, run, map) = linear();
    let targets = [0, 1];
    let setting = setting(&code, &targets);
    let gain = [0.4, 0.15];
    let out = run_with(&setting, &constants(&setting, 0.0, gain, 1e-300), &map, &run);

    let discrete = linear_step();
    let k = Vector2::new(gain[0], gain[1]);
    let c = nalgebra::RowVector2::new(1.0, 0.0);
    let mut x = Vector2::new(map[9][0], map[9][1]);
    for step in 10..run.targets.len() {
        let predicted = discrete * x;
        x = predicted + k * (run.measurements[step][0] - (c * predicted)[0]);
        let gap = (out[step][0] - x[0]).abs().max((out[step][1] - x[1]).abs());
        assert!(gap < 1e-12, "k = {step}: {:?} vs {x:?}", &out[step]);
    }
    // The tolerance bites: a gain off by 1 % leaves the closed form by more.
    let off = run_with(&setting, &constants(&setting, 0.0, [0.404, 0.15], 1e-300), &map, &run);
    let last = run.targets.len() - 1;
    assert!((off[last][0] - x[0]).abs() > 1e-6);
}

#[test]
fn on_a_linear_plant_the_start_up_gain_falls_from_k0_to_k_in_closed_form() {
    // As above, with estimate j = k − N + 1 of the start-up (j ≤ J = 3N) blending the map by
    // g_j = 1/(1 + j/T) (G = 0) and correcting by K_j = K + (K₀ − K)/(1 + j/T), then by K alone:
    // x̄ = A_d x̂(k−1), x̂(k) = x̄ + g_j (F(k) − x̄) + K_j (y(k) − C x̄).
    let (code, run, map) = linear();
    let targets = [0, 1];
    let setting = setting(&code, &targets);
    let (gain, start, schedule) = ([0.4, 0.15], [0.9, 0.6], 2.0);
    let with = |start: [f64; 2]| CorrectionConstants {
        k_start: start.to_vec(),
        ..constants(&setting, 0.0, gain, schedule)
    };
    let out = run_with(&setting, &with(start), &map, &run);

    let discrete = linear_step();
    let c = nalgebra::RowVector2::new(1.0, 0.0);
    let (k, k0) = (Vector2::new(gain[0], gain[1]), Vector2::new(start[0], start[1]));
    let mut x = Vector2::new(map[9][0], map[9][1]);
    for step in 10..run.targets.len() {
        let j = (step - 9) as f64;
        let fall = if j <= 30.0 { 1.0 / (1.0 + j / schedule) } else { 0.0 };
        let k_j = k + (k0 - k) * fall;
        let predicted = discrete * x;
        let towards = Vector2::new(map[step][0], map[step][1]) - predicted;
        x = predicted + towards * fall + k_j * (run.measurements[step][0] - (c * predicted)[0]);
        let gap = (out[step][0] - x[0]).abs().max((out[step][1] - x[1]).abs());
        assert!(gap < 1e-12, "k = {step}: {:?} vs {x:?}", &out[step]);
    }
    // The tolerance bites: a start-up gain off by 1 % moves the estimates of the start-up by more.
    let off = run_with(&setting, &with([0.909, 0.6]), &map, &run);
    let moved = (10..40).map(|k| (off[k][0] - out[k][0]).abs()).fold(0.0, f64::max);
    assert!(moved > 1e-6, "{moved}");
}

#[test]
fn the_clamp_bounds_the_estimate_to_the_maps_range() {
    let (_, code, run, map) = fixture("specs/vanderpol.toml");
    let targets = [0, 1];
    let mut setting = setting(&code, &targets);
    setting.lower = vec![-0.5, -0.5];
    setting.upper = vec![0.5, 0.5];
    // A large gain on a biased map: without the clamp the estimate would leave [-0.5, 0.5].
    let out = run_with(&setting, &constants(&setting, 0.0, [2.0, 2.0], 1e-300), &map, &run);
    let mut clamped = 0;
    for k in 10..run.targets.len() {
        for i in 0..2 {
            assert!((-0.5..=0.5).contains(&out[k][i]), "k = {k}: {}", out[k][i]);
            clamped += usize::from(out[k][i].abs() == 0.5);
        }
    }
    assert!(clamped > 0, "the case reaches the clamp");
}
