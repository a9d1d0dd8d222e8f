//! An extended Kalman filter: the peer every design is measured against (and, later, the model
//! correction of the map). Plain arrays, no allocation, no division but one per output.
//!
//! # The filter
//!
//! With the plant `x⁺ = f(x, u) + w`, `y = h(x, u) + v`, `w ~ N(0, Q)`, `v ~ N(0, diag(r))`, each sample
//! `(y(k), u(k))`:
//!
//! ```text
//! update    for each output i (sequentially, R diagonal: one scalar division each):
//!             s = H_i P H_iᵀ + r_i,  K = P H_iᵀ / s,  x ← x + K (y_i - h_i(x, u))
//!             P ← (I - K H_i) P (I - K H_i)ᵀ + K r_i Kᵀ          (Joseph form)
//! predict   x ← f(x, u),  P ← F P Fᵀ + Q                          (F = ∂f/∂x at the updated x)
//! ```
//!
//! With bounds ([`Ekf::with_bounds`], [`crate::bounds`]), the state is projected onto them after the
//! updates and after the prediction (`P` is left as it is): the estimate and the state carried are
//! inside them, and the model is never evaluated outside.
//!
//! The estimate after a sample is the *updated* state `x̂(k|k)`. The Joseph form keeps `P` positive
//! semidefinite under rounding where `(I - K H) P` alone may not; after every step the lower triangle
//! is copied from the upper one, so `P` stays exactly symmetric without extra arithmetic.
//!
//! A sample with a NaN or infinite value is refused: the update is skipped, the prediction still runs
//! (time advances with the given input if it is finite; a non-finite input skips the prediction too), so
//! a refused sample costs the filter that sample's information and nothing else. A step whose result
//! is not finite on finite values (the model overflowed, e.g. `exp` of a diverged estimate) is not
//! taken: the filter restarts from `x̂(0)`, `P(0)` ([`crate::rules::Refused::Restarted`]), so no NaN
//! ever enters its state and it never stays stuck: the rule every filter kind follows, written once
//! in [`crate::rules`]. With a watch ([`Ekf::with_watch`], [`crate::watch`]), a filter whose normalised
//! innovations stay implausible restarts the same way.

#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!(s > 0)` is deliberate: a NaN must count as no information.

use crate::matrix::product;
use crate::Scalar;

/// The plant as the filter sees it: one sampling period of the model and its output, each with its
/// Jacobian in the state. Generated designs use [`crate::Rk4`] over their emitted [`crate::Model`].
pub trait Plant<T: Scalar, const NX: usize, const NY: usize, const NU: usize> {
    /// `f(x, u)` over one sampling period, and `F = ∂f/∂x` there.
    fn step(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NX], [[T; NX]; NX]);
    /// `h(x, u)`, and `H = ∂h/∂x` there.
    fn output(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NY], [[T; NX]; NY]);
}

/// The filter of plant `P`: the estimate, its covariance and the noise model.
#[derive(Clone, Copy, Debug)]
pub struct Ekf<T, P, const NX: usize, const NY: usize, const NU: usize> {
    /// `x̂`: after a sample, the estimate given that sample (`x̂(k|k)`).
    x: [T; NX],
    /// `P`, kept exactly symmetric.
    p: [[T; NX]; NX],
    /// `Q`, the process noise covariance per sampling period.
    q: [[T; NX]; NX],
    /// The measurement noise variances (diagonal `R`).
    r: [T; NY],
    /// Lower and upper bounds of each state (`±∞` where unbounded), when the state is bounded.
    bounds: Option<([T; NX], [T; NX])>,
    /// `x̂(0)` and `P(0)`: where a step that is not finite restarts the filter.
    start: ([T; NX], [[T; NX]; NX]),
    /// The watched mean of the normalised innovations squared ([`crate::watch`]).
    chi: T,
    /// The watch's gain and limit, when the filter is watched.
    watch: Option<(T, T)>,
    plant: P,
}

impl<T: Scalar, P: Plant<T, NX, NY, NU>, const NX: usize, const NY: usize, const NU: usize> Ekf<T, P, NX, NY, NU> {
    /// A filter of `plant` starting at `x0` with covariance `p0`, process noise `q` and measurement
    /// variances `r`.
    pub fn new(plant: P, x0: [T; NX], p0: [[T; NX]; NX], q: [[T; NX]; NX], r: [T; NY]) -> Self {
        let mut filter = Ekf {
            x: x0,
            p: p0,
            q,
            r,
            bounds: None,
            start: (x0, p0),
            chi: outputs::<T, NY>(),
            watch: None,
            plant,
        };
        symmetrise(&mut filter.p);
        filter.start.1 = filter.p;
        filter
    }

    /// The same filter with its state projected onto `[lower, upper]` after every update and every
    /// prediction (`±∞` for an unbounded side); the start is projected too.
    #[must_use]
    pub fn with_bounds(mut self, lower: [T; NX], upper: [T; NX]) -> Self {
        self.x = crate::bounds::project(&self.x, &lower, &upper);
        self.start.0 = self.x;
        self.bounds = Some((lower, upper));
        self
    }

    /// The same filter watched ([`crate::watch`]): it restarts from its start when the mean of its
    /// normalised innovations squared, `c ← c + gain (ε − c)`, exceeds `limit`.
    #[must_use]
    pub fn with_watch(mut self, gain: T, limit: T) -> Self {
        self.watch = Some((gain, limit));
        self
    }

    /// The current estimate.
    #[must_use]
    pub fn state(&self) -> [T; NX] {
        self.x
    }

    /// The current covariance `P`.
    #[must_use]
    pub fn covariance(&self) -> [[T; NX]; NX] {
        self.p
    }

    /// Takes the sample `(y, u)`: the measurement update, then the prediction to the next sample.
    /// Returns the updated estimate `x̂(k|k)`; a non-finite `y` is refused, and a step whose result
    /// is not finite restarts the filter from its start (see the module docs): the rule every filter
    /// follows, [`crate::rules::filter_sample`].
    pub fn push(&mut self, y: &[T; NY], u: &[T; NU]) -> Result<[T; NX], crate::rules::Refused> {
        let Ekf {
            x,
            p,
            q,
            r,
            bounds,
            start,
            chi,
            watch,
            plant,
        } = self;
        let steps = Steps { q, r, bounds, plant };
        let watch = *watch;
        let mut carried = (*x, *p, *chi);
        let result = crate::rules::filter_sample(
            &mut carried,
            u.iter().all(|v| v.is_finite()),
            y.iter().all(|v| v.is_finite()),
            |&(mut x, mut p, chi)| {
                let nis = steps.update(&mut x, &mut p, y, u);
                steps.project(&mut x);
                let estimate = x;
                steps.predict(&mut x, &mut p, u);
                let chi = watch.map_or(chi, |(gain, _)| crate::watch::watched(chi, nis, gain));
                (estimate, (x, p, chi))
            },
            |&(mut x, mut p, chi)| {
                steps.predict(&mut x, &mut p, u);
                (x, p, chi)
            },
            |(x, p, chi)| {
                x.iter().chain(p.iter().flatten()).all(|v| v.is_finite())
                    && watch.is_none_or(|(_, limit)| crate::watch::plausible(*chi, limit))
            },
            || (start.0, start.1, outputs::<T, NY>()),
        );
        (*x, *p, *chi) = carried;
        result
    }
}

/// What a filter's two samples read besides its state and covariance.
struct Steps<'a, T, P, const NX: usize, const NY: usize> {
    q: &'a [[T; NX]; NX],
    r: &'a [T; NY],
    bounds: &'a Option<([T; NX], [T; NX])>,
    plant: &'a P,
}

impl<T: Scalar, P, const NX: usize, const NY: usize> Steps<'_, T, P, NX, NY> {
    /// `x` projected onto the bounds, if any.
    fn project(&self, x: &mut [T; NX]) {
        if let Some((lower, upper)) = self.bounds {
            *x = crate::bounds::project(x, lower, upper);
        }
    }

    /// Sequential scalar updates in Joseph form, one per output; the normalised innovation squared
    /// `Σᵢ νᵢ² / sᵢ` over the outputs with noise (`rᵢ > 0`: a noiseless output's `sᵢ` may be 0).
    fn update<const NU: usize>(&self, x: &mut [T; NX], p: &mut [[T; NX]; NX], y: &[T; NY], u: &[T; NU]) -> T
    where
        P: Plant<T, NX, NY, NU>,
    {
        let mut nis = T::ZERO;
        for i in 0..NY {
            let (predicted, h) = self.plant.output(x, u);
            let row = h[i];
            // P Hᵢᵀ and s = Hᵢ P Hᵢᵀ + rᵢ.
            let mut ph = [T::ZERO; NX];
            for (a, out) in ph.iter_mut().enumerate() {
                for (b, &hb) in row.iter().enumerate() {
                    *out += p[a][b] * hb;
                }
            }
            let mut s = self.r[i];
            for (&hb, &phb) in row.iter().zip(&ph) {
                s += hb * phb;
            }
            if !(s > T::ZERO) {
                continue; // nothing to learn from this output (no sensitivity, no noise)
            }
            let inverse = T::one() / s;
            let gain = ph.map(|v| v * inverse);
            let innovation = y[i] - predicted[i];
            if self.r[i] > T::ZERO {
                nis += innovation * innovation * inverse;
            }
            for (x, &k) in x.iter_mut().zip(&gain) {
                *x += k * innovation;
            }
            // Joseph: P ← A P Aᵀ + K r Kᵀ with A = I - K Hᵢ.
            let mut a = [[T::ZERO; NX]; NX];
            for (r, row_a) in a.iter_mut().enumerate() {
                for (c, entry) in row_a.iter_mut().enumerate() {
                    let identity = if r == c { T::one() } else { T::ZERO };
                    *entry = identity - gain[r] * row[c];
                }
            }
            let mut next = product_transposed(&product(&a, p), &a);
            for (r, next_row) in next.iter_mut().enumerate() {
                for (c, entry) in next_row.iter_mut().enumerate() {
                    *entry += gain[r] * self.r[i] * gain[c];
                }
            }
            *p = next;
            symmetrise(p);
        }
        nis
    }

    /// `x ← f(x, u)`, `P ← F P Fᵀ + Q`, then `x` projected onto the bounds.
    fn predict<const NU: usize>(&self, x: &mut [T; NX], p: &mut [[T; NX]; NX], u: &[T; NU])
    where
        P: Plant<T, NX, NY, NU>,
    {
        let (next_x, f) = self.plant.step(x, u);
        let mut next = product_transposed(&product(&f, p), &f);
        for (next_row, q_row) in next.iter_mut().zip(self.q) {
            for (entry, &q) in next_row.iter_mut().zip(q_row) {
                *entry += q;
            }
        }
        *x = next_x;
        *p = next;
        symmetrise(p);
        self.project(x);
    }
}

/// `m`, the number of outputs: the watched mean's start, its value for a consistent filter.
fn outputs<T: Scalar, const NY: usize>() -> T {
    (0..NY).fold(T::ZERO, |m, _| m + T::one())
}

/// Copies the upper triangle of `p` onto the lower one.
#[allow(clippy::needless_range_loop)] // `p[r][c] = p[c][r]` reads and writes one array
fn symmetrise<T: Copy, const NX: usize>(p: &mut [[T; NX]; NX]) {
    for r in 0..NX {
        for c in 0..r {
            p[r][c] = p[c][r];
        }
    }
}

/// `A Bᵀ`.
fn product_transposed<T: Scalar, const M: usize>(a: &[[T; M]; M], b: &[[T; M]; M]) -> [[T; M]; M] {
    let mut out = [[T::ZERO; M]; M];
    for (r, out_row) in out.iter_mut().enumerate() {
        for (c, entry) in out_row.iter_mut().enumerate() {
            for k in 0..M {
                *entry += a[r][k] * b[c][k];
            }
        }
    }
    out
}

#[cfg(test)]
mod tests;
