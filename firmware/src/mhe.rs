//! The moving-horizon estimate's building blocks: the Gauss–Newton normal equations of a window's
//! output error, and the Cholesky solve of the small system they give. The host's converged
//! reference (a projected Levenberg–Marquardt over these, `host::observers::mhe`) and a
//! fixed-iteration observer run the same arithmetic.
//!
//! # The problem
//!
//! Over a window of `N` samples `(y(j), u(j))`, oldest first, the paper's moving-horizon observer is
//! the state at the window's start minimising the noise-weighted output error (with an optional
//! prior `x̄` weighted by `p`, the paper's first remark):
//!
//! ```text
//! C(x) = Σ_j Σ_i w_i (y_i(j) − h_i(x(j), u(j)))²  +  Σ_i p_i (x_i − x̄_i)²,
//! x(0) = x,  x(j+1) = f(x(j), u(j))
//! ```
//!
//! With `Φ(j) = ∂x(j)/∂x` (`Φ(0) = I`, `Φ(j+1) = F(j) Φ(j)`) and `J(j) = H(j) Φ(j)`, one Gauss–Newton
//! step `δ` solves
//!
//! ```text
//! (Σ_j J(j)ᵀ W J(j) + diag(p)) δ = Σ_j J(j)ᵀ W r(j) − diag(p) (x − x̄),   r(j) = y(j) − h(x(j), u(j))
//! ```
//!
//! [`normal_equations`] returns the output part of both sides, the cost and `x(N−1)` (the estimate
//! at the window's end, where the map's estimate is); the prior is the caller's (a diagonal added).
//! A non-finite measurement contributes nothing (its weight is taken as zero), as a refused sample.

use crate::{Plant, Scalar};

/// The output part of a window's Gauss–Newton system at a start `x` (see the module's documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Normal<T, const NX: usize> {
    /// `Σ_j Σ_i w_i r_i(j)²` (finite measurements only).
    pub cost: T,
    /// `Σ_j J(j)ᵀ W J(j)`.
    pub matrix: [[T; NX]; NX],
    /// `Σ_j J(j)ᵀ W r(j)`.
    pub gradient: [T; NX],
    /// `x(N−1)`: the start propagated to the window's last sample.
    pub end: [T; NX],
}

/// The normal equations of the window `samples` (oldest first, `(y(j), u(j))`) at the start `x`, with
/// output weights `weights` (`1 / σ²` per output). The model is stepped between samples, not after
/// the last one.
pub fn normal_equations<'s, T, P, const NX: usize, const NY: usize, const NU: usize>(
    plant: &P,
    x: &[T; NX],
    samples: impl IntoIterator<Item = (&'s [T; NY], &'s [T; NU])>,
    weights: &[T; NY],
) -> Normal<T, NX>
where
    T: Scalar + 's,
    P: Plant<T, NX, NY, NU>,
{
    let mut normal = Normal {
        cost: T::ZERO,
        matrix: [[T::ZERO; NX]; NX],
        gradient: [T::ZERO; NX],
        end: *x,
    };
    let mut state = *x;
    let mut sensitivity: [[T; NX]; NX] = core::array::from_fn(|r| core::array::from_fn(|c| identity(r, c)));
    // The input held since the previous sample: x(j) = f(x(j−1), u(j−1)).
    let mut held: Option<&[T; NU]> = None;
    for (y, u) in samples {
        if let Some(previous) = held {
            let (next, f) = plant.step(&state, previous);
            state = next;
            sensitivity = crate::matrix::product(&f, &sensitivity);
        }
        held = Some(u);
        let (predicted, h) = plant.output(&state, u);
        for i in 0..NY {
            let residual = y[i] - predicted[i];
            if !residual.is_finite() {
                continue;
            }
            // J_i = H_i Φ: the sensitivity of output i to the start.
            let mut row = [T::ZERO; NX];
            for (c, entry) in row.iter_mut().enumerate() {
                for (k, &hk) in h[i].iter().enumerate() {
                    *entry += hk * sensitivity[k][c];
                }
            }
            let w = weights[i];
            normal.cost += w * residual * residual;
            for (a, &ra) in row.iter().enumerate() {
                let weighted = w * ra;
                normal.gradient[a] += weighted * residual;
                for (entry, &rb) in normal.matrix[a].iter_mut().zip(&row) {
                    *entry += weighted * rb;
                }
            }
        }
    }
    normal.end = state;
    normal
}

fn identity<T: Scalar>(r: usize, c: usize) -> T {
    if r == c {
        T::one()
    } else {
        T::ZERO
    }
}

/// `x` with `A x = b` for a symmetric positive definite `A`, by the Cholesky factorisation `A = G Gᵀ`
/// (`n` square roots and `n` divisions); `None` when a pivot is not positive (or not finite).
#[allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)] // the textbook's indices // `!(pivot > 0)`: a NaN pivot is not positive either.
pub fn solve_cholesky<T: Scalar, const N: usize>(a: &[[T; N]; N], b: &[T; N]) -> Option<[T; N]> {
    let mut g = [[T::ZERO; N]; N];
    let mut inverse_diagonal = [T::ZERO; N];
    for r in 0..N {
        for c in 0..=r {
            let mut sum = a[r][c];
            for k in 0..c {
                sum -= g[r][k] * g[c][k];
            }
            if r == c {
                if !(sum > T::ZERO) || !sum.is_finite() {
                    return None;
                }
                let root = sum.sqrt();
                g[r][r] = root;
                inverse_diagonal[r] = T::one() / root;
            } else {
                g[r][c] = sum * inverse_diagonal[c];
            }
        }
    }
    // G z = b, then Gᵀ x = z.
    let mut z = [T::ZERO; N];
    for r in 0..N {
        let mut sum = b[r];
        for k in 0..r {
            sum -= g[r][k] * z[k];
        }
        z[r] = sum * inverse_diagonal[r];
    }
    let mut x = [T::ZERO; N];
    for r in (0..N).rev() {
        let mut sum = z[r];
        for k in r + 1..N {
            sum -= g[k][r] * x[k];
        }
        x[r] = sum * inverse_diagonal[r];
    }
    Some(x)
}

#[cfg(test)]
mod tests;
