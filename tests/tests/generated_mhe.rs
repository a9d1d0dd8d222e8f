//! The chip's moving-horizon estimator as a design file instantiates it
//! (`firmware::mhe::MovingHorizon` over the emitted `Discrete` model, its window, its warm start) against
//! the host's run of the same arithmetic (`Setup::chip_run`: the model's programs, the run's samples as
//! slices) with the same constants, over the design's recorded sequence: the same bits in `f32`, so
//! that the report's `mhe_chip` figures are what the chip computes. A second prior weight and
//! iteration count than the shipped ones, so that the check is of the arithmetic, not of one choice.

use firmware::mhe::{MovingHorizon, Settings};
use host::data::{Rows, Run};
use host::observers::mhe::Setup;
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
            let constants = setup.chip_constants(30.0, 3);
            let rows = |values: Vec<Vec<f64>>, width: usize| {
                let mut r = Rows::new(width);
                values.iter().for_each(|v| r.push(v));
                r
            };
            let ys: Vec<Vec<f64>> = d::RECORDED_Y
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

            let h = design.tau / design.chip_substeps as f64;
            let mut chip: MovingHorizon<
                f32,
                d::Discrete<f32>,
                { d::STATES },
                { d::OUTPUTS },
                { d::INPUTS },
                { d::HORIZON },
            > = MovingHorizon::new(
                firmware::Rk4::new(d::Plant, h as f32),
                Settings {
                    weights: array(&constants.weights),
                    prior: array(&constants.prior),
                    lower: array(&constants.lower),
                    upper: array(&constants.upper),
                    start: array(&constants.start),
                    iterations: constants.iterations,
                    damping: constants.damping as f32,
                },
            );
            let mut compared = 0;
            for (k, (y, u)) in d::RECORDED_Y.iter().zip(&d::RECORDED_U).enumerate() {
                // The recording refuses some samples (non-finite values): refused on both sides.
                match chip.push(y, u) {
                    Err(_) | Ok(None) => assert!(host[k].iter().all(|v| v.is_nan()), "sample {k}"),
                    Ok(Some(x)) => {
                        let ours: Vec<u32> = d::targets(&x, u).iter().map(|v| v.to_bits()).collect();
                        let theirs: Vec<u32> = host[k].iter().map(|&v| (v as f32).to_bits()).collect();
                        assert_eq!(ours, theirs, "sample {k}");
                        compared += 1;
                    }
                }
            }
            assert!(compared > d::RECORDED_LEN / 2, "{compared} estimates compared");
        }
    };
}

check_mhe!(vanderpol_chip_mhe_is_the_hosts, vanderpol);
check_mhe!(ecoli_x0_2_chip_mhe_is_the_hosts, ecoli_x0_2);
check_mhe!(two_tanks_chip_mhe_is_the_hosts, two_tanks);
