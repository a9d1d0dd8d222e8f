//! The integer map's tables and the straight-line code's helpers: what a generated design holds and
//! calls (reached from outside the crate through `crate::emitted::fixed`).

use super::table::FixedTable;
use crate::estimate::Estimate;
use crate::window::Sample;

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
