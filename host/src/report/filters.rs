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
        return "\nUKF against EKF: one of the two gave no finite validation figure (it diverged): the EKF is the choice.\n"
            .to_owned();
    };
    let cost = ukf.predicted_instructions / ekf.predicted_instructions;
    let verdict = verdict(pooled, tail, cost);
    format!(
        "\nUKF against EKF (both from the box centre, tuned alike): the UKF's validation RMSE is {pooled:.2}× the EKF's and its p95 {tail:.2}× (mean over targets), \
         for ~{:.0} instructions per sample against ~{:.0} ({cost:.1}×, predicted): {verdict}.\n",
        ukf.predicted_instructions, ekf.predicted_instructions
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
    use super::verdict;

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
