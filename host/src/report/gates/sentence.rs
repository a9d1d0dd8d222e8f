//! Each gate as the sentence `gen` prints and the report lists: what failed, by how much, and the
//! spec fields to change.

use std::fmt;

use super::{Gate, DRIFT_RATIO, EKF_FACTOR, LINEAR_FLOOR_SLACK};
use crate::fit::evaluate::WEAK_FRACTION;
use crate::observers::kind;

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
                // The peer in its kind's own words (another filter is not "the EKF").
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
            Gate::Drift {
                kind: name,
                target,
                plant,
                first,
                last,
                chosen,
            } => {
                let what = kind::named(name).map_or("the observer", |k| k.what);
                let who = if *chosen {
                    format!("`observer()`, {what} (`{name}`),")
                } else {
                    format!("{what} (`{name}`)")
                };
                write!(
                    f,
                    "{who} drifts on target `{target}` over the long runs{plant}: RMSE {last:.4} over the last window against \
                     {first:.4} over the first ({:.2} times, more than {DRIFT_RATIO}; the report's drift table){}",
                    last / first,
                    if *chosen {
                        "; choose a kind that does not drift (`[observer] kind`)"
                    } else {
                        ""
                    }
                )
            }
            Gate::LostRuns {
                kind: name,
                set,
                lost,
                floor_lost,
                runs,
                chosen,
                lost_none,
            } => {
                let what = kind::named(name).map_or("the observer", |k| k.what);
                let who = if *chosen {
                    format!("`observer()`, {what} (`{name}`),")
                } else {
                    format!("{what} (`{name}`)")
                };
                let fix = match lost_none.as_deref() {
                    None => String::new(),
                    Some([]) => "; every other kind judged on them lost some of them too (the floor's row in that \
                                 table says how many the best estimate of the model lost)"
                        .to_owned(),
                    Some(kinds) => format!(
                        "; of the other kinds, {} lost none of them (`[observer] kind`)",
                        kinds.iter().map(|k| format!("`{k}`")).collect::<Vec<_>>().join(", ")
                    ),
                };
                let besides = match floor_lost {
                    0 => String::new(),
                    n => format!(" (besides {n} the particle floor lost too, whose data do not determine a target)"),
                };
                write!(
                    f,
                    "{who} lost {lost} of {runs} {set} runs{besides}: at their end its RMSE on some target exceeded {} times the \
                     target's spread (the best constant estimate's), or its estimate was not finite (the report's table of lost runs){}",
                    crate::observers::lost::LOST_FRACTION,
                    fix
                )
            }
            Gate::CoarseChipModel {
                substeps,
                state,
                error,
                fewest,
            } => write!(
                f,
                "`sampling.chip_substeps` = {substeps}: {}: every observer that carries the model (the filters, the map-started \
                 and corrected kinds, the MHE) carries that error as the plant's and may lose track; {}",
                if error.is_finite() {
                    format!(
                        "after one period from the learning runs' states, the chip's model is {:.1} % of `{state}`'s range away \
                         from the simulated plant (more than {:.0} %)",
                        error * 100.0,
                        crate::plant::discretisation::TOLERANCE * 100.0
                    )
                } else {
                    format!(
                        "after one period from some learning run's state, the chip's model is not finite in `{state}` where the \
                         simulated plant is (its RK4 stages leave the model's domain, a `sqrt` of a negative value say)"
                    )
                },
                match fewest {
                    Some(n) => format!("set `sampling.chip_substeps = {n}`, the fewest within it"),
                    None => "raise `sampling.substeps` and `sampling.chip_substeps`, or sample faster (`sampling.tau`)".to_owned(),
                }
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
