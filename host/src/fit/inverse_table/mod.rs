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

mod error;
mod proof;
#[cfg(test)]
mod tests;

use firmware::Gamma;
use serde::{Deserialize, Serialize};

pub use error::TableError;
use proof::{node_error, nodes_and_bound, pointwise_curvature, Search};

/// The rows `(a_k, b_k)` of uniform segments through the knots `nodes` (in `η`), for `r ∈ [r_min, r_max]`:
/// `r = a_k + b_k t` on `t ∈ [k, k + 1]`.
fn uniform_segments((r_min, r_max): (f64, f64), nodes: &[f64]) -> Vec<[f64; 2]> {
    let span = r_max - r_min;
    nodes
        .windows(2)
        .enumerate()
        .map(|(k, pair)| {
            let (r0, r1) = (r_min + span * pair[0], r_min + span * pair[1]);
            let slope = r1 - r0;
            [r0 - slope * k as f64, slope]
        })
        .collect()
}

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

/// `Γ⁻¹` as the chip evaluates it (see the module docs), with its certificate.
#[derive(Clone, Debug, Serialize, Deserialize)]
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

    /// An unproven table, to rank candidates in the design search ([`crate::search`]) where the proof
    /// would cost 90 % of the time: uniform knots, as many as the pointwise curvature estimate asks
    /// (the count [`InverseTable::uniform`] starts from, at most [`MAX_SEGMENTS`]), no proof and no dense
    /// confirmation (`proven_bound` and `sampled_error` are NaN). Never emitted: the chosen candidate is
    /// fitted again with [`InverseTable::certify`].
    pub fn sketch(gamma: &Gamma<'_, f64>, gains: &[f64], range: (f64, f64), relative_tolerance: f64) -> Self {
        let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
        let curvature = (0..=8192)
            .map(|i| pointwise_curvature(gamma, i as f64 / 8192.0))
            .fold(0.0, f64::max);
        let estimate = ((v1 - v0) * (curvature / (8.0 * relative_tolerance)).sqrt()).ceil();
        let segments = if estimate >= 1.0 {
            estimate.min(MAX_SEGMENTS as f64) as usize
        } else {
            1
        };
        let nodes = proof::uniform_nodes(gamma, segments);
        let mut table = Self::unconfirmed(
            gamma,
            gains,
            range,
            segments as f64,
            None,
            uniform_segments(range, &nodes),
            f64::NAN,
        );
        table.sampled_error = f64::NAN;
        table
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
        let count = nodes.len() - 1;
        let segments = uniform_segments((r_min, r_max), nodes);
        Self::assemble(gamma, gains, (r_min, r_max), count as f64, None, segments, bound_eta)
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
        let starts = Some(t[..t.len() - 1].to_vec());
        Self::assemble(gamma, gains, (r_min, r_max), 1.0, starts, segments, bound_eta)
    }

    /// The table of `segments` (with their `starts` for searched knots) over `t ∈ [0, t_max]`: gains
    /// and offset scaled so that the dot product gives `t`, then confirmed densely.
    fn assemble(
        gamma: &Gamma<'_, f64>,
        gains: &[f64],
        range: (f64, f64),
        t_max: f64,
        starts: Option<Vec<f64>>,
        segments: Vec<[f64; 2]>,
        bound_eta: f64,
    ) -> Result<Self, TableError> {
        Self::unconfirmed(gamma, gains, range, t_max, starts, segments, bound_eta).confirmed(gamma)
    }

    /// [`InverseTable::assemble`] without the dense confirmation (`sampled_error` 0).
    fn unconfirmed(
        gamma: &Gamma<'_, f64>,
        gains: &[f64],
        (r_min, r_max): (f64, f64),
        t_max: f64,
        starts: Option<Vec<f64>>,
        segments: Vec<[f64; 2]>,
        bound_eta: f64,
    ) -> Self {
        let (v0, v1) = (gamma.value(0.0), gamma.value(1.0));
        let scale = t_max / (v1 - v0);
        InverseTable {
            gains: gains.iter().map(|g| g * scale).collect(),
            offset: -v0 * scale,
            starts,
            segments,
            r_min,
            r_max,
            proven_bound: bound_eta * (r_max - r_min),
            sampled_error: 0.0,
        }
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
