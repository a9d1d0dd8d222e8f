//! `ekf_restart`: the EKF from the centre of the state box, checked against the map at every sample
//! from the map's first estimate on and restarted from it as `ekf_map` starts when the two disagree
//! (a χ² threshold tuned on the tuning runs).

pub mod c;
pub mod cost;
pub mod emit;
pub mod run;

use super::{Bench, FixedSection, Kind, Needs, Tuned};
use crate::data::{Rows, Run};
use crate::observers::lost::Track;
use crate::observers::ObserverFigures;
use crate::spec::ObserverKind;
use run as restart;
use run::RestartConstants;

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::EkfRestart,
    what: "the EKF from the centre of the state box, restarted by the map",
    short: "restarted EKF",
    observer_type: "EkfRestartObserver",
    measured_as: "`EkfRestartObserver`",
    legend: "EKF restarted by the map",
    colour: (140, 86, 75),
    dots: false,
    needs: Needs {
        state_targets: true,
        filter: true,
        reads: &[ObserverKind::EkfBox, ObserverKind::EkfMap, ObserverKind::EkfRestart],
    },
    // Its cost reads the map's, known after the fit only (`cost::of_restarted`).
    cost_before_fit: None,
    missing_why: "its tables hold no restart threshold",
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

/// The threshold, chosen on the tuning runs ([`restart::tune`]), the variances the map's on them;
/// then judged.
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    let (tuned, started) = (bench.tuned.ekf_box()?, bench.tuned.ekf_map()?);
    let squared = super::ekf_map::map_squared_errors(bench, &started.state_targets)?;
    let filter = crate::plant::kalman::filter_code(bench.code, &tuned.constants);
    let code = bench.code;
    let run_restarted = |constants: &RestartConstants, run: &Run, map: &Rows| -> Track {
        let map: Vec<Vec<f64>> = map.iter().map(<[f64]>::to_vec).collect();
        Track::from(restart::estimate(
            &filter,
            &tuned.constants,
            &started.p0,
            constants,
            &started.state_targets,
            &map,
            run,
            code,
        ))
    };
    let with = |threshold: f64| RestartConstants {
        threshold,
        variances: squared.clone(),
    };
    let (threshold, _) = restart::tune(|t| {
        let constants = with(t);
        bench.tuning_score(&bench.on_tuning(|run, map| run_restarted(&constants, run, map).rows))
    });
    let constants = with(threshold);
    let map_cost = bench.start_map_cost.instructions;
    let instructions = cost::of_restarted(&filter, map_cost) + crate::search::cost::of_watch(&tuned.constants.watch);
    let figures = bench.judge("ekf_restart", instructions, &|run, map| {
        run_restarted(&constants, run, map)
    });
    bench.tuned.insert(Tuned::EkfRestart(constants));
    Some(figures)
}
