//! The design search: the paper's "static game" over `N`, `n_m` and `β` with the identification in
//! the inner loop (Sect. VI, future work), made cheap because each fit is a QP.
//!
//! Every candidate `(N, n_m, β)` of the spec's [`Search`] is fitted on the learning runs and scored on
//! the tuning runs, never on validation:
//!
//! ```text
//! score = (1/n_r) Σ_targets RMSE_tuning / spread_tuning
//! ```
//!
//! over the same tuning windows for every candidate (those ending at `k ≥ N_max − 1`), so that a
//! short horizon is not judged on the samples a long one never sees. Its cost on the chip is
//! predicted by [`cost`]; a candidate beyond the spec's [`Budget`] is kept in the table but not
//! chosen. The [`pareto`] front is over (score, instructions, delay to the first estimate); the chosen
//! candidate is the best score within budget, a cheaper one preferred within
//! [`crate::observers::CHEAPER_WITHIN`] (as `auto` prefers a cheaper observer kind).
//!
//! The learning and tuning runs are simulated once and shared by every candidate (a run is cut into
//! windows of any `N`); candidates are fitted in parallel (rayon).
//!
//! The search is bounded: [`check_size`] counts the candidates before anything is simulated and
//! refuses more than the spec's `[search] max_candidates`; while it runs, [`pace`] says how far it
//! is and how long is left (on the bar on a terminal, as plain lines without one).

pub mod cost;
pub mod pace;
pub mod pareto;
mod size;
pub mod sparsity;
mod summary;

use std::io::IsTerminal;
use std::sync::Mutex;
use std::time::Instant;

use indicatif::ProgressBar;
use rayon::prelude::*;
use serde::Serialize;

use crate::data::{self, DataSet};
use crate::fit::identify;
use crate::fit::maps::{FittedMap, Tabulation};
use crate::spec::{Budget, Design, MapSettings, Search, SpecError, Taps};
pub use cost::Cost;
pub use size::{check_size, count, DEFAULT_MAX_CANDIDATES, SECONDS_PER_CANDIDATE};
pub use summary::{short, summary};

/// One candidate of the search, fitted and scored.
#[derive(Clone, Debug, Serialize)]
pub struct Candidate {
    /// `N`.
    pub horizon: usize,
    /// `n_m`.
    pub nm: usize,
    /// `β`.
    pub beta: f64,
    /// Non-zero gains per target (sparse `L` when fewer than the regressor's entries).
    pub taps: usize,
    /// Entries of the regressor, `N·(outputs + inputs)`: every tap.
    pub regressor_len: usize,
    /// The score on the tuning runs (mean RMSE / spread); `None` when a fit failed.
    pub score: Option<f64>,
    /// RMSE per target on the tuning runs.
    pub rmse: Vec<f64>,
    /// Why a fit failed.
    pub failure: Option<String>,
    /// The predicted cost of its map on the chip (of the first target's fit shape when a fit failed).
    pub cost: Option<Cost>,
    /// Whether its cost is within the budget.
    pub within_budget: bool,
    /// Whether it is on the Pareto front (score, instructions, delay to the first estimate).
    pub on_front: bool,
}

/// What the search did and chose.
#[derive(Clone, Debug, Serialize)]
pub struct Outcome {
    /// Every candidate, in the spec's order (`N` slowest).
    pub candidates: Vec<Candidate>,
    /// Index of the chosen one.
    pub chosen: usize,
    /// The budget it was chosen within.
    pub budget: Budget,
    /// Tuning windows each candidate was scored on (the same for all).
    pub windows: usize,
    /// Wall-clock seconds the search took.
    pub seconds: f64,
}

impl Outcome {
    /// The chosen candidate.
    pub fn chosen(&self) -> &Candidate {
        &self.candidates[self.chosen]
    }

    /// The front, by increasing instructions.
    pub fn front(&self) -> Vec<&Candidate> {
        let mut front: Vec<&Candidate> = self.candidates.iter().filter(|c| c.on_front).collect();
        front.sort_by(|a, b| instructions(a).total_cmp(&instructions(b)));
        front
    }
}

fn instructions(c: &Candidate) -> f64 {
    c.cost.map_or(f64::INFINITY, |c| c.instructions)
}

/// Runs the design's search, if it has one, on the design's `learning` and `tuning` runs, and returns
/// the design with the chosen `N`, `n_m` and `β` in its [`MapSettings`] (unchanged without a search).
pub fn settle(
    mut design: Design,
    learning: &DataSet,
    tuning: &DataSet,
    progress: &ProgressBar,
) -> Result<(Design, Option<Outcome>), SpecError> {
    let Some(search) = design.search.clone() else {
        return Ok((design, None));
    };
    let outcome = run_on(&design, &search, learning, tuning, progress)?;
    let chosen = outcome.chosen();
    design.map = MapSettings {
        horizon: chosen.horizon,
        nm: chosen.nm,
        beta: chosen.beta,
        taps: (chosen.taps < chosen.regressor_len).then_some(chosen.taps),
        ..design.map
    };
    Ok((design, Some(outcome)))
}

/// Fits and scores every candidate of `search` (see the module's documentation) on the design's
/// learning and tuning runs, simulated here (`gen` simulates them once for the search and the fit:
/// [`settle`]).
pub fn run(design: &Design, search: &Search, progress: &ProgressBar) -> Result<Outcome, SpecError> {
    check_size(design, search)?;
    progress.set_message(format!("{}: simulating the runs of the search", design.name));
    run_on(
        design,
        search,
        &data::learning_set(design)?,
        &data::tuning_set(design)?,
        progress,
    )
}

/// [`run`] on the design's `learning` and `tuning` runs.
fn run_on(
    design: &Design,
    search: &Search,
    learning: &DataSet,
    tuning: &DataSet,
    progress: &ProgressBar,
) -> Result<Outcome, SpecError> {
    let start = Instant::now();
    let total = check_size(design, search)?;
    // Without a terminal the bar is hidden: say the same in plain lines (CI logs, `| tee`).
    let plain = progress.is_hidden() && !std::io::stderr().is_terminal();
    if plain {
        eprintln!(
            "{}: search: {total} candidates to fit (at most {}, `search.max_candidates`)",
            design.name, design.max_candidates
        );
    }
    let n_max = *search.horizons.iter().max().expect("a search has candidates");
    let spreads = spreads(tuning, n_max, design.targets.len());
    let windows = tuning
        .runs
        .iter()
        .map(|r| r.targets.len().saturating_sub(n_max - 1))
        .sum();
    let all = search.candidates();
    progress.set_length(total as u64);
    progress.set_position(0);
    progress.set_message(format!("{}: searching {total} candidates", design.name));
    let fitting = Instant::now();
    let pacer = Mutex::new(pace::Pacer::new(total));
    let mut candidates: Vec<Candidate> = all
        .par_iter()
        .map(|&(horizon, nm, beta)| {
            let settings = MapSettings {
                horizon,
                nm,
                beta,
                taps: None,
                ..design.map
            };
            let candidates = candidates_of(design, &settings, &search.taps, learning, tuning, n_max, &spreads);
            progress.inc(candidates.len() as u64);
            let line = pacer
                .lock()
                .unwrap_or_else(|poisoned| poisoned.into_inner())
                .advance(candidates.len(), fitting.elapsed());
            if let Some(line) = line {
                if plain {
                    eprintln!("{}: search: {line}", design.name);
                } else {
                    progress.set_message(format!("{}: search: {}", design.name, line.short()));
                }
            }
            candidates
        })
        .flatten()
        .collect();
    for c in &mut candidates {
        c.within_budget = c.score.is_some() && c.cost.is_some_and(|cost| within(&design.budget, &cost));
    }
    pareto::mark_front(&mut candidates);
    let chosen = pareto::choose(&candidates).ok_or_else(|| {
        let fitted = candidates.iter().filter(|c| c.score.is_some()).count();
        design.error(
            "budget",
            format!(
                "none of the {} candidates is within the budget ({fitted} fitted; the cheapest needs {})",
                candidates.len(),
                cheapest(&candidates, &design.time_unit)
            ),
            "raise `budget.instructions`, `budget.flash` or `budget.first_estimate`, or offer shorter horizons",
        )
    })?;
    Ok(Outcome {
        candidates,
        chosen,
        budget: design.budget,
        windows,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// Whether `cost` is within `budget`.
pub fn within(budget: &Budget, cost: &Cost) -> bool {
    budget.instructions.is_none_or(|b| cost.instructions <= b as f64)
        && budget.flash.is_none_or(|b| cost.flash <= b as f64)
        && budget
            .first_estimate
            .is_none_or(|b| cost.first_estimate <= b * (1.0 + 1e-9))
}

/// The cheapest fitted candidate's cost, for the message when none is within budget.
fn cheapest(candidates: &[Candidate], time_unit: &str) -> String {
    candidates
        .iter()
        .filter(|c| c.score.is_some())
        .filter_map(|c| c.cost)
        .min_by(|a, b| a.instructions.total_cmp(&b.instructions))
        .map_or("nothing: no candidate could be fitted".to_owned(), |c| {
            format!(
                "{:.0} instructions, {:.0} bytes of flash, a first estimate after {} {time_unit}",
                c.instructions,
                c.flash,
                crate::output::number(c.first_estimate)
            )
        })
}

/// Each target's standard deviation over the tuning windows ending at `k ≥ n_max − 1`.
fn spreads(tuning: &DataSet, n_max: usize, targets: usize) -> Vec<f64> {
    (0..targets)
        .map(|t| {
            let values: Vec<f64> = tuning
                .runs
                .iter()
                .flat_map(|run| run.targets.iter().skip(n_max - 1).map(move |row| row[t]))
                .collect();
            let mean = values.iter().sum::<f64>() / values.len() as f64;
            (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / values.len() as f64).sqrt()
        })
        .collect()
}

/// Fits every target with `settings` at every count of `taps` (one pruning path per target) and
/// scores the maps on the tuning windows ending at `k ≥ n_max − 1`: one candidate per count.
fn candidates_of(
    design: &Design,
    settings: &MapSettings,
    taps: &Taps,
    learning: &DataSet,
    tuning: &DataSet,
    n_max: usize,
    spreads: &[f64],
) -> Vec<Candidate> {
    let learning = DataSet {
        runs: learning.runs.clone(),
        horizon: settings.horizon,
    };
    let regressor_len = learning.regressor_len();
    let counts = taps.for_regressor(regressor_len);
    let blank = |taps: usize| Candidate {
        horizon: settings.horizon,
        nm: settings.nm,
        beta: settings.beta,
        taps,
        regressor_len,
        score: None,
        rmse: Vec::new(),
        failure: None,
        cost: None,
        within_budget: false,
        on_front: false,
    };
    let odds_ratios = identify::basis_of(settings);
    // maps[target][count]
    let mut maps: Vec<Vec<FittedMap>> = Vec::new();
    for (index, target) in design.targets.iter().enumerate() {
        let failure = match identify::fit_counts(
            &learning,
            index,
            &target.name,
            settings,
            &odds_ratios,
            &counts,
            Tabulation::Sketched,
        ) {
            Ok(fits) if fits.iter().all(|fit| fit.map.table.is_some()) => {
                maps.push(fits.into_iter().map(|fit| fit.map).collect());
                continue;
            }
            Ok(_) => format!("{}: Γ too flat for a certified table", target.name),
            Err(e) => format!("{}: {e}", target.name),
        };
        return counts
            .iter()
            .map(|&taps| Candidate {
                failure: Some(failure.clone()),
                ..blank(taps)
            })
            .collect();
    }
    let tuning = DataSet {
        runs: tuning.runs.clone(),
        horizon: settings.horizon,
    };
    let rmse = rmse_per_count(&maps, &tuning, n_max);
    counts
        .iter()
        .enumerate()
        .map(|(c, &taps)| {
            let mut candidate = blank(taps);
            candidate.rmse = rmse[c].clone();
            let score = candidate.rmse.iter().zip(spreads).map(|(r, s)| r / s).sum::<f64>() / spreads.len() as f64;
            candidate.score = score.is_finite().then_some(score);
            if candidate.score.is_none() {
                candidate.failure = Some("a non-finite error on the tuning runs".to_owned());
            }
            let refs: Vec<&FittedMap> = maps.iter().map(|m| &m[c]).collect();
            candidate.cost = Some(cost::of_maps(&refs, settings.horizon, design.tau));
            candidate
        })
        .collect()
}

/// RMSE of every map of `maps[target][count]` on the windows of `data` ending at `k ≥ from − 1`, as
/// `[count][target]`: the search's scores (tuning runs) and the accuracy against taps (validation).
pub(crate) fn rmse_per_count(maps: &[Vec<FittedMap>], data: &DataSet, from: usize) -> Vec<Vec<f64>> {
    let counts = maps.first().map_or(0, Vec::len);
    let mut sums = vec![vec![0.0; maps.len()]; counts];
    let mut windows = 0usize;
    let mut z = Vec::new();
    for window in data.windows().filter(|w| w.end + 1 >= from) {
        data.regressor(window, &mut z);
        for (t, target_maps) in maps.iter().enumerate() {
            let truth = data.target(window, t);
            for (c, map) in target_maps.iter().enumerate() {
                let error = map.estimate(&z).value - truth;
                sums[c][t] += error * error;
            }
        }
        windows += 1;
    }
    sums.iter()
        .map(|row| row.iter().map(|s| (s / windows as f64).sqrt()).collect())
        .collect()
}
