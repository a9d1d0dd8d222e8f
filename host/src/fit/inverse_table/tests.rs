//! Tests of the tables and their proof: closed forms, interval bounds against finite differences.

use super::proof::interval_bounds;
use super::*;
use firmware::basis;

fn gamma_of<'a>(mu: &'a [f64], odds_ratios: &'a [f64], offset: f64) -> Gamma<'a, f64> {
    Gamma {
        offset,
        mu,
        odds_ratios,
    }
}

#[test]
fn interval_bounds_enclose_the_derivatives_of_a_mixed_sign_gamma() {
    // Weights of both signs (cancelling terms), as Example 1's x1 has.
    let c: Vec<f64> = basis::paper_odds_ratios(5, 0.5).collect();
    let mu = [-0.62, 0.52, -0.29, 0.08, 0.56, -0.35, 0.12, -0.012];
    let gamma = gamma_of(&mu, &c, 0.0);
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
    let (mu, odds_ratios) = ([1.0], [c]);
    let gamma = gamma_of(&mu, &odds_ratios, 0.0);
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
    let gamma = gamma_of(&[2.0, -3.0], &[1.0, 4.0], 0.0);
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
    let (mu, odds_ratios) = ([1.0], [c]);
    let gamma = gamma_of(&mu, &odds_ratios, 0.0);
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
    let (mu, odds_ratios) = ([1.0], [c]);
    let gamma = gamma_of(&mu, &odds_ratios, 0.0);
    match InverseTable::certify(&gamma, &[1.0], (0.0, 1.0), 1e-9) {
        Err(TableError::TooManySegments { limit }) => assert_eq!(limit, MAX_SEGMENTS),
        other => panic!("{:?}", other.map(|t| t.segments.len())),
    }
}
