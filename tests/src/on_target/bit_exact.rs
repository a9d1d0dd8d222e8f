//! The same observers run on the host in f32 over the recorded sequence the chip runs, and every
//! difference from what the chip reported: the chip must match the host bit for bit.

use firmware::emitted::Maths;
use firmware::{Estimate, Saturation, Scalar};

use super::kind::Kind;
use super::measurement::{EkfSample, TargetSample};

/// One sample of an extended Kalman filter run on the host: the targets of the estimate `push`
/// returned (`None` when refused) and the state after the sample.
pub type HostEkfSample<T> = (Option<Vec<T>>, Vec<T>);

/// Runs design `name`'s extended Kalman filter (`Ekf::<T>::new()`, the written-out one) on the host over the recorded
/// sequence the chip runs (`RECORDED_Y`, `RECORDED_U`, each value taken exactly into `T`); `None` for
/// an unknown design.
pub fn host_ekf<T: Scalar + Maths>(name: &str) -> Option<Vec<HostEkfSample<T>>> {
    let mut samples = None;
    macro_rules! run {
        ($design:ident) => {
            if generated::$design::NAME == name {
                use generated::$design as d;
                let exact = |v: f32| T::literal(v, f64::from(v));
                let mut filter = d::Ekf::<T>::new();
                samples = Some(
                    d::RECORDED_Y
                        .iter()
                        .zip(&d::RECORDED_U)
                        .map(|(y, u)| {
                            let (y, u) = (y.map(exact), u.map(exact));
                            let targets = filter.push(&y, &u).ok().map(|x| d::targets(&x, &u).to_vec());
                            (targets, filter.state().to_vec())
                        })
                        .collect(),
                );
            }
        };
    }
    generated::for_each_design!(run);
    samples
}

/// Estimates as the chip prints them: per target the value's bits and the saturation flag.
pub fn bits_and_flags<T: Scalar>(estimates: &[Estimate<T>], bits: impl Fn(T) -> u32) -> Vec<(u32, char)> {
    estimates
        .iter()
        .map(|e| (bits(e.value), chip_flag(e.saturation)))
        .collect()
}

/// The saturation flag as the chip prints it.
pub fn chip_flag(saturation: Saturation) -> char {
    match saturation {
        Saturation::Low => 'L',
        Saturation::Inside => 'I',
        Saturation::High => 'H',
    }
}

/// Runs design `name`'s observer of `kind` on the host in f32, over the recorded sequence the chip
/// runs (`RECORDED_Y`, `RECORDED_U`; the integer observer in `i32` over `RECORDED_RAW_Y`,
/// `RECORDED_RAW_U`): per sample whether `push` accepted it and what `estimate`
/// gave, as the chip reports them. `None` for the EKF from the box centre (see [`host_ekf`]), an
/// unknown design or a kind the design does not have.
pub fn host_samples(name: &str, kind: Kind) -> Option<Vec<TargetSample>> {
    let mut samples = None;
    macro_rules! run {
        ($design:ident, $fresh:expr) => {{
            use generated::$design as d;
            let mut observer = $fresh;
            d::RECORDED_Y
                .iter()
                .zip(&d::RECORDED_U)
                .map(|(y, u)| TargetSample {
                    accepted: observer.push(*y, *u).is_ok(),
                    estimates: observer.estimate().map(|e| bits_and_flags(&e, f32::to_bits)),
                })
                .collect::<Vec<_>>()
        }};
    }
    // Every kind but the box EKF, measured as its filter ([`host_ekf`]).
    macro_rules! of {
        ($design:ident, $kind:ident, $type:ident) => {
            if stringify!($kind) != "ekf_box"
                && Kind::named(stringify!($kind)) == Some(kind)
                && stringify!($design) == name
            {
                samples = Some(run!($design, generated::$design::$type::new()));
            }
        };
    }
    generated::for_each_observer!(of);
    // The integer observer, over the raw sequence: a value printed as its `i32` taken as `u32` (the
    // macro is unused while no design has one).
    #[allow(unused_macros)]
    macro_rules! fixed {
        ($design:ident, $type:ident) => {
            if kind == Kind::Fixed && stringify!($design) == name {
                use generated::$design as d;
                let mut observer = d::fixed_observer();
                samples = Some(
                    d::RECORDED_RAW_Y
                        .iter()
                        .zip(&d::RECORDED_RAW_U)
                        .map(|(y, u)| TargetSample {
                            accepted: observer.push(*y, *u).is_ok(),
                            estimates: observer.estimate().map(|e| {
                                e.iter()
                                    .map(|e| (e.value as u32, chip_flag(e.saturation)))
                                    .collect()
                            }),
                        })
                        .collect::<Vec<_>>(),
                );
            }
        };
    }
    generated::for_each_fixed_observer!(fixed);
    samples
}

/// Every difference between what the chip reported (`chip`) and what the host computed (`host`),
/// sample by sample, one line each naming `what`, the sample and the target; empty when the two
/// are equal bit for bit (acceptance, the presence of an estimate, each value's bits and flag).
pub fn differences(what: &str, chip: &[TargetSample], host: &[TargetSample]) -> Vec<String> {
    let mut found = Vec::new();
    if chip.len() != host.len() {
        found.push(format!(
            "{what}: {} samples on the chip, {} on the host",
            chip.len(),
            host.len()
        ));
    }
    for (k, (chip, host)) in chip.iter().zip(host).enumerate() {
        if chip.accepted != host.accepted {
            found.push(format!(
                "{what} sample {k}: accepted {} on the chip, {} on the host",
                chip.accepted, host.accepted
            ));
        }
        match (&chip.estimates, &host.estimates) {
            (Some(on_chip), Some(on_host)) => {
                if on_chip.len() != on_host.len() {
                    found.push(format!(
                        "{what} sample {k}: {} targets on the chip, {} on the host",
                        on_chip.len(),
                        on_host.len()
                    ));
                }
                for (t, (c, h)) in on_chip.iter().zip(on_host).enumerate() {
                    if c != h {
                        found.push(format!(
                            "{what} sample {k} target {t}: chip {:08x} {} ({:e}), host {:08x} {} ({:e})",
                            c.0,
                            c.1,
                            f32::from_bits(c.0),
                            h.0,
                            h.1,
                            f32::from_bits(h.0)
                        ));
                    }
                }
            }
            (None, None) => {}
            (on_chip, on_host) => found.push(format!(
                "{what} sample {k}: an estimate on the chip: {}, on the host: {}",
                on_chip.is_some(),
                on_host.is_some()
            )),
        }
    }
    found
}

/// [`differences`] for an extended Kalman filter: the targets of every estimate `push` returned
/// (`None` when refused) and the state after every sample.
pub fn ekf_differences(what: &str, chip: &[EkfSample], host: &[HostEkfSample<f32>]) -> Vec<String> {
    let mut found = Vec::new();
    if chip.len() != host.len() {
        found.push(format!(
            "{what}: {} samples on the chip, {} on the host",
            chip.len(),
            host.len()
        ));
    }
    let bits = |values: &[f32]| values.iter().map(|v| v.to_bits()).collect::<Vec<u32>>();
    for (k, (chip, (targets, state))) in chip.iter().zip(host).enumerate() {
        let targets = targets.as_deref().map(bits);
        if chip.targets != targets {
            found.push(format!(
                "{what} sample {k}: targets {:x?} on the chip, {targets:x?} on the host",
                chip.targets
            ));
        }
        if chip.state != bits(state) {
            found.push(format!(
                "{what} sample {k}: state {:x?} on the chip, {:x?} on the host",
                chip.state,
                bits(state)
            ));
        }
    }
    found
}
