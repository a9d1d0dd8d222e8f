//! Every filter kind counts the samples it refuses and its restarts, by the one shared rule
//! (`firmware::rules`): over a sequence with lost outputs, non-finite inputs (refused) and outputs
//! that overflow the filters (restarted), the chip's counts add up to its refused pushes, the
//! overflows restart every kind, and the host, which runs the same rules over its interpreted
//! programs, counts the same. (The C counts the same too: `c_source`.)

use firmware::Estimator;
use host::data::{Rows, Run};
use host::observers::ekf;
use host::observers::kind::corrected::program::correction_code;
use host::observers::kind::corrected::run as corrected;
use host::observers::kind::ekf_restart::run::{RestartConstants, RestartStep};
use host::plant::kalman::filter_code;
use host::plant::ModelCode;
use integration_tests::load_relative;
use integration_tests::on_target::extended;

/// Runs `observer` over `(ys, us)`; its counts `(refused, restarts)`, checked against its refused
/// pushes.
fn counts<O>(mut observer: O, ys: &[Vec<f32>], us: &[Vec<f32>], counted: impl Fn(&O) -> u32) -> (u32, u32)
where
    O: Estimator<Scalar = f32>,
    O::Outputs: for<'a> TryFrom<&'a [f32]>,
    O::Inputs: for<'a> TryFrom<&'a [f32]>,
{
    let mut refused = 0;
    for (y, u) in ys.iter().zip(us) {
        let (Ok(y), Ok(u)) = (O::Outputs::try_from(y), O::Inputs::try_from(u)) else {
            panic!("a sample of the wrong width")
        };
        refused += u32::from(observer.push(y, u).is_err());
    }
    let restarts = observer.restarts();
    assert_eq!(
        counted(&observer) + restarts,
        refused,
        "the chip's counts add up to its refused pushes"
    );
    (counted(&observer), restarts)
}

macro_rules! check_refusals {
    ($test:ident, $module:ident) => {
        #[test]
        fn $test() {
            use generated::$module as d;
            let design = load_relative(d::SPEC);
            let code = ModelCode::new(&design).unwrap();
            let (ys, us) = extended(&d::RECORDED_Y, &d::RECORDED_U, d::HORIZON);
            let wide = |rows: &[Vec<f32>]| {
                Rows::from(
                    rows.iter()
                        .map(|r| r.iter().map(|&v| f64::from(v)).collect())
                        .collect::<Vec<Vec<f64>>>(),
                )
            };
            let run = Run {
                states: Rows::from(vec![vec![0.0; d::STATES]; ys.len()]),
                inputs: wide(&us),
                measurements: wide(&ys),
                targets: Rows::from(vec![vec![0.0; d::TARGETS]; ys.len()]),
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
            let maps: Vec<Vec<f32>> = ys
                .iter()
                .zip(&us)
                .map(
                    |(y, u)| match map.push(y[..].try_into().unwrap(), u[..].try_into().unwrap()) {
                        Ok(()) => map.estimate().map_or(vec![f32::NAN; d::MAP_ROWS], |e| {
                            e.iter().map(|e| e.value).collect()
                        }),
                        Err(_) => vec![f32::NAN; d::MAP_ROWS],
                    },
                )
                .collect();
            let state_targets = host::fit::helpers::state_maps(&design);
            let first = design.map.horizon - 1;
            let (constants, ekf_constants) = integration_tests::emitted_constants!(d, &design);
            let filter = filter_code(&code, &ekf_constants);
            let samples = || (0..ys.len()).map(|k| (&maps[k], &run.measurements[k], &run.inputs[k]));

            // The box filter's start as emitted (`Restart::FRESH`, `P(0)` from its triangle).
            // `(x, P)` of what is carried (a watched filter carries its mean too).
            let fresh_carried = <d::StartedEkf as firmware::emitted::Restart<
                f64,
                { d::STATES },
                { d::OUTPUTS },
                { d::INPUTS },
                { d::TARGETS },
            >>::FRESH;
            let (x0, upper) = (fresh_carried.0, fresh_carried.1);
            let mut fresh = ekf_constants.clone();
            fresh.x0 = x0.to_vec();
            let entry = |i: usize, j: usize| upper[host::plant::kalman::upper(d::STATES, i.min(j), i.max(j))];
            fresh.p0 = host::plant::Covariance::Full(
                (0..d::STATES)
                    .map(|i| (0..d::STATES).map(|j| entry(i, j)).collect())
                    .collect(),
            );
            let box_filter = filter_code(&code, &fresh);

            let chip = counts(d::EkfBoxObserver::new(), &ys, &us, |o| o.refused());
            assert!(
                chip.0 >= 2 && chip.1 >= 1,
                "bad values refused, overflows restarted: {chip:?}"
            );
            let mut host = ekf::BoxStep::<f32>::new(&box_filter, &fresh.x0, &fresh, &code);
            samples().for_each(|(_, y, u)| drop(host.step(y, u)));
            assert_eq!((host.refused(), host.restarts()), chip, "ekf_box");

            let chip = counts(d::EkfMapObserver::new(), &ys, &us, |o| o.refused());
            let mut host = ekf::StartedStep::<f32>::new(
                &filter,
                &d::STARTED_P0,
                &fresh.watch,
                &state_targets,
                first,
                &code,
            );
            samples().for_each(|(row, y, u)| drop(host.step(row, y, u)));
            assert_eq!((host.refused(), host.restarts()), chip, "ekf_map");
            assert!(chip.1 >= 1, "ekf_map restarted on the overflows: {chip:?}");
            // The run's track, as the report counts it.
            let track = ekf::estimate_started::<f32>(
                &filter,
                &d::STARTED_P0,
                &fresh.watch,
                &state_targets,
                first,
                &maps,
                &run,
                &code,
            );
            assert_eq!(track.restarts, chip.1, "ekf_map's track");

            let chip = counts(d::EkfRestartObserver::new(), &ys, &us, |o| o.refused());
            let restart = RestartConstants {
                threshold: d::RESTART_THRESHOLD,
                variances: d::RESTART_VARIANCES.to_vec(),
            };
            let mut host = RestartStep::<f32>::new(
                &box_filter,
                &fresh,
                &d::STARTED_P0,
                &restart,
                &state_targets,
                &code,
            );
            samples().for_each(|(row, y, u)| drop(host.step(row, y, u)));
            // (The map's check may restart it from the map before its step overflows: not counted.)
            assert_eq!((host.refused(), host.restarts()), chip, "ekf_restart");
            let track = host::observers::kind::ekf_restart::run::estimate::<f32>(
                &box_filter,
                &fresh,
                &d::STARTED_P0,
                &restart,
                &state_targets,
                &maps,
                &run,
                &code,
            );
            assert_eq!(track.restarts, chip.1, "ekf_restart's track");

            let chip = counts(d::CorrectedObserver::new(), &ys, &us, |o| o.refused());
            let setting = corrected::Setting {
                code: &code,
                h: constants.h,
                substeps: constants.substeps,
                state_targets: &state_targets,
                first,
                lower: constants.lower.clone(),
                upper: constants.upper.clone(),
            };
            let programs = correction_code(&code, &constants);
            let mut host = corrected::CorrectedStep::<f32>::new(&setting, &programs, &constants);
            samples().for_each(|(row, y, u)| drop(host.step(row, y, u)));
            assert_eq!((host.refused(), host.restarts()), chip, "corrected");
            let track = corrected::estimate_run::<f32>(&setting, &programs, &constants, &maps, &run);
            assert_eq!(track.restarts, chip.1, "corrected's track");
        }
    };
}

check_refusals!(vanderpol_refusals_are_counted_alike_on_chip_and_host, vanderpol);
check_refusals!(two_tanks_refusals_are_counted_alike_on_chip_and_host, two_tanks);
