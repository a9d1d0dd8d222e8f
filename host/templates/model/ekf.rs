{# The design's EKF: its constants, the filter type (`filter`) and the library filter it writes out. #}
/// Entries of the EKF's covariance kept: its upper triangle, row by row (it is symmetric).
pub const COVARIANCE: usize = {{ triangle }};

{{ q_constant }}

/// This design's extended Kalman filter, written out for its size by `gen`: the library's
/// [`firmware::Ekf`] over [`Discrete`] ([`reference_ekf`], same constants), with each sample as
/// straight-line code (no loop, no structural zero or one multiplied, `P` as its upper triangle).
/// {{ constants }}
///
/// Each sample: every output's scalar update in Joseph form, then the prediction over one sampling
/// period. A sample with a non-finite `y` is refused and only predicted; one with a non-finite `u`
/// changes nothing; a sample whose result is not finite (the model overflowed) is not taken.{{ watch_docs }}
{{ filter }}/// Whether every entry of a filter's state and covariance is finite.
fn finite<T: Scalar>(x: &[T; STATES], p: &[T; COVARIANCE]) -> bool {
    x.iter().chain(p).all(|v| v.is_finite())
}

/// A fresh EKF in `f32`, as the chip runs it.
pub fn ekf() -> Ekf {
    Ekf::new()
}

/// The library filter this design's [`Ekf`] writes out, with the same constants: what the tests
/// check the written-out one against.
pub fn reference_ekf<T: Scalar + Maths>() -> firmware::Ekf<T, Discrete<T>, STATES, OUTPUTS, INPUTS> {
    firmware::Ekf::new(
        firmware::Rk4::new(Plant, {{ h }}),
        {{ x0 }},
        {{ p0 }},
        {{ q }},
        {{ r }},
    ){{ bounds }}{{ watch }}
}

