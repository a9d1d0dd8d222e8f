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

mod table;

pub use table::{flag, FixedTable};

/// One target's map in integers: `t = offset + Σ_i gains_i raw_i`, `r = table(t)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FixedMap<'a> {
    /// One gain per regressor entry (in regressor order, newest sample first), in 2^-F per count.
    pub gains: &'a [i32],
    /// `C`: the scales' offsets and `−Γ(0)` folded in, in 2^-F.
    pub offset: i32,
    /// `Γ⁻¹` in integers.
    pub table: FixedTable<'a>,
}

impl FixedMap<'_> {
    /// `t = offset + Σ_i gains_i raw_i` in regressor order, skipping pruned taps (gain 0).
    #[must_use]
    pub fn project(&self, regressor: &[i32]) -> i32 {
        let mut sum = self.offset;
        for (&g, &z) in self.gains.iter().zip(regressor) {
            if g != 0 {
                sum = sum.wrapping_add(g.wrapping_mul(z));
            }
        }
        sum
    }

    /// The estimate from a regressor of raw samples.
    #[must_use]
    pub fn estimate(&self, regressor: &[i32]) -> Estimate<i32> {
        self.table.evaluate(self.project(regressor))
    }
}

/// `|offset| + Σ_i |gains_i| M_i + t_max` (`t_max = t_last + 1`) with `M_i` the largest raw magnitude of regressor entry
/// `i` (its signal's range; the regressor is `N` samples of `ranges.len()` signals, outputs and then
/// inputs as [`FixedDesign`] lays them out, `outputs` of them outputs): no partial sum, product or
/// `t_last − t` of [`FixedMap::estimate`] can overflow 32 bits while this is at most `2³¹ − 1`. A
/// `const fn`, so that a generated design checks its own proof at compile time.
#[must_use]
pub const fn reach(map: &FixedMap<'_>, horizon: usize, outputs: &[[i32; 2]], inputs: &[[i32; 2]]) -> i64 {
    let mut sum = (map.offset as i64).abs() + map.table.t_last as i64 + 1;
    let mut i = 0;
    while i < map.gains.len() {
        let range = if i < horizon * outputs.len() {
            outputs[i % outputs.len()]
        } else {
            inputs[(i - horizon * outputs.len()) % inputs.len()]
        };
        let magnitude = if (range[0] as i64).abs() > (range[1] as i64).abs() {
            (range[0] as i64).abs()
        } else {
            (range[1] as i64).abs()
        };
        sum += (map.gains[i] as i64).abs() * magnitude;
        i += 1;
    }
    sum
}

/// A sample was refused because a value is outside its declared raw range; the observer is unchanged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutOfRange;

impl core::fmt::Display for OutOfRange {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("sample refused: a value is outside its declared raw range (the observer is unchanged)")
    }
}

impl core::error::Error for OutOfRange {}

/// A fixed-point design: `NT` integer maps of the last `N` raw samples of `NY` outputs and `NU`
/// inputs. Generated designs override [`FixedDesign::estimate`] and [`FixedDesign::accepts`] with the
/// same sums and checks written out.
pub trait FixedDesign<const N: usize, const NY: usize, const NU: usize, const NT: usize> {
    /// Every target's map, gains laid out as the float map's.
    const MAPS: [FixedMap<'static>; NT];
    /// Each output's raw range `[min, max]`.
    const OUTPUT_RANGES: [[i32; 2]; NY];
    /// Each input's raw range `[min, max]`.
    const INPUT_RANGES: [[i32; 2]; NU];

    /// The estimates from the last `N` samples, oldest first.
    #[inline(always)]
    #[must_use]
    fn estimate(window: &[Sample<i32, NY, NU>; N]) -> [Estimate<i32>; NT] {
        estimate_by_loops(&Self::MAPS, window)
    }

    /// Whether every value is in its declared range.
    #[inline(always)]
    #[must_use]
    fn accepts(y: &[i32; NY], u: &[i32; NU]) -> bool {
        let mut inside = true;
        for (&v, [min, max]) in y
            .iter()
            .zip(Self::OUTPUT_RANGES)
            .chain(u.iter().zip(Self::INPUT_RANGES))
        {
            inside &= in_range(v, min, max);
        }
        inside
    }
}

/// `min ≤ v ≤ max`, as one unsigned comparison.
#[inline(always)]
#[must_use]
pub fn in_range(v: i32, min: i32, max: i32) -> bool {
    (v.wrapping_sub(min) as u32) <= (max.wrapping_sub(min) as u32)
}

/// Every map's estimate from a window (oldest first), summing in regressor order as
/// [`FixedMap::project`] does (integers: any order gives the same bits).
#[must_use]
pub fn estimate_by_loops<const N: usize, const NY: usize, const NU: usize, const NT: usize>(
    maps: &[FixedMap<'_>; NT],
    window: &[Sample<i32, NY, NU>; N],
) -> [Estimate<i32>; NT] {
    maps.each_ref().map(|map| {
        let (output_gains, input_gains) = map.gains.split_at_checked(N * NY).unwrap_or((map.gains, &[]));
        let mut sum = map.offset;
        for (gains, sample) in output_gains.chunks_exact(NY.max(1)).zip(window.iter().rev()) {
            for (&g, &y) in gains.iter().zip(&sample.y) {
                sum = sum.wrapping_add(g.wrapping_mul(y));
            }
        }
        for (gains, sample) in input_gains.chunks_exact(NU.max(1)).zip(window.iter().rev()) {
            for (&g, &u) in gains.iter().zip(&sample.u) {
                sum = sum.wrapping_add(g.wrapping_mul(u));
            }
        }
        map.table.evaluate(sum)
    })
}

/// The fixed-point observer of design `D`: the last `N` raw samples (stored twice, as the float
/// observer's [`Window`]) and one integer estimate per target.
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
