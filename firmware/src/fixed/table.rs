//! One target's tabulated `Γ⁻¹` in integers: the clamp by sign masks, the segment, the position in
//! it, and the saturation flag (the formula: [the module above](super)).

use crate::estimate::{Estimate, Saturation};

/// The tabulated inverse of one target in integers (see the module docs for the formula).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FixedTable<'a> {
    /// `(A_k, B_k)` of the `K` segments, in the target's LSB (and LSB per unit of `t`).
    pub segments: &'a [[i32; 2]],
    /// `F`: fractional bits of `t`.
    pub fraction_bits: u32,
    /// `F − P`: bits of the position in the segment dropped before the product.
    pub dropped_bits: u32,
    /// `P`: bits of the position the slope is multiplied by.
    pub product_bits: u32,
    /// `(K << F) − 1`, the last `t` of the table: from `K << F` on, the estimate saturates high.
    pub t_last: i32,
}

impl FixedTable<'_> {
    /// `r(t)` in the target's LSB: `t` is clamped to `[0, t_last]` by sign masks (no branch), so a
    /// saturated estimate is the table's first or last value, which the flag says. Wrapping: the
    /// host's proof keeps every in-range sample from wrapping, and no input can make this panic.
    #[inline(always)]
    #[must_use]
    pub fn evaluate(&self, t: i32) -> Estimate<i32> {
        self.clamped(t, core::hint::black_box(self.signs(t)))
    }

    /// `[t >> 31, (t_last − t) >> 31]`, to pass through `black_box` (one for all targets) before
    /// [`FixedTable::clamped`]: else the compiler turns the masks back into comparisons and, on a core
    /// without conditional execution (Cortex-M0), into branches.
    #[inline(always)]
    #[must_use]
    pub fn signs(&self, t: i32) -> [i32; 2] {
        [t >> 31, self.t_last.wrapping_sub(t) >> 31]
    }

    /// [`FixedTable::evaluate`] with `t`'s [`FixedTable::signs`] given (through `black_box`).
    #[inline(always)]
    #[must_use]
    pub fn clamped(&self, t: i32, [low, above]: [i32; 2]) -> Estimate<i32> {
        let high = above & !low; // −1 when t > t_last (never with `low`)
        let t = t & !low;
        let t = t ^ ((t ^ self.t_last) & high);
        let k = t >> self.fraction_bits; // in [0, K − 1]
        let position = t.wrapping_sub(k << self.fraction_bits) >> self.dropped_bits;
        // `get` cannot fail for `t` in [0, t_last] and keeps a panic path out; a table of a power of
        // two segments (one, for a straight Γ) is indexed through a mask: no bounds check runs.
        let len = self.segments.len();
        let index = if len.is_power_of_two() {
            k as usize & (len - 1)
        } else {
            k as usize
        };
        let [a, b] = self.segments.get(index).copied().unwrap_or([0, 0]);
        Estimate {
            value: a.wrapping_add(b.wrapping_mul(position) >> self.product_bits),
            saturation: flag(low, high),
        }
    }
}

/// The saturation of masks `low` and `high` (each 0 or −1, not both), by a table lookup rather than
/// a branch.
#[inline(always)]
#[must_use]
pub fn flag(low: i32, high: i32) -> Saturation {
    const FLAGS: [Saturation; 4] = [Saturation::Inside, Saturation::Low, Saturation::High, Saturation::Low];
    FLAGS[((low & 1) | (high & 2)) as usize & 3]
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use proptest::prelude::*;

    /// r = t² on t ∈ [0, 3] (knots 0, 1, 2, 3) with F = 8, P = 4, the LSB of r 2^-6:
    /// A_k = k² · 64, B_k = (2k + 1) · 64.
    pub(in crate::fixed) const SQUARE: FixedTable<'static> = FixedTable {
        segments: &[[0, 64], [64, 192], [256, 320]],
        fraction_bits: 8,
        dropped_bits: 4,
        product_bits: 4,
        t_last: (3 << 8) - 1,
    };

    /// The chord of t² through the knots, in exact arithmetic (the table's closed form).
    fn chord(t: f64) -> f64 {
        let k = t.floor().clamp(0.0, 2.0);
        k * k + (2.0 * k + 1.0) * (t - k)
    }

    #[test]
    fn hits_the_knots_and_saturates_at_the_tables_ends_with_the_flag() {
        for k in 0..3 {
            let e = SQUARE.evaluate(k << 8);
            assert_eq!((e.value, e.saturation), (k * k * 64, Saturation::Inside), "k = {k}");
        }
        // The last t of the table: position 255 >> 4 = 15 of 16, so 256 + 320 · 15 / 16 = 556.
        let last = SQUARE.evaluate((3 << 8) - 1);
        assert_eq!((last.value, last.saturation), (556, Saturation::Inside));
        for t in [-1, -(1 << 20), i32::MIN] {
            let e = SQUARE.evaluate(t);
            assert_eq!((e.value, e.saturation), (0, Saturation::Low), "t = {t}");
        }
        for t in [3 << 8, (3 << 8) + 1, i32::MAX] {
            let e = SQUARE.evaluate(t);
            assert_eq!((e.value, e.saturation), (556, Saturation::High), "t = {t}");
        }
    }

    /// A table of a power of two segments (indexed through a mask), t² on [0, 4]: [`SQUARE`]'s values
    /// on its first three segments, the fourth's knot, and saturation at its own ends.
    #[test]
    fn a_power_of_two_table_reads_every_segment_and_saturates() {
        const SQUARE4: FixedTable<'static> = FixedTable {
            segments: &[[0, 64], [64, 192], [256, 320], [576, 448]],
            t_last: (4 << 8) - 1,
            ..SQUARE
        };
        for t in 0..(3 << 8) {
            assert_eq!(SQUARE4.evaluate(t), SQUARE.evaluate(t), "t = {t}");
        }
        assert_eq!(SQUARE4.evaluate(3 << 8).value, 576);
        // 576 + 448 · 15 / 16 = 996 at the last t, and from there on, high.
        for (t, flag) in [
            ((4 << 8) - 1, Saturation::Inside),
            (4 << 8, Saturation::High),
            (i32::MAX, Saturation::High),
        ] {
            assert_eq!(
                SQUARE4.evaluate(t),
                Estimate {
                    value: 996,
                    saturation: flag
                },
                "t = {t}"
            );
        }
        assert_eq!(
            SQUARE4.evaluate(-1),
            Estimate {
                value: 0,
                saturation: Saturation::Low
            }
        );
    }

    proptest! {
        /// Inside, the result is the chord at t truncated to P = 4 bits of position, then floored to
        /// the LSB: within one LSB plus the slope times 2^-P of the exact chord, never above it.
        #[test]
        fn is_the_chord_within_the_truncations(t in 0i32..(3 << 8)) {
            let exact = chord(f64::from(t) / 256.0) * 64.0;
            let got = f64::from(SQUARE.evaluate(t).value);
            prop_assert!(got <= exact + 1e-9 && got >= exact - 1.0 - 320.0 / 16.0, "t = {t}: {got} vs {exact}");
        }
    }
}
