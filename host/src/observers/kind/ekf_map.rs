//! `ekf_map`: the EKF started by the map at `k = N − 1`, with the box EKF's `Q` and `R` and a
//! `P(N−1)` of the map's error scaled by one factor tuned on the tuning runs.

use super::{Bench, Constants, Kind, Needs};
use crate::data::{Rows, Run};
use crate::observers::{corrected, ekf, ObserverFigures, Started};
use crate::search::cost;
use crate::spec::ObserverKind;

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::EkfMap,
    what: "the EKF started by the map",
    observer_type: "StartedEkfObserver",
    measured_as: "`StartedEkfObserver`",
    legend: "EKF started by the map",
    colour: (148, 103, 189),
    dots: false,
    needs: Needs {
        state_targets: true,
        filter: true,
        constants: &[Constants::Ekf, Constants::Started],
    },
    cost_before_fit: Some(cost::started_before_fit),
    judged_in: crate::recording::Precision::F64,
    tune,
};

/// `P(N−1)`'s factor over the map's mean squared error per state on the tuning runs, chosen on them
/// ([`ekf::tune_started`]); then judged.
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    let tuned = bench.ekf.as_ref()?;
    let state_targets = corrected::state_targets(bench.design).ok()?;
    let map = &bench.observers.first()?.targets;
    let squared: Vec<f64> = state_targets.iter().map(|&t| map[t].rmse_tuning.powi(2)).collect();
    let filter = crate::plant::kalman::filter_code(bench.code, &tuned.constants);
    let (code, first) = (bench.code, bench.design.map.horizon - 1);
    let run_started = |p0: &[f64], run: &Run, map: &Rows| -> Rows {
        let map: Vec<Vec<f64>> = map.iter().map(<[f64]>::to_vec).collect();
        Rows::from(ekf::estimate_started(
            &filter,
            p0,
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
        bench.tuning_score(&bench.on_tuning(|run, map| run_started(&p0, run, map)))
    });
    let p0 = scaled(factor);
    let figures = bench.judge("ekf_map", cost::of_started(&filter), &|run, map| {
        run_started(&p0, run, map)
    });
    let started = Started {
        p0,
        factor,
        state_targets: state_targets.clone(),
    };
    bench.started = Some((started, squared));
    Some(figures)
}
