//! Whether the UKF is worth its cost over the EKF, per design: both filters start at the centre of
//! the state box and are tuned alike (the same search, score and tuning runs), so the difference is
//! the filter's. "Better" is on the validation runs, in the pooled RMSE and in the tail (p95 over
//! runs), each the mean over targets of the UKF's figure over the EKF's; the cost is the predicted
//! instructions per sample (measured in docs/chip.md).

use super::schema::{ObserverReport, Report};
use crate::observers::CHEAPER_WITHIN;

/// The paragraph; empty when the design lacks either filter.
pub fn ukf_against_ekf(report: &Report<'_>) -> String {
    let find = |kind: &str| report.observers.iter().find(|o| o.kind == kind);
    let (Some(ukf), Some(ekf)) = (find("ukf_box"), find("ekf_box")) else {
        return String::new();
    };
    let (Some(pooled), Some(tail)) = (
        ratio(ukf, ekf, |f| f.rmse_validation),
        ratio(ukf, ekf, |f| f.p95_validation),
    ) else {
        // Which one diverged decides which one is the choice.
        let finite = |o: &ObserverReport| {
            o.targets
                .values()
                .all(|f| f.rmse_validation.is_some_and(f64::is_finite))
        };
        let choice = match (finite(ukf), finite(ekf)) {
            (true, false) => "the EKF gave no finite validation figure (it diverged): the UKF is the choice",
            (false, true) => "the UKF gave no finite validation figure (it diverged): the EKF is the choice",
            _ => "neither gave a finite validation figure on every target (both diverged somewhere)",
        };
        return format!("\nUKF against EKF: {choice}.\n");
    };
    let cost = ukf.predicted_instructions / ekf.predicted_instructions;
    let verdict = verdict(pooled, tail, cost);
    format!(
        "\nUKF against EKF ({}): the UKF's validation RMSE is {pooled:.2}× the EKF's and its p95 {tail:.2}× (mean over targets), \
         for ~{:.0} instructions per sample against ~{:.0} ({cost:.1}×, predicted): {verdict}.\n",
        how_started(report),
        ukf.predicted_instructions,
        ekf.predicted_instructions
    )
}

/// How the two filters start and what of them is tuned, in the words of the spec's
/// `[observer.ekf]` and `[observer.ukf]` (`report.fixed_filters`): "both from the box centre, tuned
/// alike" only when the spec fixes nothing of either.
fn how_started(report: &Report<'_>) -> String {
    let fixed = |kind: &str| -> &[&'static str] {
        report
            .fixed_filters
            .iter()
            .find(|f| f.kind == kind)
            .map_or(&[], |f| f.fixed.as_slice())
    };
    starts(fixed("ekf_box"), fixed("ukf_box"))
}

/// [`how_started`] from the constants the spec fixes of each filter (`"x0"`, `"q"`, `"p0"`).
fn starts(ekf: &[&str], ukf: &[&str]) -> String {
    if ekf.is_empty() && ukf.is_empty() {
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
        one("EKF", ekf),
        one("UKF", ukf)
    )
}

/// The verdict from the UKF's pooled and tail figures over the EKF's and its cost over the EKF's:
/// worth it when both figures are lower by more than `auto`'s margin ([`CHEAPER_WITHIN`]).
fn verdict(pooled: f64, tail: f64, cost: f64) -> String {
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
            format!("worth its cost where {cost:.1}× the EKF's instructions fit: better in the pool and in the tail")
        }
        ("worse", "worse") => "not worth it: the EKF is better in the pool and in the tail, for fewer instructions".to_owned(),
        (pool, tail) => format!(
            "not clearly worth {cost:.1}× the EKF's instructions: {pool} in the pool, {tail} in the tail (within {:.0} % is as good)",
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
        assert_eq!(starts(&[], &[]), "both from the box centre, tuned alike");
        // A fixed UKF is not "from the box centre, tuned alike".
        assert_eq!(
            starts(&[], &["x0", "p0"]),
            "the EKF from the box centre, tuned; the UKF from the spec's x̂(0), with the spec's P(0), the rest tuned; \
             the same search, score and runs for what is tuned"
        );
        assert!(starts(&["q", "p0"], &[]).starts_with("the EKF from the box centre, with the spec's Q and P(0);"));
    }

    #[test]
    fn worth_it_only_when_better_in_the_pool_and_the_tail_beyond_autos_margin() {
        assert!(verdict(0.83, 0.75, 2.1).starts_with("worth its cost where 2.1×"));
        // Better in the pool, not in the tail; or within the 2 % margin: not clearly.
        assert_eq!(
            verdict(0.83, 1.01, 2.1),
            "not clearly worth 2.1× the EKF's instructions: better in the pool, as good in the tail (within 2 % is as good)"
        );
        assert!(verdict(0.985, 0.9, 2.1).contains("as good in the pool, better in the tail"));
        assert!(verdict(1.03, 0.7, 3.0).contains("worse in the pool, better in the tail"));
        assert!(verdict(1.1, 1.05, 2.1).starts_with("not worth it: the EKF is better"));
    }
}
