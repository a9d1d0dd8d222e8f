//! Where `Γ` must be increasing: the grid the QP constrains, and the much finer check afterwards.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(x > y)` is deliberate: a NaN must fail the check.

/// `Γ` is not strictly increasing at `eta` (as far as the check grid shows).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("Γ is not strictly increasing: Γ'({eta}) = {slope}")]
pub struct NotMonotone {
    /// Where.
    pub eta: f64,
    /// The slope there.
    pub slope: f64,
}

/// Chebyshev–Lobatto points on `[0, 1]`: clustered at both ends, where the steepest basis functions
/// bend (a uniform grid lets `Γ` turn non-monotone between points once `β ≥ 2`).
pub fn monotonicity_grid(points: usize) -> Vec<f64> {
    (0..points)
        .map(|q| 0.5 * (1.0 - (std::f64::consts::PI * q as f64 / (points - 1) as f64).cos()))
        .collect()
}

/// The grid `Γ` is checked on after the solve: 20 001 uniform points, 4 001 Chebyshev points and
/// geometric sequences down to 1e-15 from both ends.
pub fn check_grid() -> Vec<f64> {
    let mut grid: Vec<f64> = (0..=20_000).map(|i| i as f64 / 20_000.0).collect();
    grid.extend(monotonicity_grid(4001));
    for k in 8..=120 {
        let d = 10f64.powf(-(k as f64) / 8.0);
        grid.extend([d, 1.0 - d]);
    }
    grid.sort_by(f64::total_cmp);
    grid.dedup();
    grid
}

/// Strict monotonicity of `Γ`: `Γ' > 0` at every point of [`check_grid`], and `Γ` increasing from
/// each point to the next of a uniform grid of step 5e-5 (values of points closer than that may tie
/// in floating point). Returns the smallest slope.
pub fn check_strictly_increasing(gamma: &firmware::Gamma<'_, f64>) -> Result<f64, NotMonotone> {
    let mut min_slope = f64::INFINITY;
    for eta in check_grid() {
        let slope = gamma.slope(eta);
        if !(slope > 0.0) {
            return Err(NotMonotone { eta, slope });
        }
        min_slope = min_slope.min(slope);
    }
    let mut previous = f64::NEG_INFINITY;
    for i in 0..=20_000 {
        let eta = i as f64 / 20_000.0;
        let value = gamma.value(eta);
        if !(value > previous) {
            return Err(NotMonotone {
                eta,
                slope: gamma.slope(eta),
            });
        }
        previous = value;
    }
    Ok(min_slope)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_decreasing_gamma_is_refused() {
        // Γ(η) = 2η - 3B(η; c = 4) has Γ'(0) = 2 - 12 < 0 (w = μ c).
        let (mu, b) = ([2.0, -3.0], [1.0, 4.0]);
        let gamma = firmware::Gamma {
            offset: 0.0,
            mu: &mu,
            odds_ratios: &b,
        };
        assert!(matches!(check_strictly_increasing(&gamma), Err(NotMonotone { .. })));
        // A dip that only a fine grid sees: the slope is negative on a sliver of width 2e-5 at η = 1.
        let (mu, b) = ([1.0, -1e-4], [1.0, 1e-5]);
        let gamma = firmware::Gamma {
            offset: 0.0,
            mu: &mu,
            odds_ratios: &b,
        };
        assert!(gamma.slope(0.5) > 0.0 && gamma.slope(0.9999) > 0.0);
        assert!(matches!(check_strictly_increasing(&gamma), Err(NotMonotone { .. })));
        let (mu, b) = ([1.0, 0.5], [1.0, 4.0]);
        let gamma = firmware::Gamma {
            offset: 0.0,
            mu: &mu,
            odds_ratios: &b,
        };
        assert!(check_strictly_increasing(&gamma).is_ok());
    }

    #[test]
    fn grids_cluster_at_the_ends() {
        let grid = monotonicity_grid(201);
        assert_eq!((grid[0], grid[200]), (0.0, 1.0));
        assert!(grid[1] < 1e-4 && 1.0 - grid[199] < 1e-4);
        assert!(grid.windows(2).all(|p| p[1] > p[0]));
        let check = check_grid();
        assert!(check.len() > 20_000 && check[1] <= 1e-15 && 1.0 - check[check.len() - 2] <= 1e-15);
    }
}
