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
//!   [`WEAK_FRACTION`] of the target's spread: it barely beats
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
//! * [`Gate::StartOutsideBox`]: a filter's start the spec fixes (`[observer.ekf] x0`,
//!   `[observer.ukf] x0`) or a scenario's `observer_x0` lies outside the learning box: the filter
//!   starts where no learning or validation run starts, which is allowed (a published filter's guess
//!   may be poor on purpose) but is rarely what a user means.

use std::fmt;

use crate::fit::evaluate::WEAK_FRACTION;
use crate::fit::DesignResult;
use crate::observers::{kind, Comparison};
use crate::spec::Design;

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

impl fmt::Display for Gate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Gate::BelowLinearFloor {
                target,
                ratio,
                paper_normalisation,
            } => write!(
                f,
                "target `{target}`: the map's validation RMSE is {ratio:.3} times the linear floor's (more than {:.0} % worse): \
                 the map does not generalise from the learning runs; {}try another `map.beta` or `map.nm`, or learning runs \
                 that cover the validation box (`learning.grid`, `learning.samples`)",
                LINEAR_FLOOR_SLACK * 100.0,
                if *paper_normalisation { "set `map.normalisation = \"intercept\"`, or " } else { "" }
            ),
            Gate::OutsideLearningRange { target, fraction, range, seen } => write!(
                f,
                "target `{target}`: {:.1} % of the validation windows have a true value outside the learning range [{:.4}, {:.4}] \
                 (validation saw [{:.4}, {:.4}]): the validation runs go where no learning run went, and the map can only \
                 saturate there; widen the learning grid (`learning.grid`, more points or a wider box) or lengthen the learning runs \
                 (`learning.samples`) so that they cover it",
                fraction * 100.0,
                range.0,
                range.1,
                seen.0,
                seen.1
            ),
            Gate::Weak { target, fraction, horizon } => write!(
                f,
                "target `{target}`: validation RMSE is {:.0} % of the target's spread: the map barely beats predicting the mean \
                 (at least {:.0} %); the target may not be observable from these measurements over N = {horizon} samples: \
                 measure another output, or lengthen `map.horizon`",
                fraction * 100.0,
                WEAK_FRACTION * 100.0
            ),
            Gate::EkfBetter { target, chosen, rmse, ekf, ekf_rmse } => {
                // The peer in its kind's own words (the UKF is not "the EKF").
                let what = kind::REGISTRY
                    .iter()
                    .find(|k| k.kind.name() == *ekf)
                    .map_or("another filter", |k| k.what);
                write!(
                    f,
                    "target `{target}`: the chosen observer (`{chosen}`) has validation RMSE {rmse:.4}, more than {EKF_FACTOR} times \
                     that of {what} (`{ekf}`: {ekf_rmse:.4}): `{ekf}` is the better choice for this system (`[observer] kind = \"{ekf}\"`)"
                )
            }
            Gate::RawRangeShort { signal, covered, seen, fraction } => write!(
                f,
                "`chip.raw.{signal}`: the declared raw range stands for [{:.4}, {:.4}], but `{signal}` spans [{:.4}, {:.4}] in the \
                 learning runs ({:.1} % of their samples outside): a converter holds those samples at its range's ends, so \
                 the integer map reads values the signal does not have; declare the converter's real span (`min`, `max`, `scale`, `offset`), or scale \
                 the signal into the converter's input range",
                covered.0,
                covered.1,
                seen.0,
                seen.1,
                fraction * 100.0
            ),
            Gate::StartOutsideBox { field, state, value, range } => write!(
                f,
                "`{field}.{state}` = {value} lies outside the learning box [{}, {}] of `{state}`: the filter starts where no \
                 learning or validation run starts; if that is meant (a published filter's guess), ignore this, else give a \
                 start inside the box or widen `learning.grid.{state}`",
                range.0, range.1
            ),
        }
    }
}

/// The starts the spec gives a filter outside the learning box ([`Gate::StartOutsideBox`]).
pub fn starts_outside_box(design: &Design) -> Vec<Gate> {
    let mut outside = Vec::new();
    // The observers' starts (a scenario's plant start may lie anywhere within the bounds).
    let starts = crate::spec::starts::starts(&design.filters, &design.scenarios);
    for start in starts.iter().filter(|s| !s.plant) {
        for ((state, axis), &value) in design.model.states.iter().zip(&design.learning.axes).zip(start.values) {
            let range = match *axis {
                crate::spec::Axis::Range { min, max, .. } => (min, max),
                crate::spec::Axis::Fixed(held) => (held, held),
            };
            if !(range.0..=range.1).contains(&value) {
                outside.push(Gate::StartOutsideBox {
                    field: start.field.clone(),
                    state: state.clone(),
                    value,
                    range,
                });
            }
        }
    }
    outside
}

/// The signals whose declared raw range (`[chip.raw.<signal>]`) the learning runs leave
/// ([`Gate::RawRangeShort`]).
pub fn raw_ranges_short(design: &Design, learning: &crate::data::DataSet) -> Vec<Gate> {
    let Some(fixed) = &design.fixed else { return Vec::new() };
    let model = &design.model;
    let outputs = fixed
        .outputs
        .iter()
        .enumerate()
        .map(|(i, s)| (model.outputs[i].name.clone(), s, true, i));
    let inputs = fixed
        .inputs
        .iter()
        .enumerate()
        .map(|(i, s)| (model.inputs[i].clone(), s, false, i));
    let mut short = Vec::new();
    for (signal, scale, output, i) in outputs.chain(inputs) {
        let Some(scale) = scale else { continue };
        let ends = (
            scale.offset + scale.scale * f64::from(scale.min),
            scale.offset + scale.scale * f64::from(scale.max),
        );
        let covered = (ends.0.min(ends.1), ends.0.max(ends.1));
        let (mut outside, mut samples) = (0usize, 0usize);
        let mut seen = (f64::INFINITY, f64::NEG_INFINITY);
        for run in &learning.runs {
            let rows = if output { &run.measurements } else { &run.inputs };
            for row in rows {
                let value = row[i];
                seen = (seen.0.min(value), seen.1.max(value));
                outside += usize::from(!(covered.0..=covered.1).contains(&value));
                samples += 1;
            }
        }
        let fraction = outside as f64 / samples.max(1) as f64;
        if fraction > OUTSIDE_FRACTION {
            short.push(Gate::RawRangeShort {
                signal,
                covered,
                seen,
                fraction,
            });
        }
    }
    short
}

/// Every failed gate of a design: the starts outside the box, the raw ranges the learning runs
/// leave, then target by target, gate by gate.
pub fn check(design: &Design, result: &DesignResult, comparison: &Comparison) -> Vec<Gate> {
    let mut failed = starts_outside_box(design);
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
    failed
}

#[cfg(test)]
mod tests {
    use super::Gate;

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
        // The UKF used to be called "the EKF".
        let ukf = gate("ukf_box");
        assert!(
            ukf.contains("that of the unscented Kalman filter from the centre of the state box (`ukf_box`: 0.1000)"),
            "{ukf}"
        );
        assert!(!ukf.contains("EKF"), "{ukf}");
        assert!(gate("ekf_map").contains("`ekf_map` is the better choice"));
    }
}
