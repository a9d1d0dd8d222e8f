//! Which kind `observer()` is: the spec's, checked before the fit and after it, or for `auto` the
//! best on the tuning runs within the budget. Kept apart from the comparison that yields the
//! figures it reads ([`super::compare`]).

use crate::plant::ModelCode;
use crate::spec::{Design, ObserverKind, SpecError};

use super::score::{Score, Scoring, CHEAPER_WITHIN};
use super::{ekf, kind, ObserverFigures};

/// A kind's [score](super::score::regimes) on the tuning runs (the mean over the tuning set's regimes of
/// its terms), with its lost tuning runs.
fn tuning_score(figures: &ObserverFigures, scoring: &Scoring) -> Score {
    Score {
        lost: figures.lost.tuning.map_or(0, |l| l.lost),
        value: scoring.value(&figures.tuning_terms),
    }
}

/// What [`choose`] would refuse of the spec's `observer.kind` that is known before anything is fitted,
/// refused before the fit rather than minutes after it: a kind the map starts or checks while a state
/// is not a target, an EKF kind of a model beyond the sizes the host filters, and an EKF kind whose
/// predicted instructions exceed `budget.instructions`. The EKF's count depends on the model alone:
/// its tuned constants are all non-zero numbers written into the program, any such ones give it,
/// with the spec's `Q` where it fixes one (the map's and the corrected observer's counts need the fit, and are checked after it).
pub fn check_before_fit(design: &Design, code: &ModelCode) -> Result<(), SpecError> {
    if design.observer == ObserverKind::Auto {
        return Ok(());
    }
    let entry = kind::of(design.observer);
    if entry.needs.filter && !ekf::supported(code) {
        return Err(cannot_have(design));
    }
    let (Some(budget), Some(cost)) = (design.budget.instructions, entry.cost_before_fit) else {
        return Ok(());
    };
    let states = code.dimensions.states;
    let theta = vec![0.37f64.log10(); 2 * states];
    let mut constants = ekf::constants(design, &ekf::box_centre(design), &vec![1.0; states], &theta);
    // A full `Q` the spec fixes adds its off-diagonal entries to every prediction.
    if let Some(q) = entry.fixed.and_then(|fixed| fixed.of(design).q.as_ref()) {
        constants.q = q.clone();
    }
    let instructions = cost(code, &constants);
    if instructions > budget as f64 {
        return Err(over_budget(design, entry.kind.name(), instructions, budget as f64));
    }
    Ok(())
}

/// `observer.kind` names a kind the design cannot have.
fn cannot_have(design: &Design) -> SpecError {
    let (needs, fix) = ("a model the host can filter", "set kind = \"map\" or \"auto\"");
    design.error(
        "observer.kind",
        format!(
            "the design cannot have a `{}` observer: it needs {needs}",
            design.observer.name()
        ),
        fix,
    )
}

/// `observer.kind` names a kind over `budget.instructions`.
fn over_budget(design: &Design, name: &str, instructions: f64, budget: f64) -> SpecError {
    design.error(
        "observer.kind",
        format!(
            "the `{name}` observer needs ~{instructions:.0} instructions per sample, more than `budget.instructions` = {budget}"
        ),
        "raise `budget.instructions`, or set kind = \"auto\" to take the best kind within it",
    )
}

/// The kind `observer()` is: the spec's, or for `auto` the lowest [score](super::score::score) on the
/// tuning runs among the kinds within `[budget] instructions` (as [`cost`](crate::search::cost) predicts them;
/// the moving-horizon estimate only when that budget is set), except
/// that the cheapest kind (fewest predicted instructions) within [`CHEAPER_WITHIN`] of the best is
/// preferred. Errors when the spec asks for a kind the design cannot have or the budget
/// does not allow.
pub fn choose(
    design: &Design,
    observers: &[ObserverFigures],
    scoring: &Scoring,
) -> Result<(ObserverKind, String), SpecError> {
    let scored: Vec<(ObserverKind, &str, Score, f64)> = kind::REGISTRY
        .iter()
        .map(|k| (k.kind, k.kind.name()))
        .filter_map(|(kind, name)| {
            observers
                .iter()
                .find(|o| o.kind == name)
                .map(|o| (kind, name, tuning_score(o, scoring), o.instructions))
        })
        .collect();
    let budget = design.budget.instructions.map(|b| b as f64);
    let within = |instructions: f64| budget.is_none_or(|b| instructions <= b);
    if design.observer != ObserverKind::Auto {
        return match scored.iter().find(|s| s.0 == design.observer) {
            Some(&(_, name, _, instructions)) if !within(instructions) => {
                Err(over_budget(design, name, instructions, budget.unwrap_or_default()))
            }
            Some(&(kind, name, Score { lost, value: score }, instructions)) => Ok((
                kind,
                format!(
                    "`{name}` as the spec asks (tuning score {score:.4}{}, ~{instructions:.0} instructions)",
                    lost_words(lost)
                ),
            )),
            None => Err(cannot_have(design)),
        };
    }
    // The on-line estimate is what the map exists to avoid: `auto` takes it only when the spec sets a
    // budget that allows it.
    let offered =
        |kind: ObserverKind, instructions: f64| within(instructions) && (kind != ObserverKind::Mhe || budget.is_some());
    let allowed: Vec<&(ObserverKind, &str, Score, f64)> = scored.iter().filter(|s| offered(s.0, s.3)).collect();
    // A kind that does not beat the constant estimate explains nothing, however few runs it lost
    // (unless none beats it).
    let informative: Vec<_> = allowed
        .iter()
        .copied()
        .filter(|s| s.2.value < scoring.constant)
        .collect();
    let allowed = if informative.is_empty() { allowed } else { informative };
    // The fewest lost tuning runs first; among those, the lowest score.
    let fewest = allowed.iter().map(|s| s.2.lost).min().unwrap_or(0);
    let best = allowed
        .iter()
        .filter(|s| s.2.lost == fewest)
        .map(|s| s.2.value)
        .fold(f64::INFINITY, f64::min);
    let Some(&&(kind, name, _, _)) = allowed
        .iter()
        .filter(|s| s.2.lost == fewest && s.2.value <= best * (1.0 + CHEAPER_WITHIN))
        .min_by(|a, b| a.3.total_cmp(&b.3))
    else {
        return Err(design.error(
            "budget.instructions",
            format!(
                "no observer kind fits in {} instructions per sample (the map needs ~{:.0})",
                budget.unwrap_or_default(),
                scored.first().map_or(f64::NAN, |s| s.3)
            ),
            "raise `budget.instructions`, or shorten the map (`map.horizon`, `map.taps`)",
        ));
    };
    let all: Vec<String> = scored
        .iter()
        .map(|&(k, n, Score { lost, value: s }, i)| {
            let over = if !within(i) {
                ", over budget"
            } else if !offered(k, i) {
                ", not offered without `budget.instructions`"
            } else {
                ""
            };
            format!("{n} {s:.4}{} at ~{i:.0} instructions{over}", lost_words(lost))
        })
        .collect();
    let limit = budget.map_or(String::new(), |b| format!(" within `budget.instructions` = {b}"));
    Ok((kind, format!("`{name}` by `auto`: the fewest lost tuning runs among the kinds that beat the constant estimate, then the lowest tuning score (the mean over {} of pooled RMSE + p95 over runs, per target over its spread; {}){limit}, a cheaper kind preferred within {:.0} %", regime_names(scoring), all.join(", "), CHEAPER_WITHIN * 100.0)))
}

/// "random starts, from scenario and start-up": the regimes the score averages over.
fn regime_names(scoring: &Scoring) -> String {
    let names: Vec<&str> = scoring.regimes.parts.iter().map(|r| r.name.as_str()).collect();
    match names.split_last() {
        Some((last, [])) => (*last).to_owned(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
        None => String::new(),
    }
}

/// ", 3 tuning runs lost" (nothing when none was).
fn lost_words(lost: usize) -> String {
    match lost {
        0 => String::new(),
        1 => ", 1 tuning run lost".to_owned(),
        n => format!(", {n} tuning runs lost"),
    }
}

#[cfg(test)]
mod tests {
    //! The rule of `choose` on hand-made figures: every expected kind below is worked out by hand from
    //! the module's rule (the lowest tuning score within the budget, a cheaper kind within
    //! `CHEAPER_WITHIN` = 2 % of the best preferred, the MHE only under a set budget), not by the code.

    use super::*;
    use crate::observers::figures::{Drift, Figures};
    use crate::observers::score::Term;

    /// Example 1's spec (two targets), with `observer.kind` and `budget.instructions` as given.
    fn design(kind: ObserverKind, budget: Option<u64>) -> Design {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml");
        let mut design = crate::spec::parse(&path, &std::fs::read_to_string(&path).unwrap()).unwrap();
        design.observer = kind;
        design.budget.instructions = budget;
        design
    }

    /// A kind whose tuning RMSE is `rmse` and tuning p95 is `p95` on both targets, in one regime: with
    /// spreads of 1, its score is `rmse + p95`.
    fn kind(name: &'static str, rmse: f64, p95: f64, instructions: f64) -> ObserverFigures {
        let figures = Figures {
            rmse_validation: 0.0,
            max_error_validation: 0.0,
            p95_validation: 0.0,
            rmse_scenario: 0.0,
            rmse_transient: 0.0,
            scenarios: Vec::new(),
            scenario_draws: None,
            rmse_tuning: rmse,
            p95_tuning: p95,
            rmse_mismatch: None,
            rmse_corners: Vec::new(),
            rmse_nominal: None,
            drift: Drift { first: 0.0, last: 0.0 },
            drift_mismatch: None,
        };
        ObserverFigures {
            kind: name,
            instructions,
            targets: vec![figures.clone(), figures],
            tuning_terms: vec![Term {
                regime: "every run".into(),
                targets: vec![(rmse, p95); 2],
            }],
            tuning_estimates: Vec::new(),
            scenario: crate::data::Rows::default(),
            mismatch_scenario: None,
            lost: Default::default(),
            lost_which: Default::default(),
        }
    }

    const SPREADS: [f64; 2] = [1.0, 1.0];

    /// The scoring of `design`'s tuning set (88 runs: 64 random, 16 from the scenario, 8 edges) with
    /// `spreads`.
    fn scoring(design: &Design, spreads: &[f64]) -> Scoring {
        Scoring::of_tuning(design, spreads, 88)
    }

    fn chosen(design: &Design, observers: &[ObserverFigures]) -> ObserverKind {
        choose(design, observers, &scoring(design, &SPREADS)).unwrap().0
    }

    /// `figures` with target `target`'s `(RMSE, p95)` set to `errors` in every term.
    fn with_target(mut figures: ObserverFigures, target: usize, errors: (f64, f64)) -> ObserverFigures {
        figures
            .tuning_terms
            .iter_mut()
            .for_each(|term| term.targets[target] = errors);
        figures
    }

    /// `weights` as the scoring of Example 1's spec reads them, spreads `spreads`.
    fn weighted(spreads: &[f64], weights: &[f64]) -> Scoring {
        let mut scoring = scoring(&design(ObserverKind::Auto, None), spreads);
        scoring.weights = weights.to_vec();
        scoring
    }

    /// [`kind`] with `lost` of 80 tuning runs lost.
    fn losing(name: &'static str, rmse: f64, instructions: f64, lost: usize) -> ObserverFigures {
        let mut figures = kind(name, rmse, rmse, instructions);
        figures.lost.tuning = Some(crate::observers::lost::Lost {
            lost,
            runs: 80,
            ..Default::default()
        });
        figures
    }

    #[test]
    fn a_kind_that_does_not_beat_the_constant_estimate_is_not_chosen_for_losing_no_run() {
        let design = design(ObserverKind::Auto, None);
        // `ecoli_x0_2`'s case: every filter lost a tuning run, the corrected map none, at 9× the UKF's
        // score and above the constant estimate's.
        let observers = [
            losing("ukf_box", 0.0733, 1000.0, 1),
            losing("corrected", 0.66, 300.0, 0),
            losing("map", 0.3, 100.0, 13),
        ];
        // Scores (RMSE + p95 per target, each 2 × rmse): ukf_box 0.1466, corrected 1.32, map 0.6.
        let mut scoring = scoring(&design, &SPREADS);
        assert_eq!(
            choose(&design, &observers, &scoring).unwrap().0,
            ObserverKind::Corrected
        );
        scoring.constant = 1.1;
        let (kind, why) = choose(&design, &observers, &scoring).unwrap();
        assert_eq!(kind, ObserverKind::UkfBox, "{why}");
        assert!(why.contains("among the kinds that beat the constant estimate"), "{why}");
        // None beats it: the rule is as without it.
        scoring.constant = 0.1;
        assert_eq!(
            choose(&design, &observers, &scoring).unwrap().0,
            ObserverKind::Corrected
        );
    }

    #[test]
    fn a_kind_that_lost_a_tuning_run_is_not_chosen_over_one_that_lost_none() {
        let design = design(ObserverKind::Auto, None);
        // The two-tank case: ekf_box ties the UKF on the score (0.0216) and is cheaper, but it
        // lost a tuning run: the UKF.
        let observers = [
            losing("ekf_box", 0.0108, 300.0, 1),
            losing("ukf_box", 0.0108, 1000.0, 0),
            losing("map", 0.5, 100.0, 0),
        ];
        assert_eq!(chosen(&design, &observers), ObserverKind::UkfBox);
        // When every kind loses runs, the fewest lost wins before the score, and the 2 % preference for
        // a cheaper kind applies among those alone.
        let observers = [
            losing("ekf_box", 0.01, 300.0, 3),
            losing("ukf_box", 0.5, 1000.0, 2),
            losing("map", 0.504, 100.0, 3),
        ];
        assert_eq!(chosen(&design, &observers), ObserverKind::UkfBox);
        let (_, why) = choose(&design, &observers, &scoring(&design, &SPREADS)).unwrap();
        assert!(
            why.contains("ukf_box 1.0000, 2 tuning runs lost at ~1000 instructions"),
            "{why}"
        );
    }

    #[test]
    fn auto_takes_the_lowest_score_when_no_cheaper_kind_is_within_2_percent() {
        // Scores: map 0.30, ekf_box 0.10, corrected 0.103 (3 % above the best: too far, though cheaper).
        let observers = [
            kind("map", 0.1, 0.2, 100.0),
            kind("ekf_box", 0.04, 0.06, 300.0),
            kind("corrected", 0.05, 0.053, 200.0),
        ];
        assert_eq!(
            chosen(&design(ObserverKind::Auto, None), &observers),
            ObserverKind::EkfBox
        );
    }

    #[test]
    fn auto_prefers_the_cheapest_kind_within_2_percent_of_the_best() {
        // Scores: ekf_box 0.10 at 300 instructions, corrected 0.1015 (1.5 % above) at 200, ekf_map
        // 0.1019 (1.9 % above) at 250: all three within 2 %, the cheapest is `corrected`; the map
        // (0.30) is cheaper still but far off.
        let observers = [
            kind("map", 0.1, 0.2, 100.0),
            kind("ekf_box", 0.04, 0.06, 300.0),
            kind("corrected", 0.05, 0.0515, 200.0),
            kind("ekf_map", 0.05, 0.0519, 250.0),
        ];
        assert_eq!(
            chosen(&design(ObserverKind::Auto, None), &observers),
            ObserverKind::Corrected
        );
    }

    #[test]
    fn auto_leaves_out_kinds_over_the_budget() {
        // With 250 instructions allowed, ekf_box (300) is out; of map 0.30 at 100 and corrected 0.12
        // at 240, the corrected observer is best.
        let observers = [
            kind("map", 0.1, 0.2, 100.0),
            kind("ekf_box", 0.04, 0.06, 300.0),
            kind("corrected", 0.06, 0.06, 240.0),
        ];
        assert_eq!(
            chosen(&design(ObserverKind::Auto, Some(250)), &observers),
            ObserverKind::Corrected
        );
        assert_eq!(
            chosen(&design(ObserverKind::Auto, Some(300)), &observers),
            ObserverKind::EkfBox
        );
        // Nothing within 50: an error that says so.
        let tight = design(ObserverKind::Auto, Some(50));
        let error = choose(&tight, &observers, &scoring(&tight, &SPREADS)).unwrap_err();
        assert_eq!(error.field, "budget.instructions");
        assert!(
            error.problem.contains("no observer kind fits in 50"),
            "{}",
            error.problem
        );
    }

    #[test]
    fn auto_offers_the_mhe_only_under_a_set_budget() {
        // The MHE scores best (0.02), but without `budget.instructions` it is not offered: ekf_box
        // (0.10) is chosen; with a budget of 10 000 that allows it, the MHE is.
        let observers = [
            kind("map", 0.1, 0.2, 100.0),
            kind("ekf_box", 0.04, 0.06, 300.0),
            kind("mhe", 0.01, 0.01, 5000.0),
        ];
        assert_eq!(
            chosen(&design(ObserverKind::Auto, None), &observers),
            ObserverKind::EkfBox
        );
        assert_eq!(
            chosen(&design(ObserverKind::Auto, Some(10_000)), &observers),
            ObserverKind::Mhe
        );
    }

    #[test]
    fn a_kind_the_spec_names_is_taken_whatever_its_score_unless_over_budget_or_missing() {
        let observers = [kind("map", 0.1, 0.2, 100.0), kind("ekf_box", 0.04, 0.06, 300.0)];
        // The map scores 0.30 against ekf_box's 0.10, but the spec asks for it.
        assert_eq!(chosen(&design(ObserverKind::Map, None), &observers), ObserverKind::Map);
        assert_eq!(
            chosen(&design(ObserverKind::EkfBox, Some(300)), &observers),
            ObserverKind::EkfBox
        );
        let (over, missing) = (
            design(ObserverKind::EkfBox, Some(299)),
            design(ObserverKind::Corrected, None),
        );
        let over = choose(&over, &observers, &scoring(&over, &SPREADS)).unwrap_err();
        assert!(over.problem.contains("~300 instructions"), "{}", over.problem);
        let missing = choose(&missing, &observers, &scoring(&missing, &SPREADS)).unwrap_err();
        assert!(
            missing.problem.contains("cannot have a `corrected` observer"),
            "{}",
            missing.problem
        );
    }

    #[test]
    fn a_target_is_scored_over_its_spread() {
        // Per target (rmse + p95) / spread, averaged: a kind with errors (0.1, 0.1) on both targets
        // scores (0.2/1 + 0.2/4) / 2 = 0.125 with spreads (1, 4), and one with (0.05, 0.05) on x1 and
        // (0.2, 0.2) on x2 scores (0.1/1 + 0.4/4) / 2 = 0.1: the second wins there, and loses with
        // spreads (1, 1) (0.2 against 0.25).
        let even = kind("ekf_box", 0.1, 0.1, 300.0);
        let uneven = with_target(kind("corrected", 0.05, 0.05, 300.0), 1, (0.2, 0.2));
        assert!((tuning_score(&even, &weighted(&[1.0, 4.0], &[1.0, 1.0])).value - 0.125).abs() < 1e-12);
        assert!((tuning_score(&uneven, &weighted(&[1.0, 4.0], &[1.0, 1.0])).value - 0.1).abs() < 1e-12);
        let observers = [kind("map", 1.0, 1.0, 100.0), even, uneven];
        let auto = design(ObserverKind::Auto, None);
        assert_eq!(
            choose(&auto, &observers, &scoring(&auto, &[1.0, 4.0])).unwrap().0,
            ObserverKind::Corrected
        );
        assert_eq!(chosen(&auto, &observers), ObserverKind::EkfBox);
    }

    #[test]
    fn auto_weighs_each_target_by_its_weight() {
        // Spreads (1, 1). `even` has (rmse, p95) = (0.1, 0.1) on both targets: (0.2 w1 + 0.2 w2) /
        // (w1 + w2) = 0.2 whatever the weights. `uneven` has (0.05, 0.05) on x1 and (0.2, 0.2) on x2:
        // 0.25 with weights (1, 1) (even wins), 0.1 with (1, 0) (x2 left out: uneven wins), and
        // (0.1 + 3 · 0.4) / 4 = 0.325 with (1, 3).
        let even = kind("ekf_box", 0.1, 0.1, 300.0);
        let uneven = with_target(kind("corrected", 0.05, 0.05, 300.0), 1, (0.2, 0.2));
        assert!((tuning_score(&uneven, &weighted(&SPREADS, &[1.0, 3.0])).value - 0.325).abs() < 1e-12);
        assert!((tuning_score(&uneven, &weighted(&SPREADS, &[1.0, 0.0])).value - 0.1).abs() < 1e-12);
        assert!((tuning_score(&even, &weighted(&SPREADS, &[1.0, 3.0])).value - 0.2).abs() < 1e-12);
        let observers = [kind("map", 1.0, 1.0, 100.0), even, uneven.clone()];
        let auto = design(ObserverKind::Auto, None);
        let choice = |w2: f64| choose(&auto, &observers, &weighted(&SPREADS, &[1.0, w2])).unwrap().0;
        assert_eq!(choice(1.0), ObserverKind::EkfBox);
        assert_eq!(choice(0.0), ObserverKind::Corrected);
        assert_eq!(choice(3.0), ObserverKind::EkfBox);
        // A target of weight 0 whose figures are not finite does not poison the others' score.
        let broken = with_target(uneven, 1, (f64::NAN, 0.2));
        assert!((tuning_score(&broken, &weighted(&SPREADS, &[1.0, 0.0])).value - 0.1).abs() < 1e-12);
        assert_eq!(
            tuning_score(&broken, &weighted(&SPREADS, &[1.0, 1.0])).value,
            f64::INFINITY
        );
    }

    /// A kind with `(RMSE, p95)` of `random`, `scenario` and `start_up` on both targets in the three
    /// regimes of Example 1's tuning set: with spreads of 1, its score is the mean of the regimes' sums.
    fn in_regimes(
        name: &'static str,
        [random, scenario, start_up]: [(f64, f64); 3],
        instructions: f64,
    ) -> ObserverFigures {
        let mut figures = kind(name, random.0, random.1, instructions);
        figures.tuning_terms = [
            ("random starts", random),
            ("from scenario", scenario),
            ("start-up", start_up),
        ]
        .map(|(regime, errors)| Term {
            regime: regime.into(),
            targets: vec![errors; 2],
        })
        .to_vec();
        figures
    }

    #[test]
    fn auto_weighs_every_regime_and_not_the_pool_alone() {
        let auto = design(ObserverKind::Auto, None);
        // Example 1's tuning set has three regimes, in this order.
        let names: Vec<String> = (scoring(&auto, &SPREADS).regimes.parts.iter())
            .map(|r| r.name.clone())
            .collect();
        assert_eq!(names, ["random starts", "from scenario", "start-up"]);
        // `pool` is best from random starts (0.08 against 0.10) and twice as bad from the scenario's
        // start: (0.08 + 0.40 + 0.20) / 3 = 0.2267 against `both`'s (0.10 + 0.12 + 0.16) / 3 = 0.1267.
        let pool = in_regimes("ukf_box", [(0.04, 0.04), (0.1, 0.3), (0.1, 0.1)], 1000.0);
        let both = in_regimes("ekf_map", [(0.05, 0.05), (0.06, 0.06), (0.08, 0.08)], 400.0);
        assert!((tuning_score(&pool, &scoring(&auto, &SPREADS)).value - 0.68 / 3.0).abs() < 1e-12);
        assert!((tuning_score(&both, &scoring(&auto, &SPREADS)).value - 0.38 / 3.0).abs() < 1e-12);
        let map = in_regimes("map", [(0.5, 0.5); 3], 100.0);
        assert_eq!(
            chosen(&auto, &[map.clone(), pool.clone(), both.clone()]),
            ObserverKind::EkfMap
        );
        // A kind that wins every regime but lost a tuning run is not chosen.
        let mut lost = in_regimes("ekf_restart", [(0.01, 0.01); 3], 500.0);
        lost.lost.tuning = Some(crate::observers::lost::Lost {
            lost: 1,
            runs: 88,
            ..Default::default()
        });
        assert_eq!(
            chosen(&auto, &[map.clone(), pool.clone(), both.clone(), lost]),
            ObserverKind::EkfMap
        );
        // On the random starts' term alone (the pool of old), `pool` wins.
        let random_only = |f: &ObserverFigures| {
            let mut f = f.clone();
            f.tuning_terms.truncate(1);
            f
        };
        let pooled = [random_only(&map), random_only(&pool), random_only(&both)];
        assert_eq!(chosen(&auto, &pooled), ObserverKind::UkfBox);
        // The reason names the regimes.
        let (_, why) = choose(&auto, &[map, pool, both], &scoring(&auto, &SPREADS)).unwrap();
        assert!(
            why.contains("the mean over random starts, from scenario and start-up of"),
            "{why}"
        );
    }
}
