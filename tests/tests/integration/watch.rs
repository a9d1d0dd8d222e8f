//! The χ² watch (`firmware::watch`) restarts a box filter that has lost track with every number
//! finite: from half-way through the recorded sequence the output is off by 50 noise deviations, an
//! output the filter's model and noise say is impossible. The generated EKF and UKF (the chip's
//! code) restart and say so, and the host's interpreted programs (`ekf::BoxStep`, what `gen` tunes
//! and judges) give the same estimates, bit for bit, and the same restarts. Without the watch the
//! same filter restarts less on that sequence (only where its step overflows): the watch restarts it.
//! The EKF the map starts (`ekf_map`) and the one it checks (`ekf_restart`) carry the box EKF's
//! watch: the same sequence restarts them, alike on chip and host.

use firmware::Estimator;
use host::observers::ekf;
use host::observers::kind::ekf_restart::run::{RestartConstants, RestartStep};
use host::observers::kind::ukf_box::program::unscented_code;
use host::plant::kalman::{filter_code, EkfConstants, FilterCode, Watch};
use host::plant::{Covariance, ModelCode};
use integration_tests::load_relative;

/// The output offset, in noise standard deviations: 50, where the mean of the normalised innovations
/// squared, about 50² = 2500, exceeds Example 1's tuned limit of 1024 and neither filter's step
/// overflows at first (at 100 the UKF's does, and it restarts as often unwatched; below 32 the
/// tuned watch does not fire).
const OFFSET: f64 = 50.0;

/// The recorded sequence with every output off by [`OFFSET`] deviations from half-way on.
fn stepped(ys: &[[f32; 1]], sigma: f64) -> Vec<Vec<f32>> {
    let half = ys.len() / 2;
    (ys.iter().enumerate())
        .map(|(k, y)| {
            let offset = if k >= half { (OFFSET * sigma) as f32 } else { 0.0 };
            y.iter().map(|v| v + offset).collect()
        })
        .collect()
}

/// A run's estimates, sample by sample, as bits (`None`: refused or restarted), and its restarts.
type Bits = (Vec<Option<Vec<u32>>>, u32);

/// The host's run over `(ys, us)` of the filter `filter` with `constants`: each sample's targets
/// (`None`: refused or restarted) and the restarts.
fn host_run(filter: &FilterCode, constants: &EkfConstants, code: &ModelCode, ys: &[Vec<f32>], us: &[Vec<f32>]) -> Bits {
    let wide = |v: &[f32]| v.iter().map(|&v| f64::from(v)).collect::<Vec<f64>>();
    let mut step = ekf::BoxStep::<f32>::new(filter, &constants.x0, constants, code);
    let rows = (ys.iter().zip(us))
        .map(|(y, u)| {
            step.step(&wide(y), &wide(u))
                .map(|t| t.iter().map(|v| v.to_bits()).collect())
        })
        .collect();
    (rows, step.restarts())
}

/// The chip's run over `(ys, us)`: each sample's targets (`None`: refused or restarted, or no
/// estimate yet), restarts.
fn chip_run<O>(mut observer: O, ys: &[Vec<f32>], us: &[Vec<f32>]) -> Bits
where
    O: Estimator<Scalar = f32>,
    O::Outputs: for<'a> TryFrom<&'a [f32]>,
    O::Inputs: for<'a> TryFrom<&'a [f32]>,
{
    let rows = (ys.iter().zip(us))
        .map(|(y, u)| {
            let (Ok(y), Ok(u)) = (O::Outputs::try_from(y), O::Inputs::try_from(u)) else {
                panic!("a sample of the wrong width")
            };
            observer.push(y, u).ok()?;
            let estimate = observer.estimate()?; // none before the map's first (`ekf_map`)
            Some(estimate.as_ref().iter().map(|e| e.value.to_bits()).collect())
        })
        .collect();
    (rows, observer.restarts())
}

#[test]
fn a_filter_given_an_impossible_output_restarts_alike_on_chip_and_host() {
    use generated::vanderpol as d;
    let design = load_relative(d::SPEC);
    let code = ModelCode::new(&design).unwrap();
    let sigma = design.model.outputs[0].noise_variance.sqrt();
    let ys = stepped(&d::RECORDED_Y, sigma);
    let us: Vec<Vec<f32>> = d::RECORDED_U.iter().map(|u| u.to_vec()).collect();

    // The filters' constants as emitted: the start and `P(0)` read back in f64, `Q` and the watch.
    let (_, ekf_constants) = integration_tests::emitted_constants!(d, &design);
    let emitted = |x0: [f64; d::STATES], p0: [[f64; d::STATES]; d::STATES], q: &[f64], watch: Watch| EkfConstants {
        x0: x0.to_vec(),
        p0: Covariance::Full(p0.iter().map(|row| row.to_vec()).collect()),
        q: Covariance::Diagonal(q.to_vec()),
        watch,
        ..ekf_constants.clone()
    };
    let ekf = d::Ekf::<f64>::new();
    let ekf_constants = emitted(ekf.state(), ekf.covariance(), &d::EKF_Q, ekf_constants.watch);
    let ukf = d::Ukf::<f64>::new();
    let ukf_watch = Watch {
        window: d::UKF_WATCH_WINDOW,
        threshold: d::UKF_WATCH_THRESHOLD,
    };
    let ukf_constants = emitted(ukf.state(), ukf.covariance(), &d::UKF_Q, ukf_watch);
    assert!(ekf_constants.watch.threshold.is_finite() && ukf_watch.threshold.is_finite());

    let cases: [(&str, FilterCode, &EkfConstants, Bits); 2] = [
        (
            "ekf_box",
            filter_code(&code, &ekf_constants),
            &ekf_constants,
            chip_run(d::EkfBoxObserver::new(), &ys, &us),
        ),
        (
            "ukf_box",
            unscented_code(&code, &ukf_constants),
            &ukf_constants,
            chip_run(d::UkfBoxObserver::new(), &ys, &us),
        ),
    ];
    for (kind, filter, constants, chip) in cases {
        assert!(chip.1 >= 1, "{kind} restarts on the impossible output: {}", chip.1);
        assert_eq!(
            host_run(&filter, constants, &code, &ys, &us),
            chip,
            "{kind}: host against chip"
        );
        // Unwatched, the same filter restarts less there (only where its step overflows): the watch
        // restarted it.
        let unwatched = EkfConstants {
            watch: Watch::OFF,
            ..constants.clone()
        };
        let fewer = host_run(&filter, &unwatched, &code, &ys, &us).1;
        println!("{kind}: {} restarts watched, {fewer} unwatched", chip.1);
        assert!(fewer < chip.1, "{kind}: {fewer} restarts unwatched, {} watched", chip.1);
        // Nor does the watched one on the sequence as recorded.
        let recorded: Vec<Vec<f32>> = d::RECORDED_Y.iter().map(|y| y.to_vec()).collect();
        assert_eq!(
            host_run(&filter, constants, &code, &recorded, &us).1,
            0,
            "{kind} as recorded"
        );
    }
}

#[test]
fn the_filters_the_map_starts_or_checks_restart_on_an_impossible_output_alike_on_chip_and_host() {
    use generated::vanderpol as d;
    let design = load_relative(d::SPEC);
    let code = ModelCode::new(&design).unwrap();
    let sigma = design.model.outputs[0].noise_variance.sqrt();
    let ys = stepped(&d::RECORDED_Y, sigma);
    let us: Vec<Vec<f32>> = d::RECORDED_U.iter().map(|u| u.to_vec()).collect();
    let wide = |v: &[f32]| v.iter().map(|&v| f64::from(v)).collect::<Vec<f64>>();
    // The map's f32 estimates of the sequence as the chip computes them (NaN where it refuses).
    let mut map = d::map_observer();
    let rows: Vec<Vec<f32>> = (ys.iter().zip(&us))
        .map(|(y, u)| {
            match map.push(y[..].try_into().unwrap(), u[..].try_into().unwrap()) {
                Ok(()) => map
                    .estimate()
                    .map_or(vec![f32::NAN; d::TARGETS], |e| e.iter().map(|e| e.value).collect()),
                Err(_) => vec![f32::NAN; d::TARGETS], // the sequence's lost outputs
            }
        })
        .collect();
    let (_, ekf_constants) = integration_tests::emitted_constants!(d, &design);
    assert!(ekf_constants.watch.threshold.is_finite(), "Example 1's EKF is watched");
    let state_targets = host::fit::helpers::state_maps(&design);
    let first = design.map.horizon - 1;
    let filter = filter_code(&code, &ekf_constants);
    let bits = |t: Vec<f32>| t.iter().map(|v| v.to_bits()).collect::<Vec<u32>>();

    // `ekf_map`: where the chip's push refused or restarted (`None`), the host's row is the latest
    // estimate (NaN before the first); compare where the chip took the sample.
    let ekf_map = |watch: &Watch| {
        let mut step = ekf::StartedStep::<f32>::new(&filter, &d::STARTED_P0, watch, &state_targets, first, &code);
        let rows: Vec<Vec<u32>> = (rows.iter().zip(ys.iter().zip(&us)))
            .map(|(row, (y, u))| bits(step.step(row, &wide(y), &wide(u))))
            .collect();
        (rows, step.restarts())
    };
    let chip = chip_run(d::EkfMapObserver::new(), &ys, &us);
    let (host, restarts) = ekf_map(&ekf_constants.watch);
    assert!(chip.1 >= 1, "ekf_map restarts on the impossible output: {}", chip.1);
    assert_eq!(restarts, chip.1, "ekf_map: restarts, host against chip");
    for (k, (chip, host)) in chip.0.iter().zip(&host).enumerate() {
        if let Some(chip) = chip {
            assert_eq!(chip, host, "ekf_map at sample {k}");
        }
    }
    let fewer = ekf_map(&Watch::OFF).1;
    println!("ekf_map: {} restarts watched, {fewer} unwatched", chip.1);
    assert!(
        fewer < chip.1,
        "ekf_map: {fewer} restarts unwatched, {} watched",
        chip.1
    );

    // `ekf_restart`: the box filter as emitted (`Restart::FRESH`), checked by the map.
    let fresh = d::Ekf::<f64>::new();
    let constants = EkfConstants {
        x0: fresh.state().to_vec(),
        p0: Covariance::Full(fresh.covariance().iter().map(|row| row.to_vec()).collect()),
        ..ekf_constants.clone()
    };
    let box_filter = filter_code(&code, &constants);
    let restart = RestartConstants {
        threshold: d::RESTART_THRESHOLD,
        variances: d::RESTART_VARIANCES.to_vec(),
    };
    let ekf_restart = |constants: &EkfConstants, restart: &RestartConstants| {
        let mut step = RestartStep::<f32>::new(&box_filter, constants, &d::STARTED_P0, restart, &state_targets, &code);
        let rows: Vec<Vec<u32>> = (rows.iter().zip(ys.iter().zip(&us)))
            .map(|(row, (y, u))| bits(step.step(row, &wide(y), &wide(u))))
            .collect();
        (rows, step.restarts())
    };
    // On this sequence the map's check sees the filter and the map disagree first and restarts the
    // filter from the map (its usual work, not counted), which also restarts the watch: the chip and
    // the host agree bit for bit, restarts included.
    let chip = chip_run(d::EkfRestartObserver::new(), &ys, &us);
    let (host, restarts) = ekf_restart(&constants, &restart);
    assert_eq!(restarts, chip.1, "ekf_restart: restarts, host against chip");
    for (k, (chip, host)) in chip.0.iter().zip(&host).enumerate() {
        if let Some(chip) = chip {
            assert_eq!(chip, host, "ekf_restart at sample {k}");
        }
    }
    // With the check off (`τ = ∞`, on the host), the watch is what restarts the filter.
    let unchecked = RestartConstants {
        threshold: f64::INFINITY,
        ..restart.clone()
    };
    let unwatched = EkfConstants {
        watch: Watch::OFF,
        ..constants.clone()
    };
    let (watched, fewer) = (
        ekf_restart(&constants, &unchecked).1,
        ekf_restart(&unwatched, &unchecked).1,
    );
    println!("ekf_restart unchecked: {watched} restarts watched, {fewer} unwatched");
    assert!(
        fewer < watched,
        "ekf_restart: {fewer} restarts unwatched, {watched} watched"
    );
}
