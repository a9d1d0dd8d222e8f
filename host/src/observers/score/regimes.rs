//! The regimes a tuning score averages over: the questions a user asks of an observer, each on its
//! own runs and samples of the tuning set.
//!
//! One pool over every tuning run answers "how good from anywhere in the box, once settled", and
//! drowns the rest: the 16 runs from a scenario's start among ~90, and the first seconds of each run
//! among its hundred samples. A filter that is best from random starts and twice as bad from the
//! start the user named won the pool. The score is therefore the mean over the regimes `r` of each
//! regime's [`score`](super::score):
//!
//! ```text
//! value = (1/R) Σ_r  Σ_t w_t (RMSE_{r,t} + P95_{r,t}) / s_t  /  Σ_t w_t,
//! ```
//!
//! `RMSE_{r,t}` pooled over regime `r`'s runs and samples, `P95_{r,t}` the 95th percentile over its
//! runs of each run's RMSE there. The tuning set's regimes ([`Regimes::of_tuning`]):
//! - **random starts**: the random runs and the box's edge starts, every sample from the first
//!   estimate (sample `N − 1`) to the end;
//! - **each declared scenario**: its [`SCENARIO_TUNING_RUNS`] runs from its start, every sample from
//!   the first estimate;
//! - **start-up**: every run, the first samples from the first estimate: `tuning.start_up` where the
//!   spec sets it, else as many as the slowest box filter takes to settle ([`mod@super::settle`]; at
//!   least one horizon `N`), [`START_UP_HORIZONS`] `· N` for a design without a box filter.
//!
//! Lost runs are counted over every run, every sample from the first estimate ([`Scoring::score`]).

use super::{counted, percentile_95, Score};
use crate::data::{Rows, Run, SCENARIO_TUNING_RUNS};
use crate::observers::kind::corrected::run::START_UP_HORIZONS;
use crate::spec::Design;

/// Which samples of a regime's runs are judged, from the first estimate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Span {
    /// To the run's end.
    Whole,
    /// This many samples (fewer where the run ends before).
    First(usize),
}

/// The start-up regime's name.
pub const START_UP: &str = "start-up";

/// The random starts' regime's name.
pub const RANDOM_STARTS: &str = "random starts";

/// One regime: its name as the report shows it, its runs (indices into the set) and its samples.
#[derive(Clone, Debug, PartialEq)]
pub struct Regime {
    /// `random starts`, `from <scenario>` or `start-up`.
    pub name: String,
    /// Indices of its runs in the set.
    pub runs: Vec<usize>,
    /// Its samples of each run.
    pub span: Span,
}

/// A set's regimes and the sample of the first estimate they count from.
#[derive(Clone, Debug, PartialEq)]
pub struct Regimes {
    /// The first estimate's sample (`N − 1`).
    pub first: usize,
    /// The regimes, none empty.
    pub parts: Vec<Regime>,
}

/// How the start-up regime's length was chosen (the report says it).
#[derive(Clone, Debug, PartialEq)]
pub enum StartUpBy {
    /// `tuning.start_up`.
    Spec,
    /// As long as this box filter (the slowest) took to settle on the tuning runs' random starts, in
    /// these samples (the start-up is at least one horizon `N` whatever they are).
    Settled(&'static str, usize),
    /// [`START_UP_HORIZONS`] `· N`: no box filter settled (or none was run yet).
    Horizons,
}

/// The start-up regime's samples from the first estimate before any filter has settled:
/// `tuning.start_up`, else [`START_UP_HORIZONS`] `· N`.
pub fn start_up(design: &Design) -> (usize, StartUpBy) {
    match design.start_up {
        Some(samples) => (samples, StartUpBy::Spec),
        None => (START_UP_HORIZONS * design.map.horizon, StartUpBy::Horizons),
    }
}

impl Regimes {
    /// The regimes of the tuning set of `design` (`runs` runs, laid out as
    /// [`crate::data::tuning_set`] lays them out: random runs, each scenario's, the edge starts).
    pub fn of_tuning(design: &Design, runs: usize) -> Self {
        let random = design.tuning.trajectories.min(runs);
        let scenarios_end = (random + design.scenarios.len() * SCENARIO_TUNING_RUNS).min(runs);
        let mut parts = vec![Regime {
            name: RANDOM_STARTS.into(),
            runs: (0..random).chain(scenarios_end..runs).collect(),
            span: Span::Whole,
        }];
        for (i, scenario) in design.scenarios.iter().enumerate() {
            let from = (random + i * SCENARIO_TUNING_RUNS).min(runs);
            parts.push(Regime {
                name: format!("from {}", scenario.name),
                runs: (from..(from + SCENARIO_TUNING_RUNS).min(runs)).collect(),
                span: Span::Whole,
            });
        }
        parts.push(Regime {
            name: START_UP.into(),
            runs: (0..runs).collect(),
            span: Span::First(start_up(design).0),
        });
        parts.retain(|p| !p.runs.is_empty());
        Regimes {
            first: design.map.horizon.saturating_sub(1),
            parts,
        }
    }

    /// One regime: every one of `runs` runs, every sample from `first` (a set that is not the tuning set).
    pub fn whole(first: usize, runs: usize) -> Self {
        Regimes {
            first,
            parts: vec![Regime {
                name: "every run".into(),
                runs: (0..runs).collect(),
                span: Span::Whole,
            }],
        }
    }

    /// The random starts' runs, if the set has that regime.
    pub fn random_starts(&self) -> Option<&[usize]> {
        self.parts
            .iter()
            .find(|p| p.name == RANDOM_STARTS)
            .map(|p| p.runs.as_slice())
    }

    /// The start-up regime's samples, if there is one.
    pub fn start_up(&self) -> Option<usize> {
        self.parts
            .iter()
            .find(|p| p.name == START_UP)
            .and_then(|p| match p.span {
                Span::First(samples) => Some(samples),
                Span::Whole => None,
            })
    }

    /// Gives the start-up regime `samples` samples (none where there is no start-up regime).
    pub fn set_start_up(&mut self, samples: usize) {
        for part in self.parts.iter_mut().filter(|p| p.name == START_UP) {
            part.span = Span::First(samples);
        }
    }

    /// The samples `span` judges of a run of `len` samples.
    fn window(&self, span: Span, len: usize) -> std::ops::Range<usize> {
        let end = match span {
            Span::Whole => len,
            Span::First(samples) => (self.first + samples).min(len),
        };
        self.first.min(end)..end
    }
}

/// One regime's figures: per target, the pooled RMSE and the 95th percentile over its runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Term {
    /// The regime's name.
    pub regime: String,
    /// Per target, `(RMSE, P95)`.
    pub targets: Vec<(f64, f64)>,
}

/// What a set's score is judged against: each target's spread and weight, and the set's regimes.
#[derive(Clone, Debug, PartialEq)]
pub struct Scoring {
    /// Each target's spread over the tuning runs.
    pub spreads: Vec<f64>,
    /// Each target's weight (`[[targets]] weight`).
    pub weights: Vec<f64>,
    /// The set's regimes.
    pub regimes: Regimes,
    /// How the start-up regime's length was chosen.
    pub start_up_by: StartUpBy,
    /// The score of the constant estimate (each target's mean over the tuning runs), scored alike:
    /// `auto` offers no kind that does not beat it. Infinite until the bench measures it.
    pub constant: f64,
}

impl Scoring {
    /// The scoring of `design`'s tuning set of `runs` runs, its targets' `spreads`.
    pub fn of_tuning(design: &Design, spreads: &[f64], runs: usize) -> Self {
        Scoring {
            spreads: spreads.to_vec(),
            weights: super::weights(design),
            regimes: Regimes::of_tuning(design, runs),
            start_up_by: start_up(design).1,
            constant: f64::INFINITY,
        }
    }

    /// Each regime's figures of `estimates` of `runs`.
    pub fn terms(&self, runs: &[Run], estimates: &[Rows]) -> Vec<Term> {
        let regimes = &self.regimes;
        (regimes.parts.iter())
            .map(|regime| Term {
                regime: regime.name.clone(),
                targets: (0..self.spreads.len())
                    .map(|t| {
                        let (mut sum, mut count) = (0.0, 0usize);
                        let per_run: Vec<f64> = (regime.runs.iter())
                            .map(|&i| {
                                let window = regimes.window(regime.span, runs[i].targets.len());
                                let (squares, samples) = super::squared_errors(&runs[i], &estimates[i], t, window);
                                sum += squares;
                                count += samples;
                                (squares / samples.max(1) as f64).sqrt()
                            })
                            .collect();
                        ((sum / count.max(1) as f64).sqrt(), percentile_95(&per_run))
                    })
                    .collect(),
            })
            .collect()
    }

    /// The score's value of `terms` (see the module docs): the mean over regimes of each regime's
    /// [`score`](super::score); `f64::INFINITY` where it is not finite.
    pub fn value(&self, terms: &[Term]) -> f64 {
        of_terms(terms, &self.spreads, &self.weights)
    }

    /// One regime's [`score`](super::score) of its `term`.
    pub fn term_value(&self, term: &Term) -> f64 {
        term_value(term, &self.spreads, &self.weights)
    }

    /// The score of `estimates` of `runs`, with their lost runs over every sample from the first
    /// estimate, on the targets of weight above 0 (a run whose estimate of any target is not finite
    /// is lost still).
    pub fn score(&self, runs: &[Run], estimates: &[Rows]) -> Score {
        let first = self.regimes.first;
        Score {
            lost: crate::observers::lost::count(
                runs,
                estimates,
                &[],
                |run| first..run.targets.len(),
                &self.lost_spreads(),
            )
            .lost,
            value: self.value(&self.terms(runs, estimates)),
        }
    }

    /// The spreads a run's loss is judged against ([`counted`]).
    pub fn lost_spreads(&self) -> Vec<f64> {
        counted(&self.spreads, &self.weights)
    }
}

/// One regime's [`score`](super::score) of its `term`.
fn term_value(term: &Term, spreads: &[f64], weights: &[f64]) -> f64 {
    let (pooled, p95): (Vec<f64>, Vec<f64>) = term.targets.iter().copied().unzip();
    super::score(&pooled, &p95, spreads, weights)
}

/// The mean over `terms` of each regime's [`score`](super::score) with `spreads` and `weights`;
/// `f64::INFINITY` where it is not finite or there is no term.
pub fn of_terms(terms: &[Term], spreads: &[f64], weights: &[f64]) -> f64 {
    let each = terms.iter().map(|term| term_value(term, spreads, weights));
    let mean = each.sum::<f64>() / terms.len() as f64;
    if mean.is_finite() {
        mean
    } else {
        f64::INFINITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tuning_set_splits_into_random_starts_each_scenario_and_the_start_up() {
        // Example 1: 64 random runs, 16 from its scenario, then 2 · 2 + 2² = 8 edge starts; N = 10.
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml");
        let design = crate::spec::parse(&path, &std::fs::read_to_string(&path).unwrap()).unwrap();
        let regimes = Regimes::of_tuning(&design, 88);
        assert_eq!(regimes.first, 9);
        let random: Vec<usize> = (0..64).chain(80..88).collect();
        assert_eq!(
            regimes.parts,
            [
                Regime {
                    name: "random starts".into(),
                    runs: random,
                    span: Span::Whole
                },
                Regime {
                    name: "from scenario".into(),
                    runs: (64..80).collect(),
                    span: Span::Whole
                },
                Regime {
                    name: "start-up".into(),
                    runs: (0..88).collect(),
                    span: Span::First(30)
                },
            ]
        );
        // Before a filter settles: 3N = 30 samples; `tuning.start_up = 2.5` (s, τ = 0.1 s): 25.
        assert_eq!(start_up(&design), (30, StartUpBy::Horizons));
        let text = std::fs::read_to_string(&path)
            .unwrap()
            .replace("[tuning]", "[tuning]\nstart_up = 2.5");
        let set = crate::spec::parse(&path, &text).unwrap();
        assert_eq!(start_up(&set), (25, StartUpBy::Spec));
        let mut regimes = Regimes::of_tuning(&set, 88);
        assert_eq!(regimes.start_up(), Some(25));
        regimes.set_start_up(41);
        assert_eq!(regimes.parts[2].span, Span::First(41));
        assert_eq!(Regimes::whole(9, 88).start_up(), None);
    }

    #[test]
    fn each_regime_is_scored_on_its_own_runs_and_samples_and_the_value_is_their_mean() {
        // Truth 0 over 6 samples, first estimate at sample 1. Run 0 estimates 1 throughout; run 1
        // estimates 2 on samples 1 and 2, then 0. Regime A: run 0, samples 1..6: RMSE 1, p95 1, score 2.
        // Regime B: both runs, samples 1..3: per run 1 and 2, pooled √((2·1 + 2·4)/4) = √2.5, p95
        // 1 + 0.95 (2 − 1) = 1.95. Regime C: run 1, the first 10 samples (cut at the run's end,
        // samples 1..6): √((4 + 4)/5) = √1.6 both. Spread 1, weight 1.
        let rows = |values: &[f64]| {
            let mut rows = Rows::new(1);
            values.iter().for_each(|&v| rows.push(&[v]));
            rows
        };
        let run = || Run {
            states: rows(&[0.0; 6]),
            inputs: Rows::new(0),
            measurements: rows(&[0.0; 6]),
            targets: rows(&[0.0; 6]),
            parameters: Vec::new(),
        };
        let runs = [run(), run()];
        let estimates = [
            rows(&[9.0, 1.0, 1.0, 1.0, 1.0, 1.0]),
            rows(&[9.0, 2.0, 2.0, 0.0, 0.0, 0.0]),
        ];
        let regime = |name: &str, runs: Vec<usize>, span| Regime {
            name: name.into(),
            runs,
            span,
        };
        let scoring = Scoring {
            spreads: vec![1.0],
            weights: vec![1.0],
            regimes: Regimes {
                first: 1,
                parts: vec![
                    regime("A", vec![0], Span::Whole),
                    regime("B", vec![0, 1], Span::First(2)),
                    regime("C", vec![1], Span::First(10)),
                ],
            },
            start_up_by: StartUpBy::Horizons,
            constant: f64::INFINITY,
        };
        let terms = scoring.terms(&runs, &estimates);
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert_eq!(terms[0].targets, [(1.0, 1.0)]);
        assert!(close(terms[1].targets[0].0, 2.5f64.sqrt()) && close(terms[1].targets[0].1, 1.95));
        assert!(close(terms[2].targets[0].0, 1.6f64.sqrt()) && close(terms[2].targets[0].1, 1.6f64.sqrt()));
        let expected = (2.0 + (2.5f64.sqrt() + 1.95) + 2.0 * 1.6f64.sqrt()) / 3.0;
        assert!(close(scoring.value(&terms), expected), "{}", scoring.value(&terms));
        // The sample before the first estimate (9) is in no regime; a NaN in a judged one is infinite.
        let mut broken = estimates.clone();
        broken[1] = rows(&[0.0, f64::NAN, 2.0, 0.0, 0.0, 0.0]);
        assert_eq!(scoring.value(&scoring.terms(&runs, &broken)), f64::INFINITY);
        assert_eq!(scoring.score(&runs, &broken).lost, 1);
    }
}
