//! The design search ([`host::search`]) against a second method: a candidate's score from its
//! sketched table equals the score of the certified fit `gen` emits, computed here from scratch;
//! the budget and the choice rule hold; the search is deterministic though parallel.

use host::data::DataSet;
use host::spec::{Budget, MapSettings, Search, Taps};
use indicatif::ProgressBar;

/// Mean over targets of RMSE / spread of `result`'s certified maps on the tuning windows ending at
/// `k ≥ from`: written here from the definition, not through the search's code.
fn certified_score(design: &host::spec::Design, from: usize) -> f64 {
    let result = integration_tests::build(design);
    let tuning = host::data::tuning_set(design).unwrap();
    let data = DataSet {
        runs: tuning.runs,
        horizon: design.map.horizon,
    };
    let mut z = Vec::new();
    let mut total = 0.0;
    for t in &result.targets {
        let (mut errors, mut truths) = (Vec::new(), Vec::new());
        for window in data.windows().filter(|w| w.end >= from) {
            data.regressor(window, &mut z);
            let truth = data.target(window, t.index);
            errors.push(t.fit.map.estimate(&z).value - truth);
            truths.push(truth);
        }
        let n = truths.len() as f64;
        let mean = truths.iter().sum::<f64>() / n;
        let spread = (truths.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
        let rmse = (errors.iter().map(|e| e * e).sum::<f64>() / n).sqrt();
        total += rmse / spread;
    }
    total / result.targets.len() as f64
}

#[test]
fn a_sketched_score_is_the_certified_score_and_the_budget_and_rule_hold() {
    let mut design = integration_tests::load_relative("host/specs/vanderpol.toml");
    let search = Search {
        horizons: vec![8, 10],
        nms: vec![5],
        betas: vec![0.5],
        taps: Taps::All,
    };
    let outcome = host::search::run(&design, &search, &ProgressBar::hidden()).unwrap();
    let [short, long] = [&outcome.candidates[0], &outcome.candidates[1]];
    assert_eq!((short.horizon, long.horizon), (8, 10));
    // vanderpol.toml is (10, 5, 0.5): its certified maps, scored on the same windows (k ≥ 9).
    let certified = certified_score(&design, 9);
    let sketched = long.score.unwrap();
    println!(
        "N = 10: sketched {sketched:.6}, certified {certified:.6}; N = 8: {:.6}",
        short.score.unwrap()
    );
    assert!(
        (sketched / certified - 1.0).abs() < 1e-3,
        "sketched {sketched}, certified {certified}"
    );
    // The tolerance bites: a neighbouring candidate is told apart by far more.
    assert!((short.score.unwrap() / certified - 1.0).abs() > 0.05);
    // Without a budget the better (N = 10) is chosen; a first estimate within 0.75 s leaves N = 8.
    assert!(long.score < short.score);
    assert_eq!(outcome.chosen, 1);
    design.budget = Budget {
        first_estimate: Some(0.75),
        ..Budget::default()
    };
    let budgeted = host::search::run(&design, &search, &ProgressBar::hidden()).unwrap();
    assert_eq!(budgeted.chosen().horizon, 8);
    assert!(!budgeted.candidates[1].within_budget);
    // A budget nothing meets is an error naming the budget.
    design.budget.first_estimate = Some(0.1);
    let error = host::search::run(&design, &search, &ProgressBar::hidden()).unwrap_err();
    assert_eq!(error.field, "budget");
    // Deterministic, though the candidates are fitted in parallel.
    design.budget = Budget::default();
    let again = host::search::run(&design, &search, &ProgressBar::hidden()).unwrap();
    let scores = |o: &host::search::Outcome| o.candidates.iter().map(|c| c.score).collect::<Vec<_>>();
    assert_eq!(scores(&again), scores(&outcome));
}

/// Sparse `L` in the search: a pruned candidate's sketched score is the score of the certified fit
/// `gen` makes with that `taps` (the pruning path of a count does not depend on the other counts
/// offered), its cost counts only the kept taps, and a budget only pruning meets is met by pruning.
#[test]
fn a_pruned_candidate_is_the_fit_gen_makes_and_meets_a_budget_the_dense_map_cannot() {
    let mut design = integration_tests::load_relative("host/specs/vanderpol.toml");
    let search = Search {
        horizons: vec![10],
        nms: vec![5],
        betas: vec![0.5],
        taps: Taps::Counts(vec![4, 7]),
    };
    let outcome = host::search::run(&design, &search, &ProgressBar::hidden()).unwrap();
    let taps: Vec<usize> = outcome.candidates.iter().map(|c| c.taps).collect();
    assert_eq!(taps, [7, 4]);
    let four = &outcome.candidates[1];
    let pruned = host::spec::Design {
        map: MapSettings {
            taps: Some(4),
            ..design.map
        },
        ..design.clone()
    };
    let certified = certified_score(&pruned, 9);
    println!(
        "N = 10, 4 taps: sketched {:.6}, certified {certified:.6}",
        four.score.unwrap()
    );
    assert!((four.score.unwrap() / certified - 1.0).abs() < 1e-3);
    let result = integration_tests::build(&pruned);
    for t in &result.targets {
        assert_eq!(t.fit.map.gains.iter().filter(|&&g| g != 0.0).count(), 4);
    }
    // The cost counts the kept taps only: the same maps with their 6 pruned gains made non-zero cost
    // 2 · 6 taps more.
    let maps: Vec<_> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
    let mut dense = maps.clone();
    for map in &mut dense {
        for g in &mut map.gains {
            if *g == 0.0 {
                *g = 1e-30;
            }
        }
    }
    let of = |maps: &[host::fit::maps::FittedMap]| {
        host::search::cost::of_maps(&maps.iter().collect::<Vec<_>>(), 10, design.tau).instructions
    };
    assert!((of(&dense) - of(&maps) - 12.0 * host::search::cost::PER_TAP).abs() < 1e-9);
    let (seven, cost) = (
        outcome.candidates[0].cost.unwrap().instructions,
        four.cost.unwrap().instructions,
    );
    assert!(cost < seven, "{cost} {seven}");
    // A budget between the two is met by the 4-tap candidate only.
    design.budget.instructions = Some(((cost + seven) / 2.0) as u64);
    let budgeted = host::search::run(&design, &search, &ProgressBar::hidden()).unwrap();
    assert_eq!(budgeted.chosen().taps, 4);
}
