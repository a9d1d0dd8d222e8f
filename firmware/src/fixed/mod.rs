//! The map in integer arithmetic, for chips without an FPU (Cortex-M0/M0+, many RISC-V parts), where
//! every `f32` operation is a library routine of tens of instructions.
//!
//! Samples arrive as raw integers (ADC counts, or a Q format): signal `s`'s value in the model's unit
//! is `offset_s + scale_s · raw`, and the design declares each signal's raw range. The host folds the
//! scales and offsets into the gains, rounds them to `F` fractional bits and proves, for every sample
//! in the declared ranges, that nothing below overflows 32 bits:
//!
//! ```text
//! t = C + Σ_i G_i raw_i                       t in units of 2^-F of the table coordinate, exact
//! t ← min(max(t, 0), t_last)                 clamped to the table
//! k = t >> F,  f = t − (k << F)               the segment and the position in it, f < 2^F
//! r = A_k + ((B_k · (f >> (F − P))) >> P)     in the target's LSB: A_k the value at knot k, B_k the
//!                                             slope per unit of t, both rounded to that LSB
//! ```
//!
//! with `t` first clamped to the table, `[0, t_last = (K << F) − 1]`: outside it the estimate is the
//! table's first or last value (the learning range's ends, to within the bound) and the flag says it
//! saturated, as the float map's does. Everything is shifts, adds and 32-bit multiplies; the clamp is
//! sign masks (`x >> 31`), not branches, so every accepted sample runs the same instructions.
//! How far `r` may be from the f64 map (gain rounding times the inputs' range, the `P`-bit position,
//! the rounded table, plus the table's own proven distance to `Γ⁻¹`) is proven on the host and stated
//! in each generated design.
//!
//! A sample is refused ([`OutOfRange`]) when a value is outside its declared raw range: the overflow
//! proof holds only there (the float map's NaN check becomes this range check).
use core::marker::PhantomData;

use crate::estimate::Estimate;
use crate::window::{Sample, Window};

pub(crate) mod design;
pub(crate) mod table;

use design::FixedDesign;
#[cfg(test)]
use design::{in_range, reach, FixedMap};
#[cfg(test)]
use table::FixedTable;

/// A sample was refused because a value is outside its declared raw range; the observer is unchanged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct OutOfRange;

impl core::fmt::Display for OutOfRange {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("sample refused: a value is outside its declared raw range (the observer is unchanged)")
    }
}

impl core::error::Error for OutOfRange {}

/// The fixed-point observer of design `D`: the last `N` raw samples (stored twice, as the float
/// observer's window) and one integer estimate per target.
pub struct Observer<D, const N: usize, const NY: usize, const NU: usize, const NT: usize> {
    window: Window<i32, N, NY, NU>,
    design: PhantomData<fn() -> D>,
}

impl<D: FixedDesign<N, NY, NU, NT>, const N: usize, const NY: usize, const NU: usize, const NT: usize>
    Observer<D, N, NY, NU, NT>
{
    /// An observer with no samples yet.
    #[must_use]
    pub const fn new() -> Self {
        Observer {
            window: Window::new(),
            design: PhantomData,
        }
    }

    /// Takes one sample of raw outputs and inputs; refuses it, unchanged, when a value is outside its
    /// declared range.
    #[inline(always)]
    pub fn push(&mut self, y: [i32; NY], u: [i32; NU]) -> Result<(), OutOfRange> {
        if !D::accepts(&y, &u) {
            return Err(OutOfRange);
        }
        self.window.push(Sample { y, u });
        Ok(())
    }

    /// The estimates (target LSB) from the last `N` samples; `None` until `N` have arrived.
    #[inline(always)]
    #[must_use]
    pub fn estimate(&self) -> Option<[Estimate<i32>; NT]> {
        self.window.samples().map(D::estimate)
    }

    /// Forgets every sample.
    pub fn reset(&mut self) {
        self.window.clear();
    }

    /// `true` once `N` samples have arrived.
    #[must_use]
    pub fn is_ready(&self) -> bool {
        self.window.is_full()
    }
}

impl<D: FixedDesign<N, NY, NU, NT>, const N: usize, const NY: usize, const NU: usize, const NT: usize> Default
    for Observer<D, N, NY, NU, NT>
{
    fn default() -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests {
    use super::table::tests::SQUARE;
    use super::*;

    #[test]
    fn the_reach_adds_every_gain_times_its_signals_largest_magnitude() {
        // N = 2, one output in [−3, 2] and one input in [0, 5]: z = (y(k), y(k−1), u(k), u(k−1)).
        let map = FixedMap {
            gains: &[1, -2, 3, 0],
            offset: -7,
            table: SQUARE,
        };
        assert_eq!(reach(&map, 2, &[[-3, 2]], &[[0, 5]]), 7 + (3 << 8) + 3 + 2 * 3 + 3 * 5);
    }

    #[test]
    fn the_range_check_is_inclusive_and_refuses_wrapped_values() {
        assert!(in_range(0, 0, 4095) && in_range(4095, 0, 4095) && in_range(-5, -5, 5));
        assert!(!in_range(-1, 0, 4095) && !in_range(4096, 0, 4095) && !in_range(i32::MIN, -5, 5));
        assert!(in_range(i32::MIN, i32::MIN, i32::MAX) && in_range(i32::MAX, i32::MIN, i32::MAX));
    }

    struct Mean;
    impl FixedDesign<2, 1, 0, 1> for Mean {
        // t = 2^-8 (128 y(k) + 128 y(k−1)): the mean of the counts, K = 1 segment on [0, 1] of r = 100 t.
        const MAPS: [FixedMap<'static>; 1] = [FixedMap {
            gains: &[128, 128],
            offset: 0,
            table: FixedTable {
                segments: &[[0, 100]],
                fraction_bits: 8,
                dropped_bits: 0,
                product_bits: 8,
                t_last: 255,
            },
        }];
        const OUTPUT_RANGES: [[i32; 2]; 1] = [[0, 1]];
        const INPUT_RANGES: [[i32; 2]; 0] = [];
    }

    #[test]
    fn the_observer_refuses_out_of_range_samples_and_waits_for_n() {
        let mut observer: Observer<Mean, 2, 1, 0, 1> = Observer::new();
        observer.push([1], []).unwrap();
        assert!(observer.estimate().is_none());
        assert_eq!(observer.push([2], []), Err(OutOfRange));
        observer.push([0], []).unwrap();
        // mean 0.5 ⇒ t = 128 ⇒ r = 100 · 128 >> 8 = 50.
        assert_eq!(observer.estimate().unwrap()[0].value, 50);
        let regressor = [0, 1];
        assert_eq!(Mean::MAPS[0].estimate(&regressor), observer.estimate().unwrap()[0]);
        observer.reset();
        assert!(observer.estimate().is_none());
    }
}
