//! `corrected`: the map corrected by one model step ([`run`]), its gains
//! tuned in closed loop on the tuning runs.

pub mod c;
pub mod cost;
pub mod emit;
pub mod program;
pub mod run;

use super::{Bench, Kind, Needs, Tuned};
use crate::observers::ObserverFigures;
use crate::spec::ObserverKind;
use run as corrected;

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::Corrected,
    what: "the model-corrected map",
    short: "corrected map",
    observer_type: "CorrectedObserver",
    measured_as: "`CorrectedObserver`",
    legend: "model-corrected map",
    colour: (44, 160, 44),
    dots: false,
    needs: Needs {
        state_targets: true,
        filter: false,
        reads: &[ObserverKind::Corrected],
    },
    cost_before_fit: None,
    missing_why: "it needs every state as a target and a model the host can run",
    judged_in: crate::recording::Precision::F64,
    counts_refusals: true,
    fixed: None,
    filter_code: None,
    rust: Some(emit::rust),
    c: Some(c::c),
    tune,
};

/// Tunes the gains on the tuning runs and judges the corrected map; where a helper map could not
/// be fitted, records why the design has none.
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    let state_targets = match &bench.result.helpers {
        Ok(_) => crate::fit::helpers::state_maps(bench.design),
        Err(why) => {
            bench.unavailable.insert(ObserverKind::Corrected, why.clone());
            return None;
        }
    };
    let (design, code) = (bench.design, bench.code);
    let setting = corrected::Setting::for_design(design, bench.result, code, &state_targets);
    let tuned = corrected::tune(&setting, &bench.result.runs.tuning, bench.tuning_maps(), &bench.scoring);
    let programs = crate::observers::kind::corrected::program::correction_code(code, &tuned.constants);
    let figures = bench.judge(
        "corrected",
        cost::of_corrected(&programs, &bench.start_map_cost),
        &|run, map| corrected::estimate_rows(&setting, &programs, &tuned.constants, map, run),
    );
    bench.tuned.insert(Tuned::Corrected(tuned));
    Some(figures)
}
