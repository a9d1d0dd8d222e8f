//! `ekf_map`: the EKF started by the map at `k = N − 1`, with the box EKF's `Q` and `R` and a
//! `P(N−1)` of the map's error scaled by one factor tuned on the tuning runs.

pub mod c;
pub mod emit;

use super::{Bench, FixedSection, Kind, Needs, Tuned};
use crate::data::{Rows, Run};
use crate::observers::lost::Track;
use crate::observers::{ekf, ObserverFigures, Started};
use crate::search::cost;
use crate::spec::ObserverKind;

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::EkfMap,
    what: "the EKF started by the map",
    short: "map-started EKF",
    observer_type: "EkfMapObserver",
    measured_as: "`EkfMapObserver`",
    legend: "EKF started by the map",
    colour: (148, 103, 189),
    dots: false,
    needs: Needs {
        state_targets: true,
        filter: true,
        reads: &[ObserverKind::EkfBox, ObserverKind::EkfMap],
    },
    cost_before_fit: Some(cost::started_before_fit),
    missing_why: "it needs every state as a target and a model the host can filter",
    judged_in: crate::recording::Precision::F64,
    counts_refusals: true,
    fixed: Some(FixedSection {
        own: false,
        ..super::ekf_box::FIXED
    }),
    filter_code: None,
    rust: Some(emit::rust),
    c: Some(c::c),
    tune,
};

/// `P(N−1)`'s factor over the map's mean squared error per state on the tuning runs, chosen on them
/// ([`ekf::tune_started`]); then judged.
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    let tuned = bench.tuned.ekf_box()?;
    let state_targets = bench.state_maps()?;
    let squared = map_squared_errors(bench, &state_targets)?;
    let filter = crate::plant::kalman::filter_code(bench.code, &tuned.constants);
    let (code, first) = (bench.code, bench.design.map.horizon - 1);
    let run_started = |p0: &[f64], run: &Run, map: &Rows| -> Track {
        let map: Vec<Vec<f64>> = map.iter().map(<[f64]>::to_vec).collect();
        Track::from(ekf::estimate_started(
            &filter,
            p0,
            &tuned.constants.watch,
            &state_targets,
            first,
            &map,
            run,
            code,
        ))
    };
    let scaled = |c: f64| -> Vec<f64> { squared.iter().map(|e| c * e).collect() };
    let (factor, _) = ekf::tune_started(|c| {
        let p0 = scaled(c);
        bench.tuning_score(&bench.on_tuning(|run, map| run_started(&p0, run, map).rows))
    });
    let p0 = scaled(factor);
    let instructions = cost::of_started(&filter) + cost::of_watch(&tuned.constants.watch);
    let figures = bench.judge("ekf_map", instructions, &|run, map| run_started(&p0, run, map));
    let started = Started {
        p0,
        factor,
        state_targets: state_targets.clone(),
    };
    bench.tuned.insert(Tuned::EkfMap(started));
    Some(figures)
}

/// The map's mean squared error on the tuning runs of each state (`state_targets`: each state's
/// map row, [`crate::fit::helpers::state_maps`]): `P(N−1)`'s diagonal before its factor, and the
/// restart's variances. A target's is the map's figure; a helper's is measured here alike.
pub(super) fn map_squared_errors(bench: &Bench<'_>, state_targets: &[usize]) -> Option<Vec<f64>> {
    let map = &bench.observers.first()?.targets;
    Some(
        state_targets
            .iter()
            .enumerate()
            .map(|(i, &t)| match map.get(t) {
                Some(figures) => figures.rmse_tuning.powi(2),
                None => bench.helper_mean_squared_error(i, t),
            })
            .collect(),
    )
}
