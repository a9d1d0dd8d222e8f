//! The integer map on a data set: each window's samples converted to raw counts as a converter
//! would (rounded, clamped to its range), the chip's integer code run on them ([`firmware::fixed`]),
//! and the result held against the f64 map on the values those counts stand for (the bound) and
//! against the true targets (the accuracy).

use super::{to_raw, FixedPoint};
use crate::data::DataSet;
use crate::fit::maps::FittedMap;

/// What [`compare`] found, per target.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// Windows compared (those with every value finite).
    pub windows: usize,
    /// Samples a converter would have clamped to its range (counted once per window they are in).
    pub clamped: usize,
    /// One per target.
    pub targets: Vec<TargetComparison>,
}

/// One target's figures over the windows, target units.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetComparison {
    /// Root mean square of `fixed − true target`.
    pub rmse: f64,
    /// Largest `|fixed − true target|`.
    pub max_error: f64,
    /// Largest `|fixed − f64 map|`: what the proven bound covers.
    pub largest_difference: f64,
    /// The windows, by index in the data set's order, where `|fixed − f64 map|` exceeds the bound.
    pub beyond_bound: Vec<usize>,
}

/// The integer maps of `fixed` (with `maps`, the f64 maps they were made from) on every window of
/// `data`.
pub fn compare(fixed: &FixedPoint, maps: &[FittedMap], data: &DataSet) -> Comparison {
    let scales: Vec<_> = fixed.outputs.iter().chain(&fixed.inputs).collect();
    let (ny, n) = (fixed.outputs.len(), data.horizon);
    let mut comparison = Comparison {
        windows: 0,
        clamped: 0,
        targets: vec![
            TargetComparison {
                rmse: 0.0,
                max_error: 0.0,
                largest_difference: 0.0,
                beyond_bound: Vec::new(),
            };
            maps.len()
        ],
    };
    let (mut z, mut raw, mut values) = (Vec::new(), Vec::new(), Vec::new());
    for (index, window) in data.windows().enumerate() {
        data.regressor(window, &mut z);
        raw.clear();
        values.clear();
        for (i, &v) in z.iter().enumerate() {
            let scale = scales[if i < n * ny {
                i % ny.max(1)
            } else {
                ny + (i - n * ny) % (scales.len() - ny).max(1)
            }];
            let Some(count) = to_raw(v, scale) else { break };
            comparison.clamped += usize::from(((v - scale.offset) / scale.scale).round() != f64::from(count));
            raw.push(count);
            values.push(scale.offset + scale.scale * f64::from(count));
        }
        if raw.len() != z.len() {
            continue; // a non-finite value: the chip refuses the sample
        }
        comparison.windows += 1;
        for (t, ((target, map), figures)) in fixed.targets.iter().zip(maps).zip(&mut comparison.targets).enumerate() {
            let estimate = f64::from(target.as_firmware().estimate(&raw).value) * target.lsb();
            let reference = map.exact_estimate(&values).value;
            let error = estimate - data.target(window, t);
            figures.rmse += error * error;
            figures.max_error = figures.max_error.max(error.abs());
            let difference = (estimate - reference).abs();
            figures.largest_difference = figures.largest_difference.max(difference);
            if difference.is_nan() || difference > target.bound.total() {
                figures.beyond_bound.push(index);
            }
        }
    }
    for figures in &mut comparison.targets {
        figures.rmse = (figures.rmse / comparison.windows.max(1) as f64).sqrt();
    }
    comparison
}
