//! The map in integer arithmetic (`[chip] arithmetic = "fixed"`): the formats chosen for each target,
//! the integers the chip runs ([`firmware::fixed`]) and the proven bound on their distance to the f64
//! map.
//!
//! # Raw samples
//!
//! Signal `s` arrives as a raw integer in `[min_s, max_s]` with value `offset_s + scale_s · raw`
//! (`[chip.raw.<name>]`). A signal the spec does not declare gets a signed 16-bit Q format: raw in
//! `[−32767, 32767]`, offset 0, and `scale = 2^−q` with the largest `q` whose range covers 1.5 times
//! the signal's largest magnitude in the learning runs.
//!
//! # Formats (per target)
//!
//! With the float table's `t = c + Σ_i g_i z_i` (t per unit of `z_i`), `G_i = g_i scale_{s(i)}` and
//! `C = c + Σ_i g_i offset_{s(i)}` give `t` from raw counts. `F` is the largest number of fractional
//! bits (≤ 30) for which, with `M_i = max(|min_{s(i)}|, |max_{s(i)}|)`,
//!
//! ```text
//! |round(C 2^F)| + Σ_i |round(G_i 2^F)| M_i + K 2^F ≤ 2³¹ − 1
//! ```
//!
//! which bounds every partial sum, every product and `t_max − t` of the chip's code: no in-range
//! sample can overflow 32 bits (the emitted Rust checks the inequality again at compile time). The
//! target's LSB `2^−R` and the position bits `P ≤ F` are the pair that minimises the evaluation term of
//! the bound below while `|A_k| + |B_k|`, `|B_k| 2^P` and `|r_min|`, `|r_max|` (in LSB) fit in 31 bits.
//!
//! # The bound ([`Bound`])
//!
//! Against the f64 map on the same samples (`Γ⁻¹` by bisection, on the values the raw counts stand
//! for), with `L` the largest slope `|b_k|` of the table (the clamped table is `L`-Lipschitz in `t`):
//!
//! * table: the float table's own proven distance to `Γ⁻¹`;
//! * gains: `L (Σ_i |G_i − Gq_i 2^−F| M_i + |C − Cq 2^−F|)`, the exact rounding of the integers
//!   times the declared ranges (the sum itself is exact in integers);
//! * evaluation: `2^−R` for `A_k` and `B_k` rounded to the LSB (half each), `2^−R` for the floor of
//!   the product's shift, `(L + 2^−R) 2^−P` for the position truncated to `P` bits, and for a
//!   saturated estimate (the table's end values) `L 2^−F` (the last `t` is one `2^−F` short of the
//!   last knot) plus the float table's ends against `r_min`, `r_max` (their f64 rounding);
//!
//! plus a margin of `10⁻¹²` of the terms for the host's own f64 rounding.

mod evaluate;
mod raw;

use firmware::emitted::fixed::{FixedMap, FixedTable};

use crate::data::DataSet;
use crate::fit::maps::FittedMap;
use crate::spec::{Design, FixedSpec, RawScale};

pub use evaluate::{compare, Comparison, TargetComparison};
pub use raw::{default_scale, raw_rows, scalings, to_raw};

/// Raw magnitude of the default Q format.
pub const DEFAULT_RAW: i32 = 32_767;
/// The default Q format covers this times the largest learning magnitude.
pub const DEFAULT_HEADROOM: f64 = 1.5;
/// The largest number of fractional bits of `t`.
const MAX_FRACTION_BITS: i32 = 30;
/// `2³¹ − 1`.
const I32_MAX: f64 = i32::MAX as f64;

/// Why a design's map cannot be put in integers.
#[derive(Debug, thiserror::Error)]
pub enum FixedError {
    /// The table has searched knots.
    #[error("target `{target}`: Γ⁻¹'s table has searched knots (Γ is nearly flat somewhere), and the fixed-point map evaluates uniform knots only")]
    SearchedKnots {
        /// The target.
        target: String,
    },
    /// The map has no certified table (the emitter says why).
    #[error("target `{target}`: the map has no certified table of Γ⁻¹ to put in integers")]
    NoTable {
        /// The target.
        target: String,
    },
    /// No number of fractional bits keeps the sum within 32 bits.
    #[error("target `{target}`: the gains times the declared raw ranges reach {reach:.3e} in the table coordinate, beyond a 32-bit sum even with no fractional bit")]
    NoRoom {
        /// The target.
        target: String,
        /// `|C| + Σ |G_i| M_i + K`.
        reach: f64,
    },
}

impl FixedError {
    /// What the user can change.
    pub fn fix(&self) -> &'static str {
        match self {
            FixedError::SearchedKnots { .. } => {
                "lower `map.beta` or `map.nm` until the table is uniform, or set `[chip] arithmetic = \"float\"`"
            }
            FixedError::NoTable { .. } => "lower `map.beta` (or `map.nm`) until the map has a table",
            FixedError::NoRoom { .. } => "narrow the `[chip.raw]` ranges (`min`, `max`) to what the converters give",
        }
    }
}

/// The integer map of every target, and the raw scalings it reads.
#[derive(Clone, Debug, PartialEq)]
pub struct FixedPoint {
    /// One per output, in the model's order (declared or default).
    pub outputs: Vec<RawScale>,
    /// One per input.
    pub inputs: Vec<RawScale>,
    /// One per target, in the spec's order.
    pub targets: Vec<FixedTarget>,
}

/// One target's integers, formats and bound.
#[derive(Clone, Debug, PartialEq)]
pub struct FixedTarget {
    /// `Gq_i`, per regressor entry.
    pub gains: Vec<i32>,
    /// `Cq`.
    pub offset: i32,
    /// `(A_k, B_k)` in LSB.
    pub segments: Vec<[i32; 2]>,
    /// `F`.
    pub fraction_bits: u32,
    /// `P`.
    pub product_bits: u32,
    /// `R`: the LSB is `2^−R` target units.
    pub lsb_bits: i32,
    /// The learning range `r_max − r_min`, target units (what the bound is measured against).
    pub range: f64,
    /// `|Cq| + Σ |Gq_i| M_i + K 2^F`: at most `2³¹ − 1`, the overflow proof.
    pub reach: i64,
    /// The proven distance to the f64 map.
    pub bound: Bound,
}

/// The proven `|fixed − f64 map|` of a target, by cause (see the module docs), in target units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bound {
    /// The float table's proven distance to `Γ⁻¹`.
    pub table: f64,
    /// The gains' rounding times the raw ranges, times the table's largest slope.
    pub gains: f64,
    /// The table in integers: rounded `A_k`, `B_k`, the floor and the truncated position.
    pub evaluation: f64,
}

impl Bound {
    /// The sum of the causes.
    pub fn total(&self) -> f64 {
        self.table + self.gains + self.evaluation
    }
}

impl FixedTarget {
    /// The bound as emitted files and reports state it: rounded *up* to three significant digits,
    /// so that the figure a user reads is never below the proven one.
    pub fn stated_bound(&self) -> f64 {
        let total = self.bound.total();
        if total.is_nan() || total <= 0.0 || total.is_infinite() {
            return total;
        }
        let scale = 10f64.powi(2 - total.log10().floor() as i32);
        let stated = (total * scale).ceil() / scale;
        // Printed with three significant digits, as the emitters do; parsed back, never below.
        let printed: f64 = format!("{stated:.2e}").parse().unwrap_or(stated);
        if printed >= total {
            printed
        } else {
            stated * (1.0 + 1e-12)
        }
    }

    /// The target's LSB in target units, `2^−R`.
    pub fn lsb(&self) -> f64 {
        2f64.powi(-self.lsb_bits)
    }

    /// `(K << F) − 1`, the last `t` of the table.
    pub fn t_last(&self) -> i32 {
        ((self.segments.len() as i32) << self.fraction_bits) - 1
    }

    /// The firmware's view: what the chip runs.
    pub fn as_firmware(&self) -> FixedMap<'_> {
        FixedMap {
            gains: &self.gains,
            offset: self.offset,
            table: FixedTable {
                segments: &self.segments,
                fraction_bits: self.fraction_bits,
                dropped_bits: self.fraction_bits - self.product_bits,
                product_bits: self.product_bits,
                t_last: self.t_last(),
            },
        }
    }
}

/// Every target's integer map for `design` (whose spec asks for it), from its fitted `maps`.
pub fn quantise(
    design: &Design,
    spec: &FixedSpec,
    learning: &DataSet,
    maps: &[FittedMap],
) -> Result<FixedPoint, FixedError> {
    let (outputs, inputs) = scalings(spec, learning);
    let (n, ny) = (design.map.horizon, outputs.len());
    // The scaling of regressor entry i: N·NY outputs (newest first, all outputs of an instant
    // together), then N·NU inputs.
    let signal = |i: usize| {
        if i < n * ny {
            &outputs[i % ny.max(1)]
        } else {
            &inputs[(i - n * ny) % inputs.len().max(1)]
        }
    };
    let targets = maps
        .iter()
        .map(|map| {
            // A map without a table is refused by the emitter with its own message.
            let Some(table) = map.table.as_ref() else {
                return Err(FixedError::NoTable {
                    target: map.target.clone(),
                });
            };
            if table.starts.is_some() {
                return Err(FixedError::SearchedKnots {
                    target: map.target.clone(),
                });
            }
            let scales: Vec<&RawScale> = (0..table.gains.len()).map(signal).collect();
            target(&map.target, table, &scales)
        })
        .collect::<Result<_, _>>()?;
    Ok(FixedPoint {
        outputs,
        inputs,
        targets,
    })
}

/// One target's formats, integers and bound (see the module docs).
fn target(
    name: &str,
    table: &crate::fit::inverse_table::InverseTable,
    scales: &[&RawScale],
) -> Result<FixedTarget, FixedError> {
    let g: Vec<f64> = table.gains.iter().zip(scales).map(|(g, s)| g * s.scale).collect();
    let c = table.offset + table.gains.iter().zip(scales).map(|(g, s)| g * s.offset).sum::<f64>();
    let m: Vec<f64> = scales.iter().map(|s| f64::from(s.min.abs().max(s.max.abs()))).collect();
    let k = table.segments.len() as f64;
    let reach_at = |f: i32| {
        let unit = 2f64.powi(f);
        let gains: Vec<f64> = g.iter().map(|g| (g * unit).round()).collect();
        let reach = (c * unit).round().abs() + gains.iter().zip(&m).map(|(q, m)| q.abs() * m).sum::<f64>() + k * unit;
        (reach, gains)
    };
    let Some(f) = (0..=MAX_FRACTION_BITS).rev().find(|&f| reach_at(f).0 <= I32_MAX) else {
        return Err(FixedError::NoRoom {
            target: name.to_owned(),
            reach: reach_at(0).0,
        });
    };
    let unit = 2f64.powi(f);
    let (reach, gains) = reach_at(f);
    let offset = (c * unit).round();
    // Values at the knots and slopes, target units.
    let knots: Vec<[f64; 2]> = table
        .segments
        .iter()
        .enumerate()
        .map(|(k, [a, b])| [a + b * k as f64, *b])
        .collect();
    let slope = knots.iter().map(|[_, b]| b.abs()).fold(0.0, f64::max);
    let (lsb_bits, product_bits, evaluation) = formats(&knots, table.r_min, table.r_max, slope, f);
    // Saturated, the chip gives the table's ends: the float table's own ends against r_min and r_max
    // (exact but for rounding), and t_last one 2^-F short of the last knot.
    let last = knots.last().expect("a table has a segment");
    let ends = (knots[0][0] - table.r_min)
        .abs()
        .max((last[0] + last[1] - table.r_max).abs())
        + slope / unit;
    let lsb = 2f64.powi(lsb_bits);
    let rounding: f64 = g
        .iter()
        .zip(&gains)
        .zip(&m)
        .map(|((g, q), m)| (g - q / unit).abs() * m)
        .sum::<f64>()
        + (c - offset / unit).abs();
    let terms = c.abs() + g.iter().zip(&m).map(|(g, m)| g.abs() * m).sum::<f64>() + k;
    Ok(FixedTarget {
        gains: gains.iter().map(|&q| q as i32).collect(),
        offset: offset as i32,
        segments: knots
            .iter()
            .map(|[a, b]| [(a * lsb).round() as i32, (b * lsb).round() as i32])
            .collect(),
        fraction_bits: f as u32,
        product_bits,
        lsb_bits,
        range: table.r_max - table.r_min,
        reach: reach as i64,
        bound: Bound {
            table: table.proven_bound,
            gains: slope * (rounding + 1e-12 * terms),
            evaluation: (evaluation + ends) * (1.0 + 1e-12),
        },
    })
}

/// `(R, P, evaluation term)`: the target's LSB exponent and the position bits minimising
/// `2 · 2^−R + (L + 2^−R) 2^−P` with every integer of the table within 31 bits and `P ≤ F`.
fn formats(knots: &[[f64; 2]], r_min: f64, r_max: f64, slope: f64, f: i32) -> (i32, u32, f64) {
    let values = knots
        .iter()
        .map(|[a, b]| a.abs() + b.abs())
        .fold(r_min.abs().max(r_max.abs()), f64::max);
    let mut best: Option<(i32, u32, f64)> = None;
    for r in -30..=30 {
        let lsb = 2f64.powi(r);
        // Rounded values may grow by half an LSB each.
        if values * lsb + 1.0 > I32_MAX {
            continue;
        }
        let b = (slope * lsb).round().max(1.0);
        let Some(p) = (0..=f).rev().find(|&p| b * 2f64.powi(p) <= I32_MAX) else {
            continue;
        };
        let error = 2.0 / lsb + (slope + 1.0 / lsb) * 2f64.powi(-p);
        if best.is_none_or(|(_, _, e)| error < e) {
            best = Some((r, p as u32, error));
        }
    }
    // R = −30 always fits a finite table (the learning range is within f64's), so `best` is set.
    best.expect("an LSB of 2^30 fits any learning range")
}
