//! What a target's map gives back: the value and whether it was clamped. A module of its own so that
//! the inverse table ([`crate::inverse`]) that produces it and the map ([`crate::map`]) that returns it
//! do not import each other.

/// An estimate of one target.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Estimate<T> {
    /// The estimated value, in the target's units.
    pub value: T,
    /// Whether the estimate was clamped to an end of the learning range.
    pub saturation: Saturation,
}

/// Which end of the learning range, if any, an estimate was clamped to. The table coordinate `t` is
/// `0` at `Lᵀ Z = Γ(0)` and `t_max` at `Lᵀ Z = Γ(1)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Saturation {
    /// `0 ≤ t ≤ t_max` (`Γ(0) ≤ Lᵀ Z ≤ Γ(1)`): the estimate is inside the learning range.
    Inside,
    /// `t < 0` (or `t` is NaN): the estimate is clamped to `r_min`.
    Low,
    /// `t > t_max`: the estimate is clamped to `r_max`.
    High,
}

impl Saturation {
    /// `true` when the estimate was clamped to an end of the learning range.
    #[must_use]
    pub fn is_saturated(self) -> bool {
        self != Saturation::Inside
    }
}
