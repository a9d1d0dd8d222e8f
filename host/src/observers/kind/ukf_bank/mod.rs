//! `ukf_bank` (the kind's host half; its chip code, its C and its entry in [`super::REGISTRY`] come
//! next): a bank of box UKFs ([`firmware::bank`]), each started in its own slice of one state's
//! range in the box and weighed by the likelihood of its innovations; its estimate is their weighted
//! mean. It runs on the box UKF's tuned `Q`, `R` and watch; its layout (the axis, the members, their
//! spacing and `P(0)` on the axis) is chosen on the same tuning runs by the same score
//! ([`tuning::choose`]), and a design is to have it only where it beats the box UKF there
//! ([`tuning::beats`]): it costs `M` UKFs ([`of_bank`]).
//!
//! Why: on E. coli from `X₀ = 0.5` the UKF from the box centre loses validation runs that start with
//! little substrate (their light readings are explained as well by more substrate and less product).
//! A bank keeps every branch alive until the data decide (measured in the note of issue 50, part 11).

pub mod run;
pub mod tuning;

use crate::plant::kalman::{EkfConstants, FilterCode};

/// Instructions per sample of a bank of `members` over the member program `member` with the box
/// UKF's `constants` (its watch): per member its UKF sample and watch, its evidence (one `ln`), its
/// weight (one `exp`) and its share of the mean (a multiply-add per state); then the mean's one
/// division and scaling. A prediction, to be measured on the chip with the kind's code.
pub fn of_bank(member: &FilterCode, constants: &EkfConstants, members: usize) -> f64 {
    use crate::search::cost;
    let filter = cost::of_ekf(member) + cost::of_watch(&constants.watch);
    let mixing = cost::call("ln") + cost::call("exp") + 2.0 * member.states as f64 + 8.0;
    members as f64 * (filter + mixing) + 2.0 * member.states as f64 + 14.0
}
