//! The monotone map `Γ : [0, 1] → ℝ` and its exact inverse by bisection: the host's reference, which
//! the certified table the chip runs ([`crate::InverseTable`]) is proven against.
//!
//! Only with the `reference` feature: the chip never evaluates `Γ` (its tables fold it in), and a
//! bisection of 24 steps, each a sum of divisions, has no place in a sampling period.

use crate::{basis, Saturation, Scalar};

/// `Γ(η) = offset + Σ_j μ_j B(η; c_j) = offset + η Σ_j w_j / ((1 - η) + c_j η)`, with `w_j = μ_j c_j`.
///
/// The slices are borrowed so that the same code serves `const` tables on the target and fitted
/// vectors on the host. `mu` and `odds_ratios` have one entry per basis function; the weights
/// `w_j = μ_j c_j` are formed where they are used ([`weight`]), so the coefficients are stored once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gamma<'a, T> {
    /// `Γ(0)`: the constant basis coefficient minus any intercept of `Lᵀ Z`.
    pub offset: T,
    /// `μ_j`, the coefficients of `B(·; c_j)`.
    pub mu: &'a [T],
    /// `c_j > 0`, the odds ratios of the basis functions ([`basis`]).
    pub odds_ratios: &'a [T],
}

/// The result of `Γ⁻¹(v)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inverse<T> {
    /// `η ∈ [0, 1]` with `Γ(η) = v` to within `2^-BISECTION_STEPS` in `η`.
    pub eta: T,
    /// Whether `v` was outside `[Γ(0), Γ(1)]`.
    pub saturation: Saturation,
}

impl<T: Scalar> Gamma<'_, T> {
    /// `Γ(η)`.
    #[inline]
    #[must_use]
    pub fn value(&self, eta: T) -> T {
        let mut sum = T::zero();
        for (&m, &c) in self.mu.iter().zip(self.odds_ratios) {
            sum += weight(m, c) / basis::denominator(c, eta);
        }
        self.offset + eta * sum
    }

    /// `Γ'(η) = Σ_j w_j / ((1 - η) + c_j η)²`.
    #[must_use]
    pub fn slope(&self, eta: T) -> T {
        let mut sum = T::zero();
        for (&m, &c) in self.mu.iter().zip(self.odds_ratios) {
            let d = basis::denominator(c, eta);
            sum += weight(m, c) / d / d;
        }
        sum
    }

    /// `Γ(1) = offset + Σ_j μ_j` (every basis function is 1 at `η = 1`).
    #[must_use]
    pub fn upper(&self) -> T {
        self.value(T::one())
    }

    /// `Γ⁻¹(v)` on `[0, 1]` by bisection with exactly [`Scalar::BISECTION_STEPS`] steps whatever `v`
    /// is, so every call costs the same. Outside `[Γ(0), Γ(1)]` the result is clamped to `η = 0` or
    /// `η = 1` and says so; a NaN `v` is treated as below the range.
    #[must_use]
    pub fn inverse(&self, v: T) -> Inverse<T> {
        let (low, high) = (self.offset, self.upper());
        let saturation = if v > high {
            Saturation::High
        } else if v >= low {
            Saturation::Inside
        } else {
            Saturation::Low
        };
        let v = match saturation {
            Saturation::Inside => v,
            Saturation::Low => low,
            Saturation::High => high,
        };
        let half = T::constant(0.5);
        let (mut a, mut b) = (T::zero(), T::one());
        for _ in 0..T::BISECTION_STEPS {
            let middle = (a + b) * half;
            if self.value(middle) < v {
                a = middle;
            } else {
                b = middle;
            }
        }
        let eta = match saturation {
            Saturation::Inside => (a + b) * half,
            Saturation::Low => T::zero(),
            Saturation::High => T::one(),
        };
        Inverse { eta, saturation }
    }
}

/// `w_j = μ_j c_j`: the weight of `1 / ((1 - η) + c_j η)` in [`Gamma`], from the coefficient `μ_j` of `B(·; c_j)`.
#[must_use]
pub fn weight<T: Scalar>(mu: T, odds_ratio: T) -> T {
    mu * odds_ratio
}

/// `Γ(η)` written as the sum `offset + Σ μ_j B(η; c_j)` of [`basis::value`], the reference form.
#[must_use]
pub fn value_from_coefficients<T: Scalar>(offset: T, mu: &[T], odds_ratios: &[T], eta: T) -> T {
    let mut sum = offset;
    for (&m, &c) in mu.iter().zip(odds_ratios) {
        sum += m * basis::value(c, eta);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn odds_ratios() -> [f64; 8] {
        let mut c = [0.0; 8];
        for (slot, value) in c.iter_mut().zip(basis::paper_odds_ratios(5, 2.0)) {
            *slot = value;
        }
        c
    }

    proptest! {
        #[test]
        fn the_folded_form_gives_the_same_gamma(mu in proptest::array::uniform8(-3.0f64..3.0), offset in -5.0f64..5.0, eta in 0.0f64..=1.0) {
            let b = odds_ratios();
            let gamma = Gamma { offset, mu: &mu, odds_ratios: &b };
            let reference = value_from_coefficients(offset, &mu, &b, eta);
            prop_assert!((gamma.value(eta) - reference).abs() <= 1e-12 * (1.0 + reference.abs()) * 3000.0);
        }

        #[test]
        fn inverse_undoes_gamma(mu in proptest::array::uniform8(0.01f64..3.0), offset in -5.0f64..5.0, eta in 0.0f64..=1.0) {
            // Non-negative μ make Γ strictly increasing: every basis slope is positive.
            let b = odds_ratios();
            let gamma = Gamma { offset, mu: &mu, odds_ratios: &b };
            let inverse = gamma.inverse(gamma.value(eta));
            prop_assert_eq!(inverse.saturation, Saturation::Inside);
            // Bisection resolves η to 2^-52; rounding of Γ near η adds |δΓ| / Γ'(η) with Γ' ≥ min μ.
            let tolerance = 1e-15 + 64.0 * f64::EPSILON * (offset.abs() + mu.iter().sum::<f64>()) / gamma.slope(eta);
            prop_assert!((inverse.eta - eta).abs() <= tolerance, "{} vs {eta}", inverse.eta);
        }

        #[test]
        fn inverse_in_f32_is_within_f32_resolution(mu in proptest::array::uniform8(0.05f32..3.0), eta in 0.0f32..=1.0) {
            let b: [f32; 8] = core::array::from_fn(|j| odds_ratios()[j] as f32);
            let gamma = Gamma { offset: 0.5f32, mu: &mu, odds_ratios: &b };
            let inverse = gamma.inverse(gamma.value(eta));
            let tolerance = 1e-6 + 64.0 * f32::EPSILON * (0.5 + mu.iter().sum::<f32>()) / gamma.slope(eta);
            prop_assert!((inverse.eta - eta).abs() <= tolerance, "{} vs {eta}", inverse.eta);
        }
    }

    #[test]
    fn slope_is_the_derivative_of_value() {
        let b = odds_ratios();
        let mu = [0.3, -0.1, 0.7, 0.2, 1.0, -0.05, 0.4, 0.01];
        let gamma = Gamma {
            offset: 1.0,
            mu: &mu,
            odds_ratios: &b,
        };
        for k in 1..100 {
            let eta = k as f64 / 100.0;
            let h = 1e-7;
            let numeric = (gamma.value(eta + h) - gamma.value(eta - h)) / (2.0 * h);
            assert!((numeric - gamma.slope(eta)).abs() < 1e-5 * gamma.slope(eta).abs().max(1.0));
        }
    }

    #[test]
    fn saturates_visibly_outside_the_range() {
        let b = [1.0, 4.0];
        let mu = [1.0, 1.0];
        let gamma = Gamma {
            offset: -1.0,
            mu: &mu,
            odds_ratios: &b,
        };
        // Γ(0) = -1, Γ(1) = -1 + 1/1 + 4/4 = 1.
        assert_eq!(gamma.upper(), 1.0);
        let below = gamma.inverse(-1.5);
        assert_eq!((below.eta, below.saturation), (0.0, Saturation::Low));
        let above = gamma.inverse(7.0);
        assert_eq!((above.eta, above.saturation), (1.0, Saturation::High));
        let nan = gamma.inverse(f64::NAN);
        assert_eq!((nan.eta, nan.saturation), (0.0, Saturation::Low));
        let edge = gamma.inverse(1.0);
        assert_eq!(edge.saturation, Saturation::Inside);
        assert!((edge.eta - 1.0).abs() < 1e-15);
    }
}
