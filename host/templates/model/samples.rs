{# A Kalman filter's two samples (`<lower>_measured`, `<lower>_unmeasured`): each the straight-line body `gen` writes out from its program
   (`clippy::approx_constant`: a sigma point's spread √n may be a number clippy reads as a constant, √2). #}
/// {{ sample }} with its measurement: `(x̂(k|k), x⁺, P⁺, ε)` from `(x, P)`, `ε` the normalised
/// innovation squared ([`firmware::watch`]), written out by `gen`.
#[allow(unused_variables, non_snake_case, clippy::type_complexity, clippy::approx_constant)]
fn {{ lower }}_measured<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], y: &[T; OUTPUTS], u: &[T; INPUTS]) -> ([T; STATES], [T; STATES], [T; COVARIANCE], T) {
{{ measured }}}

/// {{ sample }} without its measurement (refused): `(x⁺, P⁺)` from `(x, P)`, written out by `gen`.
#[allow(unused_variables, non_snake_case, clippy::approx_constant)]
fn {{ lower }}_unmeasured<T: Scalar + Maths>(x: &[T; STATES], p: &[T; COVARIANCE], u: &[T; INPUTS]) -> ([T; STATES], [T; COVARIANCE]) {
{{ unmeasured }}}

