//! What every design's observers are measured against, on the host only: the on-line moving-horizon
//! estimate the map replaces solved to convergence ([`super::kind::mhe::run`]; without a prior, the paper's
//! problem, and with the prior weight the `mhe` kind tuned on the tuning runs) and the particle
//! filter's floor ([`super::particles`]). Neither
//! runs on the chip; each is judged on the validation runs, the scenario, its draws and the mismatch
//! runs ([`Bench::judge_reference`]), in parallel.

use std::sync::Mutex;

pub use super::figures::{Cost, Reference};
use super::kind::mhe::run::{self as mhe, Prior};
use super::kind::Bench;
use super::lost;
use super::particles::Floor;
use super::score::errors;
use crate::data::Rows;

/// The particle count the floor starts its check at: its moves are exact, so fewer particles than a
/// regularised filter's do (converged at 500 or 1000 on every shipped design).
pub const FIRST_PARTICLES: usize = 500;
/// The most particles the floor is run with.
pub const MAX_PARTICLES: usize = 2_000;
/// The floor's count is the first at which doubling it changes no target's validation RMSE by more
/// than this (relative).
pub const CONVERGED_WITHIN: f64 = 0.05;

/// Per-window statistics gathered across threads.
#[derive(Default)]
struct Tally {
    windows: usize,
    seconds: f64,
    max_seconds: f64,
    iterations: usize,
}

/// The references of the design on `bench`; empty when the model is beyond the host's sizes.
pub fn measure(bench: &Bench<'_>) -> Vec<Reference> {
    let (design, code, runs) = (bench.design, bench.code, &bench.result.runs);
    let (Some(setup), Some(chip)) = (mhe::Setup::new(design, code, &runs.learning), bench.tuned.mhe()) else {
        return Vec::new();
    };
    let mut references = Vec::new();
    let tuned = chip.prior;
    for (name, what, prior) in [
        ("mhe_host", "moving-horizon estimate, on-line", Prior::None),
        (
            "mhe_host_prior",
            "moving-horizon estimate with prior, on-line",
            Prior::Weight(tuned.0),
        ),
    ] {
        let tally = Mutex::new(Tally::default());
        let figures = bench.judge_reference(name, None, &|run, _| {
            let solved = setup.run(prior, run);
            let mut t = tally.lock().expect("no panic while held");
            t.windows += solved.seconds.len();
            t.seconds += solved.seconds.iter().sum::<f64>();
            t.max_seconds = solved.seconds.iter().copied().fold(t.max_seconds, f64::max);
            t.iterations += solved.iterations.iter().sum::<usize>();
            solved.rows
        });
        let t = tally.into_inner().expect("no panic while held");
        references.push(Reference {
            what,
            figures,
            cost: Cost::Solver {
                prior: matches!(prior, Prior::Weight(_)).then_some(tuned),
                windows: t.windows,
                mean_seconds: t.seconds / t.windows.max(1) as f64,
                max_seconds: t.max_seconds,
                mean_iterations: t.iterations as f64 / t.windows.max(1) as f64,
                starts: mhe::starts(design).len(),
            },
        });
    }
    references.push(floor(bench));
    references
}

/// The particle filter's floor at the first count from [`FIRST_PARTICLES`] whose doubling changes no
/// target's validation RMSE by more than [`CONVERGED_WITHIN`] (at most [`MAX_PARTICLES`]). Its
/// `lost_which.validation` holds the validation runs it lost at every count tried.
fn floor(bench: &Bench<'_>) -> Reference {
    use rayon::prelude::*;

    let (design, code, runs) = (bench.design, bench.code, &bench.result.runs);
    // The validation runs lost at every count tried: those the data do not determine (a run lost at
    // one count alone may be the cloud's failure, not the data's).
    let mut lost_at_every: Option<Vec<usize>> = None;
    // The validation runs' estimates at `count` (on the streams `judge_reference` gives them) and
    // each target's RMSE.
    let mut validation = |count: usize| -> (Vec<Rows>, Vec<f64>) {
        let floor = Floor::new(design, code, count);
        let rows: Vec<Rows> = runs
            .validation
            .runs
            .par_iter()
            .enumerate()
            .map(|(i, run)| floor.estimate_run(run, i as u64))
            .collect();
        let rmse = (0..design.targets.len())
            .map(|t| errors(&runs.validation.runs, &rows, t, bench.windows()).0)
            .collect();
        let lost = lost::which(
            &runs.validation.runs,
            &rows,
            bench.windows(),
            &bench.scoring.lost_spreads(),
        );
        lost_at_every = Some(match lost_at_every.take() {
            Some(before) => before.into_iter().filter(|i| lost.contains(i)).collect(),
            None => lost,
        });
        (rows, rmse)
    };
    let (rows, doubling) = by_doubling(FIRST_PARTICLES, MAX_PARTICLES, &mut validation);
    let floor = Floor::new(design, code, doubling.count);
    let mut figures = bench.judge_reference("floor", Some(rows), &|run, stream| floor.estimate_run(run, stream));
    figures.lost_which.validation = lost_at_every.unwrap_or_default();
    Reference {
        what: "particle filter, floor (not embeddable)",
        figures,
        cost: Cost::Particles {
            count: doubling.count,
            checked: doubling.checked,
            converged: doubling.converged,
        },
    }
}

/// What [`by_doubling`] found.
#[derive(Clone, Debug, PartialEq)]
pub struct Doubling {
    /// The count whose doubling moved no RMSE by more than [`CONVERGED_WITHIN`], or the largest tried
    /// when none did.
    pub count: usize,
    /// Each count tried with its RMSE per target.
    pub checked: Vec<(usize, Vec<f64>)>,
    /// Whether `count`'s doubling moved no RMSE by more than [`CONVERGED_WITHIN`].
    pub converged: bool,
}

/// The convergence check by doubling: `run(count)` gives the estimates at `count` particles and their
/// RMSE per target; from `first`, the count doubles until doubling it moves no RMSE by more than
/// [`CONVERGED_WITHIN`] (relative to the doubled count's) or until the doubled count would pass `max`.
/// Returns `count`'s estimates.
pub fn by_doubling<E>(first: usize, max: usize, mut run: impl FnMut(usize) -> (E, Vec<f64>)) -> (E, Doubling) {
    let mut count = first;
    let (mut estimates, rmse) = run(count);
    let mut checked = vec![(count, rmse)];
    let mut converged = false;
    while !converged && 2 * count <= max {
        let (doubled_estimates, doubled) = run(2 * count);
        let last = &checked.last().expect("one count").1;
        converged = last
            .iter()
            .zip(&doubled)
            .all(|(a, b)| (a - b).abs() <= CONVERGED_WITHIN * b.abs());
        checked.push((2 * count, doubled));
        if !converged {
            count *= 2;
            estimates = doubled_estimates;
        }
    }
    (
        estimates,
        Doubling {
            count,
            checked,
            converged,
        },
    )
}
