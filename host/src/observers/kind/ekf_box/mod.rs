//! `ekf_box`: the EKF from the centre of the state box (the design's `ekf()`), `Q` and `P0` tuned
//! as an expert tunes a filter for starts anywhere in the box: on the random tuning runs alone (the
//! scenario's start is one the chip's `ekf()` does not know; `auto` then judges it, as every kind, on
//! all the tuning runs, its tail from the scenario's start).

pub mod c;

use super::{Bench, FixedSection, Kind, Needs, Tuned};
use crate::observers::{ekf, ObserverFigures};
use crate::search::cost;
use crate::spec::ObserverKind;

/// `[observer.ekf]`: the box EKF's constants the spec fixes (the kinds over it reuse its `Q`).
pub const FIXED: FixedSection = FixedSection {
    section: "observer.ekf",
    own: true,
};

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::EkfBox,
    what: "the EKF from the centre of the state box",
    short: "EKF",
    observer_type: "EkfBoxObserver",
    measured_as: "`ekf()`",
    legend: "EKF from x̂(0)",
    colour: (255, 127, 14),
    dots: false,
    needs: Needs {
        state_targets: false,
        filter: true,
        reads: &[ObserverKind::EkfBox],
    },
    cost_before_fit: Some(cost::ekf_before_fit),
    missing_why: "the model is beyond the sizes the host filters",
    judged_in: crate::recording::Precision::F64,
    counts_refusals: true,
    fixed: Some(FIXED),
    filter_code: Some(crate::plant::kalman::filter_code),
    rust: None,
    c: Some(c::c),
    tune,
};

/// Tunes the EKF on the random tuning runs (but the constants the spec fixes), judges it from its
/// start everywhere (the scenarios included: where `ekf()` starts on the chip), and runs it once more
/// on each scenario from its `observer_x0`, the paper's comparison.
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    let code = bench.code;
    let judge = |bench: &Bench<'_>, tuned: &ekf::Tuned| {
        let filter = crate::plant::kalman::filter_code(code, &tuned.constants);
        let cost = cost::of_ekf(&filter) + cost::of_watch(&tuned.constants.watch);
        bench.judge("ekf_box", cost, &|run, _| {
            ekf::track_run(code, &tuned.constants, &tuned.constants.x0, run).expect("size checked by tune")
        })
    };
    let (tuned, figures) = bench.box_filter(
        ekf::estimates,
        &crate::plant::Coordinates::plant(code.dimensions.states),
        FIXED,
        &judge,
    )?;
    bench.from_observer_starts("ekf_box", &|x0, run| {
        ekf::estimate_run(code, &tuned.constants, x0, run).expect("size checked by tune")
    });
    bench.tuned.insert(Tuned::EkfBox(tuned));
    Some(figures)
}
