//! Quality gates: what `gen` warns about a design before a user ships it (and `gen --strict` refuses).
//! Each gate is measured on the validation runs (data no fit and no tuning saw) and says what to
//! change:
//!
//! * [`Gate::BelowLinearFloor`]: the map is worse than the plain linear least-squares map `Lᵀ Z + c` on
//!   the same windows by more than [`LINEAR_FLOOR_SLACK`]: the nonlinear fit failed to pay for itself.
//! * [`Gate::OutsideLearningRange`]: more than [`OUTSIDE_FRACTION`] of the validation windows have a
//!   true target outside the learning range `[r_min, r_max]`: the validation runs went where the
//!   learning runs never did (a pendulum going over the top, say), so the map can only saturate there.
//! * [`Gate::Weak`]: the map's validation RMSE is at least
//!   [`WEAK_FRACTION`](crate::fit::evaluate::WEAK_FRACTION) of the target's spread: it barely beats
//!   predicting the mean, and the target may not be observable from these measurements over N.
//! * [`Gate::EkfBetter`]: the chosen observer's validation RMSE is more than [`EKF_FACTOR`] times the
//!   design's best other EKF's (`ekf_box`, `ekf_map` or `ekf_restart`, other than the chosen kind) on some
//!   target: that EKF is the better choice for this system. An
//!   EKF the spec's `[budget] instructions` does not allow (as [`crate::search::cost`] predicts it)
//!   is not a choice, so it does not count.
//! * [`Gate::RawRangeShort`]: a signal's declared raw range (`[chip.raw.<signal>]`) stands for values
//!   that more than [`OUTSIDE_FRACTION`] of the learning runs' samples leave: a converter holds those
//!   samples at its range's ends, so the integer map reads values the signal does not have and is far
//!   worse than the float map there.
//! * [`Gate::StartOutsideBox`]: a filter's start the spec fixes (`[observer.<filter>] x0`)
//!   or a scenario's `observer_x0` lies outside the learning box: the filter
//!   starts where no learning or validation run starts, which is allowed (a published filter's guess
//!   may be poor on purpose) but is rarely what a user means.
//! * [`Gate::CoarseChipModel`]: the chip's model, `sampling.chip_substeps` RK4 steps per period, is
//!   more than [`crate::plant::discretisation::TOLERANCE`] of some state's range away from the
//!   simulated plant after one period on the learning runs: every observer that carries the model
//!   carries that error as the plant's ([`crate::plant::discretisation`]).
//! * [`Gate::LostRuns`]: an observer lost runs of a set it is judged on (validation, the scenario's
//!   draws, the mismatch or the long runs; [`crate::observers::lost`]). A warning for any kind;
//!   `--strict` refuses it only for `observer()`, the kind that is flashed.
//! * [`Gate::Drift`]: an observer's RMSE over the last window of the long runs is more than
//!   [`DRIFT_RATIO`] times its RMSE over the first window after the start-up, on some target (on the
//!   nominal plant or at the last corner of the uncertain parameters): it loses track slowly, which
//!   the validation runs are too short to show. A warning for any kind; `--strict` refuses it only
//!   for `observer()`.

use crate::fit::DesignResult;
use crate::observers::{kind, Comparison};
use crate::spec::Design;

mod checks;
mod sentence;
pub use checks::{coarse_chip_model, drifts, lost_runs, raw_ranges_short, starts_outside_box, DRIFT_RATIO};

/// How much worse than the linear floor the map may be before [`Gate::BelowLinearFloor`].
pub const LINEAR_FLOOR_SLACK: f64 = 0.02;
/// Largest fraction of validation windows whose true target may lie outside the learning range.
pub const OUTSIDE_FRACTION: f64 = 0.01;
/// How many times the EKF's validation RMSE the chosen observer may reach.
pub const EKF_FACTOR: f64 = 2.0;

/// One failed gate, for one target.
#[derive(Clone, Debug, PartialEq)]
pub enum Gate {
    /// See the module docs.
    BelowLinearFloor {
        /// The target.
        target: String,
        /// Map's validation RMSE over the linear map's.
        ratio: f64,
        /// Whether the spec uses the paper's normalisation (the `intercept` one is never far below
        /// the floor on the paper's examples).
        paper_normalisation: bool,
    },
    /// See the module docs.
    OutsideLearningRange {
        /// The target.
        target: String,
        /// Fraction of validation windows outside `[r_min, r_max]`.
        fraction: f64,
        /// The learning range.
        range: (f64, f64),
        /// The true target's range over the validation windows.
        seen: (f64, f64),
    },
    /// See the module docs.
    Weak {
        /// The target.
        target: String,
        /// Map's validation RMSE over the target's spread.
        fraction: f64,
        /// The horizon `N`.
        horizon: usize,
    },
    /// See the module docs.
    EkfBetter {
        /// The target.
        target: String,
        /// The chosen observer's kind.
        chosen: &'static str,
        /// Its validation RMSE.
        rmse: f64,
        /// The better EKF's (`ekf_box` from the box centre, `ekf_map` or `ekf_restart`) kind.
        ekf: &'static str,
        /// Its validation RMSE.
        ekf_rmse: f64,
    },
    /// See the module docs.
    RawRangeShort {
        /// The output or input.
        signal: String,
        /// The values the declared raw range stands for.
        covered: (f64, f64),
        /// The signal's range over the learning runs.
        seen: (f64, f64),
        /// Fraction of the learning samples outside `covered`.
        fraction: f64,
    },
    /// See the module docs.
    Drift {
        /// The observer's kind ([`crate::spec::ObserverKind::name`]).
        kind: &'static str,
        /// The target's name.
        target: String,
        /// The long runs (`""`) or those at the last corner of the uncertain parameters.
        plant: &'static str,
        /// RMSE over the first and the last window.
        first: f64,
        /// See `first`.
        last: f64,
        /// Whether it is `observer()`.
        chosen: bool,
    },
    /// See the module docs.
    LostRuns {
        /// The observer's kind ([`crate::spec::ObserverKind::name`]).
        kind: &'static str,
        /// The set, as the report names it.
        set: &'static str,
        /// Runs lost that the particle floor did not lose.
        lost: usize,
        /// Runs lost that the floor lost too (not judged: the data do not determine a target there).
        floor_lost: usize,
        /// Runs in the set.
        runs: usize,
        /// Whether it is `observer()`.
        chosen: bool,
        /// For `observer()`, of the other kinds judged on the set, those that lost none of its runs
        /// (beyond the floor's): what its fix names; `None` for another kind, or where no other kind
        /// is judged on the set.
        lost_none: Option<Vec<&'static str>>,
    },
    /// See the module docs.
    CoarseChipModel {
        /// The chip's RK4 steps per period.
        substeps: usize,
        /// The state it is farthest on.
        state: String,
        /// Its one-period error over its range.
        error: f64,
        /// The fewest steps per period within the tolerance, where some are.
        fewest: Option<usize>,
    },
    /// See the module docs.
    StartOutsideBox {
        /// The spec's field (`observer.ekf.x0`).
        field: String,
        /// The state outside.
        state: String,
        /// Its start.
        value: f64,
        /// The learning box along that state.
        range: (f64, f64),
    },
}

impl Gate {
    /// Whether `gen --strict` refuses the design for it: every gate but a kind other than
    /// `observer()` losing runs, which is a warning.
    pub fn strict(&self) -> bool {
        !matches!(
            self,
            Gate::LostRuns { chosen: false, .. } | Gate::Drift { chosen: false, .. }
        )
    }
}

/// Every failed gate of a design: the starts outside the box, the chip's model's discretisation, the
/// raw ranges the learning runs leave, then target by target, gate by gate.
pub fn check(design: &Design, result: &DesignResult, comparison: &Comparison) -> Vec<Gate> {
    let mut failed = starts_outside_box(design);
    failed.extend(coarse_chip_model(design, &result.runs.learning));
    failed.extend(raw_ranges_short(design, &result.runs.learning));
    for t in &result.targets {
        let name = design.targets[t.index].name.clone();
        let v = &t.validation;
        let ratio = v.map.rmse / v.linear.rmse;
        if ratio > 1.0 + LINEAR_FLOOR_SLACK {
            failed.push(Gate::BelowLinearFloor {
                target: name.clone(),
                ratio,
                paper_normalisation: design.map.normalisation == crate::spec::Normalisation::Paper,
            });
        }
        let range = (t.fit.map.r_min, t.fit.map.r_max);
        let (mut outside, mut windows) = (0usize, 0usize);
        let mut seen = (f64::INFINITY, f64::NEG_INFINITY);
        for window in result.runs.validation.windows() {
            let truth = result.runs.validation.target(window, t.index);
            seen = (seen.0.min(truth), seen.1.max(truth));
            outside += usize::from(!(range.0..=range.1).contains(&truth));
            windows += 1;
        }
        let fraction = outside as f64 / windows.max(1) as f64;
        if fraction > OUTSIDE_FRACTION {
            failed.push(Gate::OutsideLearningRange {
                target: name.clone(),
                fraction,
                range,
                seen,
            });
        }
        if v.is_weak() {
            failed.push(Gate::Weak {
                target: name.clone(),
                fraction: v.map.rmse / v.target_spread,
                horizon: design.map.horizon,
            });
        }
        let chosen = kind::of(comparison.chosen.0).kind.name();
        let rmse_of = |kind: &str| {
            comparison
                .observers
                .iter()
                .find(|o| o.kind == kind)
                .map(|o| o.targets[t.index].rmse_validation)
                .filter(|v| v.is_finite())
        };
        let affordable = |kind: &str| {
            let instructions = comparison
                .observers
                .iter()
                .find(|o| o.kind == kind)
                .map(|o| o.instructions);
            match (design.budget.instructions, instructions) {
                (Some(budget), Some(instructions)) => instructions <= budget as f64,
                _ => true,
            }
        };
        // The best peer: any EKF within the budget, other than the kind chosen.
        let best_ekf = kind::REGISTRY
            .iter()
            .filter(|k| k.needs.filter)
            .map(|k| k.kind.name())
            .filter(|&kind| kind != chosen && affordable(kind))
            .filter_map(|kind| rmse_of(kind).map(|v| (kind, v)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        if let (Some(rmse), Some((ekf, ekf_rmse))) = (rmse_of(chosen), best_ekf) {
            if rmse > EKF_FACTOR * ekf_rmse {
                failed.push(Gate::EkfBetter {
                    target: name,
                    chosen,
                    rmse,
                    ekf,
                    ekf_rmse,
                });
            }
        }
    }
    // The kinds' own gates last: a target's gate often says why every kind lost runs.
    failed.extend(lost_runs(comparison));
    failed.extend(drifts(design, comparison));
    failed
}

#[cfg(test)]
mod tests {
    //! The gates on hand-made results: a clean design (Example 1's spec, every figure well inside
    //! every gate) fails none, and each test moves one figure just past one gate's threshold, and
    //! another just short of it, on the two targets: each expected gate is worked out by hand from the
    //! module's rules.

    use std::sync::Arc;

    use super::*;
    use crate::data::{DataSet, Rows, Run, Runs};
    use crate::fit::evaluate::{Accuracy, Evaluation};
    use crate::fit::identify::{Certificate, Diagnostics, Fit};
    use crate::fit::maps::{FittedMap, LinearMap};
    use crate::fit::TargetResult;
    use crate::observers::{Drift, Figures, ObserverFigures};
    use crate::spec::{Normalisation, ObserverKind};

    #[test]
    fn a_better_peer_is_named_in_its_kinds_words() {
        let gate = |peer: &'static str| {
            Gate::EkfBetter {
                target: "x1".to_owned(),
                chosen: "map",
                rmse: 0.3,
                ekf: peer,
                ekf_rmse: 0.1,
            }
            .to_string()
        };
        // A filter other than the EKF used to be called "the EKF".
        let mhe = gate("mhe");
        assert!(
            mhe.contains("that of the moving-horizon estimate with fixed Gauss–Newton steps (`mhe`: 0.1000)"),
            "{mhe}"
        );
        assert!(!mhe.contains("EKF"), "{mhe}");
        assert!(gate("ekf_map").contains("`ekf_map` is the better choice"));
    }

    /// Example 1's spec: targets x1 and x2, learning box x1 ∈ [-2, 2], x2 ∈ [-5, 5], the scenario's
    /// observer start (1, 0.7), `y`'s raw range [-10.24, 10.235].
    fn design() -> Design {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml");
        crate::spec::parse(&path, &std::fs::read_to_string(&path).unwrap()).unwrap()
    }

    /// One run of 200 samples whose targets are `targets` (both states 0, `y` 0, no input).
    fn run(targets: Vec<Vec<f64>>, y: Vec<f64>) -> Run {
        Run {
            states: Rows::from(vec![vec![0.0, 0.0]; targets.len()]),
            inputs: Rows::from(vec![Vec::new(); targets.len()]),
            measurements: y.into_iter().map(|v| vec![v]).collect(),
            targets: Rows::from(targets),
            parameters: Vec::new(),
        }
    }

    /// One target's figures: the map's and the linear floor's validation RMSE, the target's spread,
    /// and the learning range of the map.
    struct Target {
        map: f64,
        linear: f64,
        spread: f64,
        range: (f64, f64),
    }

    /// Inside every gate: the map twice as good as the floor, a tenth of the spread.
    const CLEAN: Target = Target {
        map: 0.1,
        linear: 0.2,
        spread: 1.0,
        range: (-1.0, 1.0),
    };

    fn target(index: usize, t: &Target) -> TargetResult {
        let accuracy = |rmse| Accuracy { rmse, max_error: rmse };
        let evaluation = Evaluation {
            map: accuracy(t.map),
            linear: accuracy(t.linear),
            saturated_fraction: 0.0,
            target_spread: t.spread,
            windows: 200,
        };
        let map = FittedMap {
            target: String::new(),
            normalisation: Normalisation::Intercept,
            gains: Vec::new(),
            intercept: 0.0,
            mu_constant: 0.0,
            mu: Vec::new(),
            odds_ratios: Arc::from(Vec::new()),
            r_min: t.range.0,
            r_max: t.range.1,
            table: None,
        };
        let fit = Fit {
            map,
            linear: LinearMap {
                gains: Vec::new(),
                intercept: 0.0,
            },
            diagnostics: Diagnostics {
                status: clarabel::solver::SolverStatus::Solved,
                iterations: 0,
                solve_time_s: 0.0,
                constraints: 0,
                active_constraints: 0,
                collapsed: false,
                nonlinearity: 0.0,
                refinement_rounds: 0,
                min_slope_over_epsilon: 1.0,
                reduced_condition: 1.0,
                objective_over_epsilon_squared: 0.0,
            },
            certificate: Certificate {
                epsilon: 1.0,
                mean: 0.0,
                mu: Vec::new(),
                with_constant: false,
                grid: Vec::new(),
                lambda: Vec::new(),
                nu: None,
            },
        };
        TargetResult {
            index,
            fit,
            learning: evaluation,
            validation: evaluation,
        }
    }

    /// The result of two targets with `validation` truths and `y` learning samples (one run each,
    /// horizon 1: a window per sample).
    fn result(targets: [&Target; 2], validation: Vec<Vec<f64>>, y: Vec<f64>) -> DesignResult {
        let set = |runs: Vec<Run>| DataSet { runs, horizon: 1 };
        let samples = y.len();
        DesignResult {
            helpers: Ok(Vec::new()),
            runs: Runs {
                learning: set(vec![run(vec![vec![0.0, 0.0]; samples], y)]),
                validation: set(vec![run(validation.clone(), vec![0.0; validation.len()])]),
                tuning: set(Vec::new()),
                scenario: run(Vec::new(), Vec::new()),
                scenarios: Vec::new(),
                scenario_draws: None,
                long: set(Vec::new()),
                mismatch: None,
            },
            targets: vec![target(0, targets[0]), target(1, targets[1])],
        }
    }

    fn clean_result() -> DesignResult {
        result([&CLEAN, &CLEAN], vec![vec![0.0, 0.0]; 200], vec![0.0; 200])
    }

    /// An observer of kind `name` with validation RMSE `rmse` on (x1, x2).
    fn observer(name: &'static str, rmse: [f64; 2], instructions: f64) -> ObserverFigures {
        let figures = |rmse_validation| Figures {
            rmse_validation,
            max_error_validation: 0.0,
            p95_validation: 0.0,
            rmse_scenario: 0.0,
            rmse_transient: 0.0,
            scenarios: Vec::new(),
            scenario_draws: None,
            rmse_tuning: 0.0,
            p95_tuning: 0.0,
            rmse_mismatch: None,
            rmse_corners: Vec::new(),
            rmse_nominal: None,
            drift: Drift { first: 0.0, last: 0.0 },
            drift_mismatch: None,
        };
        ObserverFigures {
            kind: name,
            instructions,
            targets: rmse.map(figures).to_vec(),
            tuning_terms: Vec::new(),
            tuning_estimates: Vec::new(),
            scenario: Rows::default(),
            mismatch_scenario: None,
            lost: Default::default(),
            lost_which: Default::default(),
        }
    }

    fn comparison(chosen: ObserverKind, observers: Vec<ObserverFigures>) -> Comparison {
        Comparison {
            observers,
            references: Vec::new(),
            tuned: Default::default(),
            unavailable: Default::default(),
            beside: Vec::new(),
            from_observer_start: Vec::new(),
            chosen: (chosen, String::new()),
            scoring: crate::observers::score::Scoring {
                spreads: vec![1.0; 2],
                weights: vec![1.0; 2],
                regimes: crate::observers::score::Regimes::whole(0, 0),
                start_up_by: crate::observers::score::StartUpBy::Horizons,
                constant: f64::INFINITY,
            },
            chip_model_error: Vec::new(),
        }
    }

    fn clean_comparison() -> Comparison {
        comparison(
            ObserverKind::Map,
            vec![
                observer("map", [0.1, 0.1], 100.0),
                observer("ekf_box", [0.1, 0.1], 300.0),
            ],
        )
    }

    fn close(got: f64, want: f64) {
        assert!((got - want).abs() < 1e-12, "{got} != {want}");
    }

    #[test]
    fn a_clean_design_fails_no_gate() {
        assert_eq!(check(&design(), &clean_result(), &clean_comparison()), []);
    }

    #[test]
    fn a_lost_run_warns_for_any_kind_and_is_strict_for_the_chosen_one() {
        use crate::observers::lost::{Lost, LostRuns};
        let mut comparison = clean_comparison();
        comparison.observers[1].lost = LostRuns {
            // 3 lost, 2 of them by the particle floor too: 1 judged.
            validation: Lost {
                lost: 3,
                runs: 64,
                floor_lost: 2,
                ..Lost::default()
            },
            // Only a run the floor lost too: not a gate.
            scenario_draws: Some(Lost {
                lost: 1,
                runs: 50,
                floor_lost: 1,
                ..Lost::default()
            }),
            long: Some(Lost {
                lost: 2,
                runs: 64,
                ..Lost::default()
            }),
            tuning: Some(Lost {
                lost: 5,
                runs: 80,
                ..Lost::default()
            }), // where constants are chosen: not a gate
            ..LostRuns::default()
        };
        let gates = check(&design(), &clean_result(), &comparison);
        assert_eq!(gates.len(), 2, "{gates:?}");
        assert!(matches!(
            &gates[0],
            Gate::LostRuns {
                kind: "ekf_box",
                set: "validation",
                lost: 1,
                floor_lost: 2,
                runs: 64,
                chosen: false,
                lost_none: None
            }
        ));
        assert!(matches!(
            &gates[1],
            Gate::LostRuns {
                set: "long",
                lost: 2,
                ..
            }
        ));
        assert!(gates.iter().all(|g| !g.strict()), "another kind's lost runs only warn");
        assert!(
            gates[0]
                .to_string()
                .contains("(`ekf_box`) lost 1 of 64 validation runs (besides 2 the particle floor lost too"),
            "{}",
            gates[0]
        );
        comparison.chosen.0 = ObserverKind::EkfBox;
        let gates = check(&design(), &clean_result(), &comparison);
        assert!(gates.iter().all(Gate::strict), "observer()'s lost runs fail --strict");
        assert!(gates[0].to_string().starts_with("`observer()`, "), "{}", gates[0]);
        // Its fix names the other kinds that lost none of the set's runs: the map, on validation; on
        // the long runs, where the map is not judged here, none is named.
        let fix = "; of the other kinds, `map` lost none of them (`[observer] kind`)";
        assert!(gates[0].to_string().ends_with(fix), "{}", gates[0]);
        assert!(
            gates[1].to_string().ends_with("(the report's table of lost runs)"),
            "{}",
            gates[1]
        );
        // When the map loses a validation run too, no kind is offered, and the sentence says so.
        comparison.observers[0].lost.validation = Lost {
            lost: 1,
            runs: 64,
            ..Lost::default()
        };
        let gates = check(&design(), &clean_result(), &comparison);
        let chosen = gates
            .iter()
            .find(|g| {
                matches!(
                    g,
                    Gate::LostRuns {
                        chosen: true,
                        set: "validation",
                        ..
                    }
                )
            })
            .expect("observer()'s validation gate");
        assert!(
            chosen.to_string().ends_with(
                "; every other kind judged on them lost some of them too (the floor's row in that table says how many \
                 the best estimate of the model lost)"
            ),
            "{chosen}"
        );
    }

    #[test]
    fn a_drift_over_twice_the_first_window_warns_and_is_strict_for_the_chosen_one() {
        let mut comparison = clean_comparison();
        // x1: 0.1 → 0.2, exactly twice: not a drift; x2: 0.1 → 0.2001: one.
        comparison.observers[0].targets[0].drift = Drift { first: 0.1, last: 0.2 };
        comparison.observers[0].targets[1].drift = Drift {
            first: 0.1,
            last: 0.2001,
        };
        let gates = check(&design(), &clean_result(), &comparison);
        assert_eq!(gates.len(), 1, "{gates:?}");
        let Gate::Drift {
            kind, target, chosen, ..
        } = &gates[0]
        else {
            panic!("{gates:?}")
        };
        assert_eq!((*kind, target.as_str(), *chosen), ("map", "x2", true));
        assert!(gates[0].strict());
        assert!(gates[0].to_string().contains("2.00 times"), "{}", gates[0]);
        comparison.chosen.0 = ObserverKind::EkfBox;
        assert!(!check(&design(), &clean_result(), &comparison)[0].strict());
    }

    #[test]
    fn a_map_over_2_percent_worse_than_the_linear_floor_fails() {
        // x1: 0.2041 / 0.2 = 1.0205 > 1.02; x2: 0.2039 / 0.2 = 1.0195, within the slack.
        let x1 = Target { map: 0.2041, ..CLEAN };
        let x2 = Target { map: 0.2039, ..CLEAN };
        let result = result([&x1, &x2], vec![vec![0.0, 0.0]; 200], vec![0.0; 200]);
        let mut design = design();
        for paper in [false, true] {
            if paper {
                design.map.normalisation = Normalisation::Paper;
            }
            let gates = check(&design, &result, &clean_comparison());
            let [Gate::BelowLinearFloor {
                target,
                ratio,
                paper_normalisation,
            }] = &gates[..]
            else {
                panic!("{gates:?}");
            };
            assert_eq!((target.as_str(), *paper_normalisation), ("x1", paper));
            close(*ratio, 1.0205);
        }
    }

    #[test]
    fn over_1_percent_of_validation_windows_outside_the_learning_range_fails() {
        // x1 in [-1, 1]: 3 of 200 windows at 1.5 are outside (1.5 %), the ends themselves inside; it
        // saw [-1, 1.5]. x2: 2 of 200 at -1.2 (1 %, not more).
        let mut truths = vec![vec![0.0, 0.0]; 200];
        for row in &mut truths[..3] {
            row[0] = 1.5;
        }
        truths[3][0] = -1.0;
        truths[4][0] = 1.0;
        for row in &mut truths[10..12] {
            row[1] = -1.2;
        }
        let result = result([&CLEAN, &CLEAN], truths, vec![0.0; 200]);
        let gates = check(&design(), &result, &clean_comparison());
        let expected = Gate::OutsideLearningRange {
            target: "x1".to_owned(),
            fraction: 0.015,
            range: (-1.0, 1.0),
            seen: (-1.0, 1.5),
        };
        assert_eq!(gates, [expected]);
    }

    #[test]
    fn a_map_at_70_percent_of_the_spread_is_weak() {
        // x1: 0.7 of a spread of 1 (at the bound: weak); x2: 0.69 (below it). The floor is 1.0, so
        // that the linear gate stays quiet.
        let x1 = Target {
            map: 0.7,
            linear: 1.0,
            ..CLEAN
        };
        let x2 = Target {
            map: 0.69,
            linear: 1.0,
            ..CLEAN
        };
        let result = result([&x1, &x2], vec![vec![0.0, 0.0]; 200], vec![0.0; 200]);
        let gates = check(&design(), &result, &clean_comparison());
        let expected = Gate::Weak {
            target: "x1".to_owned(),
            fraction: 0.7,
            horizon: 10,
        };
        assert_eq!(gates, [expected]);
    }

    #[test]
    fn an_ekf_within_the_budget_over_twice_as_good_as_the_chosen_kind_fails() {
        // The map: 0.3 on both targets. ekf_box (600 instructions): 0.1 and 0.2; ekf_map (400):
        // 0.14 and 0.16; ekf_restart diverged (NaN, never a peer). Without a budget, x1's best peer
        // is ekf_box, 0.3 > 2·0.1; x2's is ekf_map, 0.3 < 2·0.16.
        let observers = || {
            vec![
                observer("map", [0.3, 0.3], 100.0),
                observer("ekf_box", [0.1, 0.2], 600.0),
                observer("ekf_map", [0.14, 0.16], 400.0),
                observer("ekf_restart", [f64::NAN, f64::NAN], 300.0),
            ]
        };
        let gate = |ekf, ekf_rmse| Gate::EkfBetter {
            target: "x1".to_owned(),
            chosen: "map",
            rmse: 0.3,
            ekf,
            ekf_rmse,
        };
        let mut design = design();
        let gates_of = |design: &Design, chosen| check(design, &clean_result(), &comparison(chosen, observers()));
        assert_eq!(gates_of(&design, ObserverKind::Map), [gate("ekf_box", 0.1)]);
        // Within 500 instructions ekf_box is not a choice: x1's peer is ekf_map, 0.3 > 2·0.14.
        design.budget.instructions = Some(500);
        assert_eq!(gates_of(&design, ObserverKind::Map), [gate("ekf_map", 0.14)]);
        // Within 399, no EKF is a choice.
        design.budget.instructions = Some(399);
        assert_eq!(gates_of(&design, ObserverKind::Map), []);
        // ekf_box chosen (no budget): its own figures are not its peer's, and ekf_map (0.14, 0.16)
        // is not twice as good as 0.1 or 0.2.
        design.budget.instructions = None;
        assert_eq!(gates_of(&design, ObserverKind::EkfBox), []);
    }

    #[test]
    fn a_filters_start_outside_the_learning_box_fails_and_the_plants_does_not() {
        let mut design = design();
        assert!(starts_outside_box(&design).is_empty());
        // The scenario's observer start at x1 = 2.5 (box [-2, 2]); the plant's at x1 = 3 is no gate;
        // the EKF's at x2 = -6 (box [-5, 5]), its x1 = 2 on the box's edge is inside.
        design.scenarios[0].observer_x0 = Some(vec![2.5, 0.7]);
        design.scenarios[0].x0 = vec![3.0, 0.0];
        design.filters.of_mut("observer.ekf").x0 = Some(vec![2.0, -6.0]);
        let gate = |field: &str, state: &str, value, range| Gate::StartOutsideBox {
            field: field.to_owned(),
            state: state.to_owned(),
            value,
            range,
        };
        assert_eq!(
            starts_outside_box(&design),
            [
                gate("observer.ekf.x0", "x2", -6.0, (-5.0, 5.0)),
                gate("scenario.observer_x0", "x1", 2.5, (-2.0, 2.0)),
            ]
        );
    }

    #[test]
    fn a_raw_range_left_by_over_1_percent_of_the_learning_samples_fails() {
        // y's raw range: -10.24 + 0.005·[0, 4095] = [-10.24, 10.235]. 3 of 200 samples at 10.3 leave
        // it (1.5 %), 2 of 200 (1 %) do not count.
        let mut y = vec![0.0; 200];
        y[..3].fill(10.3);
        let design = design();
        let learning = |y: Vec<f64>| result([&CLEAN, &CLEAN], vec![vec![0.0, 0.0]; 200], y).runs.learning;
        let gates = raw_ranges_short(&design, &learning(y.clone()));
        let [Gate::RawRangeShort {
            signal,
            covered,
            seen,
            fraction,
        }] = &gates[..]
        else {
            panic!("{gates:?}");
        };
        assert_eq!((signal.as_str(), *seen), ("y", (0.0, 10.3)));
        close(covered.0, -10.24);
        close(covered.1, 10.235);
        close(*fraction, 0.015);
        y[2] = 0.0;
        assert_eq!(raw_ranges_short(&design, &learning(y)), []);
        // A negative scale covers the same span from the other end.
        let mut flipped = design.clone();
        let scale = flipped.fixed.as_mut().unwrap().outputs[0].as_mut().unwrap();
        (scale.scale, scale.offset) = (-0.005, 10.235);
        let mut y = vec![0.0; 200];
        y[..3].fill(-10.3);
        let gates = raw_ranges_short(&flipped, &learning(y));
        let [Gate::RawRangeShort { covered, .. }] = &gates[..] else {
            panic!("{gates:?}");
        };
        close(covered.0, -10.24);
        close(covered.1, 10.235);
    }
}
