//! The design's unscented Kalman filter written out for its size: one sample as two straight-line
//! programs with the EKF's interface ([`FilterCode`]: `x̂(k|k)`, `x⁺` and `P⁺`'s upper triangle), over
//! the same model programs and the same RK4 substep as the EKF ([`crate::plant::kalman`]), so that the
//! host's run and emitted code compute the same operations and the filter needs no derivative.
//!
//! Sigma points: the scaled unscented transform (E. Wan and R. van der Merwe, "The unscented Kalman
//! filter for nonlinear estimation", 2000) with α = 1, β = 0 and κ = 0, which is the spherical-radial
//! cubature rule (I. Arasaratnam and S. Haykin, "Cubature Kalman filters", 2009): with
//! λ = α²(n + κ) − n = 0 the points `x ± √(n + λ) Lᵢ`, `Lᵢ` the columns of `P`'s Cholesky factor, are
//! weighted
//!
//! ```text
//! W₀ᵐ = λ / (n + λ) = 0,   W₀ᶜ = W₀ᵐ + 1 − α² + β = 0,   Wᵢᵐ = Wᵢᶜ = 1 / (2 (n + λ)) = 1 / (2n)
//! ```
//!
//! so the centre `x` carries no weight and is not drawn: `2n` points, every weight positive and equal.
//! Measured against the often quoted β = 2, κ = 3 − n (whose centre point weighs 1/3 and 7/3 for
//! two states), tuned alike on the same runs: Example 1's validation RMSE 0.0550 / 0.0851 against
//! 0.0582 / 0.0860, E. coli's 0.037 / 0.064 against 0.042 / 0.082, with one model step fewer per
//! sample. α = 1 keeps every weight of order one, so that single precision loses no digits (the
//! often quoted α = 10⁻³ puts `W₀ᵐ` near −10⁶). One sample:
//!
//! ```text
//! sample   X = σ(x, P), Yᵢ = h(Xᵢ), ŷ = Σ Wᵢᵐ Yᵢ, S = Σ Wᵢᶜ (Yᵢ − ŷ)(Yᵢ − ŷ)ᵀ + R,
//!          C = Σ Wᵢᶜ (Xᵢ − x)(Yᵢ − ŷ)ᵀ, K = C S⁻¹, x̂ = x + K (y − ŷ), P ← P − C Kᵀ,
//!          then the prediction from (x̂, P)
//! predict  X = σ(x, P), Xᵢ' = f(Xᵢ) (the chip's RK4 substeps), x⁺ = Σ Wᵢᵐ Xᵢ',
//!          P⁺ = Σ Wᵢᶜ (Xᵢ' − x⁺)(Xᵢ' − x⁺)ᵀ + Q
//! ```
//!
//! With physical bounds (`[model.bounds]`) the update's sigma points are projected onto them, and
//! their own mean and spread (`x̄ = Σ Wᵢᵐ Xᵢ`, `Σ Wᵢᶜ (Xᵢ − x̄)(Xᵢ − x̄)ᵀ`) take the place of `x` and `P`
//! in the update: without projection they are `x` and `P`, and with it `P − C Kᵀ` is the Schur
//! complement of the projected points' joint spread, positive semi-definite. Updating the analytic
//! `P` with a `C` of projected points instead can make it indefinite (measured on E. coli, where the
//! substrate runs out: the next factor's floored pivot then spread the points, and the product's
//! estimate was off by up to 369 g/L where it never exceeds 0.6).
//!
//! `S⁻¹` is applied by forward and back substitution through `S`'s Cholesky factor. Both Cholesky
//! factors are written out for the design's size with every pivot kept at least `ε` times its
//! diagonal entry's size plus the smallest normal `f32` ([`pivot`]): a `P` that rounding made
//! slightly indefinite still gives finite sigma points. With physical bounds (`[model.bounds]`), the
//! sigma points, `x̂` and `x⁺` are projected onto them, as the EKF projects its state.
//!
//! `P` is read and written as its upper triangle, row by row ([`crate::plant::kalman::upper`]); only
//! `r ≤ c` is computed and mirrored, so `P⁺` is symmetric by construction.

use crate::spec::ast::Binary;

use crate::plant::kalman::{filter_programs, substep, EkfConstants, FilterCode};
use crate::plant::program::{Builder, Leaf};
use crate::plant::{Coordinates, ModelCode};

/// The scheme's α.
pub const ALPHA: f64 = 1.0;
/// The scheme's β.
pub const BETA: f64 = 0.0;

/// The scheme's κ for `n` states: 0 (the cubature rule).
pub fn kappa(_n: usize) -> f64 {
    0.0
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

/// Writes one sample of the UKF of `code` (the plant's model) with `constants` (the EKF's: `Q`, `R`,
/// the RK4 substeps; `x0` and `p0` are the start, not part of a sample) as programs, its state in the
/// model's log coordinates ([`ModelCode::logarithmic`]: every state bounded below carried by its
/// logarithm, so that no sigma point crosses the bound), in which `constants` are. Each sigma point
/// is stepped by the plant's RK4 in the plant's coordinates (one `exp` and one `ln` per log state and
/// point, not an `exp` in every model evaluation) and read back.
pub fn unscented_code(code: &ModelCode, constants: &EkfConstants) -> FilterCode {
    unscented(code, constants, false)
}

/// [`unscented_code`] for a member of a bank of UKFs (`ukf_bank`): its measured program also gives
/// `√det S = Π Lᵢᵢ` after the normalised innovation squared, `L` the Cholesky factor of the
/// innovations' covariance `S`, so that the bank weighs the member by the likelihood of its
/// innovation, `N(ν; 0, S) ∝ exp(−ε/2) / √det S`.
pub fn member_code(code: &ModelCode, constants: &EkfConstants) -> FilterCode {
    unscented(code, constants, true)
}

/// [`unscented_code`], with `√det S` when `root`.
fn unscented(code: &ModelCode, constants: &EkfConstants, root: bool) -> FilterCode {
    let log = &code.logarithmic();
    filter_programs(
        log,
        |b, x, p| update(b, log, &constants.r, x, p, root),
        |b, x, p| predict(b, code, log, constants, x, p),
    )
}

/// Whether the scheme draws the centre `x` (it does when a centre weight is not 0).
fn centred(n: usize) -> bool {
    let (_, mean0, covariance0, _) = weights(n);
    mean0 != 0.0 || covariance0 != 0.0
}

/// The sigma points of `(x, P)`, each projected onto the bounds: `x` when the scheme weighs it
/// ([`centred`]), then `x + c Lᵢ` for every column `i`, then `x − c Lᵢ`.
fn sigma_points(b: &mut Builder<'_>, code: &ModelCode, x: &[usize], p: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let nx = x.len();
    let (spread, ..) = weights(nx);
    let factor = cholesky(b, p);
    let mut points = if centred(nx) { vec![x.to_vec()] } else { Vec::new() };
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

/// The scheme's weights for `count` sigma points: `(W₀ᵐ, W₀ᶜ, W)` when the first is the centre, else
/// `None` for the centre's and `W` for every point.
fn point_weights(count: usize) -> (Option<(f64, f64)>, f64) {
    let n = count / 2;
    let (_, mean0, covariance0, rest) = weights(n);
    ((count % 2 == 1).then_some((mean0, covariance0)), rest)
}

/// `Σ Wᵢᵐ vᵢ` over the sigma points' values `values` (each a vector) as `W (v₁ + … + v₂ₙ)`, plus
/// `W₀ᵐ v₀` when the centre is drawn: the points but the centre share one weight.
fn mean(b: &mut Builder<'_>, values: &[Vec<usize>]) -> Vec<usize> {
    let (centre, rest) = point_weights(values.len());
    let wi = b.number(rest);
    let w0 = centre.map(|(mean0, _)| b.number(mean0));
    let others = if w0.is_some() { &values[1..] } else { values };
    (0..values[0].len())
        .map(|k| {
            let sum = others[1..].iter().fold(others[0][k], |sum, v| b.add(sum, v[k]));
            let weighted = b.mul(wi, sum);
            match w0 {
                Some(w0) => {
                    let first = b.mul(w0, values[0][k]);
                    b.add(first, weighted)
                }
                None => weighted,
            }
        })
        .collect()
}

/// `Σ Wᵢᶜ aᵢ bᵢᵀ` over the sigma points' deviations `a` and `b` (entry `[r][c]`), as `W Σ aᵢ bᵢᵀ`,
/// plus `W₀ᶜ a₀ b₀ᵀ` when the centre is drawn; with `symmetric`, only `r ≤ c` is computed and
/// mirrored.
fn cross(bld: &mut Builder<'_>, a: &[Vec<usize>], b: &[Vec<usize>], symmetric: bool) -> Vec<Vec<usize>> {
    let (centre, rest) = point_weights(a.len());
    let wi = bld.number(rest);
    let w0 = centre.map(|(_, covariance0)| bld.number(covariance0));
    let skip = usize::from(w0.is_some());
    let zero = bld.number(0.0);
    let (rows, columns) = (a[0].len(), b[0].len());
    let mut out = vec![vec![zero; columns]; rows];
    for r in 0..rows {
        for c in (if symmetric { r } else { 0 })..columns {
            let (left, right): (Vec<usize>, Vec<usize>) =
                a[skip..].iter().zip(&b[skip..]).map(|(a, b)| (a[r], b[c])).unzip();
            let sum = bld.dot(zero, &left, &right);
            let weighted = bld.mul(wi, sum);
            out[r][c] = match w0 {
                Some(w0) => {
                    let first = bld.mul(a[0][r], b[0][c]);
                    let first = bld.mul(w0, first);
                    bld.add(first, weighted)
                }
                None => weighted,
            };
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

/// The measurement update from every output at once: the normalised innovation squared, and with
/// `root` the product of the diagonal of `S`'s Cholesky factor after it.
fn update(
    b: &mut Builder<'_>,
    code: &ModelCode,
    r: &[f64],
    x: &mut [usize],
    p: &mut [Vec<usize>],
    root: bool,
) -> Vec<usize> {
    let (nx, ny) = (x.len(), code.dimensions.outputs);
    let points = sigma_points(b, code, x, p);
    let outputs: Vec<Vec<usize>> = points
        .iter()
        .map(|point| b.inline(&code.output, point)[..ny].to_vec())
        .collect();
    let predicted = mean(b, &outputs);
    let dy = deviations(b, &outputs, &predicted);
    // With bounds, the projected points stand for `(x, P)`: their mean and spread replace `x` and `P`
    // (without projection they are `x` and `P` exactly), so that `P − C Kᵀ`, the Schur complement
    // of the points' joint spread with `R`, stays positive semi-definite.
    let bounded = code.bounds.iter().any(|b| b.min.is_some() || b.max.is_some());
    if bounded {
        let centre = mean(b, &points);
        x.copy_from_slice(&centre);
    }
    let dx = deviations(b, &points, x);
    if bounded {
        let spread = cross(b, &dx, &dx, true);
        for (row, values) in p.iter_mut().zip(spread) {
            row.copy_from_slice(&values);
        }
    }
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
    // The normalised innovation squared νᵀ S⁻¹ ν = |w|², L w = ν by forward substitution.
    let mut w = vec![one; ny];
    for i in 0..ny {
        let known: Vec<usize> = (0..i).map(|j| factor[i][j]).collect();
        let left = b.negate(innovation[i]);
        let sum = b.dot(left, &known, &w[..i]);
        let value = b.negate(sum);
        w[i] = b.mul(value, inverse[i]);
    }
    let zero = b.number(0.0);
    let nis = b.dot(zero, &w, &w);
    for row in 0..nx {
        for col in row..nx {
            let taken = b.dot(zero, &c[row], &gain[col]);
            let entry = b.sub(p[row][col], taken);
            p[row][col] = entry;
            p[col][row] = entry;
        }
    }
    let mut scalars = vec![nis];
    if root {
        let product = (1..ny).fold(factor[0][0], |product, i| b.mul(product, factor[i][i]));
        scalars.push(product);
    }
    scalars
}

/// The prediction: every sigma point (of `log`'s coordinates) through the chip's RK4 substeps of the
/// plant's model `plant`, in the plant's coordinates.
fn predict(
    b: &mut Builder<'_>,
    plant: &ModelCode,
    log: &ModelCode,
    constants: &EkfConstants,
    x: &mut Vec<usize>,
    p: &mut [Vec<usize>],
) {
    let nx = x.len();
    let points = sigma_points(b, log, x, p);
    let moved: Vec<Vec<usize>> = points
        .iter()
        .map(|point| {
            let mut next = to_plant(b, &log.coordinates, point);
            for _ in 0..constants.substeps {
                next = substep(b, plant, constants.h, &next).0;
            }
            to_log(b, &log.coordinates, &next)
        })
        .collect();
    let next = mean(b, &moved);
    let dx = deviations(b, &moved, &next);
    let spread = cross(b, &dx, &dx, true);
    for r in 0..nx {
        for c in r..nx {
            let q = b.number(constants.q.entry(r, c));
            let entry = b.add(spread[r][c], q);
            p[r][c] = entry;
            p[c][r] = entry;
        }
    }
    *x = next;
}

/// The plant's state of `z` (`eᶻ + (m − c)`, no lower than `m`, for a log coordinate).
fn to_plant(b: &mut Builder<'_>, coordinates: &Coordinates, z: &[usize]) -> Vec<usize> {
    z.iter()
        .zip(&coordinates.0)
        .map(|(&z, log)| match log {
            Some(log) => {
                let s = b.call("exp", z);
                let (shift, min) = (b.number(log.shift()), b.number(log.min));
                let x = b.add(s, shift);
                b.at_least(x, min)
            }
            None => z,
        })
        .collect()
}

/// `z` of the plant's state `x` (`ln(x − m + c)`, read on the bound where a step left it below).
fn to_log(b: &mut Builder<'_>, coordinates: &Coordinates, x: &[usize]) -> Vec<usize> {
    x.iter()
        .zip(&coordinates.0)
        .map(|(&x, log)| match log {
            Some(log) => {
                let (shift, offset) = (b.number(log.shift()), b.number(log.offset));
                let s = b.sub(x, shift);
                let s = b.at_least(s, offset);
                b.call("ln", s)
            }
            None => x,
        })
        .collect()
}

mod cholesky;
use cholesky::cholesky;
pub use cholesky::pivot;

#[cfg(test)]
mod tests;
