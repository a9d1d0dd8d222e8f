//! The plant's model on the chip: `ẋ = f(x, u)`, `y = h(x, u)` as the spec writes them ([`Model`],
//! emitted by the host from the expression trees), and its discretisation over one sampling period
//! by classical RK4 with the input held ([`Rk4`]), which is what an [`crate::Ekf`] predicts with.
//!
//! # The Jacobian of the step
//!
//! `F = ∂x(t + τ)/∂x(t)` is the exact derivative of the *discrete* RK4 map (forward-mode, carried
//! through the stages), not an approximation of the continuous flow's: with `A = ∂f/∂x`,
//!
//! ```text
//! k1 = f(x),             D1 = A(x)
//! k2 = f(x + h/2 k1),    D2 = A(x + h/2 k1) (I + h/2 D1)
//! k3 = f(x + h/2 k2),    D3 = A(x + h/2 k2) (I + h/2 D2)
//! k4 = f(x + h k3),      D4 = A(x + h k3) (I + h D3)
//! x⁺ = x + h/6 (k1 + 2 k2 + 2 k3 + k4),    ∂x⁺/∂x = I + h/6 (D1 + 2 D2 + 2 D3 + D4)
//! ```
//!
//! and the substeps' derivatives multiply. The same number of substeps runs every sample.

pub use crate::matrix::product;
use crate::{ekf::Plant, Scalar};

/// The continuous-time model with its Jacobians in the state. Generated designs implement it (a unit
/// struct per design) from the spec's expressions, written out as straight-line code.
pub trait Model<T, const NX: usize, const NY: usize, const NU: usize> {
    /// `f(x, u)` and `∂f/∂x` there.
    fn derivative(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NX], [[T; NX]; NX]);
    /// `h(x, u)` and `∂h/∂x` there.
    fn output(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NY], [[T; NX]; NY]);
}

/// One sampling period of a [`Model`] by `SUBSTEPS` classical RK4 steps of width `h = τ / SUBSTEPS`,
/// the input held.
#[derive(Clone, Copy, Debug)]
pub struct Rk4<T, M, const SUBSTEPS: usize> {
    model: M,
    /// `h`, `h/2` and `h/6`, fixed at construction.
    h: T,
    half: T,
    sixth: T,
}

impl<T: Scalar, M, const SUBSTEPS: usize> Rk4<T, M, SUBSTEPS> {
    /// The discretised `model`, each substep of width `h` (`τ / SUBSTEPS`, rounded by the host).
    pub fn new(model: M, h: T) -> Self {
        const { assert!(SUBSTEPS >= 1, "at least one RK4 step per sample") };
        let two = T::one() + T::one();
        Rk4 {
            model,
            h,
            half: h / two,
            sixth: h / (two + two + two),
        }
    }

    /// The model.
    pub fn model(&self) -> &M {
        &self.model
    }

    /// `h`, the width of one substep.
    pub fn h(&self) -> T {
        self.h
    }
}

impl<T: Scalar, M: Model<T, NX, NY, NU>, const NX: usize, const NY: usize, const NU: usize, const SUBSTEPS: usize>
    Plant<T, NX, NY, NU> for Rk4<T, M, SUBSTEPS>
{
    fn step(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NX], [[T; NX]; NX]) {
        let (mut x, mut jacobian) = self.substep(x, u);
        for _ in 1..SUBSTEPS {
            let (next, d) = self.substep(&x, u);
            x = next;
            jacobian = product(&d, &jacobian);
        }
        (x, jacobian)
    }

    fn output(&self, x: &[T; NX], u: &[T; NU]) -> ([T; NY], [[T; NX]; NY]) {
        self.model.output(x, u)
    }
}

impl<T: Scalar, M, const SUBSTEPS: usize> Rk4<T, M, SUBSTEPS> {
    /// One RK4 step of width `h` and its derivative in `x`.
    fn substep<const NX: usize, const NY: usize, const NU: usize>(
        &self,
        x: &[T; NX],
        u: &[T; NU],
    ) -> ([T; NX], [[T; NX]; NX])
    where
        M: Model<T, NX, NY, NU>,
    {
        let two = T::one() + T::one();
        let (k1, d1) = self.model.derivative(x, u);
        let (k2, d2) = self.stage(x, &k1, &d1, self.half, u);
        let (k3, d3) = self.stage(x, &k2, &d2, self.half, u);
        let (k4, d4) = self.stage(x, &k3, &d3, self.h, u);
        let mut next = *x;
        let mut jacobian = identity();
        for i in 0..NX {
            next[i] += self.sixth * (k1[i] + two * (k2[i] + k3[i]) + k4[i]);
            for j in 0..NX {
                jacobian[i][j] += self.sixth * (d1[i][j] + two * (d2[i][j] + d3[i][j]) + d4[i][j]);
            }
        }
        (next, jacobian)
    }

    /// The stage at `x + w k` and its derivative `A(x + w k) (I + w D)`.
    fn stage<const NX: usize, const NY: usize, const NU: usize>(
        &self,
        x: &[T; NX],
        k: &[T; NX],
        d: &[[T; NX]; NX],
        w: T,
        u: &[T; NU],
    ) -> ([T; NX], [[T; NX]; NX])
    where
        M: Model<T, NX, NY, NU>,
    {
        let mut point = *x;
        let mut moved = identity();
        for i in 0..NX {
            point[i] += w * k[i];
            for j in 0..NX {
                moved[i][j] += w * d[i][j];
            }
        }
        let (value, a) = self.model.derivative(&point, u);
        (value, product(&a, &moved))
    }
}

/// The identity matrix.
fn identity<T: Scalar, const M: usize>() -> [[T; M]; M] {
    let mut m = [[T::ZERO; M]; M];
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = T::one();
    }
    m
}

#[cfg(test)]
mod tests;
