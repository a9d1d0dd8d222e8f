//! The certified table of `Γ⁻¹` the chip evaluates instead of a bisection.
//!
//! # What is tabulated
//!
//! `φ = Γ⁻¹ : [Γ(0), Γ(1)] → [0, 1]` is interpolated linearly between knots ([`firmware::InverseTable`]).
//!
//! * **Uniform knots** (the rule): `K + 1` knots uniform in `v`, `v_k = Γ(0) + k h`,
//!   `h = (Γ(1) - Γ(0)) / K`, with `η_k = φ(v_k)` from the f64 bisection. The affine steps are folded
//!   into the emitted numbers: the gains become `L K / (Γ(1) - Γ(0))`, so the dot product gives
//!   `t = (v - Γ(0)) / h` directly, the segment is `⌊t⌋`, and each stores `r = a_k + b_k t` in the
//!   target's units.
//! * **Searched knots** (the fallback, when uniform knots would need more than
//!   [`MAX_UNIFORM_SEGMENTS`]: a `Γ` almost flat somewhere, as large `β` or the paper's normalisation
//!   give): knots placed in `η` by halving `[0, 1]` wherever the proven bound below is not yet met, so
//!   they crowd where `φ` bends; `v_k = Γ(η_k)` is evaluated, not inverted. The gains become
//!   `L / (Γ(1) - Γ(0))`, so `t ∈ [0, 1]`, and the chip finds the segment by a binary search of fixed
//!   length `⌈log₂ K⌉`; segment `k` stores `r = a_k + b_k (t - t_k)`.
//!
//! # What is proven
//!
//! On `[v_k, v_{k+1}]` linear interpolation is within `h_k²/8 · sup |φ''|` of `φ` (`h_k` the segment's
//! width in `v`), and `φ''(v) = -Γ''(η) / Γ'(η)³` at `η = φ(v) ∈ [η_k, η_{k+1}]`. `Γ' = Σ w_j / d_j²` and
//! `Γ'' = -2 Σ w_j (c_j - 1) / d_j³` with `d_j(η) = 1 + (c_j - 1) η` linear and positive, so on any
//! interval each term is monotone and bounded by its values at the ends: summing termwise gives a lower
//! bound of `Γ'` and an upper bound of `|Γ''|` (interval arithmetic, widened by a relative `1e-13` of the
//! terms' magnitudes for the rounding of the sums). Where those bounds are loose (terms of opposite
//! signs cancel), the interval is halved until they are tight. A positive lower bound of `Γ'` on every
//! piece also proves that `Γ` is strictly increasing on all of `[0, 1]`, not only on a grid.
//!
//! The certificate of a table is, per segment, `h_k²/8 · sup|Γ''|/Γ'³` plus the error of its knots
//! (bisection to `2⁻⁵²` and the rounding of `Γ` there, over the lower bound of `Γ'`), in exact
//! arithmetic; its maximum, times `r_max - r_min`, is the `proven_bound`. The f32 evaluation on the
//! chip adds rounding, bounded separately ([`crate::emit::precision`]).
//!
//! # What is sampled
//!
//! Every table is then confirmed on a million points uniform in `η` (`|table(Γ(η)) - η|`, no
//! inversion needed), and the test suite compares it with the f64 bisection on a million points
//! uniform in `v`. Neither is part of the proof; both would catch a wrong one.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x > y)` is deliberate: a NaN must fail the check.

use firmware::Gamma;
use serde::Serialize;

/// Accuracy asked of every table: `sup |r_table - Γ⁻¹| ≤ RELATIVE_TOLERANCE · (r_max - r_min)`.
pub const RELATIVE_TOLERANCE: f64 = 1e-4;
/// The most segments of a table with uniform knots (8 bytes each in flash); beyond, searched knots.
pub const MAX_UNIFORM_SEGMENTS: usize = 1024;
/// The most segments one target's table may have (searched knots: 12 bytes each in flash).
pub const MAX_SEGMENTS: usize = 4096;
/// Points of the dense confirmation.
pub const CONFIRMATION_POINTS: usize = 1_000_000;
/// Halvings allowed when bounding over one interval.
const MAX_DEPTH: u32 = 40;
/// Halvings allowed when bounding over one searched segment: a few suffice where terms cancel, as the
/// segments themselves are halved where they do not.
const SEARCHED_BOUND_DEPTH: u32 = 6;
/// Relative widening of termwise sums for their rounding.
const ROUNDING_MARGIN: f64 = 1e-13;

/// Why a table could not be certified.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TableError {
    /// No positive lower bound of `Γ'` could be proven near `eta`.
    #[error("Γ' cannot be proven positive near η = {eta} (lower bound {slope_bound:e})")]
    NotIncreasing {
        /// Where.
        eta: f64,
        /// The best lower bound found there.
        slope_bound: f64,
    },
    /// The proven bound needs more than the allowed segments.
    #[error("the inverse needs more than {limit} segments for a proven error of {RELATIVE_TOLERANCE:e} of the range")]
    TooManySegments {
        /// The limit that was reached.
        limit: usize,
    },
    /// Two knots near `eta` are closer than f64 resolves in `t`: `Γ` is flat there to rounding.
    #[error("Γ is too flat near η = {eta} for its inverse to be tabulated in double precision")]
    Unresolvable {
        /// Where.
        eta: f64,
    },
    /// The dense confirmation found an error above the proven bound: a defect of the proof.
    #[error("the dense check found an error of {sampled:e} above the proven bound {bound:e}")]
    BoundViolated {
        /// The largest error seen.
        sampled: f64,
        /// The proven bound.
        bound: f64,
    },
}

/// `Γ⁻¹` as the chip evaluates it (see the module docs), with its certificate.
#[derive(Clone, Debug, Serialize)]
pub struct InverseTable {
    /// `L t_max / (Γ(1) - Γ(0))`: the dot product gives `t` directly.
    pub gains: Vec<f64>,
    /// `-Γ(0) t_max / (Γ(1) - Γ(0))`, where the dot product starts.
    pub offset: f64,
    /// `None` for uniform knots (`t_max = K`); the left knots `t_k` of the segments for searched
    /// ones (`t_0 = 0`, `t_max = 1`).
    pub starts: Option<Vec<f64>>,
    /// `(a_k, b_k)`, target units: `r = a_k + b_k t` on `[k, k + 1]` (uniform knots), or
    /// `r = a_k + b_k (t - t_k)` on `[t_k, t_{k+1}]` (searched).
    pub segments: Vec<[f64; 2]>,
    /// Smallest learning target: the estimate below `t = 0`.
    pub r_min: f64,
    /// Largest learning target: the estimate above `t_max`.
    pub r_max: f64,
    /// Proven `sup |r_table - Γ⁻¹|` over `[Γ(0), Γ(1)]`, target units, exact arithmetic.
    pub proven_bound: f64,
    /// Largest `|r_table - Γ⁻¹|` seen on the dense confirmation, target units.
    pub sampled_error: f64,
}

impl InverseTable {
    /// The certified table of `gamma` for a map with gains `gains` and targets in `[r_min, r_max]`,
    /// with a proven bound within `relative_tolerance · (r_max - r_min)`: uniform knots if at most
    /// [`MAX_UNIFORM_SEGMENTS`] do, searched knots otherwise.
    pub fn certify(
        gamma: &Gamma<'_, f64>,
        gains: &[f64],
        range: (f64, f64),
        relative_tolerance: f64,
    ) -> Result<Self, TableError> {
        match Self::uniform(gamma, gains, range, relative_tolerance) {
            Err(TableError::TooManySegments { .. }) => Self::searched(gamma, gains, range, relative_tolerance),
            other => other,
        }
    }

    /// The table with (about) the fewest uniform knots that meets the tolerance, if at most
    /// [`MAX_UNIFORM_SEGMENTS`] segments do.
    pub fn uniform(
        gamma: &Gamma<'_, f64>,
        gains: &[f64],
        range: (f64, f64),
        relative_tolerance: f64,
    ) -> Result<Self, TableError> {
        let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
        // The count from the largest pointwise |φ''| on a fine grid (an estimate: the proof follows),
        // leaving 1 % of the tolerance to the knots' error, which is ~1e-15.
        let interpolation = 0.99 * relative_tolerance;
        let curvature = (0..=8192)
            .map(|i| pointwise_curvature(gamma, i as f64 / 8192.0))
            .fold(0.0, f64::max);
        let mut segments = ((v1 - v0) * (curvature / (8.0 * interpolation)).sqrt()).ceil();
        if !(segments >= 1.0) {
            segments = 1.0;
        }
        let mut segments = segments.min((MAX_UNIFORM_SEGMENTS + 1) as f64) as usize;
        loop {
            if segments > MAX_UNIFORM_SEGMENTS {
                return Err(TableError::TooManySegments {
                    limit: MAX_UNIFORM_SEGMENTS,
                });
            }
            let (nodes, bound) = nodes_and_bound(gamma, segments, interpolation)?;
            if bound <= relative_tolerance {
                return Self::from_nodes(gamma, gains, range, &nodes, bound);
            }
            // The pointwise estimate missed a peak between grid points: grow by 10 %.
            segments += segments.div_ceil(10);
        }
    }

    /// The table with searched knots that meets the tolerance, if at most [`MAX_SEGMENTS`] segments do:
    /// `[0, 1]` is halved in `η` wherever a segment's proven bound is above the tolerance.
    pub fn searched(
        gamma: &Gamma<'_, f64>,
        gains: &[f64],
        range: (f64, f64),
        relative_tolerance: f64,
    ) -> Result<Self, TableError> {
        let interpolation = 0.99 * relative_tolerance;
        let mut knots = vec![0.0];
        let mut search = Search {
            gamma,
            goal: interpolation,
            knots: &mut knots,
            curvature_bound: 0.0,
            min_slope: f64::INFINITY,
        };
        search.split(0.0, 1.0, gamma.value(0.0), gamma.value(1.0), MAX_DEPTH)?;
        let bound = search.curvature_bound + node_error(gamma, search.min_slope);
        Self::from_searched_knots(gamma, gains, range, &knots, bound)
    }

    /// A table of exactly `segments` segments, with the bound it is proven to meet (whatever it is).
    /// For tests: [`InverseTable::certify`] chooses the count.
    pub fn with_segments(
        gamma: &Gamma<'_, f64>,
        gains: &[f64],
        range: (f64, f64),
        segments: usize,
    ) -> Result<Self, TableError> {
        let (nodes, bound) = nodes_and_bound(gamma, segments.max(1), 0.0)?;
        Self::from_nodes(gamma, gains, range, &nodes, bound)
    }

    fn from_nodes(
        gamma: &Gamma<'_, f64>,
        gains: &[f64],
        (r_min, r_max): (f64, f64),
        nodes: &[f64],
        bound_eta: f64,
    ) -> Result<Self, TableError> {
        let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
        let count = nodes.len() - 1;
        let scale = count as f64 / (v1 - v0);
        let span = r_max - r_min;
        let segments = nodes
            .windows(2)
            .enumerate()
            .map(|(k, pair)| {
                let (r0, r1) = (r_min + span * pair[0], r_min + span * pair[1]);
                let slope = r1 - r0;
                [r0 - slope * k as f64, slope]
            })
            .collect();
        InverseTable {
            gains: gains.iter().map(|g| g * scale).collect(),
            offset: -v0 * scale,
            starts: None,
            segments,
            r_min,
            r_max,
            proven_bound: bound_eta * span,
            sampled_error: 0.0,
        }
        .confirmed(gamma)
    }

    /// The searched table through the knots `η_k` (the last is 1), whose interpolation is proven within
    /// `bound_eta` in `η` units.
    fn from_searched_knots(
        gamma: &Gamma<'_, f64>,
        gains: &[f64],
        (r_min, r_max): (f64, f64),
        knots: &[f64],
        bound_eta: f64,
    ) -> Result<Self, TableError> {
        let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
        let scale = 1.0 / (v1 - v0);
        let span = r_max - r_min;
        let t: Vec<f64> = knots
            .iter()
            .map(|&eta| match eta {
                0.0 => 0.0,
                1.0 => 1.0,
                eta => (gamma.value(eta) - v0) * scale,
            })
            .collect();
        let mut segments = Vec::with_capacity(knots.len() - 1);
        for k in 0..knots.len() - 1 {
            if !(t[k + 1] > t[k]) {
                return Err(TableError::Unresolvable { eta: knots[k] });
            }
            let slope = span * (knots[k + 1] - knots[k]) / (t[k + 1] - t[k]);
            segments.push([r_min + span * knots[k], slope]);
        }
        InverseTable {
            gains: gains.iter().map(|g| g * scale).collect(),
            offset: -v0 * scale,
            starts: Some(t[..t.len() - 1].to_vec()),
            segments,
            r_min,
            r_max,
            proven_bound: bound_eta * span,
            sampled_error: 0.0,
        }
        .confirmed(gamma)
    }

    /// This table with its dense confirmation, or [`TableError::BoundViolated`].
    fn confirmed(mut self, gamma: &Gamma<'_, f64>) -> Result<Self, TableError> {
        self.sampled_error = self.confirm(gamma, CONFIRMATION_POINTS);
        // The sampled error includes the f64 rounding of t (which the steepest slope magnifies) and of
        // the segment's sum: allow a few ulp of each.
        let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
        let t_rounding = 8.0 * f64::EPSILON * self.t_max() * (1.0 + (v0.abs() + v1.abs()) / (v1 - v0));
        let steepest = self.segments.iter().map(|[_, b]| b.abs()).fold(0.0, f64::max);
        let rounding =
            64.0 * f64::EPSILON * (self.r_min.abs() + self.r_max.abs() + self.largest_term()) + steepest * t_rounding;
        if !(self.sampled_error <= self.proven_bound + rounding) {
            return Err(TableError::BoundViolated {
                sampled: self.sampled_error,
                bound: self.proven_bound,
            });
        }
        Ok(self)
    }

    /// The firmware's view, in f64.
    pub fn as_firmware(&self) -> firmware::InverseTable<'_, f64> {
        firmware::InverseTable {
            knots: match &self.starts {
                None => firmware::Knots::Uniform,
                Some(starts) => firmware::Knots::Searched(starts),
            },
            segments: &self.segments,
            t_max: self.t_max(),
            r_min: self.r_min,
            r_max: self.r_max,
        }
    }

    /// `"uniform"` or `"searched"`: how the chip finds a segment.
    pub fn knots_kind(&self) -> &'static str {
        match self.starts {
            None => "uniform",
            Some(_) => "searched",
        }
    }

    /// Where the table ends: `K` for uniform knots, `1` for searched ones.
    pub fn t_max(&self) -> f64 {
        match self.starts {
            None => self.segments.len() as f64,
            Some(_) => 1.0,
        }
    }

    /// Where segment `k` starts (its `t_k`; `k` for uniform knots).
    pub fn start(&self, k: usize) -> f64 {
        match &self.starts {
            None => k as f64,
            Some(starts) => starts[k],
        }
    }

    /// `max_k |a_k| + |b_k| (t_{k+1} - s_k)` with `s_k = 0` for uniform and `t_k` for searched knots:
    /// the size of the terms the evaluation adds.
    pub fn largest_term(&self) -> f64 {
        (0..self.segments.len())
            .map(|k| {
                let [a, b] = self.segments[k];
                let end = if k + 1 < self.segments.len() {
                    self.start(k + 1)
                } else {
                    self.t_max()
                };
                let origin = if self.starts.is_some() { self.start(k) } else { 0.0 };
                a.abs() + b.abs() * (end - origin)
            })
            .fold(0.0, f64::max)
    }

    /// The largest `|table(Γ(η)) - r(η)|` over `points` values of `η` uniform in `[0, 1]`.
    pub fn confirm(&self, gamma: &Gamma<'_, f64>, points: usize) -> f64 {
        let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
        let scale = self.t_max() / (v1 - v0);
        let table = self.as_firmware();
        let span = self.r_max - self.r_min;
        (0..=points)
            .map(|i| {
                let eta = i as f64 / points as f64;
                let t = (gamma.value(eta) - v0) * scale;
                (table.evaluate(t).value - (self.r_min + span * eta)).abs()
            })
            .fold(0.0, f64::max)
    }
}

/// The knots `η_k = φ(v_k)` and the proven bound of the interpolation in `η` units. Each segment's
/// interval is halved until its bound meets `goal` (or cannot be improved): the bound is proven either way.
fn nodes_and_bound(gamma: &Gamma<'_, f64>, segments: usize, goal: f64) -> Result<(Vec<f64>, f64), TableError> {
    let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
    let h = (v1 - v0) / segments as f64;
    let mut nodes: Vec<f64> = (0..=segments)
        .map(|k| match k {
            0 => 0.0,
            k if k == segments => 1.0,
            k => gamma.inverse(v0 + k as f64 * h).eta,
        })
        .collect();
    // The bisection is monotone in v, so the knots are ordered; make sure of it for the bounds below.
    for k in 1..nodes.len() {
        nodes[k] = nodes[k].max(nodes[k - 1]);
    }
    let budget = 8.0 * goal / (h * h);
    let (mut curvature, mut min_slope) = (0.0f64, f64::INFINITY);
    for pair in nodes.windows(2) {
        let local = sup_curvature(gamma, pair[0], pair[1], budget, MAX_DEPTH)?;
        curvature = curvature.max(local.curvature);
        min_slope = min_slope.min(local.min_slope);
    }
    Ok((nodes, h * h / 8.0 * curvature + node_error(gamma, min_slope)))
}

/// How far a knot from the f64 bisection may be from `φ(v_k)`: `2⁻⁵²` of bisection, plus the
/// rounding of `Γ` near the root over the smallest slope.
fn node_error(gamma: &Gamma<'_, f64>, min_slope: f64) -> f64 {
    let size: f64 = gamma.offset.abs()
        + gamma
            .weights
            .iter()
            .zip(gamma.odds_ratios)
            .map(|(w, c)| (w / c).abs())
            .sum::<f64>();
    2f64.powi(-52) + 64.0 * f64::EPSILON * size / min_slope
}

/// The recursive placement of searched knots.
struct Search<'a, 'g> {
    gamma: &'a Gamma<'g, f64>,
    /// Interpolation error allowed per segment, `η` units.
    goal: f64,
    /// Knots so far, increasing, starting at 0.
    knots: &'a mut Vec<f64>,
    /// Largest proven `h_k²/8 · sup|φ''|` of the accepted segments.
    curvature_bound: f64,
    /// Smallest proven lower bound of `Γ'` over the accepted segments.
    min_slope: f64,
}

impl Search<'_, '_> {
    /// Accepts `[a, b]` (`v_a = Γ(a)`, `v_b = Γ(b)`) as a segment if its proven bound meets the goal,
    /// halves it otherwise (at most `depth` times).
    fn split(&mut self, a: f64, b: f64, va: f64, vb: f64, depth: u32) -> Result<(), TableError> {
        if self.knots.len() > MAX_SEGMENTS {
            return Err(TableError::TooManySegments { limit: MAX_SEGMENTS });
        }
        let h = vb - va;
        let budget = 8.0 * self.goal / (h * h);
        let middle = 0.5 * (a + b);
        let splittable = depth > 0 && middle > a && middle < b;
        // Bounds on [a, b], tightened by halving it for the bounds only (no knot), then a knot at b if
        // they meet the goal; otherwise a knot in the middle.
        match sup_curvature(self.gamma, a, b, budget, SEARCHED_BOUND_DEPTH) {
            Ok(sup) if sup.curvature <= budget || !splittable => {
                self.curvature_bound = self.curvature_bound.max(h * h / 8.0 * sup.curvature);
                self.min_slope = self.min_slope.min(sup.min_slope);
                self.knots.push(b);
                return Ok(());
            }
            Err(e) if !splittable => return Err(e),
            _ => {}
        }
        let v_middle = self.gamma.value(middle);
        self.split(a, middle, va, v_middle, depth - 1)?;
        self.split(middle, b, v_middle, vb, depth - 1)
    }
}

/// A proven bound over an interval of `η`.
#[derive(Clone, Copy, Debug)]
struct Sup {
    /// Upper bound of `|Γ''| / Γ'³`.
    curvature: f64,
    /// Lower bound of `Γ'` (positive).
    min_slope: f64,
}

/// Termwise interval bounds of `Γ'` (lower) and `|Γ''|` (upper) on `[a, b]`.
fn interval_bounds(gamma: &Gamma<'_, f64>, a: f64, b: f64) -> (f64, f64) {
    let (mut slope_low, mut slope_size) = (0.0, 0.0);
    let (mut bend_low, mut bend_high, mut bend_size) = (0.0, 0.0, 0.0);
    for (&w, &c) in gamma.weights.iter().zip(gamma.odds_ratios) {
        let (da, db) = (firmware::basis::denominator(c, a), firmware::basis::denominator(c, b));
        let (d_low, d_high) = (da.min(db), da.max(db));
        // w / d²: monotone in d.
        let (s1, s2) = (w / (d_high * d_high), w / (d_low * d_low));
        slope_low += s1.min(s2);
        slope_size += s1.abs().max(s2.abs());
        // q / d³ with q = -2 w (c - 1): monotone in d.
        let q = -2.0 * w * (c - 1.0);
        let (b1, b2) = (q / (d_high * d_high * d_high), q / (d_low * d_low * d_low));
        bend_low += b1.min(b2);
        bend_high += b1.max(b2);
        bend_size += b1.abs().max(b2.abs());
    }
    let slope = slope_low - ROUNDING_MARGIN * slope_size;
    let bend = bend_low.abs().max(bend_high.abs()) + ROUNDING_MARGIN * bend_size;
    (slope, bend)
}

/// `|Γ''| / Γ'³` at a point (an estimate: chooses the first segment count and when to stop halving).
fn pointwise_curvature(gamma: &Gamma<'_, f64>, eta: f64) -> f64 {
    let (slope, bend) = interval_bounds(gamma, eta, eta);
    bend / (slope * slope * slope)
}

/// A proven upper bound of `|Γ''|/Γ'³` on `[a, b]`, halving the interval (at most `depth` times)
/// where the termwise lower bound of `Γ'` is not positive, or where the bound exceeds `budget` while
/// still more than 1 % above the pointwise values at the ends and the middle (once it is that tight,
/// halving cannot bring it under the budget: the segment is too long, and splitting would only
/// multiply the work).
fn sup_curvature(gamma: &Gamma<'_, f64>, a: f64, b: f64, budget: f64, depth: u32) -> Result<Sup, TableError> {
    let (slope, bend) = interval_bounds(gamma, a, b);
    let middle = 0.5 * (a + b);
    let splittable = depth > 0 && middle > a && middle < b;
    if slope > 0.0 {
        let curvature = bend / (slope * slope * slope);
        let tight = || {
            let pointwise = [a, middle, b]
                .iter()
                .map(|&eta| pointwise_curvature(gamma, eta))
                .fold(0.0, f64::max);
            curvature <= 1.01 * pointwise
        };
        if curvature <= budget || !splittable || tight() {
            return Ok(Sup {
                curvature,
                min_slope: slope,
            });
        }
    } else if !splittable {
        return Err(TableError::NotIncreasing {
            eta: middle,
            slope_bound: slope,
        });
    }
    let left = sup_curvature(gamma, a, middle, budget, depth - 1)?;
    let right = sup_curvature(gamma, middle, b, budget, depth - 1)?;
    Ok(Sup {
        curvature: left.curvature.max(right.curvature),
        min_slope: left.min_slope.min(right.min_slope),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use firmware::basis;

    fn gamma_of<'a>(weights: &'a [f64], odds_ratios: &'a [f64], offset: f64) -> Gamma<'a, f64> {
        Gamma {
            offset,
            weights,
            odds_ratios,
        }
    }

    #[test]
    fn interval_bounds_enclose_the_derivatives_of_a_mixed_sign_gamma() {
        // Weights of both signs (cancelling terms), as Example 1's x1 has.
        let c: Vec<f64> = basis::paper_odds_ratios(5, 0.5).collect();
        let mu = [-0.62, 0.52, -0.29, 0.08, 0.56, -0.35, 0.12, -0.012];
        let w: Vec<f64> = mu.iter().zip(&c).map(|(m, c)| m * c).collect();
        let gamma = gamma_of(&w, &c, 0.0);
        for k in 0..50 {
            let (a, b) = (k as f64 / 50.0, (k + 1) as f64 / 50.0);
            let (slope_low, bend_high) = interval_bounds(&gamma, a, b);
            for i in 0..=100 {
                let eta = a + (b - a) * i as f64 / 100.0;
                assert!(gamma.slope(eta) >= slope_low, "Γ'({eta}) below its bound");
                // Γ'' by central differences of the exact Γ'.
                let h = 1e-6;
                let bend = (gamma.slope(eta + h) - gamma.slope(eta - h)) / (2.0 * h);
                assert!(
                    bend.abs() <= bend_high * (1.0 + 1e-6) + 1e-9,
                    "Γ''({eta}) = {bend} above {bend_high}"
                );
            }
        }
    }

    #[test]
    fn a_linear_gamma_gets_one_exact_segment() {
        // Γ(η) = 1 + 3η: φ is linear, so the table is exact with one segment (two knots).
        let gamma = gamma_of(&[3.0], &[1.0], 1.0);
        let table = InverseTable::certify(&gamma, &[2.0], (-1.0, 5.0), RELATIVE_TOLERANCE).unwrap();
        assert_eq!(table.segments.len(), 1);
        assert!(table.proven_bound < 1e-12 && table.sampled_error < 1e-12, "{table:?}");
        // t = (v - 1) · 1/3, folded: gains 2/3, offset -1/3; r = -1 + 6 t.
        assert!((table.gains[0] - 2.0 / 3.0).abs() < 1e-15 && (table.offset + 1.0 / 3.0).abs() < 1e-15);
        assert!((table.segments[0][0] + 1.0).abs() < 1e-13 && (table.segments[0][1] - 6.0).abs() < 1e-13);
    }

    #[test]
    fn knots_follow_the_closed_form_for_a_single_bent_basis_function() {
        // Γ = B(η; c): φ(v) = v / (c - (c - 1) v) on [0, 1], so |φ''| = 2|c-1|c / (c - (c-1)v)³ and
        // the uniform-knot bound needs K = ⌈sqrt(max|φ''| / (8 tol))⌉ segments.
        let c = 4.0;
        let weights = [c];
        let gamma = gamma_of(&weights, &weights, 0.0);
        let tol = 1e-4;
        let table = InverseTable::certify(&gamma, &[1.0], (0.0, 1.0), tol).unwrap();
        let max_phi2: f64 = 2.0 * (c - 1.0) * c / 1.0; // at v = 1, c - (c-1) = 1
        let exact = (max_phi2 / (8.0 * tol)).sqrt().ceil() as usize;
        let k = table.segments.len();
        assert!(
            k >= exact && k <= exact + exact / 5 + 1,
            "{k} segments, closed form {exact}"
        );
        assert!(table.proven_bound <= tol && table.sampled_error <= table.proven_bound);
        // The bound is tight: the largest sampled error is at least half of it.
        assert!(table.sampled_error >= 0.5 * table.proven_bound, "{table:?}");
    }

    #[test]
    fn a_decreasing_gamma_cannot_be_certified() {
        // Γ'(η) = 2 - 12/(1 + 3η)² < 0 near η = 0.
        let gamma = gamma_of(&[2.0, -12.0], &[1.0, 4.0], 0.0);
        assert!(matches!(
            InverseTable::certify(&gamma, &[1.0], (0.0, 1.0), RELATIVE_TOLERANCE),
            Err(TableError::NotIncreasing { .. })
        ));
    }

    #[test]
    fn a_steep_inverse_falls_back_to_searched_knots_that_meet_the_closed_form() {
        // Γ = B(η; c = e^12): max φ'' = 2c(c - 1) ≈ 5e10, so uniform knots would need
        // K ≈ sqrt(5e10 / 8e-4) ≈ 8·10⁶ segments; knots placed by the curvature need a few hundred.
        let c = 12f64.exp();
        let weights = [c];
        let gamma = gamma_of(&weights, &weights, 0.0);
        assert!(matches!(
            InverseTable::uniform(&gamma, &[1.0], (0.0, 1.0), RELATIVE_TOLERANCE),
            Err(TableError::TooManySegments {
                limit: MAX_UNIFORM_SEGMENTS
            })
        ));
        let table = InverseTable::certify(&gamma, &[1.0], (0.0, 1.0), RELATIVE_TOLERANCE).unwrap();
        let starts = table.starts.as_ref().expect("searched knots");
        println!("B(η; e^12): {} searched segments", table.segments.len());
        assert!(table.segments.len() <= 400, "{} segments", table.segments.len());
        assert_eq!(starts[0], 0.0);
        assert!(starts.windows(2).all(|s| s[0] < s[1]) && *starts.last().unwrap() < 1.0);
        assert!(table.proven_bound <= RELATIVE_TOLERANCE);
        // Against the closed form φ(v) = v / (c - (c - 1) v) (here t = v), uniform in v and in η.
        let evaluator = table.as_firmware();
        let phi = |v: f64| v / (c - (c - 1.0) * v);
        let b = |eta: f64| c * eta / (1.0 + (c - 1.0) * eta);
        let mut worst: f64 = 0.0;
        for i in 0..=200_000 {
            let x = i as f64 / 200_000.0;
            worst = worst.max((evaluator.evaluate(x).value - phi(x)).abs());
            worst = worst.max((evaluator.evaluate(b(x)).value - x).abs());
        }
        // The rounding of φ near v = 1, where φ' = c: a few ulp of v magnified by c.
        assert!(
            worst <= table.proven_bound + 8.0 * f64::EPSILON * c,
            "{worst:e} vs {:e}",
            table.proven_bound
        );
        // And the bound is not loose: the largest error is at least half of it.
        assert!(
            worst >= 0.5 * table.proven_bound,
            "{worst:e} vs {:e}",
            table.proven_bound
        );
    }

    #[test]
    fn a_table_beyond_the_segment_limit_is_refused() {
        // The same Γ at a tolerance of 1e-9: the searched knots grow as tolerance^(-1/2), past MAX_SEGMENTS.
        let c = 12f64.exp();
        let weights = [c];
        let gamma = gamma_of(&weights, &weights, 0.0);
        match InverseTable::certify(&gamma, &[1.0], (0.0, 1.0), 1e-9) {
            Err(TableError::TooManySegments { limit }) => assert_eq!(limit, MAX_SEGMENTS),
            other => panic!("{:?}", other.map(|t| t.segments.len())),
        }
    }
}
