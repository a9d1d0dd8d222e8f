//! One sample of a [`FilterCode`] run in `T` as the emitted code runs it: the programs' leaves read
//! from the state, the covariance's upper triangle, the sample and the inputs; the results split into
//! `x̂(k|k)`, `x⁺`, `P⁺` and the numbers after them.

use firmware::emitted::Maths;
use firmware::Scalar;

use super::super::program::Leaf;
use super::{FilterCode, Sampled};

impl FilterCode {
    /// Runs one sample from `x` and `p` (upper triangle) in `T` exactly as the emitted code does:
    /// with `y`, the update and the prediction; without, the prediction alone.
    pub fn run<T: Scalar + Maths>(
        &self,
        x: &[T],
        p: &[T],
        y: Option<&[T]>,
        u: &[T],
        scratch: &mut Vec<T>,
    ) -> Sampled<T> {
        self.run_watched(x, p, y, u, scratch).0
    }

    /// [`FilterCode::run`], with the sample's normalised innovation squared when it is measured.
    pub fn run_watched<T: Scalar + Maths>(
        &self,
        x: &[T],
        p: &[T],
        y: Option<&[T]>,
        u: &[T],
        scratch: &mut Vec<T>,
    ) -> (Sampled<T>, Option<T>) {
        let (sampled, scalars) = self.run_all(x, p, y, u, scratch);
        (sampled, scalars.map(|s| s[0]))
    }

    /// [`FilterCode::run`] of a measured sample, with every number the measured program gives after
    /// `P⁺` ([`FilterCode::scalars`]).
    pub fn run_scored<T: Scalar + Maths>(
        &self,
        x: &[T],
        p: &[T],
        y: &[T],
        u: &[T],
        scratch: &mut Vec<T>,
    ) -> (Sampled<T>, Vec<T>) {
        let (sampled, scalars) = self.run_all(x, p, Some(y), u, scratch);
        (sampled, scalars.unwrap_or_default())
    }

    /// One sample's results, split, with the scalars after `P⁺` when it is measured.
    fn run_all<T: Scalar + Maths>(
        &self,
        x: &[T],
        p: &[T],
        y: Option<&[T]>,
        u: &[T],
        scratch: &mut Vec<T>,
    ) -> (Sampled<T>, Option<Vec<T>>) {
        let program = if y.is_some() { &self.measured } else { &self.unmeasured };
        let results = program.eval_with(&self.parameters, scratch, |leaf| match leaf {
            Leaf::State(i) => x[i],
            Leaf::Input(i) => u[i],
            Leaf::Covariance(k) => p[k],
            Leaf::Measurement(i) => y.map_or(T::literal(f32::NAN, f64::NAN), |y| y[i]),
            // Parameters are the program's constants, read before this; a filter reads no map.
            Leaf::Parameter(_) | Leaf::Map(_) | Leaf::Blend(_) => T::literal(f32::NAN, f64::NAN),
        });
        self.split(results, y.is_some())
    }

    /// A program's results as `(x̂(k|k), x⁺, P⁺)` and, measured, the scalars after them.
    fn split<T>(&self, mut results: Vec<T>, measured: bool) -> (Sampled<T>, Option<Vec<T>>) {
        let n = self.states;
        let scalars = measured.then(|| results.split_off(results.len() - self.scalars));
        let estimate = measured.then(|| results.drain(..n).collect());
        let covariance = results.split_off(n);
        ((estimate, results, covariance), scalars)
    }
}
