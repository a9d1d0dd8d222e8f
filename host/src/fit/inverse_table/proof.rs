//! The proof behind a table (see [`super`]): knots and their error, termwise interval bounds of `Γ'`
//! and `Γ''`, and the placement of searched knots.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x > y)` is deliberate: a NaN must fail the check.

use firmware::gamma::weight;
use firmware::Gamma;

use super::{TableError, MAX_DEPTH, MAX_SEGMENTS, ROUNDING_MARGIN, SEARCHED_BOUND_DEPTH};

/// The knots `η_k = φ(v_k)` and the proven bound of the interpolation in `η` units. Each segment's
/// interval is halved until its bound meets `goal` (or cannot be improved): the bound is proven either way.
pub(super) fn nodes_and_bound(
    gamma: &Gamma<'_, f64>,
    segments: usize,
    goal: f64,
) -> Result<(Vec<f64>, f64), TableError> {
    let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
    let h = (v1 - v0) / segments as f64;
    let nodes = uniform_nodes(gamma, segments);
    let budget = 8.0 * goal / (h * h);
    let (mut curvature, mut min_slope) = (0.0f64, f64::INFINITY);
    for pair in nodes.windows(2) {
        let local = sup_curvature(gamma, pair[0], pair[1], budget, MAX_DEPTH)?;
        curvature = curvature.max(local.curvature);
        min_slope = min_slope.min(local.min_slope);
    }
    Ok((nodes, h * h / 8.0 * curvature + node_error(gamma, min_slope)))
}

/// The knots `η_k = φ(v_k)` of `segments` segments uniform in `v`, by the f64 bisection.
pub(super) fn uniform_nodes(gamma: &Gamma<'_, f64>, segments: usize) -> Vec<f64> {
    let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
    let h = (v1 - v0) / segments as f64;
    let mut nodes: Vec<f64> = (0..=segments)
        .map(|k| match k {
            0 => 0.0,
            k if k == segments => 1.0,
            k => gamma.inverse(v0 + k as f64 * h).eta,
        })
        .collect();
    // The bisection is monotone in v, so the knots are ordered; make sure of it for the bounds.
    for k in 1..nodes.len() {
        nodes[k] = nodes[k].max(nodes[k - 1]);
    }
    nodes
}

/// How far a knot from the f64 bisection may be from `φ(v_k)`: `2⁻⁵²` of bisection, plus the
/// rounding of `Γ` near the root over the smallest slope.
pub(super) fn node_error(gamma: &Gamma<'_, f64>, min_slope: f64) -> f64 {
    let size: f64 = gamma.offset.abs()
        + gamma
            .mu
            .iter()
            .zip(gamma.odds_ratios)
            .map(|(&m, &c)| (weight(m, c) / c).abs())
            .sum::<f64>();
    2f64.powi(-52) + 64.0 * f64::EPSILON * size / min_slope
}

/// The recursive placement of searched knots.
pub(super) struct Search<'a, 'g> {
    pub(super) gamma: &'a Gamma<'g, f64>,
    /// Interpolation error allowed per segment, `η` units.
    pub(super) goal: f64,
    /// Knots so far, increasing, starting at 0.
    pub(super) knots: &'a mut Vec<f64>,
    /// Largest proven `h_k²/8 · sup|φ''|` of the accepted segments.
    pub(super) curvature_bound: f64,
    /// Smallest proven lower bound of `Γ'` over the accepted segments.
    pub(super) min_slope: f64,
}

impl Search<'_, '_> {
    /// Accepts `[a, b]` (`v_a = Γ(a)`, `v_b = Γ(b)`) as a segment if its proven bound meets the goal,
    /// halves it otherwise (at most `depth` times).
    pub(super) fn split(&mut self, a: f64, b: f64, va: f64, vb: f64, depth: u32) -> Result<(), TableError> {
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
pub(super) struct Sup {
    /// Upper bound of `|Γ''| / Γ'³`.
    pub(super) curvature: f64,
    /// Lower bound of `Γ'` (positive).
    pub(super) min_slope: f64,
}

/// Termwise interval bounds of `Γ'` (lower) and `|Γ''|` (upper) on `[a, b]`.
pub(super) fn interval_bounds(gamma: &Gamma<'_, f64>, a: f64, b: f64) -> (f64, f64) {
    let (mut slope_low, mut slope_size) = (0.0, 0.0);
    let (mut bend_low, mut bend_high, mut bend_size) = (0.0, 0.0, 0.0);
    for (&m, &c) in gamma.mu.iter().zip(gamma.odds_ratios) {
        let w = weight(m, c);
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
pub(super) fn pointwise_curvature(gamma: &Gamma<'_, f64>, eta: f64) -> f64 {
    let (slope, bend) = interval_bounds(gamma, eta, eta);
    bend / (slope * slope * slope)
}

/// A proven upper bound of `|Γ''|/Γ'³` on `[a, b]`, halving the interval (at most `depth` times)
/// where the termwise lower bound of `Γ'` is not positive, or where the bound exceeds `budget` while
/// still more than 1 % above the pointwise values at the ends and the middle (once it is that tight,
/// halving cannot bring it under the budget: the segment is too long, and splitting would only
/// multiply the work).
pub(super) fn sup_curvature(
    gamma: &Gamma<'_, f64>,
    a: f64,
    b: f64,
    budget: f64,
    depth: u32,
) -> Result<Sup, TableError> {
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
