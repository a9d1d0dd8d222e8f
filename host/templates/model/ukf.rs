{# The design's UKF: its constants and the filter type (`filter`). #}
{{ q_constant }}

/// This design's unscented Kalman filter, written out for its size by `gen`: the scaled unscented
/// transform (Wan & van der Merwe; α = {{ alpha }}, β = {{ beta }}, κ = {{ kappa }}: the cubature rule, `2n`
/// sigma points `x ± √n Lᵢ` of equal weight) from the Cholesky factor of `P` (each pivot floored: `P`
/// stays positive definite), every one through [`Discrete`], projected onto the model's bounds; each measured sample one joint update of every
/// output (`K = C S⁻¹` through the Cholesky factor of `S`, no inverse), `P` kept as its upper
/// triangle. {{ constants }}
///
/// A sample with a non-finite `y` is refused and only predicted; one with a non-finite `u` changes
/// nothing; a sample whose result is not finite is not taken.
{{ filter }}/// A fresh UKF in `f32`, as the chip runs it.
pub fn ukf() -> Ukf {
    Ukf::new()
}

