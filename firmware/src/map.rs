//! One fitted map `r = Γ⁻¹(Lᵀ Z)`, rescaled from `η` to the target's units.

use crate::{Gamma, Saturation, Scalar};

/// The map for one target: `r = r_min + r_span · Γ⁻¹(Lᵀ Z)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TargetMap<'a, T> {
    /// `L`, one gain per regressor entry, in regressor order (newest sample first).
    pub gains: &'a [T],
    /// The monotone map `Γ`.
    pub gamma: Gamma<'a, T>,
    /// Smallest target value on the learning data.
    pub r_min: T,
    /// `r_max - r_min` over the learning data (positive).
    pub r_span: T,
}

/// An estimate of one target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate<T> {
    /// The estimated value, in the target's units.
    pub value: T,
    /// Whether `Γ⁻¹` clamped the estimate to an end of the learning range.
    pub saturation: Saturation,
}

impl<T: Scalar> TargetMap<'_, T> {
    /// `v = Lᵀ Z`. Entries beyond the shorter of `gains` and `regressor` are ignored.
    pub fn project(&self, regressor: &[T]) -> T {
        let mut sum = T::zero();
        for (&g, &z) in self.gains.iter().zip(regressor) {
            sum += g * z;
        }
        sum
    }

    /// `r = r_min + r_span · Γ⁻¹(v)` for a projection `v` already computed.
    pub fn estimate_from_projection(&self, v: T) -> Estimate<T> {
        let inverse = self.gamma.inverse(v);
        Estimate {
            value: self.r_min + self.r_span * inverse.eta,
            saturation: inverse.saturation,
        }
    }

    /// `F(Z) = r_min + r_span · Γ⁻¹(Lᵀ Z)`.
    pub fn estimate(&self, regressor: &[T]) -> Estimate<T> {
        self.estimate_from_projection(self.project(regressor))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_gamma_gives_a_rescaled_linear_map() {
        // Γ(η) = 2 + 4η  ⇒  η = (Lᵀ Z - 2) / 4, r = -1 + 3 η.
        let gains = [1.0f64, -0.5];
        let (w, c) = ([4.0], [1.0]);
        let map = TargetMap {
            gains: &gains,
            gamma: Gamma {
                offset: 2.0,
                weights: &w,
                odds_ratios: &c,
            },
            r_min: -1.0,
            r_span: 3.0,
        };
        let z = [4.0, 2.0]; // v = 3 ⇒ η = 0.25 ⇒ r = -0.25
        let estimate = map.estimate(&z);
        assert!((estimate.value + 0.25).abs() < 1e-14);
        assert_eq!(estimate.saturation, Saturation::Inside);
        assert_eq!(
            map.estimate(&[100.0, 0.0]),
            Estimate {
                value: 2.0,
                saturation: Saturation::High
            }
        );
    }
}
