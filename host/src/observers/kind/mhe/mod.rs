//! `mhe`: the moving-horizon estimate as the chip runs it (the design's `MheObserver`,
//! [`firmware::mhe::Observer`]): the prior's weight tuned on the tuning runs with the converged
//! estimate ([`mhe::tune_prior`]), then the fewest Gauss–Newton steps per sample of
//! [`mhe::CHIP_ITERATIONS`] whose tuning score is within [`mhe::CHIP_WITHIN`] of the converged
//! estimate's, then the χ² watch's threshold over the windows' costs as the filters' is chosen
//! ([`WATCH_THRESHOLDS`], over `N` windows); judged in `f32`, the chip's arithmetic. `auto` offers it only within
//! `budget.instructions` ([`crate::observers::choose`]).

pub mod c;
pub mod cost;
pub mod emit;
pub mod run;

use super::{Bench, Kind, Needs, Tuned};
use crate::data::Rows;
use crate::observers::ekf::tuning::WATCH_THRESHOLDS;
use crate::observers::score;
use crate::observers::ObserverFigures;
use crate::plant::kalman::Watch;
use crate::spec::ObserverKind;
use run as mhe;
use run::ChipTuned;

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::Mhe,
    what: "the moving-horizon estimate with fixed Gauss–Newton steps",
    short: "MHE",
    observer_type: "MheObserver",
    measured_as: "`MheObserver`",
    legend: "MHE on the chip",
    colour: (23, 190, 207),
    dots: false,
    needs: Needs {
        state_targets: false,
        filter: true,
        reads: &[ObserverKind::Mhe],
    },
    cost_before_fit: None,
    missing_why: "the model is beyond the sizes the host runs a moving-horizon estimate for",
    judged_in: crate::recording::Precision::F32,
    counts_refusals: false,
    fixed: None,
    filter_code: None,
    rust: Some(emit::rust),
    c: Some(c::c),
    tune,
};

/// The prior's weight and the steps, chosen on the tuning runs; then judged in `f32`.
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    use rayon::prelude::*;
    let (design, code, runs) = (bench.design, bench.code, &bench.result.runs);
    let setup = mhe::Setup::new(design, code, &runs.learning)?;
    let tuning = &runs.tuning.runs;
    let prior = mhe::tune_prior(&setup, tuning, |rows| bench.tuning_score(rows));
    let mut scores = Vec::new();
    let mut chosen = None;
    for iterations in mhe::CHIP_ITERATIONS {
        let constants = setup.chip_constants(prior.0, iterations);
        let rows: Vec<Rows> = tuning
            .par_iter()
            .map(|run| setup.chip_run::<f32>(&constants, run).rows)
            .collect();
        let score = bench.tuning_score(&rows);
        scores.push((iterations, score));
        if score <= (1.0 + mhe::CHIP_WITHIN) * prior.1 {
            chosen = Some(constants);
            break;
        }
    }
    let mut constants = chosen.unwrap_or_else(|| {
        let last = *mhe::CHIP_ITERATIONS.last().expect("counts to try");
        setup.chip_constants(prior.0, last)
    });
    // The watch's threshold as the filters' (`ekf::tuning`): over a window of N windows, the lowest
    // score, of equals the largest finite τ, no watch only where strictly best.
    let watched = |threshold: f64| {
        let mut constants = constants.clone();
        constants.watch = Watch {
            window: design.map.horizon,
            threshold,
        };
        constants
    };
    let (threshold, _) = score::lowest(&WATCH_THRESHOLDS, |t| {
        let constants = watched(t);
        let rows: Vec<Rows> = tuning
            .iter()
            .map(|run| setup.chip_run::<f32>(&constants, run).rows)
            .collect();
        bench.tuning_score(&rows)
    });
    constants = watched(threshold);
    let instructions = cost::of_mhe(code, design.map.horizon, constants.iterations, constants.substeps)
        + crate::search::cost::of_watch(&constants.watch);
    let figures = bench.judge("mhe", instructions, &|run, _| setup.chip_run::<f32>(&constants, run));
    bench.tuned.insert(Tuned::Mhe(ChipTuned {
        prior,
        constants,
        scores,
    }));
    Some(figures)
}
