//! `ekf_box`: the EKF from the centre of the state box (the design's `ekf()`), `Q` and `P0` tuned
//! as an expert tunes a filter for starts anywhere in the box: on the random tuning runs alone (the
//! scenario's start is one the chip's `ekf()` does not know; `auto` then judges it, as every kind, on
//! all the tuning runs, its tail from the scenario's start).

use super::{Bench, Constants, Kind, Needs};
use crate::observers::score::errors;
use crate::observers::{ekf, ObserverFigures};
use crate::search::cost;
use crate::spec::ObserverKind;

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::EkfBox,
    what: "the EKF from the centre of the state box",
    observer_type: "BoxEkfObserver",
    measured_as: "`ekf()`",
    legend: "EKF from x̂(0)",
    colour: (255, 127, 14),
    dots: false,
    needs: Needs {
        state_targets: false,
        filter: true,
        constants: &[Constants::Ekf],
    },
    cost_before_fit: Some(cost::ekf_before_fit),
    judged_in: crate::recording::Precision::F64,
    tune,
};

/// Tunes the EKF on the random tuning runs (but the constants the spec fixes), judges it from its
/// start everywhere (the scenario included: where `ekf()` starts on the chip), and runs it once more
/// from the scenario's `observer_x0`, the paper's comparison.
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    let (design, code) = (bench.design, bench.code);
    let judge = |bench: &Bench<'_>, tuned: &ekf::Tuned| {
        let filter = crate::plant::kalman::filter_code(code, &tuned.constants);
        bench.judge("ekf_box", cost::of_ekf(&filter), &|run, _| {
            ekf::estimate_run(code, &tuned.constants, &tuned.constants.x0, run).expect("size checked by tune")
        })
    };
    let (tuned, figures) = bench.box_filter(ekf::estimates, &design.filters.ekf, &judge)?;
    let scenario = &bench.result.runs.scenario;
    if let Some(x0) = design.scenario.as_ref().and_then(|s| s.observer_x0.clone()) {
        let rows = ekf::estimate_run(code, &tuned.constants, &x0, scenario).expect("size checked by tune");
        let one = std::slice::from_ref(scenario);
        let rmse = (0..design.targets.len())
            .map(|t| errors(one, std::slice::from_ref(&rows), t, bench.windows()).0)
            .collect();
        bench.ekf_from_observer_x0 = Some((x0, rmse));
    }
    bench.ekf = Some(tuned);
    Some(figures)
}
