//! The tuning score term by term: per kind, each regime's score ([`crate::observers::score::regimes`])
//! and their mean, the number `auto` chooses on, so that a user sees why a kind won and which kind
//! wins which regime.

use std::fmt::Write;

use serde::Serialize;

use crate::observers::figures::Comparison;
use crate::observers::score::regimes::{Span, START_UP};
use crate::observers::score::settle::{OVER_RUNS, SETTLED_WITHIN};
use crate::observers::score::StartUpBy;

/// How far above the best of a regime a kind may score and still count as winning it too.
pub const WINS_WITHIN: f64 = 0.10;

/// The tuning score of every kind, regime by regime.
#[derive(Serialize)]
pub struct TuningScore {
    /// Each target's spread over the tuning runs, in the spec's order of targets.
    pub spreads: Vec<f64>,
    /// Each target's weight.
    pub weights: Vec<f64>,
    /// The regimes, in the order of each kind's terms.
    pub regimes: Vec<RegimeReport>,
    /// How the start-up regime's length was chosen, in words.
    pub start_up_by: String,
    /// Per kind, in the report's order of observers.
    pub kinds: Vec<KindScore>,
    /// The constant estimate's score (each target's mean over the tuning runs); `null` if unmeasured.
    pub constant: Option<f64>,
}

/// One regime of the tuning set.
#[derive(Serialize)]
pub struct RegimeReport {
    /// `random starts`, `from <scenario>` or `start-up`.
    pub name: String,
    /// Its runs.
    pub runs: usize,
    /// Its samples of each run from the first estimate; `null`: to the run's end.
    pub samples: Option<usize>,
}

/// One kind's score on the tuning runs.
#[derive(Serialize)]
pub struct KindScore {
    /// The kind.
    pub kind: &'static str,
    /// Each regime's score (`null` where it is not finite).
    pub terms: Vec<Option<f64>>,
    /// Per regime, per target in the spec's order: the pooled RMSE and the p95 over its runs.
    pub figures: Vec<Vec<(Option<f64>, Option<f64>)>>,
    /// Their mean: the tuning score.
    pub score: Option<f64>,
    /// Tuning runs lost (counted before the score).
    pub lost: usize,
}

/// The table's data from the comparison.
pub fn assemble(comparison: &Comparison) -> TuningScore {
    let scoring = &comparison.scoring;
    let finite = |v: f64| v.is_finite().then_some(v);
    TuningScore {
        constant: finite(scoring.constant),
        spreads: scoring.spreads.clone(),
        weights: scoring.weights.clone(),
        regimes: (scoring.regimes.parts.iter())
            .map(|r| RegimeReport {
                name: r.name.clone(),
                runs: r.runs.len(),
                samples: match r.span {
                    Span::Whole => None,
                    Span::First(samples) => Some(samples),
                },
            })
            .collect(),
        start_up_by: match scoring.start_up_by {
            StartUpBy::Spec => "as `tuning.start_up` sets it".to_owned(),
            StartUpBy::Settled(kind, samples) => format!(
                "{}: `{kind}`, the slowest box filter, settles in {samples} samples on the random starts (the error of {:.0} % of the runs within {SETTLED_WITHIN}× its steady level to the run's end)",
                if let Some(n) = comparison.scoring.regimes.start_up().filter(|&n| n > samples) { format!("at least one horizon N = {n}") } else { "as long as a box filter takes to settle".to_owned() },
                OVER_RUNS * 100.0
            ),
            StartUpBy::Horizons => format!(
                "{} horizons N: no box filter to settle",
                crate::observers::kind::corrected::run::START_UP_HORIZONS
            ),
        },
        kinds: (comparison.observers.iter())
            .filter(|o| !o.tuning_terms.is_empty())
            .map(|o| KindScore {
                kind: o.kind,
                terms: o.tuning_terms.iter().map(|t| finite(scoring.term_value(t))).collect(),
                figures: (o.tuning_terms.iter())
                    .map(|t| t.targets.iter().map(|&(r, p)| (finite(r), finite(p))).collect())
                    .collect(),
                score: finite(scoring.value(&o.tuning_terms)),
                lost: o.lost.tuning.map_or(0, |l| l.lost),
            })
            .collect(),
    }
}

/// `report.md`'s table: a row per kind, a column per regime, then the score and the lost runs; and
/// which kind wins each regime (the lowest score there among the kinds that lost the fewest tuning
/// runs among those that beat the constant estimate), or the one kind within [`WINS_WITHIN`] of the best in every regime.
/// `tau` and `time_unit`: the design's sample period and its unit, to state the start-up's length.
pub fn table(score: &TuningScore, tau: f64, time_unit: &str) -> String {
    if score.kinds.is_empty() {
        return String::new();
    }
    let what: Vec<String> = (score.regimes.iter())
        .map(|r| match r.samples {
            None => format!("{} ({} runs, every sample from the first estimate)", r.name, r.runs),
            Some(k) => format!(
                "{} ({} runs, the first {k} samples = {} {} from the first estimate{})",
                r.name,
                r.runs,
                crate::output::number(k as f64 * tau),
                time_unit,
                if r.name == START_UP {
                    format!(", {}", score.start_up_by)
                } else {
                    String::new()
                }
            ),
        })
        .collect();
    let mut s = format!(
        "\nThe tuning score, term by term: per regime of the tuning runs, Σ weight · (pooled RMSE + p95 over runs) / spread over the targets, / Σ weight; the score is the mean over the regimes, lost tuning runs counted first among the kinds that beat the constant estimate{}. Regimes: {}.\n\n| observer | {} | score | lost tuning |\n|---|{}---|---|\n",
        score.constant.map_or(String::new(), |c| format!(" (each target's mean over the tuning runs, which scores {c:.4})")),
        what.join("; "),
        (score.regimes.iter().map(|r| r.name.as_str())).collect::<Vec<_>>().join(" | "),
        "---|".repeat(score.regimes.len()),
    );
    let show = |v: Option<f64>| v.map_or("diverged".to_owned(), |v| format!("{v:.4}"));
    for k in &score.kinds {
        let terms: Vec<String> = k.terms.iter().map(|&t| show(t)).collect();
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} |",
            k.kind,
            terms.join(" | "),
            show(k.score),
            k.lost
        );
    }
    s.push_str(&winners(score));
    s
}

/// Which kind wins which regime, or the one that is within [`WINS_WITHIN`] of the best in all.
fn winners(score: &TuningScore) -> String {
    // As `auto` chooses: among the kinds that beat the constant estimate (all, when none does).
    let beats = |k: &&KindScore| k.score.is_some_and(|v| score.constant.is_none_or(|c| v < c));
    let informative: Vec<&KindScore> = score.kinds.iter().filter(beats).collect();
    let candidates = if informative.is_empty() {
        score.kinds.iter().collect()
    } else {
        informative
    };
    let fewest = candidates.iter().map(|k| k.lost).min().unwrap_or(0);
    let kinds: Vec<&KindScore> = candidates.into_iter().filter(|k| k.lost == fewest).collect();
    let term = |k: &KindScore, r: usize| k.terms[r].unwrap_or(f64::INFINITY);
    let best: Vec<f64> = (0..score.regimes.len())
        .map(|r| kinds.iter().map(|k| term(k, r)).fold(f64::INFINITY, f64::min))
        .collect();
    let everywhere: Vec<&str> = (kinds.iter())
        .filter(|k| (0..best.len()).all(|r| term(k, r) <= best[r] * (1.0 + WINS_WITHIN)))
        .map(|k| k.kind)
        .collect();
    if !everywhere.is_empty() {
        return format!(
            "\nWithin {:.0} % of the best in every regime: `{}`.\n",
            WINS_WITHIN * 100.0,
            everywhere.join("`, `")
        );
    }
    let each: Vec<String> = (score.regimes.iter().zip(&best).enumerate())
        .map(|(r, (regime, &b))| {
            let winner = kinds.iter().find(|k| term(k, r) == b).map_or("none", |k| k.kind);
            format!("{}: `{winner}`", regime.name)
        })
        .collect();
    format!(
        "\nNo kind is within {:.0} % of the best in every regime; the best of each: {}.\n",
        WINS_WITHIN * 100.0,
        each.join(", ")
    )
}
