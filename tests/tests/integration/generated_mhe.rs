//! The chip's moving-horizon observer as a design file instantiates it (`firmware::mhe::Observer` over
//! the emitted `Discrete` model and targets, its window, its warm start) against the host's run of
//! the same arithmetic (`Setup::chip_run`: the model's programs, the run's samples as slices) with the
//! same constants, over the design's recorded sequence: the same bits in `f32`, so that the report's
//! `mhe` figures are what the chip computes. Another prior weight, step count and watch than the
//! shipped ones, so that the check is of the arithmetic, not of one choice; and the sequence again
//! with an output the model cannot follow from half-way on, where the watch restarts both alike.

use std::sync::OnceLock;

use firmware::emitted::mhe::{Horizon, Settings};
use firmware::mhe::Observer;
use host::data::{Rows, Run};
use host::observers::kind::mhe::run::{ChipConstants, Setup};
use host::plant::kalman::Watch;
use host::plant::ModelCode;
use integration_tests::load_relative;

/// `v` rounded to `f32`, as an array.
fn array<const N: usize>(v: &[f64]) -> [f32; N] {
    std::array::from_fn(|i| v[i] as f32)
}

macro_rules! check_mhe {
    ($test:ident, $module:ident) => {
        #[test]
        fn $test() {
            use generated::$module as d;
            let design = load_relative(&format!("host/specs/{}.toml", stringify!($module)));
            let code = ModelCode::new(&design).unwrap();
            let learning = host::data::learning_set(&design).unwrap();
            let setup = Setup::new(&design, &code, &learning).expect("the host filters it");
            // Watched over N windows at τ = 4: the stepped sequence below restarts it more often.
            let constants = ChipConstants {
                watch: Watch {
                    window: d::HORIZON,
                    threshold: 4.0,
                },
                ..setup.chip_constants(30.0, 3)
            };
            let rows = |values: Vec<Vec<f64>>, width: usize| {
                let mut r = Rows::new(width);
                values.iter().for_each(|v| r.push(v));
                r
            };
            // As recorded, then with every output off by 50 noise deviations from half-way on (an
            // output the model cannot follow: the watch restarts the estimator).
            let mut restarts = Vec::new();
            for offset in [0.0, 50.0] {
                let sigmas: Vec<f32> = design
                    .model
                    .outputs
                    .iter()
                    .map(|o| o.noise_variance.sqrt() as f32)
                    .collect();
                let recorded_y: Vec<[f32; d::OUTPUTS]> = (d::RECORDED_Y.iter().enumerate())
                    .map(|(k, y)| {
                        let off = if k >= d::RECORDED_LEN / 2 { offset } else { 0.0 };
                        std::array::from_fn(|i| y[i] + off * sigmas[i])
                    })
                    .collect();
                let ys: Vec<Vec<f64>> = recorded_y
                    .iter()
                    .map(|y| y.iter().map(|&v| f64::from(v)).collect())
                    .collect();
                let us: Vec<Vec<f64>> = d::RECORDED_U
                    .iter()
                    .map(|u| u.iter().map(|&v| f64::from(v)).collect())
                    .collect();
                let run = Run {
                    states: rows(vec![vec![0.0; d::STATES]; ys.len()], d::STATES),
                    inputs: rows(us, d::INPUTS),
                    measurements: rows(ys, d::OUTPUTS),
                    targets: rows(vec![vec![0.0; d::TARGETS]; d::RECORDED_LEN], d::TARGETS),
                    parameters: Vec::new(),
                };
                let host = setup.chip_run::<f32>(&constants, &run);

                // The design file's model and targets with these constants.
                struct Other;
                static SETTINGS: OnceLock<(Settings<f32, { d::STATES }, { d::OUTPUTS }>, f32)> = OnceLock::new();
                impl Horizon<f32, { d::STATES }, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }> for Other {
                    type Plant = d::Discrete<f32>;
                    fn plant() -> d::Discrete<f32> {
                        firmware::Rk4::new(d::Plant, SETTINGS.get().expect("set").1)
                    }
                    fn settings() -> Settings<f32, { d::STATES }, { d::OUTPUTS }> {
                        SETTINGS.get().expect("set").0
                    }
                    fn targets(x: &[f32; d::STATES], u: &[f32; d::INPUTS]) -> [f32; d::TARGETS] {
                        d::targets(x, u)
                    }
                }
                let settings = Settings {
                    weights: array(&constants.weights),
                    prior: array(&constants.prior),
                    lower: array(&constants.lower),
                    upper: array(&constants.upper),
                    start: array(&constants.start),
                    iterations: constants.iterations,
                    damping: constants.damping as f32,
                    watch: constants
                        .watch
                        .constants(d::HORIZON * d::OUTPUTS)
                        .map(|w| firmware::emitted::mhe::Watch {
                            start: w.start as f32,
                            gain: w.gain as f32,
                            limit: w.limit as f32,
                        }),
                };
                SETTINGS.get_or_init(|| (settings, constants.h as f32));
                let mut chip: Observer<
                    f32,
                    Other,
                    { d::HORIZON },
                    { d::STATES },
                    { d::OUTPUTS },
                    { d::INPUTS },
                    { d::TARGETS },
                > = Observer::new();
                let mut compared = 0;
                for (k, (y, u)) in recorded_y.iter().zip(&d::RECORDED_U).enumerate() {
                    // The recording refuses some samples (non-finite values): refused on both sides. A
                    // restart keeps the latest estimate, on both sides.
                    let before = chip.restarts();
                    let refused = chip.push(*y, *u).is_err() && chip.restarts() == before;
                    if refused || chip.estimate().is_none() {
                        assert!(host.rows[k].iter().all(|v| v.is_nan()), "sample {k}");
                        continue;
                    }
                    let ours: Vec<u32> = chip
                        .estimate()
                        .unwrap()
                        .iter()
                        .map(|e| e.value.to_bits())
                        .collect();
                    let theirs: Vec<u32> = host.rows[k].iter().map(|&v| (v as f32).to_bits()).collect();
                    assert_eq!(ours, theirs, "sample {k}");
                    compared += 1;
                }
                assert!(compared > d::RECORDED_LEN / 2, "{compared} estimates compared");
                assert_eq!(
                    chip.restarts(),
                    host.restarts,
                    "restarts on the recorded sequence, offset {offset}"
                );
                restarts.push(chip.restarts());
            }
            assert!(
                restarts[1] > restarts[0],
                "restarts as recorded and stepped: {restarts:?}"
            );
        }
    };
}

check_mhe!(vanderpol_chip_mhe_is_the_hosts, vanderpol);
check_mhe!(ecoli_x0_2_chip_mhe_is_the_hosts, ecoli_x0_2);
check_mhe!(two_tanks_chip_mhe_is_the_hosts, two_tanks);
