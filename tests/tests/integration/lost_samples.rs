//! A lost output costs the observers the map starts one sample, not their track: over a refused
//! sample (a NaN or infinite output, the input known) what they carry takes the model's period
//! (`Follower::predict`), so that it stays in step with the plant.
//!
//! On Example 1's scenario, 300 samples (30 s), with the output of samples 40, 41 and 70 lost, the
//! mean |error| from t = 8 s on is held to the clean run's, and an observer that lets the lost
//! samples pass without the model's period (as the firmware did before: the same as never receiving
//! them) is shown to fail the same bound, so the bound bites.

use generated::vanderpol as d;

const LOST: [usize; 3] = [40, 41, 70];
/// From t = 8 s: past the last lost sample and the map's window after it.
const FROM: usize = 80;

/// The scenario's states and outputs, 300 samples.
fn scenario() -> (Vec<Vec<f64>>, Vec<f32>) {
    let mut design = host::spec::load(&integration_tests::specs_folder().join("vanderpol.toml")).unwrap();
    design.scenarios[0].samples = 300;
    let run = host::data::scenario_run(&design, &design.model, "scenario")
        .unwrap()
        .unwrap();
    let states = run.states.iter().map(<[f64]>::to_vec).collect();
    let y = run.measurements.iter().map(|y| y[0] as f32).collect();
    (states, y)
}

/// Mean |error| per state from [`FROM`] on of an observer fed `samples` (`None`: not fed at all),
/// against `states`.
fn mean_error<O>(mut observer: O, samples: &[Option<f32>], states: &[Vec<f64>]) -> [f64; 2]
where
    O: FnMut(f32) -> Option<[f32; 2]>,
{
    let mut sums = [0.0; 2];
    let mut count = 0;
    for (k, sample) in samples.iter().enumerate() {
        let Some(y) = sample else { continue };
        let estimate = observer(*y);
        if k >= FROM {
            let x = estimate.expect("an estimate after the start");
            for (sum, (&e, &truth)) in sums.iter_mut().zip(x.iter().zip(&states[k])) {
                *sum += (f64::from(e) - truth).abs();
            }
            count += 1;
        }
    }
    sums.map(|s| s / f64::from(count))
}

macro_rules! run {
    ($observer:ty, $samples:expr, $states:expr) => {{
        let mut o = <$observer>::new();
        mean_error(
            |y| {
                let _ = o.push([y], []);
                o.estimate().map(|e| [e[0].value, e[1].value])
            },
            $samples,
            $states,
        )
    }};
}

#[test]
fn a_lost_output_keeps_the_model_in_step() {
    let (states, y) = scenario();
    let clean: Vec<Option<f32>> = y.iter().copied().map(Some).collect();
    let mut lost = clean.clone();
    let mut skipped = clean.clone();
    for k in LOST {
        lost[k] = Some(f32::NAN);
        skipped[k] = None;
    }
    // Within 10 % (and 2e-3, the noise of so few samples) of the clean run's error.
    let close = |with: [f64; 2], without: [f64; 2]| with.iter().zip(&without).all(|(&a, &b)| a <= 1.1 * b + 2e-3);

    let corrected = run!(d::CorrectedObserver, &clean, &states);
    let corrected_lost = run!(d::CorrectedObserver, &lost, &states);
    let corrected_skipped = run!(d::CorrectedObserver, &skipped, &states);
    println!("corrected: clean {corrected:.4?}, lost {corrected_lost:.4?}, skipped {corrected_skipped:.4?}");
    assert!(close(corrected_lost, corrected), "{corrected_lost:?} vs {corrected:?}");
    assert!(
        !close(corrected_skipped, corrected),
        "the bound does not bite: skipping the lost samples gives {corrected_skipped:?}"
    );

    let ekf = run!(d::EkfMapObserver, &clean, &states);
    let ekf_lost = run!(d::EkfMapObserver, &lost, &states);
    println!("map-started EKF: clean {ekf:.4?}, lost {ekf_lost:.4?}");
    assert!(close(ekf_lost, ekf), "{ekf_lost:?} vs {ekf:?}");
}
