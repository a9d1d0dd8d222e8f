//! One target's map `r = Γ⁻¹(Lᵀ Z)` as the chip evaluates it: a projection onto the table
//! coordinate `t`, then the tabulated inverse ([`InverseTable`]).

use crate::estimate::Estimate;
#[cfg(test)]
use crate::estimate::Saturation;
use crate::{InverseTable, Scalar};

/// The map for one target: `t = offset + Σ_i gains_i z_i`, `r = table(t)`.
///
/// The gains are the fitted `L` scaled by `K / (Γ(1) - Γ(0))` and the offset holds `-Γ(0)` at the same
/// scale, so that `t ∈ [0, K]` exactly when `Lᵀ Z ∈ [Γ(0), Γ(1)]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TargetMap<'a, T> {
    /// One gain per regressor entry, in regressor order (newest sample first).
    pub gains: &'a [T],
    /// The constant the projection starts from.
    pub offset: T,
    /// `Γ⁻¹` in the coordinate `t`, in the target's units.
    pub inverse: InverseTable<'a, T>,
}

impl<T: Scalar> TargetMap<'_, T> {
    /// `t = offset + Σ_i gains_i z_i`, summed in that order, skipping pruned taps (gain exactly 0, as
    /// the generated code does). Entries beyond the shorter of `gains` and `regressor` are ignored.
    #[must_use]
    pub fn project(&self, regressor: &[T]) -> T {
        let mut sum = self.offset;
        for (&g, &z) in self.gains.iter().zip(regressor) {
            if g != T::ZERO {
                sum += g * z;
            }
        }
        sum
    }

    /// `F(Z)`: the tabulated inverse of the projection.
    #[must_use]
    pub fn estimate(&self, regressor: &[T]) -> Estimate<T> {
        self.inverse.evaluate(self.project(regressor))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Knots;

    #[test]
    fn a_linear_map_is_exact_with_one_segment() {
        // v = z0 - 0.5 z1 on Γ(η) = 2 + 4η (so Γ⁻¹ is linear: one segment), r = -1 + 3η.
        // t = (v - 2)/4, r = -1 + 3t.
        let gains = [0.25f64, -0.125];
        let map = TargetMap {
            gains: &gains,
            offset: -0.5,
            inverse: InverseTable {
                knots: Knots::Uniform,
                segments: &[[-1.0, 3.0]],
                t_max: 1.0,
                r_min: -1.0,
                r_max: 2.0,
            },
        };
        let estimate = map.estimate(&[4.0, 2.0]); // v = 3 ⇒ η = 0.25 ⇒ r = -0.25
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
