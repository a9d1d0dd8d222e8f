//! The design's unscented Kalman filter written out for its size: one sample as two straight-line
//! programs with the EKF's interface ([`FilterCode`]: `x̂(k|k)`, `x⁺` and `P⁺`'s upper triangle), over
//! the same model programs and the same RK4 substep as the EKF ([`super::kalman`]), so that the
//! host's run and emitted code compute the same operations and the filter needs no derivative.
//!
//! Sigma points: the scaled unscented transform (E. Wan and R. van der Merwe, "The unscented Kalman
//! filter for nonlinear estimation", 2000) with α = 1, β = 2 (Gaussian prior) and κ = max(3 − n, 0)
//! (Julier's n + κ = 3 where n ≤ 3). With λ = α²(n + κ) − n, the 2n + 1 points are `x` and
//! `x ± √(n + λ) Lᵢ`, `Lᵢ` the columns of `P`'s Cholesky factor, weighted
//!
//! ```text
//! W₀ᵐ = λ / (n + λ),   W₀ᶜ = W₀ᵐ + 1 − α² + β,   Wᵢᵐ = Wᵢᶜ = 1 / (2 (n + λ))   (i = 1 … 2n)
//! ```
//!
//! α = 1 keeps every weight of order one, so that single precision loses no digits to a large
//! negative `W₀` (the often quoted α = 10⁻³ puts `W₀ᵐ` near −10⁶ for two states). One sample:
//!
//! ```text
//! sample   X = σ(x, P), Yᵢ = h(Xᵢ), ŷ = Σ Wᵢᵐ Yᵢ, S = Σ Wᵢᶜ (Yᵢ − ŷ)(Yᵢ − ŷ)ᵀ + R,
//!          C = Σ Wᵢᶜ (Xᵢ − x)(Yᵢ − ŷ)ᵀ, K = C S⁻¹, x̂ = x + K (y − ŷ), P ← P − C Kᵀ,
//!          then the prediction from (x̂, P)
//! predict  X = σ(x, P), Xᵢ' = f(Xᵢ) (the chip's RK4 substeps), x⁺ = Σ Wᵢᵐ Xᵢ',
//!          P⁺ = Σ Wᵢᶜ (Xᵢ' − x⁺)(Xᵢ' − x⁺)ᵀ + Q
//! ```
//!
//! `S⁻¹` is applied by forward and back substitution through `S`'s Cholesky factor. Both Cholesky
//! factors are written out for the design's size with every pivot kept at least `ε` times its
//! diagonal entry and at least the smallest normal `f32` ([`pivot`]): a `P` that rounding made
//! slightly indefinite still gives finite sigma points. With physical bounds (`[model.bounds]`), the
//! sigma points, `x̂` and `x⁺` are projected onto them, as the EKF projects its state.
//!
//! `P` is read and written as its upper triangle, row by row ([`super::kalman::upper`]); only
//! `r ≤ c` is computed and mirrored, so `P⁺` is symmetric by construction.

use crate::spec::ast::Binary;

use super::kalman::{filter_programs, substep, EkfConstants, FilterCode};
use super::program::{Builder, Leaf};
use super::ModelCode;

/// The scheme's α.
pub const ALPHA: f64 = 1.0;
/// The scheme's β (2: optimal for a Gaussian prior).
pub const BETA: f64 = 2.0;

/// The scheme's κ for `n` states: `max(3 − n, 0)`.
pub fn kappa(n: usize) -> f64 {
    (3.0 - n as f64).max(0.0)
}

/// `(√(n + λ), W₀ᵐ, W₀ᶜ, Wᵢ)` for `n` states.
pub fn weights(n: usize) -> (f64, f64, f64, f64) {
    let n = n as f64;
    let lambda = ALPHA * ALPHA * (n + kappa(n as usize)) - n;
    let spread = n + lambda;
    let mean0 = lambda / spread;
    (
        spread.sqrt(),
        mean0,
        mean0 + 1.0 - ALPHA * ALPHA + BETA,
        1.0 / (2.0 * spread),
    )
}

/// Writes one sample of the UKF of `code` with `constants` (the EKF's: `Q`, `R`, the RK4 substeps;
/// `x0` and `p0` are the start, not part of a sample) as programs.
pub fn unscented_code(code: &ModelCode, constants: &EkfConstants) -> FilterCode {
    filter_programs(
        code,
        |b, x, p| update(b, code, &constants.r, x, p),
        |b, x, p| predict(b, code, constants, x, p),
    )
}

/// The sigma points of `(x, P)`, each projected onto the bounds: `x`, then `x + c Lᵢ` for every
/// column `i`, then `x − c Lᵢ`.
fn sigma_points(b: &mut Builder<'_>, code: &ModelCode, x: &[usize], p: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let nx = x.len();
    let (spread, ..) = weights(nx);
    let factor = cholesky(b, p);
    let mut points = vec![x.to_vec()];
    for sign in [1.0, -1.0] {
        let scale = b.number(sign * spread);
        for column in 0..nx {
            let mut point: Vec<usize> = x
                .iter()
                .zip(&factor)
                .map(|(&at, row)| {
                    let moved = b.mul(scale, row[column]);
                    b.add(at, moved)
                })
                .collect();
            b.project(&mut point, &code.bounds);
            points.push(point);
        }
    }
    points
}

/// `Σ Wᵢᵐ vᵢ` over the sigma points' values `values` (each a vector) as `W₀ᵐ v₀ + W (v₁ + … + v₂ₙ)`:
/// the points but the first share one weight.
fn mean(b: &mut Builder<'_>, values: &[Vec<usize>]) -> Vec<usize> {
    let (_, mean0, _, rest) = weights((values.len() - 1) / 2);
    let (w0, wi) = (b.number(mean0), b.number(rest));
    (0..values[0].len())
        .map(|k| {
            let sum = values[2..].iter().fold(values[1][k], |sum, v| b.add(sum, v[k]));
            let first = b.mul(w0, values[0][k]);
            let others = b.mul(wi, sum);
            b.add(first, others)
        })
        .collect()
}

/// `Σ Wᵢᶜ aᵢ bᵢᵀ` over the sigma points' deviations `a` and `b` (entry `[r][c]`), as `W₀ᶜ a₀ b₀ᵀ +
/// W Σ aᵢ bᵢᵀ`; with `symmetric`, only `r ≤ c` is computed and mirrored.
fn cross(bld: &mut Builder<'_>, a: &[Vec<usize>], b: &[Vec<usize>], symmetric: bool) -> Vec<Vec<usize>> {
    let (_, _, covariance0, rest) = weights((a.len() - 1) / 2);
    let (w0, wi) = (bld.number(covariance0), bld.number(rest));
    let zero = bld.number(0.0);
    let (rows, columns) = (a[0].len(), b[0].len());
    let mut out = vec![vec![zero; columns]; rows];
    for r in 0..rows {
        for c in (if symmetric { r } else { 0 })..columns {
            let (left, right): (Vec<usize>, Vec<usize>) = a[1..].iter().zip(&b[1..]).map(|(a, b)| (a[r], b[c])).unzip();
            let sum = bld.dot(zero, &left, &right);
            let first = bld.mul(a[0][r], b[0][c]);
            let first = bld.mul(w0, first);
            let others = bld.mul(wi, sum);
            out[r][c] = bld.add(first, others);
            if symmetric {
                out[c][r] = out[r][c];
            }
        }
    }
    out
}

/// `vᵢ − m` for every point's value `vᵢ`: 0 where `vᵢ` is `m` itself (the update's first point, `x`).
fn deviations(b: &mut Builder<'_>, values: &[Vec<usize>], m: &[usize]) -> Vec<Vec<usize>> {
    values
        .iter()
        .map(|v| {
            v.iter()
                .zip(m)
                .map(|(&v, &m)| if v == m { b.number(0.0) } else { b.sub(v, m) })
                .collect()
        })
        .collect()
}

/// The measurement update from every output at once.
fn update(b: &mut Builder<'_>, code: &ModelCode, r: &[f64], x: &mut [usize], p: &mut [Vec<usize>]) {
    let (nx, ny) = (x.len(), code.dimensions.outputs);
    let points = sigma_points(b, code, x, p);
    let outputs: Vec<Vec<usize>> = points
        .iter()
        .map(|point| b.inline(&code.output, point)[..ny].to_vec())
        .collect();
    let predicted = mean(b, &outputs);
    let dy = deviations(b, &outputs, &predicted);
    let dx = deviations(b, &points, x);
    let mut s = cross(b, &dy, &dy, true);
    for (i, &variance) in r.iter().enumerate() {
        let noise = b.number(variance);
        s[i][i] = b.add(s[i][i], noise);
    }
    let c = cross(b, &dx, &dy, false);
    // K = C S⁻¹, row by row: S kᵀ = cᵀ through S = L Lᵀ.
    let factor = cholesky(b, &s);
    let one = b.number(1.0);
    let inverse: Vec<usize> = (0..ny).map(|i| b.binary(Binary::Div, one, factor[i][i])).collect();
    let gain: Vec<Vec<usize>> = (0..nx)
        .map(|row| {
            let mut z = vec![one; ny];
            for i in 0..ny {
                let known: Vec<usize> = (0..i).map(|j| factor[i][j]).collect();
                let left = b.negate(c[row][i]);
                let sum = b.dot(left, &known, &z[..i]);
                let value = b.negate(sum);
                z[i] = b.mul(value, inverse[i]);
            }
            let mut k = vec![one; ny];
            for i in (0..ny).rev() {
                let known: Vec<usize> = (i + 1..ny).map(|j| factor[j][i]).collect();
                let left = b.negate(z[i]);
                let sum = b.dot(left, &known, &k[i + 1..]);
                let value = b.negate(sum);
                k[i] = b.mul(value, inverse[i]);
            }
            k
        })
        .collect();
    let innovation: Vec<usize> = (0..ny)
        .map(|i| {
            let measured = b.leaf(Leaf::Measurement(i));
            b.sub(measured, predicted[i])
        })
        .collect();
    for (e, k) in x.iter_mut().zip(&gain) {
        *e = b.dot(*e, k, &innovation);
    }
    let zero = b.number(0.0);
    for row in 0..nx {
        for col in row..nx {
            let taken = b.dot(zero, &c[row], &gain[col]);
            let entry = b.sub(p[row][col], taken);
            p[row][col] = entry;
            p[col][row] = entry;
        }
    }
}

/// The prediction: every sigma point through the chip's RK4 substeps.
fn predict(b: &mut Builder<'_>, code: &ModelCode, constants: &EkfConstants, x: &mut Vec<usize>, p: &mut [Vec<usize>]) {
    let nx = x.len();
    let points = sigma_points(b, code, x, p);
    let moved: Vec<Vec<usize>> = points
        .iter()
        .map(|point| {
            let mut next = point.clone();
            for _ in 0..constants.substeps {
                next = substep(b, code, constants.h, &next).0;
            }
            next
        })
        .collect();
    let next = mean(b, &moved);
    let dx = deviations(b, &moved, &next);
    let spread = cross(b, &dx, &dx, true);
    for r in 0..nx {
        for c in r..nx {
            let q = b.number(if r == c { constants.q[r] } else { 0.0 });
            let entry = b.add(spread[r][c], q);
            p[r][c] = entry;
            p[c][r] = entry;
        }
    }
    *x = next;
}

/// The lower Cholesky factor of the symmetric `m` (read from `r ≤ c`), each pivot at least
/// [`pivot`]'s floor.
fn cholesky(b: &mut Builder<'_>, m: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let n = m.len();
    let zero = b.number(0.0);
    let one = b.number(1.0);
    let mut l = vec![vec![zero; n]; n];
    let mut inverse = vec![one; n];
    for j in 0..n {
        let row: Vec<usize> = l[j][..j].to_vec();
        let squares = b.dot(zero, &row, &row);
        let left = b.sub(m[j][j], squares);
        let diagonal = pivot(b, left, m[j][j]);
        l[j][j] = b.call("sqrt", diagonal);
        inverse[j] = b.binary(Binary::Div, one, l[j][j]);
        for i in j + 1..n {
            let (a, c) = (l[i][..j].to_vec(), l[j][..j].to_vec());
            let products = b.dot(zero, &a, &c);
            let left = b.sub(m[j][i], products);
            l[i][j] = b.mul(left, inverse[j]);
        }
    }
    l
}

/// `max(d, ε · diagonal, MIN_POSITIVE)` (ε and the smallest normal number of `f32`): the pivot that
/// keeps a factor finite where rounding made the matrix slightly indefinite.
pub fn pivot(b: &mut Builder<'_>, d: usize, diagonal: usize) -> usize {
    let epsilon = b.number(f64::from(f32::EPSILON));
    let relative = b.mul(epsilon, diagonal);
    let floor = b.number(f64::from(f32::MIN_POSITIVE));
    let at_least = b.binary(Binary::Max, relative, floor);
    b.binary(Binary::Max, d, at_least)
}

#[cfg(test)]
mod tests;
