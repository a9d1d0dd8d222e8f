//! The particles' weights: normalising, the effective count, tempering, systematic resampling and
//! the cloud's spread for the moves.

use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// A Cholesky factor of the cloud's covariance over the coordinates `coordinates` (a constant
/// coordinate: a tiny variance); `None` when not finite.
pub(super) fn spread(x: &[Vec<f64>], coordinates: &[usize]) -> Option<nalgebra::DMatrix<f64>> {
    let m = x.first().map_or(0, Vec::len) as f64;
    let mean: Vec<f64> = coordinates.iter().map(|&i| x[i].iter().sum::<f64>() / m).collect();
    let covariance = nalgebra::DMatrix::from_fn(coordinates.len(), coordinates.len(), |a, b| {
        let (i, j) = (coordinates[a], coordinates[b]);
        let c = (x[i].iter().zip(&x[j]))
            .map(|(p, q)| (p - mean[a]) * (q - mean[b]))
            .sum::<f64>()
            / m;
        if a == b {
            c + 1e-24 * (1.0 + mean[a] * mean[a])
        } else {
            c
        }
    });
    Some(covariance.cholesky()?.l())
}

/// Normalised weights from log-weights; equal when none is finite (every particle lost: none
/// explains the samples).
pub(super) fn normalised(log_weights: &[f64]) -> Vec<f64> {
    let top = log_weights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !top.is_finite() {
        return vec![1.0 / log_weights.len() as f64; log_weights.len()];
    }
    let mut weights: Vec<f64> = log_weights.iter().map(|&lw| (lw - top).exp()).collect();
    let total: f64 = weights.iter().sum();
    weights.iter_mut().for_each(|w| *w /= total);
    weights
}

/// The effective count `1 / Σ w²` of normalised weights.
pub(super) fn effective(weights: &[f64]) -> f64 {
    1.0 / weights.iter().map(|w| w * w).sum::<f64>()
}

/// The effective count of `w e^{exponent ℓ}`, `(Σ v)² / Σ v²` (0 when no weight is left).
pub(super) fn effective_tempered(log_weights: &[f64], likelihood: &[f64], exponent: f64) -> f64 {
    let tempered = |(&lw, &l): (&f64, &f64)| if exponent > 0.0 { lw + exponent * l } else { lw };
    let pairs = || log_weights.iter().zip(likelihood).map(tempered);
    let top = pairs().fold(f64::NEG_INFINITY, f64::max);
    if !top.is_finite() {
        return 0.0;
    }
    let (sum, squares) = pairs().fold((0.0, 0.0), |(s, q), v| {
        let e = (v - top).exp();
        (s + e, q + e * e)
    });
    sum * sum / squares
}

/// `w ← w e^{exponent ℓ}` in logarithms (nothing for a zero exponent, whatever `ℓ`).
pub(super) fn temper(log_weights: &mut [f64], likelihood: &[f64], exponent: f64) {
    if exponent > 0.0 {
        for (lw, &l) in log_weights.iter_mut().zip(likelihood) {
            *lw += exponent * l;
        }
    }
}

/// Systematic resampling: each particle's index among the `M` picked by `weights` (normalised).
pub(super) fn systematic(weights: &[f64], rng: &mut ChaCha8Rng) -> Vec<usize> {
    let m = weights.len();
    let offset: f64 = rng.random::<f64>();
    let mut picked = Vec::with_capacity(m);
    let (mut cumulative, mut p) = (weights[0], 0);
    for j in 0..m {
        let point = (j as f64 + offset) / m as f64;
        while point > cumulative && p + 1 < m {
            p += 1;
            cumulative += weights[p];
        }
        picked.push(p);
    }
    picked
}
