//! Paper Example 2 (E. coli): the learning sets, the state P = 0, the substrate staying non-negative,
//! and the family observer picking the design of the batch's initial biomass.

use integration_tests::{build, load_relative};

#[test]
fn learning_sets_follow_the_formula() {
    for spec in ["host/specs/ecoli_x0_0p5.toml", "host/specs/ecoli_x0_2.toml"] {
        let design = load_relative(spec);
        let data = host::data::learning_set(&design).unwrap();
        assert_eq!(data.runs.len(), 25);
        // n_E = n_g (N_s - N + 1) = 25 · 38 = 950 (the paper prints 925).
        assert_eq!(data.window_count(), 950);
        assert_eq!(data.regressor_len(), 3 * 2);
    }
}

#[test]
fn p_equal_zero_is_a_legitimate_state() {
    // P = 0 starts half the learning runs, and it is the bound every filter projects P onto
    // (`[model.bounds]`): the model and its Jacobian must be finite there. The death term reads
    // `exp(-k_p/max(P, 0.001))`, whose derivative in P is 0 below 0.001; `exp(-k_p/P)` itself would
    // give 0·∞ = NaN in the Jacobian at P = 0.
    let design = load_relative("host/specs/ecoli_x0_2.toml");
    let model = &design.model;
    let mut environment = Vec::new();
    let mut dx = [0.0; 3];
    model.derivative(&[2.0, 3.0, 0.0], &[], &mut environment, &mut dx);
    assert!(dx.iter().all(|v| v.is_finite()), "{dx:?}");
    let death = environment[model.scope().iter().position(|n| *n == "death").unwrap()];
    // k_d exp(-500): 7e-219, zero for every purpose (P changes by y_p mu X ~ 0.04 g/L/h).
    assert!((0.0..1e-200).contains(&death), "{death}");
    let code = host::plant::ModelCode::new(&design).unwrap();
    for p in [0.0, 1e-3, 0.5] {
        let (f, jacobian) = code.derivative(&[2.0, 3.0, p], &[], &mut Vec::new());
        assert!(
            f.iter().chain(&jacobian).all(|v: &f64| v.is_finite()),
            "at P = {p}: {f:?} {jacobian:?}"
        );
    }
    // Without the max, the slope at P = 0 is 0·∞: `gen` finds it on the bound and evaluates the
    // Jacobian with P a thousandth of its learning range [0, 0.3] inside (`host::plant::JACOBIAN_INSIDE`),
    // where it is finite: the same Jacobian as at P = 3e-4 itself, and the value at P = 0 as written.
    let text = std::fs::read_to_string(integration_tests::workspace_root().join("host/specs/ecoli_x0_2.toml"))
        .unwrap()
        .replace("k_d*exp(-k_p/max(P, 0.001))", "k_d*exp(-k_p/P)");
    let unguarded = integration_tests::design("ecoli_x0_2", &text);
    let code = host::plant::ModelCode::new(&unguarded).unwrap();
    let (f, jacobian) = code.derivative(&[2.0, 3.0, 0.0], &[], &mut Vec::new());
    assert!(jacobian.iter().all(|v: &f64| v.is_finite()), "{jacobian:?}");
    let inside = host::plant::JACOBIAN_INSIDE * 0.3;
    let (_, at_inside) = code.derivative(&[2.0, 3.0, inside], &[], &mut Vec::new());
    assert_eq!(jacobian, at_inside);
    let (f_guarded, _) =
        host::plant::ModelCode::new(&design)
            .unwrap()
            .derivative(&[2.0, 3.0, 0.0], &[], &mut Vec::new());
    assert_eq!(
        f, f_guarded,
        "the values at P = 0 are the model's (death → 0 either way)"
    );
}

#[test]
fn substrate_never_goes_negative() {
    for spec in ["host/specs/ecoli_x0_0p5.toml", "host/specs/ecoli_x0_2.toml"] {
        let design = load_relative(spec);
        let s = design.model.states.iter().position(|n| n == "S").unwrap();
        for set in [
            host::data::learning_set(&design).unwrap(),
            host::data::validation_set(&design).unwrap(),
        ] {
            let lowest = set
                .runs
                .iter()
                .flat_map(|r| r.states.iter().map(|x| x[s]))
                .fold(f64::INFINITY, f64::min);
            assert!(lowest >= 0.0, "{spec}: S reached {lowest}");
        }
    }
}

#[test]
fn family_observer_uses_the_member_of_the_initial_biomass() {
    let members = [("host/specs/ecoli_x0_0p5.toml", 0), ("host/specs/ecoli_x0_2.toml", 1)];
    for (spec, expected) in members {
        let design = load_relative(spec);
        let result = build(&design);
        let (mut right, mut runs) = (0, 0);
        for run in &result.runs.validation.runs {
            let mut family = generated::ecoli::observer();
            let mut own = match expected {
                0 => FamilyMember::Low(generated::ecoli_x0_0p5::map_observer()),
                _ => FamilyMember::High(generated::ecoli_x0_2::map_observer()),
            };
            for (y, u) in run.measurements.iter().zip(&run.inputs) {
                let y = [y[0] as f32, y[1] as f32];
                let u: [f32; 0] = core::array::from_fn(|i| u[i] as f32);
                family.push(y, u).unwrap();
                own.push(y, u);
                if family.chosen() == Some(expected) {
                    assert_eq!(family.estimate(), own.estimate());
                }
            }
            runs += 1;
            right += usize::from(family.chosen() == Some(expected));
        }
        // X(0) is measured with noise of standard deviation √0.1 = 0.32 and the members are 1.5 apart:
        // a wrong choice needs an error beyond 0.75 = 2.37 σ, probability 0.9 %, about 1 run in 100;
        // 6 or more would happen with probability 3e-4.
        assert!(
            runs - right <= 5,
            "{spec}: only {right} of {runs} runs chose the right member"
        );
    }
}

enum FamilyMember {
    Low(generated::ecoli_x0_0p5::MapObserver),
    High(generated::ecoli_x0_2::MapObserver),
}

impl FamilyMember {
    fn push(&mut self, y: [f32; 2], u: [f32; 0]) {
        match self {
            FamilyMember::Low(o) => o.push(y, u).unwrap(),
            FamilyMember::High(o) => o.push(y, u).unwrap(),
        }
    }

    fn estimate(&self) -> Option<[firmware::Estimate<f32>; 2]> {
        match self {
            FamilyMember::Low(o) => o.estimate(),
            FamilyMember::High(o) => o.estimate(),
        }
    }
}
