//! Any observer kind over recorded measurements, as the chip runs it: the map over the window of
//! accepted samples ([`crate::recording::estimate`]), and the observers it starts through the one
//! host mirror of `firmware::Started` ([`super::started::run`]), in `f64`. A sample with a NaN or
//! infinite output or input is refused (no estimate on its row, nothing changes); every change of the
//! `run` column restarts the observer.

use crate::data::{Rows, Run};
use crate::plant::ModelCode;
use crate::recording::{self, EstimateRow, Row};
use crate::spec::{Design, ObserverKind};
use crate::tables::Tables;

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
}

/// `kind`'s estimates over `rows` (one row out per row in, per target the value and whether it was
/// clamped to its learning range) by the fitted design `tables`. `ObserverKind::Auto` is the kind
/// `gen` chose (`observer()`).
pub fn estimate(
    design: &Design,
    tables: &Tables,
    code: &ModelCode,
    kind: ObserverKind,
    rows: &[Row],
) -> Result<Vec<EstimateRow>, RecordedError> {
    let maps = &tables.maps;
    let horizon = tables.horizon;
    let kind = match kind {
        ObserverKind::Auto => tables.chosen,
        other => other,
    };
    let unavailable = |kind: &'static str, why: String| RecordedError::Unavailable {
        design: design.name.clone(),
        kind,
        why,
    };
    let mut out = Vec::with_capacity(rows.len());
    for segment in rows.chunk_by(|a, b| a.run == b.run) {
        let map = recording::estimate(maps, horizon, segment);
        if kind == ObserverKind::Map {
            out.extend(map);
            continue;
        }
        let values: Vec<Vec<f64>> = map
            .iter()
            .map(|row| row.iter().map(|e| e.map_or(f64::NAN, |(v, _)| v)).collect())
            .collect();
        let run = Run {
            states: Rows::new(0),
            inputs: segment.iter().map(|r| r.u.clone()).collect(),
            measurements: segment.iter().map(|r| r.y.clone()).collect(),
            targets: Rows::new(maps.len()),
            parameters: Vec::new(),
        };
        let (estimates, clamps) = match kind {
            ObserverKind::Corrected => {
                let constants = tables.corrected.as_ref().ok_or_else(|| {
                    unavailable(
                        "corrected",
                        "it needs every state as a target and a model the host can run".to_owned(),
                    )
                })?;
                let state_targets = corrected::state_targets(design).map_err(|why| unavailable("corrected", why))?;
                let setting = corrected::Setting::for_maps(design, horizon, maps, code, &state_targets);
                let programs = crate::plant::correction::correction_code(code, constants);
                let estimates = corrected::estimate_run(&setting, &programs, constants, &values, &run);
                let bounds: Vec<(usize, f64, f64)> = state_targets
                    .iter()
                    .zip(constants.lower.iter().zip(&constants.upper))
                    .map(|(&t, (&lo, &hi))| (t, lo, hi))
                    .collect();
                (estimates, bounds)
            }
            _ => {
                let (Some(constants), Some((p0, state_targets))) = (&tables.ekf, &tables.started) else {
                    return Err(unavailable(
                        "ekf",
                        "it needs every state as a target and a model the host can filter".to_owned(),
                    ));
                };
                let filter = crate::plant::kalman::filter_code(code, constants);
                let estimates = ekf::estimate_started(&filter, p0, state_targets, horizon - 1, &values, &run, code);
                (estimates, Vec::new())
            }
        };
        for row in estimates {
            if row.iter().any(|v| v.is_nan()) {
                out.push(vec![None; row.len()]);
                continue;
            }
            // The corrected map's clamp sets a state exactly to its bound: that is its saturation.
            let clamped = clamps.iter().any(|&(t, lo, hi)| row[t] == lo || row[t] == hi);
            out.push(row.iter().map(|&v| Some((v, clamped))).collect());
        }
    }
    Ok(out)
}
