//! The design's extended Kalman filter written out for its size: one sample of
//! [`firmware::Ekf`] over [`firmware::Rk4`] as two straight-line programs, so that the chip runs no
//! loop, no index arithmetic and no multiplication by a structural zero or one.
//!
//! The programs compute exactly the library filter's steps (see `firmware::ekf` and
//! `firmware::model`), in the same order:
//!
//! ```text
//! sample   (x, P, y, u) → (x̂(k|k), x⁺, P⁺)     every output's Joseph update, then the prediction
//! predict  (x, P, u)    → (x⁺, P⁺)             the prediction alone (a refused measurement)
//! ```
//!
//! With physical bounds on states (`[model.bounds]`), `x̂(k|k)` and `x⁺` are projected onto them
//! (`firmware::bounds`, selects), as the library filter does with `Ekf::with_bounds`.
//!
//! `P` is read and written as its upper triangle, row by row ([`upper`]): it is symmetric, so the
//! lower entries would be copies. The filter's constants (`Q`, `R`, the substep `h`) are numbers of
//! the programs, so the products they take part in fold where they can.

use crate::spec::ast::Binary;

use super::program::{Builder, Leaf, Names, Program};
use super::{Covariance, ModelCode};

mod sample;
mod watch;
pub use watch::Watch;

/// A Kalman filter's constants (the EKF's, and every filter kind's that shares its frame), chosen on the tuning runs or fixed by the spec
/// (`[observer.ekf]`).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct EkfConstants {
    /// `x̂(0)`.
    pub x0: Vec<f64>,
    /// `P(0)`: diagonal when tuned, full when a spec fixes it so.
    pub p0: Covariance,
    /// `Q`, per sampling period: diagonal when tuned, full when a spec fixes it so.
    pub q: Covariance,
    /// `R` diagonal: the outputs' noise variances.
    pub r: Vec<f64>,
    /// RK4 substeps per sample on the chip.
    pub substeps: usize,
    /// Width of one substep, `τ / substeps`.
    pub h: f64,
    /// The χ² watch on the normalised innovations (`firmware::watch`), for the filters from the box
    /// centre.
    #[serde(default)]
    pub watch: Watch,
}

/// The two programs of one sample.
#[derive(Clone, Debug)]
pub struct FilterCode {
    /// Results: `x̂(k|k)` (states), `x⁺` (states), `P⁺` (upper triangle), then `scalars` numbers: the
    /// normalised innovation squared (`firmware::watch`) and, for a bank's member, the root of
    /// `det S` (`ukf_bank`).
    pub measured: Program,
    /// Results: `x⁺` (states), `P⁺` (upper triangle).
    pub unmeasured: Program,
    /// The targets of an estimate, in the filter's coordinates (the model's `targets`).
    pub targets: Program,
    /// The model's parameters, as the programs read them.
    pub parameters: Vec<(String, f64)>,
    /// States.
    pub states: usize,
    /// The numbers the measured program gives after `P⁺`: 1 (the normalised innovation squared), or 2
    /// (and `√det S`, a bank member's).
    pub scalars: usize,
}

/// What one sample gives: the updated estimate (`None` without a measurement), the predicted state
/// and the predicted covariance's upper triangle.
pub type Sampled<T> = (Option<Vec<T>>, Vec<T>, Vec<T>);

/// The upper triangle, row by row, of the diagonal matrix `diag(values)`: how a filter's `P` starts.
pub fn diagonal_upper(values: &[f64]) -> Vec<f64> {
    let n = values.len();
    (0..n)
        .flat_map(|r| (r..n).map(move |c| (r, c)))
        .map(|(r, c)| if r == c { values[r] } else { 0.0 })
        .collect()
}

/// Entries of the upper triangle of an `n × n` matrix.
pub fn triangle(n: usize) -> usize {
    n * (n + 1) / 2
}

/// Index of entry `(r, c)` (either order) in the upper triangle of an `n × n` matrix, row by row.
pub fn upper(n: usize, r: usize, c: usize) -> usize {
    let (r, c) = if r <= c { (r, c) } else { (c, r) };
    r * n - r * (r + 1) / 2 + c
}

/// Writes one sample of the EKF of `code` with `constants` as programs.
pub fn filter_code(code: &ModelCode, constants: &EkfConstants) -> FilterCode {
    filter_programs(
        code,
        |b, x, p| {
            let mut nis = b.number(0.0);
            for i in 0..code.dimensions.outputs {
                if let Some(term) = update(b, code, constants.r[i], i, x, p) {
                    nis = b.add(nis, term);
                }
            }
            vec![nis]
        },
        |b, x, p| predict(b, code, constants, x, p),
    )
}

/// The two programs of one sample of a filter of `code` (the EKF's here; other filters build theirs): the state and the
/// covariance's upper triangle read as leaves; with a measurement, `update` (which gives the
/// normalised innovation squared, and for a bank's member `√det S`) and the projection onto the
/// bounds, whose state is the first result; then `predict`, the projection, `x⁺` and `P⁺`'s upper
/// triangle as results, and with a measurement `update`'s numbers last.
pub(crate) fn filter_programs(
    code: &ModelCode,
    update: impl Fn(&mut Builder<'_>, &mut Vec<usize>, &mut [Vec<usize>]) -> Vec<usize>,
    predict: impl Fn(&mut Builder<'_>, &mut Vec<usize>, &mut [Vec<usize>]),
) -> FilterCode {
    let build = |measured: bool| {
        let nx = code.dimensions.states;
        let mut b = Builder::new(Names {
            parameters: &code.parameters,
            states: &[],
            inputs: &[],
        });
        let mut x: Vec<usize> = (0..nx).map(|i| b.leaf(Leaf::State(i))).collect();
        let mut p: Vec<Vec<usize>> = (0..nx)
            .map(|r| (0..nx).map(|c| b.leaf(Leaf::Covariance(upper(nx, r, c)))).collect())
            .collect();
        let mut scalars = Vec::new();
        if measured {
            scalars = update(&mut b, &mut x, &mut p);
            b.project(&mut x, &code.bounds);
            for &e in &x {
                b.result(e);
            }
        }
        predict(&mut b, &mut x, &mut p);
        b.project(&mut x, &code.bounds);
        for &e in &x {
            b.result(e);
        }
        for (r, row) in p.iter().enumerate() {
            for &entry in &row[r..] {
                b.result(entry);
            }
        }
        for &scalar in &scalars {
            b.result(scalar);
        }
        let mut program = b.finish();
        program.prune();
        (program, scalars.len())
    };
    let (measured, scalars) = build(true);
    FilterCode {
        measured,
        unmeasured: build(false).0,
        targets: code.targets.clone(),
        parameters: code.parameters.clone(),
        states: code.dimensions.states,
        scalars,
    }
}

/// Output `i`'s scalar update in Joseph form (`firmware::Ekf::update`); its term of the normalised
/// innovation squared, `νᵢ² / sᵢ`, where the output has noise (a noiseless output's `sᵢ` may be 0).
fn update(
    b: &mut Builder<'_>,
    code: &ModelCode,
    variance: f64,
    i: usize,
    x: &mut [usize],
    p: &mut [Vec<usize>],
) -> Option<usize> {
    let (nx, ny) = (x.len(), code.dimensions.outputs);
    let output = b.inline(&code.output, x);
    let h = &output[ny + i * nx..ny + (i + 1) * nx];
    let zero = b.number(0.0);
    let ph: Vec<usize> = (0..nx).map(|a| b.dot(zero, &p[a], h)).collect();
    let r = b.number(variance);
    let mut s = b.dot(r, h, &ph);
    if variance == 0.0 {
        // No measurement noise: `s` may be 0 where this output tells nothing; the library skips the
        // update there, which a gain of 0 reproduces.
        let tiny = b.number(f64::from(f32::MIN_POSITIVE));
        s = b.binary(Binary::Max, s, tiny);
    }
    let one = b.number(1.0);
    let inverse = b.binary(Binary::Div, one, s);
    let gain: Vec<usize> = ph.iter().map(|&v| b.mul(v, inverse)).collect();
    let measured = b.leaf(Leaf::Measurement(i));
    let innovation = b.sub(measured, output[i]);
    for (e, &k) in x.iter_mut().zip(&gain) {
        let step = b.mul(k, innovation);
        *e = b.add(*e, step);
    }
    let term = (variance > 0.0).then(|| {
        let squared = b.mul(innovation, innovation);
        b.mul(squared, inverse)
    });
    // A = I - K Hᵢ; P ← A P Aᵀ + K r Kᵀ, the upper triangle.
    let a: Vec<Vec<usize>> = (0..nx)
        .map(|row| {
            (0..nx)
                .map(|c| {
                    let identity = b.number(if row == c { 1.0 } else { 0.0 });
                    let kh = b.mul(gain[row], h[c]);
                    b.sub(identity, kh)
                })
                .collect()
        })
        .collect();
    let ap = product(b, &a, p);
    let next = product_transposed(b, &ap, &a);
    for row in 0..nx {
        for c in row..nx {
            let kr = b.mul(gain[row], r);
            let krk = b.mul(kr, gain[c]);
            let entry = b.add(next[row][c], krk);
            p[row][c] = entry;
            p[c][row] = entry;
        }
    }
    term
}

/// `x ← f(x, u)`, `P ← F P Fᵀ + Q` with `CHIP_SUBSTEPS` RK4 steps (`firmware::Rk4::step`).
fn predict(b: &mut Builder<'_>, code: &ModelCode, constants: &EkfConstants, x: &mut Vec<usize>, p: &mut [Vec<usize>]) {
    let nx = x.len();
    let (mut next, mut jacobian) = substep(b, code, constants.h, x);
    for _ in 1..constants.substeps {
        let (after, d) = substep(b, code, constants.h, &next);
        next = after;
        jacobian = product(b, &d, &jacobian);
    }
    let fp = product(b, &jacobian, p);
    let fpf = product_transposed(b, &fp, &jacobian);
    for r in 0..nx {
        for c in r..nx {
            let q = b.number(constants.q.entry(r, c));
            let entry = b.add(fpf[r][c], q);
            p[r][c] = entry;
            p[c][r] = entry;
        }
    }
    *x = next;
}

/// One RK4 step of width `h` and its derivative in `x` (`firmware::Rk4::substep`).
pub(crate) fn substep(b: &mut Builder<'_>, code: &ModelCode, h: f64, x: &[usize]) -> (Vec<usize>, Vec<Vec<usize>>) {
    let nx = x.len();
    // The library's `h / 2` and `h / 6`, computed at construction in the filter's precision.
    let width = b.number(h);
    let (two, six) = (b.number(2.0), b.number(6.0));
    let half = b.unfolded(Binary::Div, width, two);
    let sixth = b.unfolded(Binary::Div, width, six);
    let derivative = |b: &mut Builder<'_>, at: &[usize]| {
        let values = b.inline(&code.derivative, at);
        let a: Vec<Vec<usize>> = (0..nx).map(|i| values[nx * (i + 1)..nx * (i + 2)].to_vec()).collect();
        (values[..nx].to_vec(), a)
    };
    let stage = |b: &mut Builder<'_>, k: &[usize], d: &[Vec<usize>], w: usize| {
        let point: Vec<usize> = (0..nx)
            .map(|i| {
                let moved = b.mul(w, k[i]);
                b.add(x[i], moved)
            })
            .collect();
        let moved: Vec<Vec<usize>> = (0..nx)
            .map(|i| {
                (0..nx)
                    .map(|j| {
                        let identity = b.number(if i == j { 1.0 } else { 0.0 });
                        let wd = b.mul(w, d[i][j]);
                        b.add(identity, wd)
                    })
                    .collect()
            })
            .collect();
        let (value, a) = derivative(b, &point);
        let chained = product(b, &a, &moved);
        (value, chained)
    };
    let (k1, d1) = derivative(b, x);
    let (k2, d2) = stage(b, &k1, &d1, half);
    let (k3, d3) = stage(b, &k2, &d2, half);
    let (k4, d4) = stage(b, &k3, &d3, width);
    let combine = |b: &mut Builder<'_>, start: usize, v1: usize, v2: usize, v3: usize, v4: usize| {
        let middle = b.add(v2, v3);
        let doubled = b.mul(two, middle);
        let sum = b.add(v1, doubled);
        let sum = b.add(sum, v4);
        let scaled = b.mul(sixth, sum);
        b.add(start, scaled)
    };
    let next = (0..nx).map(|i| combine(b, x[i], k1[i], k2[i], k3[i], k4[i])).collect();
    let jacobian = (0..nx)
        .map(|i| {
            (0..nx)
                .map(|j| {
                    let identity = b.number(if i == j { 1.0 } else { 0.0 });
                    combine(b, identity, d1[i][j], d2[i][j], d3[i][j], d4[i][j])
                })
                .collect()
        })
        .collect();
    (next, jacobian)
}

/// `A B` (`firmware::emitted::product`: each entry summed from 0 in order).
fn product(b: &mut Builder<'_>, a: &[Vec<usize>], m: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let n = a.len();
    let zero = b.number(0.0);
    (0..n)
        .map(|r| {
            (0..n)
                .map(|c| {
                    let column: Vec<usize> = (0..n).map(|k| m[k][c]).collect();
                    b.dot(zero, &a[r], &column)
                })
                .collect()
        })
        .collect()
}

/// `A Bᵀ`, the upper triangle only (the rest is left as the upper's mirror; callers read `r ≤ c`).
fn product_transposed(b: &mut Builder<'_>, a: &[Vec<usize>], m: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let n = a.len();
    let zero = b.number(0.0);
    let mut out = vec![vec![zero; n]; n];
    for r in 0..n {
        for c in r..n {
            out[r][c] = b.dot(zero, &a[r], &m[c]);
            out[c][r] = out[r][c];
        }
    }
    out
}

#[cfg(test)]
mod tests;
