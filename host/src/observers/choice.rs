//! Which kind `observer()` is: the spec's, checked before the fit and after it, or for `auto` the
//! best on the tuning runs within the budget. Kept apart from the comparison that yields the
//! figures it reads ([`super::compare`]).

use crate::plant::ModelCode;
use crate::spec::{Design, ObserverKind, SpecError};

use super::score::{self, CHEAPER_WITHIN};
use super::{corrected, ekf, kind, ObserverFigures};

/// A kind's [score](score::score) on the tuning runs.
fn tuning_score(figures: &ObserverFigures, spreads: &[f64]) -> f64 {
    let pooled: Vec<f64> = figures.targets.iter().map(|f| f.rmse_tuning).collect();
    let p95: Vec<f64> = figures.targets.iter().map(|f| f.p95_tuning).collect();
    score::score(&pooled, &p95, spreads)
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
    if (entry.needs.state_targets && corrected::state_targets(design).is_err())
        || (entry.needs.filter && !ekf::supported(code))
    {
        return Err(cannot_have(design));
    }
    let (Some(budget), Some(cost)) = (design.budget.instructions, entry.cost_before_fit) else {
        return Ok(());
    };
    let states = code.dimensions.states;
    let theta = vec![0.37f64.log10(); 2 * states];
    let mut constants = ekf::constants(design, &ekf::box_centre(design), &vec![1.0; states], &theta);
    // A full `Q` the spec fixes adds its off-diagonal entries to every prediction.
    let fixed = match design.observer {
        ObserverKind::UkfBox => &design.filters.ukf,
        _ => &design.filters.ekf,
    };
    if let Some(q) = &fixed.q {
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
    let (needs, fix) = if kind::of(design.observer).needs.state_targets {
        (
            "every state as a target and a model the host can filter",
            "add a target per state (expr = the state's name), or set kind = \"map\" or \"auto\"",
        )
    } else {
        ("a model the host can filter", "set kind = \"map\" or \"auto\"")
    };
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

/// The kind `observer()` is: the spec's, or for `auto` the lowest [score](score::score) on the
/// tuning runs among the kinds within `[budget] instructions` (as [`cost`](crate::search::cost) predicts them;
/// the moving-horizon estimate only when that budget is set), except
/// that the cheapest kind (fewest predicted instructions) within [`CHEAPER_WITHIN`] of the best is
/// preferred. Errors when the spec asks for a kind the design cannot have or the budget
/// does not allow.
pub fn choose(
    design: &Design,
    observers: &[ObserverFigures],
    spreads: &[f64],
) -> Result<(ObserverKind, String), SpecError> {
    let scored: Vec<(ObserverKind, &str, f64, f64)> = kind::REGISTRY
        .iter()
        .map(|k| (k.kind, k.kind.name()))
        .filter_map(|(kind, name)| {
            observers
                .iter()
                .find(|o| o.kind == name)
                .map(|o| (kind, name, tuning_score(o, spreads), o.instructions))
        })
        .collect();
    let budget = design.budget.instructions.map(|b| b as f64);
    let within = |instructions: f64| budget.is_none_or(|b| instructions <= b);
    if design.observer != ObserverKind::Auto {
        return match scored.iter().find(|s| s.0 == design.observer) {
            Some(&(_, name, _, instructions)) if !within(instructions) => {
                Err(over_budget(design, name, instructions, budget.unwrap_or_default()))
            }
            Some(&(kind, name, score, instructions)) => Ok((
                kind,
                format!("`{name}` as the spec asks (tuning score {score:.4}, ~{instructions:.0} instructions)"),
            )),
            None => Err(cannot_have(design)),
        };
    }
    // The on-line estimate is what the map exists to avoid: `auto` takes it only when the spec sets a
    // budget that allows it.
    let offered =
        |kind: ObserverKind, instructions: f64| within(instructions) && (kind != ObserverKind::Mhe || budget.is_some());
    let allowed: Vec<&(ObserverKind, &str, f64, f64)> = scored.iter().filter(|s| offered(s.0, s.3)).collect();
    let best = allowed.iter().map(|s| s.2).fold(f64::INFINITY, f64::min);
    let Some(&&(kind, name, _, _)) = allowed
        .iter()
        .filter(|s| s.2 <= best * (1.0 + CHEAPER_WITHIN))
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
        .map(|&(k, n, s, i)| {
            let over = if !within(i) {
                ", over budget"
            } else if !offered(k, i) {
                ", not offered without `budget.instructions`"
            } else {
                ""
            };
            format!("{n} {s:.4} at ~{i:.0} instructions{over}")
        })
        .collect();
    let limit = budget.map_or(String::new(), |b| format!(" within `budget.instructions` = {b}"));
    Ok((kind, format!("`{name}` by `auto`: the lowest tuning score (pooled RMSE + p95 over runs, per target over its spread; {}){limit}, a cheaper kind preferred within {:.0} %", all.join(", "), CHEAPER_WITHIN * 100.0)))
}
