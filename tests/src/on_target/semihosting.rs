//! Parsing what the on-target programs print over semihosting: the map-started runner's `KIND`
//! blocks and the EKF program's lines, into [`ObserverMeasurement`]s and an [`EkfMeasurement`].

use super::kind::Kind;
use super::measurement::{EkfMeasurement, EkfSample, ObserverMeasurement, TargetSample};
use super::unavailable::{failed, Unavailable};

/// Parses the runner's output: per `KIND` block its `E …`, `S …` and `STACK …` lines (the costs
/// measured elsewhere are left at zero).
pub(super) fn parse(text: &str) -> Result<Vec<ObserverMeasurement>, Unavailable> {
    let mut observers: Vec<ObserverMeasurement> = Vec::new();
    let number = |field: &str, line: &str| -> Result<usize, Unavailable> {
        field.parse().map_err(|e| failed(format!("{field:?} in {line:?}: {e}")))
    };
    for line in text.lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        if let ["KIND", name, start_up] = fields.as_slice() {
            let kind = Kind::named(name).ok_or_else(|| failed(format!("unknown kind in {line:?}")))?;
            observers.push(ObserverMeasurement {
                kind,
                start_up: number(start_up, line)?,
                samples: Vec::new(),
                instructions: Vec::new(),
                divisions: Vec::new(),
                cycles: Vec::new(),
                stack_bytes: 0,
                observer_bytes: 0,
                flash_bytes: 0,
                static_ram_bytes: 0,
            });
            continue;
        }
        let Some(observer) = observers.last_mut() else {
            continue;
        };
        match fields.as_slice() {
            ["E", _k, accepted, rest @ ..] => {
                if rest.len() % 2 != 0 {
                    return Err(failed(format!("an estimate without its flag in {line:?}")));
                }
                let estimates = rest
                    .chunks(2)
                    .map(|c| {
                        let bits = u32::from_str_radix(c[0], 16)
                            .map_err(|e| failed(format!("{:?} in {line:?}: {e}", c[0])))?;
                        match c[1] {
                            "L" | "I" | "H" => Ok((bits, c[1].chars().next().unwrap_or('?'))),
                            other => Err(failed(format!("saturation flag {other:?} in {line:?}"))),
                        }
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                observer.samples.push(TargetSample {
                    accepted: *accepted == "1",
                    estimates: (!estimates.is_empty()).then_some(estimates),
                });
            }
            ["S", bytes] => observer.observer_bytes = number(bytes, line)?,
            ["STACK", bytes] => observer.stack_bytes = number(bytes, line)?,
            _ => {}
        }
    }
    if observers.is_empty() || observers.iter().any(|o| o.samples.is_empty()) {
        return Err(failed(format!("no estimate in the output:\n{text}")));
    }
    Ok(observers)
}

/// Parses the EKF program's `K …`, `S …` and `STACK …` lines.
pub(super) fn parse_ekf(text: &str) -> Result<EkfMeasurement, Unavailable> {
    let mut filter = EkfMeasurement::default();
    let bits = |fields: &[&str]| -> Result<Vec<u32>, Unavailable> {
        fields
            .iter()
            .map(|f| u32::from_str_radix(f, 16).map_err(|e| failed(format!("{f:?} in the EKF output: {e}"))))
            .collect()
    };
    for line in text.lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        match fields.as_slice() {
            ["K", _k, accepted, rest @ ..] => {
                let marker = rest
                    .iter()
                    .position(|&f| f == "X")
                    .ok_or_else(|| failed(format!("no state in {line:?}")))?;
                let (targets, state) = (&rest[..marker], &rest[marker + 1..]);
                filter.samples.push(EkfSample {
                    targets: (*accepted == "1").then(|| bits(targets)).transpose()?,
                    state: bits(state)?,
                });
            }
            ["S", bytes] => {
                filter.filter_bytes = bytes.parse().map_err(|e| failed(format!("{line:?}: {e}")))?;
            }
            ["STACK", bytes] => {
                filter.stack_bytes = bytes.parse().map_err(|e| failed(format!("{line:?}: {e}")))?;
            }
            _ => {}
        }
    }
    if filter.samples.is_empty() {
        return Err(failed(format!("no sample in the EKF output:\n{text}")));
    }
    Ok(filter)
}
