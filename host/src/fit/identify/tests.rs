//! Tests of the identification: KKT conditions, invariances, recovery of a map of the model's class.

use super::*;

/// [`super::fit`] with the basis of `settings`, as [`crate::fit::run`] builds it once per design.
fn fit(data: &DataSet, target: usize, name: &str, settings: &MapSettings) -> Result<Fit, FitError> {
    super::fit(data, target, name, settings, &basis_of(settings))
}
use crate::data::{Run, Window};
use crate::spec::Normalisation;
use nalgebra::{DMatrix, DVector};
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;

/// A data set with horizon 1 whose "measurements" are the given regressors.
pub(super) fn pairs(samples: &[(Vec<f64>, f64)]) -> DataSet {
    let run = Run {
        states: vec![vec![]; samples.len()].into(),
        inputs: vec![vec![]; samples.len()].into(),
        measurements: samples.iter().map(|s| s.0.clone()).collect(),
        targets: samples.iter().map(|s| vec![s.1]).collect(),
        parameters: Vec::new(),
    };
    DataSet {
        runs: vec![run],
        horizon: 1,
    }
}

pub(super) fn settings(normalisation: Normalisation, nm: usize, beta: f64, epsilon: f64) -> MapSettings {
    MapSettings {
        horizon: 1,
        nm,
        beta,
        epsilon,
        normalisation,
        monotonicity_grid: 201,
        taps: None,
    }
}

/// Regressors and targets of a known map r = 3 + 2 Γ⁻¹(Lᵀ Z), Γ from the same basis family.
pub(super) fn synthetic(seed: u64, count: usize) -> Vec<(Vec<f64>, f64)> {
    let odds_ratios: Vec<f64> = basis::paper_odds_ratios(3, 1.0).collect();
    let mu = [0.2, 1.5, 0.1, 0.8];
    let gamma = firmware::Gamma {
        offset: 0.0,
        mu: &mu,
        odds_ratios: &odds_ratios,
    };
    let gains = [0.7, -0.4, 0.25];
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut samples = Vec::new();
    // Two samples at η = 0 and η = 1 exactly, so that r_min and r_max are 3 and 5.
    for v in [gamma.value(0.0), gamma.upper()] {
        let mut z: Vec<f64> = (0..3).map(|_| rng.sample::<f64, _>(StandardNormal)).collect();
        z[0] = (v - gains[1] * z[1] - gains[2] * z[2]) / gains[0];
        samples.push((z, 3.0 + 2.0 * gamma.inverse(v).eta));
    }
    while samples.len() < count {
        let z: Vec<f64> = (0..3).map(|_| 2.0 * rng.sample::<f64, _>(StandardNormal)).collect();
        let v: f64 = gains.iter().zip(&z).map(|(g, z)| g * z).sum();
        let inverse = gamma.inverse(v);
        if !inverse.saturation.is_saturated() {
            samples.push((z, 3.0 + 2.0 * inverse.eta));
        }
    }
    samples
}

#[test]
fn recovers_a_map_of_its_own_class() {
    let learning = synthetic(1, 600);
    let fit = fit(
        &pairs(&learning),
        0,
        "r",
        &settings(Normalisation::Intercept, 3, 1.0, 0.01),
    )
    .unwrap();
    let fresh = synthetic(2, 300);
    let table = fit.map.table.as_ref().expect("a certified table");
    for (z, r) in fresh.iter().skip(2) {
        let exact = fit.map.exact_estimate(z);
        assert!((exact.value - r).abs() < 1e-5, "estimate {} vs truth {r}", exact.value);
        // The library estimate is the table: within its proven bound of the exact inverse.
        let tabulated = fit.map.estimate(z);
        assert!((tabulated.value - exact.value).abs() <= table.proven_bound + 1e-12);
    }
    // The linear floor cannot: Γ is far from a line.
    let worst_linear = fresh
        .iter()
        .map(|(z, r)| (fit.linear.estimate(z) - r).abs())
        .fold(0.0, f64::max);
    assert!(worst_linear > 1e-2, "{worst_linear}");
}

#[test]
fn linear_floor_matches_an_independent_least_squares_solve() {
    let samples = synthetic(3, 400);
    let fit = fit(
        &pairs(&samples),
        0,
        "r",
        &settings(Normalisation::Intercept, 3, 1.0, 0.01),
    )
    .unwrap();
    let a = DMatrix::from_fn(samples.len(), 4, |i, j| if j < 3 { samples[i].0[j] } else { 1.0 });
    let b = DVector::from_iterator(samples.len(), samples.iter().map(|s| s.1));
    let x = a.clone().svd(true, true).solve(&b, 1e-14).unwrap();
    for j in 0..3 {
        assert!(
            (fit.linear.gains[j] - x[j]).abs() < 1e-10 * x.amax(),
            "{} vs {}",
            fit.linear.gains[j],
            x[j]
        );
    }
    assert!((fit.linear.intercept - x[3]).abs() < 1e-10 * x.amax());
}

/// Checks the KKT conditions of a fit against matrices built directly from the data: the reduced
/// gradient `2/n_E (P⊥B)ᵀ (P⊥B) μ`, with `P⊥` the projector off `Z`'s columns by an SVD solve.
fn assert_kkt(data: &DataSet, settings: &MapSettings) {
    let fit = fit(data, 0, "r", settings).unwrap();
    let c = &fit.certificate;
    let windows: Vec<Window> = data.windows().collect();
    let n_e = windows.len();
    let n_z = data.regressor_len();
    let (r_min, r_max) = (fit.map.r_min, fit.map.r_max);
    let odds_ratios = &fit.map.odds_ratios;
    let m = c.mu.len();
    let l_count = if c.with_constant { n_z } else { n_z + 1 };
    let mut z_matrix = DMatrix::zeros(n_e, l_count);
    let mut b_matrix = DMatrix::zeros(n_e, m);
    let mut z = Vec::new();
    for (i, &w) in windows.iter().enumerate() {
        data.regressor(w, &mut z);
        for j in 0..n_z {
            z_matrix[(i, j)] = z[j];
        }
        if !c.with_constant {
            z_matrix[(i, n_z)] = 1.0;
        }
        let eta = (data.target(w, 0) - r_min) / (r_max - r_min);
        let values: Vec<f64> = c
            .with_constant
            .then_some(1.0)
            .into_iter()
            .chain(odds_ratios.iter().map(|&b| basis::value(b, eta)))
            .collect();
        for j in 0..m {
            b_matrix[(i, j)] = values[j];
        }
    }
    let projected = &b_matrix - &z_matrix * z_matrix.clone().svd(true, true).solve(&b_matrix, 1e-13).unwrap();
    let mu = DVector::from_column_slice(&c.mu);
    let gradient = 2.0 / n_e as f64 * projected.transpose() * (&projected * &mu);
    let slope_row = |eta: f64| -> DVector<f64> {
        DVector::from_iterator(
            m,
            c.with_constant
                .then_some(0.0)
                .into_iter()
                .chain(odds_ratios.iter().map(|&b| basis::slope(b, eta))),
        )
    };
    let mut multiplier_term = DVector::zeros(m);
    let mut complementarity: f64 = 0.0;
    for (&eta, &lambda) in c.grid.iter().zip(&c.lambda) {
        let row = slope_row(eta);
        let slack = row.dot(&mu) - c.epsilon;
        assert!(
            slack >= -1e-6 * c.epsilon,
            "constraint at η = {eta} violated: slack {slack}"
        );
        assert!(lambda >= -1e-9, "negative multiplier {lambda}");
        complementarity = complementarity.max((lambda * slack).abs());
        multiplier_term += lambda * row;
    }
    if c.with_constant {
        let integral = DVector::from_iterator(
            m,
            std::iter::once(1.0).chain(odds_ratios.iter().map(|&b| basis::integral(b))),
        );
        assert!(
            (integral.dot(&mu) - c.mean).abs() < 1e-8 * (1.0 + c.mean.abs()),
            "equality violated"
        );
        multiplier_term += c.nu.unwrap() * integral;
    }
    let residual = (&gradient - &multiplier_term).norm();
    let scale = gradient.norm().max(multiplier_term.norm());
    assert!(
        residual <= 1e-5 * scale,
        "stationarity residual {residual} vs gradient {scale}"
    );
    assert!(complementarity <= 1e-6 * scale, "complementarity {complementarity}");
}

/// A window set with a real nonlinearity and noise: r = x, y = x³ + noise over a grid.
fn cubic(seed: u64) -> DataSet {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let samples: Vec<(Vec<f64>, f64)> = (0..800)
        .map(|_| {
            let x: f64 = rng.random_range(-1.5..1.5);
            let noise: f64 = rng.sample(StandardNormal);
            (vec![x * x * x + 0.05 * noise, x + 0.2 * noise], x)
        })
        .collect();
    pairs(&samples)
}

#[test]
fn kkt_conditions_hold_with_either_normalisation() {
    for normalisation in [Normalisation::Intercept, Normalisation::Paper] {
        for beta in [0.5, 2.0, 4.0] {
            assert_kkt(&cubic(5), &settings(normalisation, 5, beta, 0.05));
        }
    }
}

#[test]
fn intercept_fit_is_invariant_to_epsilon_and_to_a_shift_of_the_target() {
    let data = cubic(6);
    let mut shifted = data.clone();
    for t in shifted.runs[0].targets.iter_mut() {
        t[0] += 10.0;
    }
    let base = fit(&data, 0, "r", &settings(Normalisation::Intercept, 5, 1.0, 0.01)).unwrap();
    let other_epsilon = fit(&data, 0, "r", &settings(Normalisation::Intercept, 5, 1.0, 3.0)).unwrap();
    let moved = fit(&shifted, 0, "r", &settings(Normalisation::Intercept, 5, 1.0, 0.01)).unwrap();
    let mut z = Vec::new();
    for w in data.windows() {
        data.regressor(w, &mut z);
        let e = base.map.estimate(&z).value;
        assert!((other_epsilon.map.estimate(&z).value - e).abs() < 1e-9);
        assert!((moved.map.estimate(&z).value - 10.0 - e).abs() < 1e-9);
    }
    // The paper's normalisation is not shift-invariant: its estimates move.
    let paper = fit(&data, 0, "r", &settings(Normalisation::Paper, 5, 1.0, 0.01)).unwrap();
    let paper_moved = fit(&shifted, 0, "r", &settings(Normalisation::Paper, 5, 1.0, 0.01)).unwrap();
    let largest_change = data
        .windows()
        .map(|w| {
            data.regressor(w, &mut z);
            (paper_moved.map.estimate(&z).value - 10.0 - paper.map.estimate(&z).value).abs()
        })
        .fold(0.0, f64::max);
    assert!(largest_change > 1e-3, "{largest_change}");
}

#[test]
fn constant_target_is_an_error() {
    let samples: Vec<(Vec<f64>, f64)> = (0..50).map(|i| (vec![i as f64, 1.0 / (1.0 + i as f64)], 2.0)).collect();
    let error = fit(
        &pairs(&samples),
        0,
        "r",
        &settings(Normalisation::Intercept, 3, 1.0, 0.01),
    )
    .unwrap_err();
    assert!(matches!(error, FitError::ConstantTarget { value: 2.0 }), "{error:?}");
}
