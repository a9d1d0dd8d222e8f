//! The monotone basis of `Γ`.
//!
//! The paper (eq. `efdelabase`) builds `Γ` from `{1} ∪ {B1_i}_{i=1}^{n_m-1} ∪ {B2_i}_{i=1}^{n_m}` with
//! `α_i = e^{β(1-i)} - 1`, `B1_i(η) = (1+α_i) η / (1+α_i η)` and `B2_i(η) = η / (1+α_i-α_i η)`.
//! Both are members of one family, written with an *odds ratio* `c > 0`:
//!
//! ```text
//! B(η; c) = c η / ((1 - η) + c η):   B/(1-B) = c · η/(1-η),   B(0) = 0,  B(1) = 1,
//!                                     B'(η) = c / ((1 - η) + c η)² > 0,
//! ```
//!
//! with `B1_i = B(·; e^{β(1-i)})` (`c ≤ 1`, convex) and `B2_i = B(·; e^{β(i-1)})` (`c ≥ 1`, concave).
//! Since `α_1 = 0`, `B1_1 = B2_1 = η` (`c = 1`): the paper's list holds that function twice, which makes
//! its least-squares Hessian singular. [`paper_odds_ratios`] keeps every distinct function once:
//! `2 n_m - 2` non-constant functions (for `n_m ≥ 2`), plus the constant where the fit uses it.
//!
//! Why odds ratios rather than the paper's `α` (or `b = c - 1`): the steepest convex functions have
//! `c` as small as `e^{-30}`, where `1 + b` rounds to 0 in `f32` and `1 + b η` vanishes at `η = 1`;
//! `(1 - η) + c η` keeps full relative precision for every `c`, and rounding `c` changes `B` by at most
//! one part in `2^24`.
//!
//! Only with the `reference` feature: the host fits and tabulates `Γ` with these functions; the chip
//! runs the tables and never evaluates a basis function.

use crate::Scalar;

/// `(1 - η) + c η`, the denominator of `B(η; c)`.
#[inline]
#[must_use]
pub fn denominator<T: Scalar>(odds_ratio: T, eta: T) -> T {
    (T::one() - eta) + odds_ratio * eta
}

/// `B(η; c) = c η / ((1 - η) + c η)`.
#[inline]
#[must_use]
pub fn value<T: Scalar>(odds_ratio: T, eta: T) -> T {
    odds_ratio * eta / denominator(odds_ratio, eta)
}

/// `dB/dη = c / ((1 - η) + c η)²`.
#[inline]
#[must_use]
pub fn slope<T: Scalar>(odds_ratio: T, eta: T) -> T {
    let d = denominator(odds_ratio, eta);
    odds_ratio / (d * d)
}

/// `∫₀¹ B(η; c) dη = c (1/b - ln(c)/b²)` with `b = c - 1`, by its Taylor series in `b` near `c = 1`
/// where the closed form cancels. Host-side (f64): the switch-over is tuned for f64.
#[must_use]
pub fn integral(odds_ratio: f64) -> f64 {
    let (c, b) = (odds_ratio, odds_ratio - 1.0);
    if b.abs() < 1e-3 {
        // 1/b - ln(1+b)/b² = 1/2 - b/3 + b²/4 - b³/5 + b⁴/6 - …; the b⁵ term is below 1e-15.
        c * (0.5 + b * (-1.0 / 3.0 + b * (0.25 + b * (-0.2 + b / 6.0))))
    } else {
        c * (1.0 / b - libm::log(c) / (b * b))
    }
}

/// Odds ratios `c` of the paper's distinct non-constant basis functions, in the order
/// `η (= B1_1 = B2_1)`, `B1_2 … B1_{n_m-1}` (convex), `B2_2 … B2_{n_m}` (concave).
pub fn paper_odds_ratios(nm: usize, beta: f64) -> impl Iterator<Item = f64> + Clone {
    let convex = (2..nm).map(move |i| libm::exp(beta * (1.0 - i as f64)));
    let concave = (2..=nm).map(move |i| libm::exp(beta * (i as f64 - 1.0)));
    core::iter::once(1.0).chain(convex).chain(concave)
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
    fn odds_ratios_give_the_papers_distinct_functions() {
        let (nm, beta) = (5, 1.3);
        let c: Vec<f64> = paper_odds_ratios(nm, beta).collect();
        assert_eq!(c.len(), 2 * nm - 2);
        let alpha = |i: usize| (beta * (1.0 - i as f64)).exp() - 1.0;
        for k in 0..=20 {
            let eta = k as f64 / 20.0;
            // B1_1 = B2_1 = η
            assert!((value(c[0], eta) - paper_b1(alpha(1), eta)).abs() < 1e-15);
            assert!((value(c[0], eta) - paper_b2(alpha(1), eta)).abs() < 1e-15);
            for i in 2..nm {
                assert!((value(c[i - 1], eta) - paper_b1(alpha(i), eta)).abs() < 1e-14);
            }
            for i in 2..=nm {
                assert!((value(c[nm - 3 + i], eta) - paper_b2(alpha(i), eta)).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn one_moment_function_gives_only_eta() {
        assert_eq!(paper_odds_ratios(1, 2.0).collect::<Vec<_>>(), [1.0]);
    }

    #[test]
    fn tiny_odds_ratios_stay_exact_in_f32() {
        // c = e^{-20}: with the paper's form 1 + α rounds to 0 in f32; here B(1) = 1 and B(½) ≈ c.
        let c = (-20.0f64).exp();
        assert_eq!(value(c as f32, 1.0f32), 1.0);
        let half = value(c as f32, 0.5f32) as f64;
        assert!((half / value(c, 0.5) - 1.0).abs() < 4.0 * f32::EPSILON as f64, "{half}");
        assert!(slope(c as f32, 1.0f32).is_finite());
    }

    proptest! {
        #[test]
        fn slope_matches_central_differences(log_c in -8.0f64..9.0, eta in 0.001f64..0.999) {
            let c = log_c.exp();
            let h: f64 = 1e-7;
            let numeric = (value(c, eta + h) - value(c, eta - h)) / (2.0 * h);
            let exact = slope(c, eta);
            prop_assert!((numeric - exact).abs() <= 1e-6 * exact.abs().max(1.0), "{numeric} vs {exact}");
        }

        #[test]
        fn integral_matches_quadrature(c in prop_oneof![0.01f64..0.999, 0.999f64..1.001, 1.001f64..1e3]) {
            // Composite Simpson on a grid graded towards the steep end (near 0 for c > 1, near 1 for c < 1).
            let n = 20_000;
            let grade = |s: f64| if c >= 1.0 { s * s } else { 1.0 - (1.0 - s) * (1.0 - s) };
            let mut sum = 0.0;
            for i in 0..n {
                let (s0, s1) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
                let (a, e) = (grade(s0), grade(s1));
                let m = 0.5 * (a + e);
                sum += (e - a) / 6.0 * (value(c, a) + 4.0 * value(c, m) + value(c, e));
            }
            let exact = integral(c);
            prop_assert!((sum - exact).abs() < 1e-9, "c={c}: quadrature {sum} vs closed form {exact}");
        }

        #[test]
        fn series_agrees_with_closed_form_where_both_are_accurate(b in prop_oneof![-1e-3f64..-3e-4, 3e-4f64..1e-3]) {
            // There the closed form loses only ~eps/b² ≈ 1e-9 and the series is exact to ~b⁵ ≈ 1e-15.
            let c = 1.0 + b;
            let closed = c * (1.0 / b - c.ln() / (b * b));
            prop_assert!((integral(c) - closed).abs() < 1e-8);
        }
    }
}
