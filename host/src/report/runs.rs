//! Which figure comes from which runs: every set of [`Runs`] with its size, seed and the figures
//! computed on it, for `report.json` and a table of `report.md`.

use serde::Serialize;

use crate::data::{uncertain, DataSet, Run, Runs};
use crate::spec::Design;

/// One set of runs.
#[derive(Clone, Debug, Serialize)]
pub struct RunSet {
    /// Its name in the report.
    pub set: &'static str,
    /// Runs.
    pub runs: usize,
    /// Samples per run: the shortest and the longest.
    pub samples: (usize, usize),
    /// The seed it is drawn from (and the generator's stream, when not 0).
    pub seed: String,
    /// What is computed on it.
    pub figures: &'static str,
}

/// Every set of `runs` (simulated for `design`), in the order the pipeline uses them.
pub fn sets(design: &Design, runs: &Runs) -> Vec<RunSet> {
    let one = |set, runs: &[Run], seed: String, figures| RunSet {
        set,
        runs: runs.len(),
        samples: (
            runs.iter().map(|r| r.targets.len()).min().unwrap_or(0),
            runs.iter().map(|r| r.targets.len()).max().unwrap_or(0),
        ),
        seed,
        figures,
    };
    let of = |set, data: &DataSet, seed: String, figures| one(set, &data.runs, seed, figures);
    let scenario_seed = design.scenario().map(|s| s.seed);
    let mut sets = vec![
        of(
            "learning",
            &runs.learning,
            design.learning.seed.to_string(),
            "the maps' fit (and `RMSE learning`)",
        ),
        of(
            "tuning",
            &runs.tuning,
            match design.scenarios.len() {
                0 => design.tuning.seed.to_string(),
                1 => format!("{} (the scenario's starts: stream 1)", design.tuning.seed),
                n => format!("{} (the scenarios' starts: streams 1–{n})", design.tuning.seed),
            },
            "every tuned constant, the design search's and `auto`'s scores (`RMSE tuning`, `p95 tuning`)",
        ),
        of(
            "validation",
            &runs.validation,
            design.validation.seed.to_string(),
            "`RMSE validation`, `p95 validation`, `max error validation`, the quality gates",
        ),
        one(
            "scenario",
            std::slice::from_ref(&runs.scenario),
            scenario_seed.map_or(format!("{} (the first validation run)", design.validation.seed), |s| {
                s.to_string()
            }),
            "`RMSE scenario`, `RMSE transient`, the estimation figure, the chip's recorded sequence",
        ),
    ];
    if runs.scenarios.len() > 1 {
        let seeds: Vec<String> = design.scenarios[1..].iter().map(|s| s.seed.to_string()).collect();
        sets.push(one(
            "other scenarios",
            &runs.scenarios[1..],
            seeds.join(", "),
            "each scenario's figures (*Scenarios*)",
        ));
    }
    if let (Some(draws), Some(seed)) = (&runs.scenario_draws, scenario_seed) {
        sets.push(of(
            "scenario draws",
            draws,
            format!("{seed} (stream 2)"),
            "the scenario's noise draws: their RMSE and p95",
        ));
    }
    let long_seed = uncertain::free_seed(design, 1).to_string();
    sets.push(of(
        "long",
        &runs.long,
        long_seed.clone(),
        "drift (`RMSE first` and `RMSE last`)",
    ));
    if let Some(m) = &runs.mismatch {
        let seed = uncertain::mismatch_seed(design).to_string();
        sets.push(of(
            "mismatch",
            &m.corners_set,
            seed.clone(),
            "`RMSE mismatch` and each corner's RMSE",
        ));
        sets.push(of(
            "mismatch nominal",
            &m.nominal_set,
            seed,
            "the same runs on the nominal plant",
        ));
        sets.push(of(
            "mismatch long",
            &m.long,
            long_seed,
            "drift on the plant at the last corner",
        ));
        sets.push(one(
            "mismatch scenario",
            std::slice::from_ref(&m.scenario),
            scenario_seed.map_or(uncertain::mismatch_seed(design).to_string(), |s| s.to_string()),
            "the estimation figure on the plant at the last corner",
        ));
    }
    sets
}

/// `report.md`'s table of the sets.
pub fn table(sets: &[RunSet]) -> String {
    let mut s =
        String::from("| set | runs | samples per run | seed | figures computed on it |\n|---|---|---|---|---|\n");
    for set in sets {
        let samples = match set.samples {
            (a, b) if a == b => a.to_string(),
            (a, b) => format!("{a}–{b}"),
        };
        s.push_str(&format!(
            "| {} | {} | {samples} | {} | {} |\n",
            set.set, set.runs, set.seed, set.figures
        ));
    }
    s
}
