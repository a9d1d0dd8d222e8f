//! The written-out sample against the library filter it writes out (`firmware::Ekf` over
//! `firmware::Rk4` of the same model, run by the host's interpreter), on a model with every construct
//! and on Example 1: equal, not merely close (a swapped index or a dropped term shows as O(0.1)).

use std::path::Path;

use firmware::{Ekf, Rk4};

use super::*;
use crate::observers::ekf::Stepped;
use crate::plant::program::Op;
use crate::plant::{Compiled, Covariance};
use crate::spec::ast::Binary;

/// Constants with `Q` diagonal, or full (`full_q`: the same diagonal, every other entry 2e-4, as a
/// spec may fix it).
fn constants(code: &ModelCode, substeps: usize, r: &[f64], full_q: bool) -> EkfConstants {
    let n = code.dimensions.states;
    let diagonal: Vec<f64> = (0..n).map(|i| 1e-3 * (i + 1) as f64).collect();
    let q = match full_q {
        true => Covariance::Full(
            (0..n)
                .map(|i| (0..n).map(|j| if i == j { diagonal[i] } else { 2e-4 }).collect())
                .collect(),
        ),
        false => Covariance::Diagonal(diagonal),
    };
    EkfConstants {
        x0: vec![0.0; n],
        p0: Covariance::Diagonal(vec![1.0; n]),
        q,
        r: r.to_vec(),
        substeps,
        h: 0.1 / substeps as f64,
        watch: crate::plant::kalman::Watch::OFF,
    }
}

/// A symmetric positive definite matrix from `seed`: `M Mᵀ + I/10`.
fn covariance<const N: usize>(seed: f64) -> [[f64; N]; N] {
    let m: [[f64; N]; N] = std::array::from_fn(|i| std::array::from_fn(|j| ((i * N + j) as f64 * 0.77 + seed).sin()));
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..N).map(|k| m[i][k] * m[j][k]).sum::<f64>() + if i == j { 0.1 } else { 0.0 })
    })
}

/// Largest |a - b| relative to max(1, |b|).
fn gap(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(a, b)| (a - b).abs() / b.abs().max(1.0))
        .fold(0.0, f64::max)
}

/// One sample of the written-out programs and of the library filter from the same `(x, P)`.
fn compare<const NX: usize, const NY: usize, const NU: usize>(
    code: &ModelCode,
    constants: &EkfConstants,
    x: [f64; NX],
    p: [[f64; NX]; NX],
    y: Option<[f64; NY]>,
    u: [f64; NU],
) -> f64 {
    let written = filter_code(code, constants);
    let triangle: Vec<f64> = (0..NX)
        .flat_map(|r| (r..NX).map(move |c| (r, c)))
        .map(|(r, c)| p[r][c])
        .collect();
    let (estimate, next, covariance) = written.run(&x, &triangle, y.as_ref().map(|y| &y[..]), &u, &mut Vec::new());

    let full = |c: &Covariance| std::array::from_fn(|i| std::array::from_fn(|j| c.entry(i, j)));
    let plant = Stepped {
        step: Rk4::new(Compiled::new(code), constants.h),
        substeps: constants.substeps,
    };
    let mut library: Ekf<f64, _, NX, NY, NU> =
        Ekf::new(plant, x, p, full(&constants.q), std::array::from_fn(|i| constants.r[i]));
    let pushed = library.push(&y.unwrap_or([f64::NAN; NY]), &u);
    let mut worst = gap(&next, &library.state());
    let full = library.covariance();
    let expected: Vec<f64> = (0..NX)
        .flat_map(|r| (r..NX).map(move |c| (r, c)))
        .map(|(r, c)| full[r][c])
        .collect();
    worst = worst.max(gap(&covariance, &expected));
    match (estimate, pushed) {
        (Some(e), Ok(l)) => worst.max(gap(&e, &l)),
        (None, Err(_)) => worst,
        (e, l) => panic!("written-out {e:?}, library {l:?}"),
    }
}

#[test]
fn the_written_out_sample_is_the_library_filters_on_every_construct() {
    let code = ModelCode::new(&crate::plant::tests::design()).unwrap();
    let mut worst = 0.0_f64;
    for (k, (x, u)) in crate::plant::tests::points().take(100).enumerate() {
        let y = [(k as f64 * 0.3).sin(), (k as f64 * 0.7).cos()];
        // `Q` diagonal, as tuned, and full, as a spec may fix it.
        for (substeps, full_q) in [(1, false), (3, false), (1, true), (3, true)] {
            let c = constants(&code, substeps, &[0.1, 0.2], full_q);
            worst = worst.max(compare::<3, 2, 1>(&code, &c, x, covariance(k as f64), Some(y), u));
            worst = worst.max(compare::<3, 2, 1>(&code, &c, x, covariance(k as f64), None, u));
        }
    }
    // The same operations in the same order; the folded `0·a`, `1·a`, `0 + a` are exact for finite
    // values: the same numbers, not merely close ones.
    assert!(worst == 0.0, "written-out vs library: {worst:e}");
}

#[test]
fn the_written_out_sample_is_the_library_filters_on_example_1() {
    let design = crate::spec::load(Path::new("specs/vanderpol.toml")).unwrap();
    let code = ModelCode::new(&design).unwrap();
    let c = constants(&code, 1, &[0.2], false);
    let mut worst = 0.0_f64;
    for k in 0..200 {
        let t = k as f64;
        let x = [2.0 * (0.31 * t).sin(), 5.0 * (0.17 * t).cos()];
        worst = worst.max(compare::<2, 1, 0>(
            &code,
            &c,
            x,
            covariance(t),
            Some([(0.5 * t).sin()]),
            [],
        ));
    }
    assert!(worst == 0.0, "written-out vs library: {worst:e}");
}

#[test]
fn a_noise_free_output_without_sensitivity_leaves_the_estimate_as_the_library_does() {
    // r = 0 and an output that does not see the state where P is 0: s = 0, no update (the library's
    // `continue`), where a plain division would give NaN.
    let design = crate::spec::load(Path::new("specs/vanderpol.toml")).unwrap();
    let code = ModelCode::new(&design).unwrap();
    let c = constants(&code, 1, &[0.0], false);
    let gap = compare::<2, 1, 0>(&code, &c, [0.3, -0.2], [[0.0; 2]; 2], Some([1.0]), []);
    assert!(gap == 0.0, "{gap:e}");
    let written = filter_code(&code, &c);
    assert!(written
        .measured
        .ops
        .iter()
        .any(|op| matches!(op, Op::Binary(Binary::Max, _, _))));
}

#[test]
fn structural_zeros_and_ones_cost_nothing() {
    let design = crate::spec::load(Path::new("specs/vanderpol.toml")).unwrap();
    let code = ModelCode::new(&design).unwrap();
    let written = filter_code(&code, &constants(&code, 1, &[0.2], false));
    let program = &written.measured;
    let number = |i: usize| match program.ops[i] {
        Op::Number(v) => Some(v),
        _ => None,
    };
    for op in &program.ops {
        if let Op::Binary(b, x, y) = *op {
            let trivial = |v: Option<f64>| v == Some(0.0) || (v == Some(1.0) && b == Binary::Mul);
            assert!(
                !(trivial(number(x)) || trivial(number(y))),
                "{op:?} with a structural 0 or 1 operand"
            );
        }
    }
    // Example 1's sample: 4 derivative evaluations, the Jacobian's chain, 1 Joseph update, F P Fᵀ.
    // Counted by hand with the folds: about 190 operations; a loop-for-loop copy would be over 300.
    assert!(program.ops.len() < 260, "{} operations", program.ops.len());
}

#[test]
fn the_upper_triangle_is_numbered_row_by_row() {
    let n = 4;
    let mut seen = vec![];
    for r in 0..n {
        for c in r..n {
            assert_eq!(upper(n, r, c), upper(n, c, r));
            seen.push(upper(n, r, c));
        }
    }
    assert_eq!(seen, (0..triangle(n)).collect::<Vec<_>>());
}
