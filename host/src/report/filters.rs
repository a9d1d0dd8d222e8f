//! Whether each other filter from the centre of the state box is worth its cost over the EKF, per
//! design: the filters start there and are tuned alike (the same search, score and tuning runs), so
//! the difference is the filter's. "Better" is on the validation runs, in the pooled RMSE and in the
//! tail (p95 over runs), each the mean over targets of the filter's figure over the EKF's; the cost
//! is the predicted instructions per sample (measured in docs/chip.md). The filters are the kinds
//! whose constants are one filter's ([`crate::observers::kind::Kind::filter_code`]).

use super::schema::{ObserverReport, Report};
use crate::observers::kind::{self, Kind, REGISTRY};
use crate::observers::CHEAPER_WITHIN;
use crate::spec::ObserverKind;

/// One paragraph per filter besides the EKF; empty when the design lacks the EKF or the filter.
pub fn against_ekf(report: &Report<'_>) -> String {
    let ekf = kind::of(ObserverKind::EkfBox);
    REGISTRY
        .iter()
        .filter(|entry| entry.filter_code.is_some() && entry.kind != ekf.kind)
        .map(|filter| one_against(report, filter, ekf))
        .collect()
}

/// The paragraph of `filter` against `peer` (the EKF).
fn one_against(report: &Report<'_>, filter: &Kind, peer: &Kind) -> String {
    let find = |kind: &str| report.observers.iter().find(|o| o.kind == kind);
    let (Some(a), Some(b)) = (find(filter.kind.name()), find(peer.kind.name())) else {
        return String::new();
    };
    let (name, peer_name) = (filter.short, peer.short);
    let (Some(pooled), Some(tail)) = (ratio(a, b, |f| f.rmse_validation), ratio(a, b, |f| f.p95_validation)) else {
        // Which one diverged decides which one is the choice.
        let finite = |o: &ObserverReport| {
            o.targets
                .values()
                .all(|f| f.rmse_validation.is_some_and(f64::is_finite))
        };
        let choice = match (finite(a), finite(b)) {
            (true, false) => {
                format!("the {peer_name} gave no finite validation figure (it diverged): the {name} is the choice")
            }
            (false, true) => {
                format!("the {name} gave no finite validation figure (it diverged): the {peer_name} is the choice")
            }
            _ => "neither gave a finite validation figure on every target (both diverged somewhere)".to_owned(),
        };
        return format!("\n{name} against {peer_name}: {choice}.\n");
    };
    let cost = a.predicted_instructions / b.predicted_instructions;
    let verdict = verdict(peer_name, pooled, tail, cost);
    format!(
        "\n{name} against {peer_name} ({}): the {name}'s validation RMSE is {pooled:.2}× the {peer_name}'s and its p95 {tail:.2}× (mean over targets), \
         for ~{:.0} instructions per sample against ~{:.0} ({cost:.1}×, predicted): {verdict}.\n",
        how_started(report, filter, peer),
        a.predicted_instructions,
        b.predicted_instructions
    )
}

/// How the two filters start and what of them is tuned, in the words of the spec's
/// `[observer.<filter>]` sections (`report.fixed_filters`): "both from the box centre, tuned alike"
/// only when the spec fixes nothing of either.
fn how_started(report: &Report<'_>, filter: &Kind, peer: &Kind) -> String {
    let fixed = |kind: &str| -> &[&'static str] {
        report
            .fixed_filters
            .iter()
            .find(|f| f.kind == kind)
            .map_or(&[], |f| f.fixed.as_slice())
    };
    starts(
        (peer.short, fixed(peer.kind.name())),
        (filter.short, fixed(filter.kind.name())),
    )
}

/// [`how_started`] from each filter's short name and the constants the spec fixes of it (`"x0"`,
/// `"q"`, `"p0"`), the peer's first.
fn starts((peer, peer_fixed): (&str, &[&str]), (filter, fixed): (&str, &[&str])) -> String {
    if peer_fixed.is_empty() && fixed.is_empty() {
        return "both from the box centre, tuned alike".to_owned();
    }
    let one = |name: &str, fixed: &[&str]| {
        let start = if fixed.contains(&"x0") {
            "from the spec's x̂(0)"
        } else {
            "from the box centre"
        };
        let constants: Vec<&str> = fixed
            .iter()
            .filter_map(|c| match *c {
                "q" => Some("Q"),
                "p0" => Some("P(0)"),
                _ => None,
            })
            .collect();
        let tuned = match constants.len() {
            0 => "tuned".to_owned(),
            2 => "with the spec's Q and P(0)".to_owned(),
            _ => format!("with the spec's {}, the rest tuned", constants[0]),
        };
        format!("the {name} {start}, {tuned}")
    };
    format!(
        "{}; {}; the same search, score and runs for what is tuned",
        one(peer, peer_fixed),
        one(filter, fixed)
    )
}

/// The verdict from a filter's pooled and tail figures over its peer's (`peer`: the EKF) and its cost
/// over the peer's: worth it when both figures are lower by more than `auto`'s margin
/// ([`CHEAPER_WITHIN`]).
fn verdict(peer: &str, pooled: f64, tail: f64, cost: f64) -> String {
    let (better, worse) = (1.0 - CHEAPER_WITHIN, 1.0 + CHEAPER_WITHIN);
    let word = |ratio: f64| {
        if ratio < better {
            "better"
        } else if ratio > worse {
            "worse"
        } else {
            "as good"
        }
    };
    match (word(pooled), word(tail)) {
        ("better", "better") => {
            format!("worth its cost where {cost:.1}× the {peer}'s instructions fit: better in the pool and in the tail")
        }
        ("worse", "worse") => format!("not worth it: the {peer} is better in the pool and in the tail, for fewer instructions"),
        (pool, tail) => format!(
            "not clearly worth {cost:.1}× the {peer}'s instructions: {pool} in the pool, {tail} in the tail (within {:.0} % is as good)",
            100.0 * CHEAPER_WITHIN
        ),
    }
}

/// The mean over targets of `figure(a) / figure(b)`; `None` when a figure is missing (a filter
/// diverged).
fn ratio(
    a: &ObserverReport,
    b: &ObserverReport,
    figure: impl Fn(&super::schema::FiguresReport) -> Option<f64>,
) -> Option<f64> {
    let ratios: Option<Vec<f64>> = a
        .targets
        .iter()
        .map(|(name, f)| Some(figure(f)? / figure(b.targets.get(name)?)?))
        .collect();
    let ratios = ratios?;
    Some(ratios.iter().sum::<f64>() / ratios.len() as f64)
}

#[cfg(test)]
mod tests {
    use super::{starts, verdict};

    #[test]
    fn the_filters_starts_are_the_specs_words() {
        let none: &[&str] = &[];
        assert_eq!(
            starts(("EKF", none), ("PF", none)),
            "both from the box centre, tuned alike"
        );
        // A filter with fixed constants is not "from the box centre, tuned alike".
        assert_eq!(
            starts(("EKF", none), ("PF", &["x0", "p0"])),
            "the EKF from the box centre, tuned; the PF from the spec's x̂(0), with the spec's P(0), the rest tuned; \
             the same search, score and runs for what is tuned"
        );
        assert!(starts(("EKF", &["q", "p0"]), ("PF", none))
            .starts_with("the EKF from the box centre, with the spec's Q and P(0);"));
    }

    #[test]
    fn worth_it_only_when_better_in_the_pool_and_the_tail_beyond_autos_margin() {
        assert!(verdict("EKF", 0.83, 0.75, 2.1).starts_with("worth its cost where 2.1× the EKF's"));
        // Better in the pool, not in the tail; or within the 2 % margin: not clearly.
        assert_eq!(
            verdict("EKF", 0.83, 1.01, 2.1),
            "not clearly worth 2.1× the EKF's instructions: better in the pool, as good in the tail (within 2 % is as good)"
        );
        assert!(verdict("EKF", 0.985, 0.9, 2.1).contains("as good in the pool, better in the tail"));
        assert!(verdict("EKF", 1.03, 0.7, 3.0).contains("worse in the pool, better in the tail"));
        assert!(verdict("EKF", 1.1, 1.05, 2.1).starts_with("not worth it: the EKF is better"));
    }
}
