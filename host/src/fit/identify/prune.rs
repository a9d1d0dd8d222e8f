//! Sparse `L` (the paper's future work): fewer taps, fewer multiply-adds on the chip.
//!
//! Backward elimination guided by the multipliers. For fixed `μ` the best `L` on a support `S` is
//! least squares, and forcing tap `j` to zero raises the objective by exactly
//!
//! ```text
//! Δ_j = l_j² / [(Z̃_Sᵀ Z̃_S)⁻¹]_jj = l_j² / ‖row j of R_SS⁻¹‖²,
//! ```
//!
//! the multiplier of the constraint `l_j = 0` times half the step it forces. The tap with the smallest
//! `Δ_j` goes, one at a time; `μ` is re-fitted (the QP on the smaller support) at every point of a
//! fixed [`schedule`] (`n_z`, then ×¾ each time), so that `Γ` follows the shrinking support. A
//! requested count between two schedule points branches off the path, prunes to the count with the
//! last `μ` and solves its own QP: the support of a count never depends on which other counts were
//! asked for, so the design search and `gen` get the same map.
//!
//! The intercept (normalisation `intercept`) is never pruned; pruned gains are exactly 0, which the
//! emitted code skips.

use nalgebra::{DMatrix, DVector};

pub use crate::spec::search::{auto_counts, schedule};

use super::{Fit, FitError, Learning};
use crate::fit::maps::Tabulation;

/// One fit per entry of `counts` (taps kept per target; a count of at least `n_z` is the dense fit),
/// in the same order, from one elimination path.
pub(crate) fn fit_path(
    learning: &Learning<'_>,
    counts: &[usize],
    target_name: &str,
    tabulation: Tabulation,
) -> Result<Vec<Fit>, FitError> {
    let n_z = learning.regressor_len();
    let mut wanted: Vec<usize> = counts.iter().map(|&c| c.clamp(1, n_z)).collect();
    wanted.sort_unstable_by(|a, b| b.cmp(a));
    wanted.dedup();
    let smallest = *wanted.last().unwrap_or(&n_z);
    let mut fits: Vec<(usize, Fit)> = Vec::new();

    let mut support = learning.dense();
    let dense = learning.fit(&support, target_name, fit_tabulation(&wanted, n_z, tabulation))?;
    let mut mu = DVector::from_column_slice(&dense.certificate.mu);
    if wanted.contains(&n_z) {
        fits.push((n_z, dense));
    }
    for point in schedule(n_z).into_iter().skip(1) {
        for &count in wanted.iter().filter(|&&c| point < c && c < support.len()) {
            let branch = prune_to(learning, support.clone(), &mu, count)?;
            fits.push((count, learning.fit(&branch, target_name, tabulation)?));
        }
        if point < smallest {
            break;
        }
        support = prune_to(learning, support, &mu, point)?;
        let fit = learning.fit(&support, target_name, fit_tabulation(&wanted, point, tabulation))?;
        mu = DVector::from_column_slice(&fit.certificate.mu);
        if wanted.contains(&point) {
            fits.push((point, fit));
        }
    }
    Ok(counts
        .iter()
        .map(|&c| {
            let c = c.clamp(1, n_z);
            fits.iter()
                .find(|(count, _)| *count == c)
                .expect("every count was fitted")
                .1
                .clone()
        })
        .collect())
}

/// A refit only needed for its `μ` does not need a certified table.
fn fit_tabulation(wanted: &[usize], count: usize, tabulation: Tabulation) -> Tabulation {
    if wanted.contains(&count) {
        tabulation
    } else {
        Tabulation::Sketched
    }
}

/// Removes the tap with the smallest `Δ_j` (see the module's documentation) until `count` remain.
fn prune_to(
    learning: &Learning<'_>,
    mut support: Vec<usize>,
    mu: &DVector<f64>,
    count: usize,
) -> Result<Vec<usize>, FitError> {
    while support.len() > count {
        let costs = deletion_costs(learning, &support, mu)?;
        let cheapest = (0..costs.len())
            .min_by(|&a, &b| costs[a].total_cmp(&costs[b]))
            .expect("a support being pruned has taps");
        support.remove(cheapest);
    }
    Ok(support)
}

/// `Δ_j` of every tap of `support`, for fixed `μ` (in the factor's `μ` columns).
pub(super) fn deletion_costs(
    learning: &Learning<'_>,
    support: &[usize],
    mu: &DVector<f64>,
) -> Result<Vec<f64>, FitError> {
    // The L block of the support's factor and its coupling to μ (no whitening needed here).
    let factor = learning.factor_of(support);
    let l_count = support.len() + usize::from(!learning.with_constant());
    let r_ll = factor.view((0, 0), (l_count, l_count));
    let r_lmu = factor.view((0, l_count), (l_count, mu.len()));
    let l = r_ll
        .solve_upper_triangular(&(r_lmu * mu))
        .ok_or(FitError::DependentRegressor { column: support[0] })?;
    let inverse = r_ll
        .solve_upper_triangular(&DMatrix::identity(l_count, l_count))
        .ok_or(FitError::DependentRegressor { column: support[0] })?;
    Ok((0..support.len())
        .map(|j| l[j] * l[j] / inverse.row(j).norm_squared())
        .collect())
}

#[cfg(test)]
mod tests {
    use super::super::tests::{pairs, settings, synthetic};
    use super::*;
    use crate::data::{Column, DataSet, Window};
    use crate::fit::identify::basis_of;
    use crate::spec::{MapSettings, Normalisation};
    use firmware::basis;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;
    use rand_distr::StandardNormal;

    #[test]
    fn the_schedule_shrinks_by_a_quarter_down_to_one_tap() {
        assert_eq!(schedule(16), vec![16, 12, 9, 7, 6, 5, 4, 3, 2, 1]);
        assert_eq!(schedule(1), vec![1]);
        assert_eq!(auto_counts(16), vec![16, 12, 9, 7, 6, 5, 4]);
        assert_eq!(auto_counts(10), vec![10, 8, 6, 5, 4, 3]);
    }

    /// The known map of [`synthetic`] (taps 0–2) with two more regressor entries it does not read:
    /// entries 1 and 3 are noise, so the true support is {0, 2, 4}.
    fn padded(seed: u64, count: usize) -> DataSet {
        let mut rng = ChaCha8Rng::seed_from_u64(seed + 100);
        let samples = synthetic(seed, count)
            .into_iter()
            .map(|(z, r)| {
                let mut noise = || rng.sample::<f64, _>(StandardNormal);
                (vec![z[0], noise(), z[1], noise(), z[2]], r)
            })
            .collect::<Vec<_>>();
        pairs(&samples)
    }

    #[test]
    fn deletion_costs_are_the_rise_of_an_independent_refit() {
        let data = padded(5, 300);
        for normalisation in [Normalisation::Intercept, Normalisation::Paper] {
            let settings = settings(normalisation, 3, 1.0, 0.01);
            let odds_ratios = basis_of(&settings);
            let learning = Learning::gather(&data, Column::Target(0), &settings, &odds_ratios).unwrap();
            let dense = learning.fit(&learning.dense(), "r", Tabulation::Sketched).unwrap();
            let mu = DVector::from_column_slice(&dense.certificate.mu);
            let support = [0, 1, 3, 4];
            let costs = deletion_costs(&learning, &support, &mu).unwrap();
            // Independently: least squares of B(η) μ on the raw columns, with and without each tap.
            let windows: Vec<Window> = data.windows().collect();
            let (r_min, r_max) = (dense.map.r_min, dense.map.r_max);
            let mut z = Vec::new();
            let mut rows = Vec::new();
            let mut target = Vec::new();
            for &w in &windows {
                data.regressor(w, &mut z);
                let eta = (data.target(w, 0) - r_min) / (r_max - r_min);
                let basis: Vec<f64> = odds_ratios.iter().map(|&c| basis::value(c, eta)).collect();
                let with_constant = normalisation == Normalisation::Paper;
                let values: Vec<f64> = with_constant.then_some(1.0).into_iter().chain(basis).collect();
                target.push(values.iter().zip(mu.iter()).map(|(b, m)| b * m).sum::<f64>());
                rows.push(z.clone());
            }
            let rss = |taps: &[usize]| {
                let with_constant = normalisation == Normalisation::Paper;
                let columns = taps.len() + usize::from(!with_constant);
                let a = DMatrix::from_fn(rows.len(), columns, |i, j| taps.get(j).map_or(1.0, |&t| rows[i][t]));
                let b = DVector::from_column_slice(&target);
                let x = a.clone().svd(true, true).solve(&b, 1e-14).unwrap();
                (a * x - b).norm_squared()
            };
            let full = rss(&support);
            for (j, cost) in costs.iter().enumerate() {
                let without: Vec<usize> = support.iter().copied().filter(|&t| t != support[j]).collect();
                let rise = rss(&without) - full;
                assert!(
                    (cost - rise).abs() <= 1e-8 * rise.abs().max(full),
                    "{normalisation:?} tap {}: Δ = {cost}, refit rise {rise}",
                    support[j]
                );
            }
        }
    }

    #[test]
    fn pruning_keeps_the_taps_the_map_reads_and_recovers_it() {
        let data = padded(6, 600);
        let settings = MapSettings {
            taps: Some(3),
            ..settings(Normalisation::Intercept, 3, 1.0, 0.01)
        };
        let fit = super::super::fit(&data, 0, "r", &settings, &basis_of(&settings)).unwrap();
        let kept: Vec<usize> = (0..5).filter(|&i| fit.map.gains[i] != 0.0).collect();
        assert_eq!(kept, vec![0, 2, 4], "gains {:?}", fit.map.gains);
        let fresh = padded(7, 200);
        let mut z = Vec::new();
        for w in fresh.windows().skip(2) {
            fresh.regressor(w, &mut z);
            let error = fit.map.exact_estimate(&z).value - fresh.target(w, 0);
            assert!(error.abs() < 1e-5, "{error}");
        }
        // Its linear floor reads the same taps: least squares on them, solved independently.
        let windows: Vec<Window> = data.windows().collect();
        let a = DMatrix::from_fn(windows.len(), 4, |i, j| {
            data.regressor(windows[i], &mut z);
            [z[0], z[2], z[4], 1.0][j]
        });
        let b = DVector::from_iterator(windows.len(), windows.iter().map(|&w| data.target(w, 0)));
        let x = a.svd(true, true).solve(&b, 1e-14).unwrap();
        let floor = &fit.linear;
        assert_eq!((floor.gains[1], floor.gains[3]), (0.0, 0.0));
        for (got, want) in [floor.gains[0], floor.gains[2], floor.gains[4], floor.intercept]
            .iter()
            .zip(x.iter())
        {
            assert!((got - want).abs() < 1e-9 * x.amax(), "{got} vs {want}");
        }
        // The bound bites: one tap too few cannot recover the map.
        let two = MapSettings {
            taps: Some(2),
            ..settings
        };
        let fit = super::super::fit(&data, 0, "r", &two, &basis_of(&two)).unwrap();
        let worst = fresh
            .windows()
            .skip(2)
            .map(|w| {
                fresh.regressor(w, &mut z);
                (fit.map.exact_estimate(&z).value - fresh.target(w, 0)).abs()
            })
            .fold(0.0, f64::max);
        assert!(worst > 1e-2, "{worst}");
    }

    #[test]
    fn a_count_is_fitted_the_same_whichever_other_counts_are_asked_for() {
        let data = padded(8, 300);
        let settings = settings(Normalisation::Intercept, 3, 1.0, 0.01);
        let odds_ratios = basis_of(&settings);
        let learning = Learning::gather(&data, Column::Target(0), &settings, &odds_ratios).unwrap();
        let alone = fit_path(&learning, &[2], "r", Tabulation::Sketched).unwrap();
        let together = fit_path(&learning, &[5, 4, 2], "r", Tabulation::Sketched).unwrap();
        assert_eq!(alone[0].map.gains, together[2].map.gains);
        assert_eq!(together[0].map.gains.iter().filter(|&&g| g != 0.0).count(), 5);
        assert_eq!(together[1].map.gains.iter().filter(|&&g| g != 0.0).count(), 4);
    }
}
