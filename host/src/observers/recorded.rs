//! Any observer kind over recorded measurements, as the chip runs it: the map over the window of
//! accepted samples ([`crate::recording::estimate`]), and the observers it starts through the one
//! host mirror of `firmware::Started` ([`super::started::run`]), in `f64` or, bit for bit as the
//! chip, in `f32`. A sample with a NaN or infinite output or input is refused (no estimate on its row;
//! the map's window skips it, a started observer takes the model's period over it when the input is
//! finite); every change of the `run` column restarts the observer.

use crate::data::{Rows, Run};
use crate::plant::ModelCode;
use crate::recording::{self, EstimateRow, MapEvaluator, NoTable, Precision, Row, Status};
use crate::spec::{Design, ObserverKind};
use crate::tables::Tables;

use firmware::Saturation;

use super::{corrected, ekf};

/// Why a kind cannot run on this design.
#[derive(Debug, thiserror::Error)]
pub enum RecordedError {
    /// The design has no observer of that kind (see the report's observers).
    #[error(
        "the design `{design}` has no `{kind}` observer: {why}; ask for --kind map, or for a kind its report lists"
    )]
    Unavailable {
        /// The design.
        design: String,
        /// The kind asked for.
        kind: &'static str,
        /// Why (from the comparison).
        why: String,
    },
    /// `--precision f32` without the emitted tables.
    #[error(transparent)]
    NoTable(#[from] NoTable),
}

/// `kind`'s estimates over `rows` (one row out per row in) by the fitted design `tables`, in
/// `precision`. `ObserverKind::Auto` is the kind `gen` chose (`observer()`).
pub fn estimate(
    design: &Design,
    tables: &Tables,
    code: &ModelCode,
    kind: ObserverKind,
    precision: Precision,
    rows: &[Row],
) -> Result<Vec<EstimateRow>, RecordedError> {
    let maps = MapEvaluator::new(&tables.maps, precision)?;
    let kind = match kind {
        ObserverKind::Auto => tables.chosen,
        other => other,
    };
    let mut out = Vec::with_capacity(rows.len());
    for segment in rows.chunk_by(|a, b| a.run == b.run) {
        let map = recording::estimate(&maps, tables.horizon, segment);
        if kind == ObserverKind::Map {
            out.extend(map);
            continue;
        }
        if kind == ObserverKind::EkfBox {
            let boxed = match precision {
                Precision::F64 => from_box::<f64>(design, tables, code, segment)?,
                Precision::F32 => from_box::<f32>(design, tables, code, segment)?,
            };
            out.extend(boxed);
            continue;
        }
        let followed = match precision {
            Precision::F64 => follow::<f64>(design, tables, code, kind, &map, segment)?,
            Precision::F32 => follow::<f32>(design, tables, code, kind, &map, segment)?,
        };
        out.extend(followed);
    }
    Ok(out)
}

/// One run of recorded rows as the observers read it: its outputs and inputs (no truth).
fn as_run(segment: &[Row], targets: usize) -> Run {
    Run {
        states: Rows::new(0),
        inputs: segment.iter().map(|r| r.u.clone()).collect(),
        measurements: segment.iter().map(|r| r.y.clone()).collect(),
        targets: Rows::new(targets),
        parameters: Vec::new(),
    }
}

/// The EKF from the box centre over one run, in `T`, as `BoxEkfObserver` runs it: an estimate from
/// the first accepted sample, refused samples marked.
fn from_box<T: firmware::Scalar + firmware::Maths + Into<f64>>(
    design: &Design,
    tables: &Tables,
    code: &ModelCode,
    segment: &[Row],
) -> Result<Vec<EstimateRow>, RecordedError> {
    let constants = tables.ekf.as_ref().ok_or_else(|| RecordedError::Unavailable {
        design: design.name.clone(),
        kind: "ekf_box",
        why: "the model is beyond the sizes the host filters".to_owned(),
    })?;
    let run = as_run(segment, tables.maps.len());
    let filter = crate::plant::kalman::filter_code(code, constants);
    Ok(ekf::estimate_box::<T>(&filter, constants, &run, code)
        .into_iter()
        .map(|row| match row {
            Some(values) => EstimateRow {
                status: Status::Ok,
                targets: values.into_iter().map(|v| (v.into(), Saturation::Inside)).collect(),
            },
            None => EstimateRow::without(Status::Refused),
        })
        .collect())
}

/// The observer `kind` (corrected, map-started or restarted EKF) over one run, in `T`, started or
/// checked by the map's rows `map`.
fn follow<T: firmware::Scalar + firmware::Maths + Into<f64>>(
    design: &Design,
    tables: &Tables,
    code: &ModelCode,
    kind: ObserverKind,
    map: &[EstimateRow],
    segment: &[Row],
) -> Result<Vec<EstimateRow>, RecordedError> {
    let unavailable = |kind: &'static str, why: String| RecordedError::Unavailable {
        design: design.name.clone(),
        kind,
        why,
    };
    let targets = tables.maps.len();
    // NaN where the map has no estimate; an f32 estimate converts back to itself exactly.
    let values: Vec<Vec<T>> = map
        .iter()
        .map(|row| match row.status {
            Status::Ok => row.targets.iter().map(|&(v, _)| T::literal(v as f32, v)).collect(),
            _ => vec![T::literal(f32::NAN, f64::NAN); targets],
        })
        .collect();
    let run = as_run(segment, targets);
    let (estimates, clamps) = match kind {
        ObserverKind::Corrected => {
            let constants = tables.corrected.as_ref().ok_or_else(|| {
                unavailable(
                    "corrected",
                    "it needs every state as a target and a model the host can run".to_owned(),
                )
            })?;
            let state_targets = corrected::state_targets(design).map_err(|why| unavailable("corrected", why))?;
            let setting = corrected::Setting::for_maps(design, tables.horizon, &tables.maps, code, &state_targets);
            let programs = crate::plant::correction::correction_code(code, constants);
            let estimates = corrected::estimate_run::<T>(&setting, &programs, constants, &values, &run);
            let bounds: Vec<(usize, T, T)> = state_targets
                .iter()
                .zip(constants.lower.iter().zip(&constants.upper))
                .map(|(&t, (&lo, &hi))| (t, T::literal(lo as f32, lo), T::literal(hi as f32, hi)))
                .collect();
            (estimates, bounds)
        }
        ObserverKind::EkfRestart => {
            let (Some(constants), Some((p0, state_targets)), Some(restart)) =
                (&tables.ekf, &tables.started, &tables.restart)
            else {
                return Err(unavailable(
                    "ekf_restart",
                    "it needs every state as a target and a model the host can filter".to_owned(),
                ));
            };
            let filter = crate::plant::kalman::filter_code(code, constants);
            let estimates =
                super::restart::estimate::<T>(&filter, constants, p0, restart, state_targets, &values, &run, code);
            (estimates, Vec::new())
        }
        _ => {
            let (Some(constants), Some((p0, state_targets))) = (&tables.ekf, &tables.started) else {
                return Err(unavailable(
                    "ekf_map",
                    "it needs every state as a target and a model the host can filter".to_owned(),
                ));
            };
            let filter = crate::plant::kalman::filter_code(code, constants);
            let estimates =
                ekf::estimate_started::<T>(&filter, p0, state_targets, tables.horizon - 1, &values, &run, code);
            (estimates, Vec::new())
        }
    };
    Ok(estimates
        .into_iter()
        .zip(segment)
        .zip(map)
        .map(|((row, sample), map_row)| {
            if sample.y.iter().chain(&sample.u).any(|v| !v.is_finite()) {
                return EstimateRow::without(Status::Refused);
            }
            if row.iter().any(|v| !v.is_finite()) {
                return EstimateRow::without(Status::NoEstimateYet);
            }
            let values: Vec<f64> = row.into_iter().map(Into::into).collect();
            // The first estimate is the map's, with its flags.
            if map_row.status == Status::Ok && map_row.targets.iter().map(|t| t.0).eq(values.iter().copied()) {
                return map_row.clone();
            }
            // Later, the corrected map's clamp sets a state exactly to an end of its box.
            let saturation = |t: usize| match clamps.iter().find(|&&(s, _, _)| s == t) {
                Some(&(_, lo, _)) if values[t] == lo.into() => Saturation::Low,
                Some(&(_, _, hi)) if values[t] == hi.into() => Saturation::High,
                _ => Saturation::Inside,
            };
            EstimateRow {
                status: Status::Ok,
                targets: values.iter().enumerate().map(|(t, &v)| (v, saturation(t))).collect(),
            }
        })
        .collect())
}
