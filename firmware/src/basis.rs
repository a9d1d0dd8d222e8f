//! The monotone basis of `Γ`.
//!
//! The paper (eq. `efdelabase`) builds `Γ` from `{1} ∪ {B1_i}_{i=1}^{n_m-1} ∪ {B2_i}_{i=1}^{n_m}` with
//! `α_i = e^{β(1-i)} - 1`, `B1_i(η) = (1+α_i) η / (1+α_i η)` and `B2_i(η) = η / (1+α_i-α_i η)`.
//! Both are members of one family,
//!
//! ```text
//! B(η; b) = (1 + b) η / (1 + b η),   b > -1:   B(0) = 0,  B(1) = 1,  B'(η) = (1 + b) / (1 + b η)² > 0,
//! ```
//!
//! with `B1_i = B(·; α_i)` (`b ∈ (-1, 0]`, convex) and `B2_i = B(·; -α_i/(1+α_i)) = B(·; e^{β(i-1)} - 1)`
//! (`b ≥ 0`, concave). Since `α_1 = 0`, `B1_1 = B2_1 = η`: the paper's list holds that function twice,
//! which makes its least-squares Hessian singular. [`paper_curvatures`] keeps every distinct function
//! once: `2 n_m - 2` non-constant functions (for `n_m ≥ 2`), plus the constant where the fit uses it.

use crate::Scalar;

/// `B(η; b) = (1 + b) η / (1 + b η)`.
#[inline]
pub fn value<T: Scalar>(curvature: T, eta: T) -> T {
    (T::one() + curvature) * eta / (T::one() + curvature * eta)
}

/// `dB/dη = (1 + b) / (1 + b η)²`.
#[inline]
pub fn slope<T: Scalar>(curvature: T, eta: T) -> T {
    let denominator = T::one() + curvature * eta;
    (T::one() + curvature) / (denominator * denominator)
}

/// `∫₀¹ B(η; b) dη = (1 + b) (1/b - ln(1 + b)/b²)`, by its Taylor series near `b = 0` where the closed
/// form cancels catastrophically.
pub fn integral<T: Scalar>(curvature: T) -> T {
    let b = curvature;
    let one = T::one();
    if b.abs() < T::constant(1e-3) {
        // 1/b - ln(1+b)/b² = 1/2 - b/3 + b²/4 - b³/5 + b⁴/6 - …; the b⁵ term is below 1e-15.
        let series = T::constant(0.5)
            + b * (T::constant(-1.0 / 3.0)
                + b * (T::constant(0.25) + b * (T::constant(-0.2) + b * T::constant(1.0 / 6.0))));
        (one + b) * series
    } else {
        (one + b) * (one / b - (one + b).ln() / (b * b))
    }
}

/// Curvatures `b` of the paper's distinct non-constant basis functions, in the order
/// `η (= B1_1 = B2_1)`, `B1_2 … B1_{n_m-1}` (convex), `B2_2 … B2_{n_m}` (concave).
pub fn paper_curvatures(nm: usize, beta: f64) -> impl Iterator<Item = f64> + Clone {
    let convex = (2..nm).map(move |i| libm::exp(beta * (1.0 - i as f64)) - 1.0);
    let concave = (2..=nm).map(move |i| libm::exp(beta * (i as f64 - 1.0)) - 1.0);
    core::iter::once(0.0).chain(convex).chain(concave)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The paper's formulas, written as the paper writes them, as the independent reference.
    fn paper_b1(alpha: f64, eta: f64) -> f64 {
        (1.0 + alpha) * eta / (1.0 + alpha * eta)
    }
    fn paper_b2(alpha: f64, eta: f64) -> f64 {
        eta / (1.0 + alpha - alpha * eta)
    }

    #[test]
    fn curvatures_are_the_papers_distinct_functions() {
        let (nm, beta) = (5, 1.3);
        let b: Vec<f64> = paper_curvatures(nm, beta).collect();
        assert_eq!(b.len(), 2 * nm - 2);
        let alpha = |i: usize| (beta * (1.0 - i as f64)).exp() - 1.0;
        for k in 0..=20 {
            let eta = k as f64 / 20.0;
            // B1_1 = B2_1 = η
            assert!((value(b[0], eta) - paper_b1(alpha(1), eta)).abs() < 1e-15);
            assert!((value(b[0], eta) - paper_b2(alpha(1), eta)).abs() < 1e-15);
            for i in 2..nm {
                assert!((value(b[i - 1], eta) - paper_b1(alpha(i), eta)).abs() < 1e-14);
            }
            for i in 2..=nm {
                assert!((value(b[nm - 3 + i], eta) - paper_b2(alpha(i), eta)).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn one_moment_function_gives_only_eta() {
        assert_eq!(paper_curvatures(1, 2.0).collect::<Vec<_>>(), [0.0]);
    }

    proptest! {
        #[test]
        fn slope_matches_central_differences(b in -0.95f64..1.0e4, eta in 0.001f64..0.999) {
            let h: f64 = 1e-7;
            let numeric = (value(b, eta + h) - value(b, eta - h)) / (2.0 * h);
            let exact = slope(b, eta);
            prop_assert!((numeric - exact).abs() <= 1e-6 * exact.abs().max(1.0), "{numeric} vs {exact}");
        }

        #[test]
        fn integral_matches_quadrature(b in prop_oneof![-0.99f64..-1e-3, -1e-3f64..1e-3, 1e-3f64..1e3]) {
            // Composite Simpson on a grid graded towards the steep end (near 0 for b > 0, near 1 for b < 0).
            let n = 20_000;
            let grade = |s: f64| if b >= 0.0 { s * s } else { 1.0 - (1.0 - s) * (1.0 - s) };
            let mut sum = 0.0;
            for i in 0..n {
                let (s0, s1) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
                let (a, c) = (grade(s0), grade(s1));
                let m = 0.5 * (a + c);
                sum += (c - a) / 6.0 * (value(b, a) + 4.0 * value(b, m) + value(b, c));
            }
            let exact = integral(b);
            prop_assert!((sum - exact).abs() < 1e-9, "b={b}: quadrature {sum} vs closed form {exact}");
        }

        #[test]
        fn series_agrees_with_closed_form_where_both_are_accurate(b in prop_oneof![-1e-3f64..-3e-4, 3e-4f64..1e-3]) {
            // There the closed form loses only ~eps/b² ≈ 1e-9 and the series is exact to ~b⁵ ≈ 1e-15.
            let closed = (1.0 + b) * (1.0 / b - (1.0 + b).ln() / (b * b));
            prop_assert!((integral(b) - closed).abs() < 1e-8);
        }
    }
}
