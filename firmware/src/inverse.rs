//! `Γ⁻¹` on the chip: a piecewise-linear table, with knots uniform in `v = Lᵀ Z` (the rule) or, for a
//! `Γ` too steep for that, knots placed where the curvature of `Γ⁻¹` needs them (the fallback).
//!
//! # Uniform knots ([`Knots::Uniform`])
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
//!
//! # Searched knots ([`Knots::Searched`])
//!
//! Where `Γ` is almost flat somewhere, `Γ⁻¹` is steep there and uniform knots would be needed by the
//! thousand everywhere. The fallback puts knots `s_0 = 0 < s_1 < … < s_{K-1}` (in `t = (v - Γ(0)) /
//! (Γ(1) - Γ(0))`, so `t_max = 1`) where they are needed and finds the segment by a binary search of
//! fixed length `⌈log₂ K⌉` (selects, no branch on the data): segment `k` is `r = a_k + b_k (t - s_k)`,
//! `a_k` the estimate at its left knot, which keeps the f32 sum free of cancellation.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(t >= 0)` is deliberate: a NaN must count as low.

use crate::estimate::{Estimate, Saturation};
use crate::Scalar;

/// Where the knots of an [`InverseTable`] are, which decides how a segment is found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Knots<'a, T> {
    /// Knot `k` at `t = k`: segment `k` is `r = a_k + b_k t` on `[k, k + 1]`, found as `⌊t⌋`.
    Uniform,
    /// Knot `k` at `starts[k]` (`starts[0] = 0`, increasing, one per segment): segment `k` is
    /// `r = a_k + b_k (t - s_k)` on `[s_k, s_{k+1}]`, found by a binary search of fixed length.
    Searched(&'a [T]),
}

/// The tabulated inverse of one target, in the table coordinate `t ∈ [0, t_max]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InverseTable<'a, T> {
    /// Where the segments start.
    pub knots: Knots<'a, T>,
    /// `(a_k, b_k)` of the `K` segments (see [`Knots`] for the formula).
    pub segments: &'a [[T; 2]],
    /// The end of the last segment (`K` for uniform knots, `1` for searched ones): `t > t_max`
    /// saturates high.
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
    #[must_use]
    pub fn evaluate(&self, t: T) -> Estimate<T> {
        let k = match self.knots {
            // ⌊t⌋, saturating: NaN and negatives give 0.
            Knots::Uniform => t.index(),
            Knots::Searched(starts) => search(starts, t),
        };
        self.evaluate_segment(t, k)
    }

    /// `r(t)` on segment `k` (the last one if `k` is beyond it), saturated as [`InverseTable::evaluate`]
    /// does. For code that finds `k` itself: generated designs write the search out step by step.
    #[inline(always)]
    #[must_use]
    pub fn evaluate_segment(&self, t: T, k: usize) -> Estimate<T> {
        let k = k.min(self.segments.len().saturating_sub(1));
        let start = match self.knots {
            Knots::Uniform => T::ZERO,
            Knots::Searched(starts) => starts.get(k).copied().unwrap_or(T::ZERO),
        };
        // `get` cannot fail for a non-empty table; an empty one (never emitted) gives r_min.
        let [a, b] = self.segments.get(k).copied().unwrap_or([self.r_min, T::ZERO]);
        let inside = a + b * (t - start);
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

/// The largest `k` with `starts[k] ≤ t` (0 if there is none, or `t` is NaN), for increasing `starts`.
///
/// Branch-free binary search: the candidate range `[base, base + len)` shrinks by [`search_halves`]
/// whatever `t` is, so the steps are fixed by the table's length.
#[inline(always)]
fn search<T: Scalar>(starts: &[T], t: T) -> usize {
    search_halves(starts.len()).fold(0, |base, half| search_step(starts, t, base, half))
}

/// The steps of the search over `len` knots: `half = ⌊len/2⌋`, then `len - half`, … while `len > 1`
/// (`⌈log₂ len⌉` of them). The host writes them into generated code as constants.
pub fn search_halves(len: usize) -> impl Iterator<Item = usize> {
    let mut remaining = len;
    core::iter::from_fn(move || {
        (remaining > 1).then(|| {
            let half = remaining / 2;
            remaining -= half;
            half
        })
    })
}

/// One step of the search: `base + half` if `starts[base + half] ≤ t`, else `base` (a select, no
/// branch). Out of the table (never, in a search by [`search_halves`]) the step stays at `base`.
#[inline(always)]
#[must_use]
pub fn search_step<T: Scalar>(starts: &[T], t: T, base: usize, half: usize) -> usize {
    let above = starts.get(base + half).is_some_and(|&s| s <= t);
    select(above, base + half, base)
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
        knots: Knots::Uniform,
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

    /// r = t² on [0, 1] through the uneven knots t = 0, 0.5, 0.75, 1: segments (r(s_k), chord slope).
    const SQUARE_SEARCHED: InverseTable<'static, f64> = InverseTable {
        knots: Knots::Searched(&[0.0, 0.5, 0.75]),
        segments: &[[0.0, 0.5], [0.25, 1.25], [0.5625, 1.75]],
        t_max: 1.0,
        r_min: 0.0,
        r_max: 1.0,
    };

    #[test]
    fn searched_knots_interpolate_the_chords_and_saturate() {
        for (t, r, s) in [
            (0.0, 0.0, Saturation::Inside),
            (0.5, 0.25, Saturation::Inside),
            (0.75, 0.5625, Saturation::Inside),
            (1.0, 1.0, Saturation::Inside),
            (0.25, 0.125, Saturation::Inside),
            (0.625, 0.40625, Saturation::Inside),
            (0.875, 0.78125, Saturation::Inside),
            (-0.1, 0.0, Saturation::Low),
            (f64::NAN, 0.0, Saturation::Low),
            (1.5, 1.0, Saturation::High),
        ] {
            let e = SQUARE_SEARCHED.evaluate(t);
            assert_eq!((e.value, e.saturation), (r, s), "t = {t}");
        }
    }

    proptest! {
        #[test]
        fn the_search_takes_the_ceiling_of_log2_steps(len in 1usize..100_000) {
            let steps = search_halves(len).count() as u32;
            prop_assert_eq!(steps, len.next_power_of_two().trailing_zeros());
        }

        #[test]
        fn the_fixed_length_search_finds_what_a_scan_finds(
            mut starts in proptest::collection::vec(0.0f64..100.0, 1..70),
            t in prop_oneof![-10.0f64..110.0, Just(f64::NAN), Just(f64::INFINITY)],
        ) {
            starts.sort_by(f64::total_cmp);
            let scan = starts.iter().rposition(|&s| s <= t).unwrap_or(0);
            prop_assert_eq!(search(&starts, t), scan);
        }

        #[test]
        fn is_continuous_and_increasing(t in 0.0f64..3.0, dt in 0.0f64..0.5) {
            let (lo, hi) = (SQUARE.evaluate(t).value, SQUARE.evaluate((t + dt).min(3.0)).value);
            prop_assert!(hi >= lo - 1e-12);
            // Within a segment the chord of t² lies above t² by at most 1/4 (h²/8 · max|r''| = 1/4).
            prop_assert!(lo >= t * t - 1e-12 && lo <= t * t + 0.25 + 1e-12);
        }

        #[test]
        fn any_f32_gives_a_finite_estimate_in_range(bits in any::<u32>()) {
            let table = InverseTable::<f32> { knots: Knots::Uniform, segments: &[[0.0, 1.0], [-2.0, 3.0], [-6.0, 5.0]], t_max: 3.0, r_min: 0.0, r_max: 9.0 };
            let e = table.evaluate(f32::from_bits(bits));
            prop_assert!(e.value.is_finite() && (0.0..=9.0).contains(&e.value));
        }
    }
}
