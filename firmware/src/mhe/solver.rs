//! The moving-horizon estimate's arithmetic (see the [module's](super) documentation): the normal
//! equations of a window, their Cholesky solve, and one window's projected Gauss–Newton steps. What
//! the chip's observer runs and the host's converged reference calls; reached from outside the crate
//! through `crate::emitted::mhe`.

use crate::bounds::project;
use crate::watch::Watch;
use crate::window::Sample;
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
            // A non-finite residual (a prediction the model overflows; the observer stores only finite
            // samples) weighs nothing: by selects, so that it does not change the instructions run.
            let residual = y[i] - predicted[i];
            let finite = residual.is_finite();
            let residual = core::hint::select_unpredictable(finite, residual, T::ZERO);
            // J_i = H_i Φ: the sensitivity of output i to the start.
            let mut row = [T::ZERO; NX];
            for (c, entry) in row.iter_mut().enumerate() {
                for (k, &hk) in h[i].iter().enumerate() {
                    *entry += hk * sensitivity[k][c];
                }
            }
            let w = core::hint::select_unpredictable(finite, weights[i], T::ZERO);
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

/// `x` with `A x = b` for a symmetric positive definite `A`, by the square-root-free Cholesky
/// factorisation `A = L D Lᵀ` (`L` unit lower triangular, `D` diagonal): `n` divisions and no square
/// root, so no software `sqrtf` (whose path depends on its argument) on a chip; `None` when a pivot
/// of `D` is not positive (or not finite).
#[allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)] // the textbook's indices
pub fn solve_cholesky<T: Scalar, const M: usize>(a: &[[T; M]; M], b: &[T; M]) -> Option<[T; M]> {
    let mut l = [[T::ZERO; M]; M];
    let mut d = [T::ZERO; M];
    let mut inverse_d = [T::ZERO; M];
    for j in 0..M {
        let mut pivot = a[j][j];
        for k in 0..j {
            pivot -= l[j][k] * l[j][k] * d[k];
        }
        if !(pivot > T::ZERO) || !pivot.is_finite() {
            return None;
        }
        d[j] = pivot;
        inverse_d[j] = T::one() / pivot;
        for i in j + 1..M {
            let mut sum = a[i][j];
            for k in 0..j {
                sum -= l[i][k] * l[j][k] * d[k];
            }
            l[i][j] = sum * inverse_d[j];
        }
    }
    // L z = b, then Lᵀ x = D⁻¹ z.
    let mut z = [T::ZERO; M];
    for r in 0..M {
        let mut sum = b[r];
        for k in 0..r {
            sum -= l[r][k] * z[k];
        }
        z[r] = sum;
    }
    let mut x = [T::ZERO; M];
    for r in (0..M).rev() {
        let mut sum = z[r] * inverse_d[r];
        for k in r + 1..M {
            sum -= l[k][r] * x[k];
        }
        x[r] = sum;
    }
    Some(x)
}

/// `x(N−1)`: the start `x` carried through the window `samples` (oldest first).
pub fn propagate<'s, T, P, const NX: usize, const NY: usize, const NU: usize>(
    plant: &P,
    x: &[T; NX],
    samples: impl IntoIterator<Item = &'s [T; NU]>,
) -> [T; NX]
where
    T: Scalar + 's,
    P: Plant<T, NX, NY, NU>,
{
    let mut state = *x;
    let mut held: Option<&[T; NU]> = None;
    for u in samples {
        if let Some(previous) = held {
            state = plant.step(&state, previous).0;
        }
        held = Some(u);
    }
    state
}

/// One window's estimate as [`super::Observer`] computes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solved<T, const NX: usize> {
    /// The state at the window's start.
    pub start: [T; NX],
    /// The state at the window's newest sample, projected onto the box.
    pub end: [T; NX],
    /// The window's output cost `Σ_j Σ_i w_i r_i(j)²` at the last Gauss–Newton step's start (what
    /// the χ² watch reads: its mean is `N m` when the model and the noise are right).
    pub cost: T,
}

/// One window's estimate as [`super::Observer`] computes it: `settings.iterations` projected
/// Gauss–Newton steps from `centre` (the prior's centre too, when `prior`), then the solution carried
/// to the window's end and projected.
pub fn solve_window<T, P, const NX: usize, const NY: usize, const NU: usize>(
    plant: &P,
    settings: &Settings<T, NX, NY>,
    samples: &[Sample<T, NY, NU>],
    centre: &[T; NX],
    prior: bool,
) -> Solved<T, NX>
where
    T: Scalar,
    P: Plant<T, NX, NY, NU>,
{
    let s = settings;
    let mut x = *centre;
    let mut cost = T::ZERO;
    for _ in 0..s.iterations {
        let mut normal = normal_equations(plant, &x, samples.iter().map(|s| (&s.y, &s.u)), &s.weights);
        cost = normal.cost;
        for i in 0..NX {
            if prior {
                normal.matrix[i][i] += s.prior[i];
                normal.gradient[i] -= s.prior[i] * (x[i] - centre[i]);
            }
            normal.matrix[i][i] += s.damping * normal.matrix[i][i];
        }
        let Some(step) = solve_cholesky(&normal.matrix, &normal.gradient) else {
            break;
        };
        let mut next = x;
        for (value, delta) in next.iter_mut().zip(step) {
            *value += delta;
        }
        x = project(&next, &s.lower, &s.upper);
    }
    let end = propagate::<T, P, NX, NY, NU>(plant, &x, samples.iter().map(|s| &s.u));
    Solved {
        start: x,
        end: project(&end, &s.lower, &s.upper),
        cost,
    }
}

/// What [`super::Observer`] is tuned with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings<T, const NX: usize, const NY: usize> {
    /// `1 / σ²` per output.
    pub weights: [T; NY],
    /// The prior's weight per state (`p / s²`; zero: none).
    pub prior: [T; NX],
    /// Lower bound of each state (the box the start is sought in).
    pub lower: [T; NX],
    /// Upper bound of each state.
    pub upper: [T; NX],
    /// Where the first window's iterations start.
    pub start: [T; NX],
    /// Gauss–Newton steps per sample.
    pub iterations: usize,
    /// Levenberg's damping, relative to each diagonal entry: keeps the system positive definite where
    /// a state barely reaches the outputs.
    pub damping: T,
    /// The χ² watch over the windows' output costs ([`crate::watch`]), where the observer is watched:
    /// a run of implausible windows restarts it.
    pub watch: Option<Watch<T>>,
}
