//! Every observer of a design judged on the same data: each kind of the registry ([`kind::REGISTRY`])
//! tuned in its order, and each target's error on the validation runs, the scenario (whole, and its transient), its noise draws, the long and mismatch runs and the
//! tuning runs. Every constant is chosen on the tuning runs only; the maps were fitted on the learning
//! runs only, so every other figure is on data neither saw.

pub mod choice;
pub mod ekf;
pub mod figures;
pub mod kind;
pub mod lost;
pub mod particles;
pub mod recorded;
pub mod references;
pub mod score;
pub mod started;

pub use choice::{check_before_fit, choose};
pub use figures::{Beside, Comparison, Drift, Figures, FromObserverStart, ObserverFigures, TRANSIENT_TIME};
pub use kind::map_estimates;
pub use kind::Started;
pub use score::CHEAPER_WITHIN;

use crate::fit::DesignResult;
use crate::plant::ModelCode;
use crate::spec::{Design, SpecError};

/// Tunes every kind of [`kind::REGISTRY`] on the tuning runs, in its order, and judges each on the
/// validation runs, the scenario and (with uncertain parameters) the mismatch runs of `result`.
/// `progress` names the kind being tuned and then the references (long runs and scenarios make each
/// take minutes).
pub fn compare(
    design: &Design,
    result: &DesignResult,
    code: &ModelCode,
    progress: &indicatif::ProgressBar,
) -> Result<Comparison, SpecError> {
    let mut bench = kind::Bench::new(design, result, code);
    let samples = |set: &crate::data::DataSet| set.runs.iter().map(|r| r.targets.len()).sum::<usize>();
    let runs = &result.runs;
    let judged = samples(&runs.tuning)
        + samples(&runs.validation)
        + runs.scenarios.iter().map(|r| r.targets.len()).sum::<usize>();
    for (i, kind) in kind::REGISTRY.iter().enumerate() {
        progress.set_message(format!(
            "{}: tuning and judging `{}` ({}/{}, on {judged} samples of tuning, validation and scenario runs)",
            design.name,
            kind.kind.name(),
            i + 1,
            kind::REGISTRY.len()
        ));
        if let Some(figures) = (kind.tune)(&mut bench) {
            bench.observers.push(figures);
        }
        let last_box_filter = kind::REGISTRY.iter().rposition(|k| k.filter_code.is_some());
        if Some(i) == last_box_filter {
            bench.settle_start_up();
        }
        if let Some(refused) = bench.refused.take() {
            return Err(refused);
        }
    }
    let chosen = choose(design, &bench.observers, &bench.scoring)?;
    progress.set_message(format!(
        "{}: the host-only references (the on-line moving-horizon estimate, the particle floor)",
        design.name
    ));
    let references = references::measure(&bench);
    // The runs the floor lost too are shown beside each observer's, and not judged (`lost`).
    if let Some(floor) = references.iter().find(|r| r.figures.kind == "floor") {
        let observers = (bench.observers.iter_mut()).chain(bench.beside.iter_mut().map(|b| &mut b.figures));
        for o in observers {
            o.lost.with_floor(&o.lost_which, &floor.figures.lost_which);
        }
    }
    Ok(Comparison {
        references,
        observers: bench.observers,
        tuned: bench.tuned,
        unavailable: bench.unavailable,
        chosen,
        scoring: bench.scoring,
        beside: bench.beside,
        from_observer_start: bench.from_observer_start,
        chip_model_error: chip_model_error(design, result),
    })
}

/// See [`Comparison::chip_model_error`]: over the validation runs' states, relative to each state's
/// range over the learning runs.
fn chip_model_error(design: &Design, result: &DesignResult) -> Vec<f64> {
    let spreads = ekf::state_spreads(&result.runs.learning, design.model.states.len());
    crate::plant::discretisation::per_state(design, &result.runs.validation, &spreads, design.chip_substeps)
}
