//! `ukf_box`: the unscented Kalman filter from the centre of the state box (the design's `ukf()`),
//! its own `Q` and `P0` tuned as the box EKF's are, by the same search on the same random tuning runs
//! ([`ukf::tune`]); judged from the box centre everywhere, as `ekf()` is.

pub mod c;
pub mod cost;
pub mod emit;
pub mod program;
pub mod run;

use super::{Bench, FixedSection, Kind, Needs, Tuned};
use crate::observers::{ekf, ObserverFigures};
use crate::spec::ObserverKind;
use program::unscented_code;
use run as ukf;

/// `[observer.ukf]`: the UKF's constants the spec fixes.
pub const FIXED: FixedSection = FixedSection {
    section: "observer.ukf",
    own: true,
};

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::UkfBox,
    what: "the unscented Kalman filter from the centre of the state box",
    short: "UKF",
    observer_type: "UkfBoxObserver",
    measured_as: "`UkfBoxObserver`",
    legend: "UKF from x̂(0)",
    colour: (188, 189, 34),
    dots: false,
    needs: Needs {
        state_targets: false,
        filter: true,
        reads: &[ObserverKind::UkfBox],
    },
    cost_before_fit: Some(cost::ukf_before_fit),
    missing_why: "the model is beyond the sizes the host filters",
    judged_in: crate::recording::Precision::F32,
    counts_refusals: true,
    fixed: Some(FIXED),
    filter_code: Some(unscented_code),
    rust: Some(emit::rust),
    c: Some(c::c),
    tune,
};

/// Tunes the UKF on the random tuning runs (as the box EKF, but the constants the spec fixes), then
/// judges it from its start, and on each scenario from its `observer_x0`.
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    // Its state and constants are in the model's log coordinates ([`unscented_code`]).
    let code = bench.code;
    let judge = |bench: &Bench<'_>, tuned: &ekf::Tuned| {
        let filter = unscented_code(code, &tuned.constants);
        let cost = cost::of_ukf(&filter) + crate::search::cost::of_watch(&tuned.constants.watch);
        bench.judge("ukf_box", cost, &|run, _| {
            ukf::track_run(code, &filter, &tuned.constants.x0, &tuned.constants, run)
        })
    };
    let (tuned, figures) = bench.box_filter(ukf::estimates, &code.log_coordinates, FIXED, &judge)?;
    let filter = unscented_code(code, &tuned.constants);
    bench.from_observer_starts("ukf_box", &|x0, run| {
        ukf::estimate_run(
            code,
            &filter,
            &code.log_coordinates.to_filter(x0),
            &tuned.constants,
            run,
        )
    });
    bench.tuned.insert(Tuned::UkfBox(tuned));
    Some(figures)
}
