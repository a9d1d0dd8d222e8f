//! `Γ⁻¹` on the chip: a piecewise-linear table with knots uniform in `v = Lᵀ Z`.
//!
//! The host tabulates the exact inverse at `K + 1` knots `v_k = Γ(0) + k (Γ(1) - Γ(0)) / K` and folds
//! every affine step into the tables:
//!
//! ```text
//! t = (v - Γ(0)) K / (Γ(1) - Γ(0))          folded into the gains: t = offset + Σ_i g_i z_i
//! r(t) = a_k + b_k t   for t ∈ [k, k + 1]    a_k, b_k in the target's units (r_min + r_span η folded in)
//! ```
//!
//! So one estimate is a dot product, one float-to-int conversion, two loads and one multiply-add:
//! no division, no loop, the same instructions whatever `t` is. The interpolant is continuous and
//! increasing, equal to `Γ⁻¹` at the knots; how far it may be from `Γ⁻¹` in between is proven on the
//! host from bounds of `Γ'` and `Γ''` (see the host's `inverse_table` module) and stated in each
//! generated file.

use crate::{Estimate, Saturation, Scalar};

/// The tabulated inverse of one target, in the table coordinate `t ∈ [0, K]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InverseTable<'a, T> {
    /// `(a_k, b_k)` of the `K` segments: `r = a_k + b_k t` on `[k, k + 1]`.
    pub segments: &'a [[T; 2]],
    /// `K`, the number of segments, as a float: `t > t_max` saturates high.
    pub t_max: T,
    /// The estimate at `t ≤ 0` (and for a NaN `t`): the smallest learning target.
    pub r_min: T,
    /// The estimate at `t ≥ K`: the largest learning target.
    pub r_max: T,
}

impl<T: Scalar> InverseTable<'_, T> {
    /// `r(t)`, clamped to `[r_min, r_max]` outside `[0, K]`, which the result says. A NaN `t` gives
    /// `r_min`, flagged low: the estimate is always finite.
    #[inline(always)]
    pub fn evaluate(&self, t: T) -> Estimate<T> {
        // ⌊t⌋, saturating (NaN and negatives give 0), kept on the last segment for t ≥ K.
        let k = t.index().min(self.segments.len().saturating_sub(1));
        // `get` cannot fail for a non-empty table; an empty one (never emitted) gives r_min.
        let [a, b] = self.segments.get(k).copied().unwrap_or([self.r_min, T::ZERO]);
        let inside = a + b * t;
        let (low, high) = (!(t >= T::ZERO), t > self.t_max);
        // Selects rather than branches: the same instructions whatever t is.
        let edge = select(low, self.r_min, self.r_max);
        let edge_flag = select(low, Saturation::Low, Saturation::High);
        Estimate {
            value: select(low | high, edge, inside),
            saturation: select(low | high, edge_flag, Saturation::Inside),
        }
    }
}

/// `if condition { a } else { b }`, asking for a conditional move rather than a branch.
#[inline(always)]
fn select<V>(condition: bool, a: V, b: V) -> V {
    core::hint::select_unpredictable(condition, a, b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// r = t² on [0, 3] through the knots t = 0, 1, 2, 3: segments (a_k, b_k) of the chords.
    const SQUARE: InverseTable<'static, f64> = InverseTable {
        segments: &[[0.0, 1.0], [-2.0, 3.0], [-6.0, 5.0]],
        t_max: 3.0,
        r_min: 0.0,
        r_max: 9.0,
    };

    #[test]
    fn interpolates_the_chords_and_hits_the_knots() {
        for (t, r) in [
            (0.0, 0.0),
            (1.0, 1.0),
            (2.0, 4.0),
            (3.0, 9.0),
            (0.5, 0.5),
            (1.5, 2.5),
            (2.25, 5.25),
        ] {
            let e = SQUARE.evaluate(t);
            assert_eq!((e.value, e.saturation), (r, Saturation::Inside), "t = {t}");
        }
    }

    #[test]
    fn saturates_visibly_and_never_returns_a_non_finite_value() {
        for (t, r, s) in [
            (-0.5, 0.0, Saturation::Low),
            (f64::NEG_INFINITY, 0.0, Saturation::Low),
            (f64::NAN, 0.0, Saturation::Low),
            (3.5, 9.0, Saturation::High),
            (f64::INFINITY, 9.0, Saturation::High),
            (f64::MAX, 9.0, Saturation::High),
        ] {
            assert_eq!(
                SQUARE.evaluate(t),
                Estimate {
                    value: r,
                    saturation: s
                },
                "t = {t}"
            );
        }
    }

    proptest! {
        #[test]
        fn is_continuous_and_increasing(t in 0.0f64..3.0, dt in 0.0f64..0.5) {
            let (lo, hi) = (SQUARE.evaluate(t).value, SQUARE.evaluate((t + dt).min(3.0)).value);
            prop_assert!(hi >= lo - 1e-12);
            // Within a segment the chord of t² lies above t² by at most 1/4 (h²/8 · max|r''| = 1/4).
            prop_assert!(lo >= t * t - 1e-12 && lo <= t * t + 0.25 + 1e-12);
        }

        #[test]
        fn any_f32_gives_a_finite_estimate_in_range(bits in any::<u32>()) {
            let table = InverseTable::<f32> { segments: &[[0.0, 1.0], [-2.0, 3.0], [-6.0, 5.0]], t_max: 3.0, r_min: 0.0, r_max: 9.0 };
            let e = table.evaluate(f32::from_bits(bits));
            prop_assert!(e.value.is_finite() && (0.0..=9.0).contains(&e.value));
        }
    }
}
