//! Whether the particle filter is a floor for a design, and the words the report says of it.

use super::super::schema::{BeatenReport, FloorReport};
use super::mean_ratio;

/// An observer beats the particle filter on a target when its validation RMSE there is below
/// `1 − BEATEN_BEYOND` times the filter's: beyond the filter's Monte Carlo error (its doubling check
/// allows 5 %), the filter is then not the best estimate, so no floor.
pub const BEATEN_BEYOND: f64 = 0.05;

/// Whether a particle filter is a floor: `converged` by doubling, and no observer (kind, validation
/// RMSE per target) below `1 −` [`BEATEN_BEYOND`] times its validation RMSE `floor` on any target
/// (`targets`: their names, in the same order).
pub fn floor_verdict(
    converged: bool,
    targets: &[String],
    floor: &[f64],
    observers: &[(&'static str, Vec<f64>)],
) -> FloorReport {
    let beaten_by: Vec<BeatenReport> = observers
        .iter()
        .flat_map(|(kind, rmse)| {
            (targets.iter().zip(floor).zip(rmse))
                .filter(|&((_, &floor), &rmse)| rmse < (1.0 - BEATEN_BEYOND) * floor)
                .map(|((target, &floor), &rmse)| BeatenReport {
                    kind,
                    target: target.clone(),
                    rmse_validation: rmse,
                    floor_rmse_validation: floor,
                })
        })
        .collect();
    FloorReport {
        converged,
        is_floor: converged && beaten_by.is_empty() && floor.iter().all(|v| v.is_finite()),
        beaten_by,
    }
}

/// Why a particle filter is not a floor, in a clause; with each observer's RMSE against the filter's
/// when `figures`.
pub(super) fn no_floor_reason(floor: &FloorReport, figures: bool) -> String {
    let mut reasons = Vec::new();
    if !floor.converged {
        reasons.push(format!(
            "the particle filter did not converge (at {} particles, the most the host runs, doubling still moved a target's validation RMSE by more than {:.0} %)",
            crate::observers::references::MAX_PARTICLES,
            100.0 * crate::observers::references::CONVERGED_WITHIN
        ));
    }
    let mut kinds: Vec<&str> = floor.beaten_by.iter().map(|b| b.kind).collect();
    kinds.dedup();
    if !kinds.is_empty() {
        let by: Vec<String> = kinds
            .iter()
            .map(|kind| {
                let on: Vec<String> = (floor.beaten_by.iter().filter(|b| b.kind == *kind))
                    .map(|b| {
                        if figures {
                            format!(
                                "{} {:.4} against {:.4}",
                                b.target, b.rmse_validation, b.floor_rmse_validation
                            )
                        } else {
                            b.target.clone()
                        }
                    })
                    .collect();
                format!("`{kind}` ({})", on.join(", "))
            })
            .collect();
        reasons.push(format!(
            "observers beat the particle filter by more than {:.0} % on validation RMSE: {}",
            100.0 * BEATEN_BEYOND,
            by.join(", ")
        ));
    }
    if reasons.is_empty() {
        reasons.push("a target's validation RMSE is not finite".to_owned());
    }
    reasons.join("; and ")
}

/// The sentence on the observers (kind, validation RMSE per target) against the particle filter's
/// validation RMSE `floor`: the best one's ratio when `verdict` says it is a floor, else why there is
/// none, and no ratio.
pub(super) fn against_floor(verdict: &FloorReport, floor: &[f64], observers: &[(&str, Vec<f64>)]) -> String {
    if !verdict.is_floor {
        return format!(
            "\nNo floor for this design: {}; no observer is placed against the particle filter.\n",
            no_floor_reason(verdict, false)
        );
    }
    let best = (observers.iter())
        .map(|(kind, rmse)| (kind, mean_ratio(rmse, floor)))
        .filter(|(_, r)| r.is_finite())
        .min_by(|a, b| a.1.total_cmp(&b.1));
    best.map_or(String::new(), |(kind, ratio)| {
        format!(
            "\nBest embeddable observer on the validation runs: `{kind}`, {ratio:.2}× the floor's RMSE (mean over targets).\n"
        )
    })
}
