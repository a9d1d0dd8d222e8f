//! The generated observers started by the map (`Corrector`, `StartedEkf` in `firmware::Started`)
//! against the host's own runs of the same observers (`host::observers::kind::corrected::run::estimate_run`,
//! `host::observers::ekf::estimate_started`), in f32 over each design's recorded sequence: bit for
//! bit, so that the report's figures are what the chip computes. The recorded sequence holds samples
//! the observers must refuse: both sides give no estimate there (a NaN row) and carry the state over
//! them by the model's period.

use firmware::emitted::Follower;
use firmware::Started;
use host::data::{Rows, Run};
use host::observers::ekf;
use host::observers::kind::corrected::program::correction_code;
use host::observers::kind::corrected::run as corrected;
use host::plant::kalman::filter_code;
use host::plant::ModelCode;
use integration_tests::load_relative;

macro_rules! check_followers {
    ($test:ident, $module:ident) => {
        #[test]
        fn $test() {
            use generated::$module as d;
            let design = load_relative(d::SPEC);
            let code = ModelCode::new(&design).unwrap();
            let samples: Vec<([f32; d::OUTPUTS], [f32; d::INPUTS])> = d::RECORDED_Y
                .iter()
                .zip(&d::RECORDED_U)
                .map(|(y, u)| (*y, *u))
                .collect();
            let finite =
                |(y, u): &([f32; d::OUTPUTS], [f32; d::INPUTS])| y.iter().chain(u.iter()).all(|v| v.is_finite());
            assert!(
                samples.iter().filter(|s| finite(s)).count() < d::RECORDED_LEN,
                "the sequence holds refused samples"
            );
            let widen = |rows: Vec<Vec<f64>>| Rows::from(rows);
            let run = Run {
                states: widen(vec![vec![0.0; d::STATES]; samples.len()]),
                inputs: widen(
                    samples
                        .iter()
                        .map(|(_, u)| u.iter().map(|&v| f64::from(v)).collect())
                        .collect(),
                ),
                measurements: widen(
                    samples
                        .iter()
                        .map(|(y, _)| y.iter().map(|&v| f64::from(v)).collect())
                        .collect(),
                ),
                targets: widen(vec![vec![0.0; d::TARGETS]; samples.len()]),
                parameters: Vec::new(),
            };
            // The f32 estimates of the map the followers read (the targets', then the helpers'), as
            // the chip computes them (NaN where it refuses the sample).
            let mut map = firmware::Observer::<
                f32,
                d::StartDesign,
                { d::HORIZON },
                { d::OUTPUTS },
                { d::INPUTS },
                { d::MAP_ROWS },
            >::new();
            let maps: Vec<Vec<f32>> = samples
                .iter()
                .map(|(y, u)| match map.push(*y, *u) {
                    Ok(()) => map.estimate().map_or(vec![f32::NAN; d::MAP_ROWS], |e| {
                        e.iter().map(|e| e.value).collect()
                    }),
                    Err(_) => vec![f32::NAN; d::MAP_ROWS],
                })
                .collect();
            /// Runs a generated observer over the whole recorded sequence (refused samples included).
            fn chip<F: Follower<f32, { d::STATES }, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>>() -> Vec<Vec<u32>> {
                let mut observer: Started<
                    f32,
                    d::StartDesign,
                    F,
                    { d::HORIZON },
                    { d::STATES },
                    { d::OUTPUTS },
                    { d::INPUTS },
                    { d::MAP_ROWS },
                    { d::TARGETS },
                > = Started::new();
                let mut out = Vec::new();
                for (y, u) in d::RECORDED_Y.iter().zip(&d::RECORDED_U) {
                    let finite = y.iter().chain(u.iter()).all(|v| v.is_finite());
                    assert_eq!(observer.push(*y, *u).is_ok(), finite);
                    let estimate = observer.estimate().filter(|_| finite);
                    out.push(estimate.map_or(vec![f32::NAN.to_bits(); d::TARGETS], |e| {
                        e.iter().map(|e| e.value.to_bits()).collect()
                    }));
                }
                out
            }
            let bits = |rows: Vec<Vec<f32>>| -> Vec<Vec<u32>> {
                rows.iter()
                    .map(|r| r.iter().map(|v| v.to_bits()).collect())
                    .collect()
            };
            let state_targets = host::fit::helpers::state_maps(&design);
            let first = design.map.horizon - 1;

            let (constants, ekf_constants) = integration_tests::emitted_constants!(d, &design);
            let setting = corrected::Setting {
                code: &code,
                h: constants.h,
                substeps: constants.substeps,
                state_targets: &state_targets,
                first,
                lower: constants.lower.clone(),
                upper: constants.upper.clone(),
            };
            let host = corrected::estimate_run::<f32>(
                &setting,
                &correction_code(&code, &constants),
                &constants,
                &maps,
                &run,
            )
            .rows;
            let chip_corrected = chip::<d::Corrector>();
            assert_eq!(chip_corrected, bits(host));
            assert!(
                chip_corrected
                    .iter()
                    .filter(|r| f32::from_bits(r[0]).is_finite())
                    .count()
                    > d::RECORDED_LEN / 2
            );

            let filter = filter_code(&code, &ekf_constants);
            let host = ekf::estimate_started::<f32>(
                &filter,
                &d::STARTED_P0,
                &ekf_constants.watch,
                &state_targets,
                first,
                &maps,
                &run,
                &code,
            )
            .rows;
            assert_eq!(chip::<d::StartedEkf>(), bits(host));
        }
    };
}

check_followers!(vanderpol_followers_are_the_hosts, vanderpol);
check_followers!(two_tanks_followers_are_the_hosts, two_tanks);
// Helper maps for X and S (targets P and muX): the followers read the map's four rows.
check_followers!(ecoli_followers_are_the_hosts, ecoli_x0_0p5);
