//! How far the chip's f32 estimates are from the host's f64 ones (the library's map, the host's
//! mirrors of the observers the map starts, the f64 EKF): the largest difference the reports give.

use firmware::{Estimate, Saturation};
use host::emit::precision::compare;

use super::bit_exact::host_ekf;
use super::kind::{Kind, ObserverKind};
use super::measurement::{EkfMeasurement, ObserverMeasurement, TargetSample};

/// The largest `|target − host|` over the targets of design `name`'s extended Kalman filter, the chip
/// (f32) against the same filter in f64 on the host over the same recorded sequence; an error when the
/// two do not refuse the same samples.
pub fn compare_ekf_with_f64(name: &str, measured: &EkfMeasurement) -> Result<f64, String> {
    let host = host_ekf::<f64>(name).ok_or_else(|| format!("no generated design {name}"))?;
    let targets: Vec<Option<Vec<f64>>> = host.into_iter().map(|(targets, _)| targets).collect();
    ekf_largest_difference(&format!("{name} EKF"), measured, &targets)
}

/// The largest `|chip − host|` of an EKF's targets, `host` giving per sample the f64 filter's targets
/// (`None` where it refused the sample); an error when the two do not refuse the same samples or a
/// difference is NaN (one side NaN, the other not).
pub fn ekf_largest_difference(what: &str, measured: &EkfMeasurement, host: &[Option<Vec<f64>>]) -> Result<f64, String> {
    if host.len() != measured.samples.len() {
        return Err(format!(
            "{what}: {} samples on the target, {} recorded",
            measured.samples.len(),
            host.len()
        ));
    }
    let mut largest: f64 = 0.0;
    for (k, (sample, host_targets)) in measured.samples.iter().zip(host).enumerate() {
        match (&sample.targets, host_targets) {
            (Some(target), Some(host)) => {
                for (t, (&bits, &h)) in target.iter().zip(host).enumerate() {
                    let on_target = f64::from(f32::from_bits(bits));
                    if on_target.is_nan() && h.is_nan() {
                        continue;
                    }
                    let difference = (on_target - h).abs();
                    if difference.is_nan() {
                        return Err(format!(
                            "{what} sample {k} target {t}: {on_target} on the target, {h} on the host"
                        ));
                    }
                    largest = largest.max(difference);
                }
            }
            (None, None) => {}
            (target, _) => {
                return Err(format!(
                    "{what} sample {k}: accepted {} on the target, {} on the host",
                    target.is_some(),
                    host_targets.is_some()
                ))
            }
        }
    }
    Ok(largest)
}

/// The largest `|target − host|` of design `name`'s observer that the map starts (or of its
/// moving-horizon observer), measured on the chip (f32), against the host's mirror of the same
/// observer in f64 (`host::observers`) started by the library's f64 map, over the same recorded sequence (the mirror runs the accepted samples: a
/// refused one changes nothing). An error for a kind the design does not have, or when the two do
/// not estimate at the same samples.
pub fn compare_started_with_f64(name: &str, measured: &ObserverMeasurement) -> Result<f64, String> {
    use host::data::{Rows, Run};
    use host::observers::ekf;
    use host::observers::kind::corrected::program::correction_code;
    use host::observers::kind::corrected::run as corrected;
    use host::plant::kalman::filter_code;
    use host::plant::ModelCode;

    let (design, result) = shipped_build(name)?;
    let code = ModelCode::new(&design).map_err(|e| e.to_string())?;
    // The map row of every state (a target's or a helper map's); the moving-horizon observer reads none.
    let state_targets = match measured.kind {
        Kind::Of(ObserverKind::Mhe) => Vec::new(),
        _ => host::fit::helpers::state_maps(&design),
    };
    let first = design.map.horizon - 1;
    let widen = |values: &[f32]| values.iter().map(|&v| f64::from(v)).collect::<Vec<f64>>();
    let mut host: Option<Vec<Vec<f64>>> = None;
    macro_rules! mirror {
        // Compared elsewhere: the map with the library's ([`compare_with_library`]), the filters
        // with themselves in f64 ([`compare_ekf_with_f64`], [`compare_ukf_with_f64`]).
        ($design:ident, map, $type:ident) => {};
        ($design:ident, ekf_box, $type:ident) => {};
        ($design:ident, ukf_box, $type:ident) => {};
        ($design:ident, $kind:ident, $type:ident) => {
            if Kind::named(stringify!($kind)) == Some(measured.kind) && stringify!($design) == name {
                use generated::$design as d;
                // Every sample, the refused ones included: over them the observer carries its state
                // one period (`Follower::predict`).
                let all: Vec<(Vec<f64>, Vec<f64>)> = d::RECORDED_Y
                    .iter()
                    .zip(&d::RECORDED_U)
                    .map(|(y, u)| (widen(y), widen(u)))
                    .collect();
                let rows: Vec<host::recording::Row> = all
                    .iter()
                    .map(|(y, u)| host::recording::Row {
 time: None,
                        run: String::new(),
                        y: y.clone(),
                        u: u.clone(),
                    })
                    .collect();
                let maps: Vec<Vec<f64>> = host::recording::regressors(design.map.horizon, &rows)
                    .iter()
                    .map(|z| match z {
                        Some(z) => result.start_maps().map(|t| t.fit.map.estimate(z).value).collect(),
                        None => vec![f64::NAN; d::MAP_ROWS],
                    })
                    .collect();
                let run = Run {
                    states: Rows::from(vec![vec![0.0; d::STATES]; all.len()]),
                    inputs: Rows::from(all.iter().map(|(_, u)| u.clone()).collect::<Vec<_>>()),
                    measurements: Rows::from(all.iter().map(|(y, _)| y.clone()).collect::<Vec<_>>()),
                    targets: Rows::from(vec![vec![0.0; d::TARGETS]; all.len()]),
                    parameters: Vec::new(),
                };
                let estimates: Vec<Vec<f64>> = mirror!(@ $kind, d, design, code, state_targets, first, maps, run);
                host = Some(
                    estimates
                        .into_iter()
                        .zip(&all)
                        .filter(|(_, (y, u))| y.iter().chain(u).all(|v| v.is_finite()))
                        .map(|(estimate, _)| estimate)
                        .collect(),
                );
            }
        };
        (@ mhe, $d:ident, $design:ident, $code:ident, $targets:ident, $first:ident, $maps:ident, $run:ident) => {{
            // The host's mirror in f64 with the constants the design file carries.
            use firmware::emitted::mhe::Horizon;
            let settings = <$d::Mhe as Horizon<f64, { $d::STATES }, { $d::OUTPUTS }, { $d::INPUTS }, { $d::TARGETS }>>::settings();
            let plant = <$d::Mhe as Horizon<f64, { $d::STATES }, { $d::OUTPUTS }, { $d::INPUTS }, { $d::TARGETS }>>::plant();
            let constants = host::observers::kind::mhe::run::ChipConstants {
                weights: settings.weights.to_vec(),
                prior: settings.prior.to_vec(),
                lower: settings.lower.to_vec(),
                upper: settings.upper.to_vec(),
                start: settings.start.to_vec(),
                iterations: settings.iterations,
                damping: settings.damping,
                h: plant.h(),
                substeps: $d::CHIP_SUBSTEPS,
                // W = 1 / g and τ = limit / start, read back from the emitted watch.
                watch: settings.watch.map_or(host::plant::kalman::Watch::OFF, |w| host::plant::kalman::Watch {
                    window: (1.0 / w.gain).round() as usize,
                    threshold: w.limit / w.start,
                }),
            };
            let _ = (&$targets, $first, &$maps);
            host::observers::kind::mhe::run::chip::chip_run::<f64>(&$code, $d::HORIZON, &constants, &$run)
                .rows
                .iter()
                .map(<[f64]>::to_vec)
                .collect::<Vec<Vec<f64>>>()
        }};
        (@ corrected, $d:ident, $design:ident, $code:ident, $targets:ident, $first:ident, $maps:ident, $run:ident) => {{
            let (constants, _) = crate::emitted_constants!($d, &$design);
            let setting = corrected::Setting {
                code: &$code,
                h: constants.h,
                substeps: constants.substeps,
                state_targets: &$targets,
                first: $first,
                lower: constants.lower.clone(),
                upper: constants.upper.clone(),
            };
            corrected::estimate_run::<f64>(&setting, &correction_code(&$code, &constants), &constants, &$maps, &$run).rows
        }};
        (@ ekf_map, $d:ident, $design:ident, $code:ident, $targets:ident, $first:ident, $maps:ident, $run:ident) => {{
            let (_, ekf_constants) = crate::emitted_constants!($d, &$design);
            let filter = filter_code(&$code, &ekf_constants);
            ekf::estimate_started::<f64>(&filter, &$d::STARTED_P0, &ekf_constants.watch, &$targets, $first, &$maps, &$run, &$code).rows
        }};
        (@ ekf_restart, $d:ident, $design:ident, $code:ident, $targets:ident, $first:ident, $maps:ident, $run:ident) => {{
            let (_, mut ekf_constants) = crate::emitted_constants!($d, &$design);
            // The filter's start as emitted: its `x̂(0)` and `P(0)`, read from its upper triangle.
            // `(x, P)` of what is carried (a watched filter carries its mean too).
            let fresh_carried = <$d::StartedEkf as firmware::emitted::Restart<
                f64,
                { $d::STATES },
                { $d::OUTPUTS },
                { $d::INPUTS },
                { $d::TARGETS },
            >>::FRESH;
            let (x0, upper) = (fresh_carried.0, fresh_carried.1);
            ekf_constants.x0 = x0.to_vec();
            let entry = |i: usize, j: usize| upper[host::plant::kalman::upper($d::STATES, i.min(j), i.max(j))];
            ekf_constants.p0 = host::plant::Covariance::Full(
                (0..$d::STATES)
                    .map(|i| (0..$d::STATES).map(|j| entry(i, j)).collect())
                    .collect(),
            );
            let filter = filter_code(&$code, &ekf_constants);
            let restart = host::observers::kind::ekf_restart::run::RestartConstants {
                threshold: $d::RESTART_THRESHOLD,
                variances: $d::RESTART_VARIANCES.to_vec(),
            };
            host::observers::kind::ekf_restart::run::estimate::<f64>(
                &filter,
                &ekf_constants,
                &$d::STARTED_P0,
                &restart,
                &$targets,
                &$maps,
                &$run,
                &$code,
            )
            .rows
        }};
    }
    generated::for_each_observer!(mirror);
    let host = host.ok_or_else(|| format!("{name} has no {:?} observer", measured.kind))?;
    largest_over_accepted(name, measured, &host)
}

/// The largest `|target − host|` of design `name`'s unscented Kalman filter (`UkfBoxObserver`) measured
/// on the chip (f32), against the same written-out filter (`Ukf<f64>`) in f64 on the host over the
/// same recorded sequence, its accepted samples.
pub fn compare_ukf_with_f64(name: &str, measured: &ObserverMeasurement) -> Result<f64, String> {
    let mut host: Option<Vec<Vec<f64>>> = None;
    macro_rules! run {
        ($design:ident, ukf_box, $type:ident) => {
            if stringify!($design) == name {
                use generated::$design as d;
                let mut filter = d::Ukf::<f64>::new();
                // Every sample is pushed (a refused one still predicts); the accepted ones kept.
                host = Some(
                    d::RECORDED_Y
                        .iter()
                        .zip(&d::RECORDED_U)
                        .filter_map(|(y, u)| {
                            let (y, u) = (y.map(f64::from), u.map(f64::from));
                            let pushed = filter.push(&y, &u);
                            let finite = y.iter().chain(u.iter()).all(|v| v.is_finite());
                            finite.then(|| match pushed {
                                // The UKF's own targets: its state may be in log coordinates.
                                Ok(x) => d::ukf_targets(&x, &u).to_vec(),
                                Err(_) => vec![f64::NAN; d::TARGETS],
                            })
                        })
                        .collect(),
                );
            }
        };
        ($design:ident, $kind:ident, $type:ident) => {};
    }
    generated::for_each_observer!(run);
    let host = host.ok_or_else(|| format!("{name} has no UKF"))?;
    largest_over_accepted(name, measured, &host)
}

/// The largest `|chip − host|` over the samples the chip accepted, `host` giving the host's targets
/// at each of them (all NaN before the observer's first estimate).
fn largest_over_accepted(name: &str, measured: &ObserverMeasurement, host: &[Vec<f64>]) -> Result<f64, String> {
    let chip: Vec<&TargetSample> = measured.samples.iter().filter(|s| s.accepted).collect();
    if chip.len() != host.len() {
        return Err(format!(
            "{name} {:?}: {} accepted samples on the chip, {} on the host",
            measured.kind,
            chip.len(),
            host.len()
        ));
    }
    let mut largest: f64 = 0.0;
    for (k, (sample, host)) in chip.iter().zip(host).enumerate() {
        let before_first = host.iter().all(|v| v.is_nan());
        match &sample.estimates {
            None if before_first => {}
            Some(estimates) if !before_first => {
                for (t, (&(bits, _), &h)) in estimates.iter().zip(host).enumerate() {
                    let difference = (f64::from(f32::from_bits(bits)) - h).abs();
                    if difference.is_nan() {
                        return Err(format!(
                            "{name} {:?} accepted sample {k} target {t}: {} on the chip, {h} on the host",
                            measured.kind,
                            f32::from_bits(bits)
                        ));
                    }
                    largest = largest.max(difference);
                }
            }
            estimates => {
                return Err(format!(
                    "{name} {:?} accepted sample {k}: an estimate on the chip: {}, on the host: {}",
                    measured.kind,
                    estimates.is_some(),
                    !before_first
                ))
            }
        }
    }
    Ok(largest)
}

/// Compares the target's estimates of design `name` with the host's f64 library estimates on the
/// same recorded sequence, by [`host::emit::precision::compare`]; returns the largest `|target - host|`.
pub fn compare_with_library(name: &str, measured: &ObserverMeasurement) -> Result<f64, String> {
    let (design, result) = shipped_build(name)?;
    let rows = host::emit::recorded_sequence(&result.runs.scenario);
    if rows.len() != measured.samples.len() {
        return Err(format!(
            "{name}: {} samples on the target, {} recorded",
            measured.samples.len(),
            rows.len()
        ));
    }
    let horizon = design.map.horizon;
    let regressors = host::recording::regressors(horizon, &rows);
    let mut largest: f64 = 0.0;
    for (k, ((row, sample), z)) in rows.iter().zip(&measured.samples).zip(&regressors).enumerate() {
        let finite = row.y.iter().chain(&row.u).all(|v| v.is_finite());
        if finite != sample.accepted {
            return Err(format!(
                "{name} sample {k}: accepted {} on the target, finite = {finite}",
                sample.accepted
            ));
        }
        let (Some(estimates), Some(z)) = (&sample.estimates, z) else {
            if z.is_some() {
                return Err(format!(
                    "{name} sample {k}: no estimate on the target after {horizon} samples"
                ));
            }
            continue;
        };
        for (t, ((bits, flag), fitted)) in estimates
            .iter()
            .zip(result.targets.iter().map(|t| &t.fit.map))
            .enumerate()
        {
            let table = fitted
                .table
                .as_ref()
                .ok_or_else(|| format!("{name}: target {t} has no table"))?;
            let saturation = match flag {
                'L' => Saturation::Low,
                'I' => Saturation::Inside,
                'H' => Saturation::High,
                other => {
                    return Err(format!(
                        "{name} sample {k} target {t}: unknown saturation flag {other:?}"
                    ))
                }
            };
            let on_target = Estimate {
                value: f32::from_bits(*bits),
                saturation,
            };
            let difference = compare(table, z, on_target, fitted.estimate(z))
                .map_err(|mismatch| format!("{name} sample {k} target {t}: target vs host: {mismatch}"))?
                .difference;
            largest = largest.max(difference);
        }
    }
    Ok(largest)
}

/// The shipped design `name` as `gen` emits it (its search settled) and its build, shared across tests.
fn shipped_build(name: &str) -> Result<(host::spec::Design, std::sync::Arc<host::fit::DesignResult>), String> {
    let path = crate::shipped_specs()
        .into_iter()
        .find(|p| host::spec::load(p).is_ok_and(|d| d.name == name))
        .ok_or_else(|| format!("no shipped spec for {name}"))?;
    let design = crate::settled(host::spec::load(&path).map_err(|e| e.to_string())?);
    let result = crate::build(&design);
    Ok((design, result))
}
