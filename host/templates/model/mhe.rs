{# The moving-horizon estimate on the chip (`Mhe`, `MheObserver`) with the constants `gen` chose. #}
/// The moving-horizon estimate's constants as `gen` chose them ([`MheObserver`], kind `mhe`): the
/// model ([`Discrete`]), the outputs' weights `1 / σ²`, the prior's weight per state, the box the
/// learning runs cover, the first window's start, {{ iterations }} Gauss–Newton step(s) per sample and
/// Levenberg's damping.
pub struct Mhe;

impl<T: Scalar + Maths> firmware::emitted::mhe::Horizon<T, STATES, OUTPUTS, INPUTS, TARGETS> for Mhe {
    type Plant = Discrete<T>;

    #[inline(always)]
    fn plant() -> Discrete<T> {
        firmware::Rk4::new(Plant, {{ h }})
    }

    #[inline(always)]
    fn settings() -> firmware::emitted::mhe::Settings<T, STATES, OUTPUTS> {
        firmware::emitted::mhe::Settings {
            weights: {{ weights }},
            prior: {{ prior }},
            lower: {{ lower }},
            upper: {{ upper }},
            start: {{ start }},
            iterations: {{ iterations }},
            damping: {{ damping }},
        }
    }

    #[inline(always)]
    fn targets(x: &[T; STATES], u: &[T; INPUTS]) -> [T; TARGETS] {
        targets(x, u)
    }
}

/// The moving-horizon estimate on the chip ([`firmware::mhe::Observer`] over [`Discrete`], kind
/// `mhe`): at every sample, {{ iterations }} Gauss–Newton step(s) over the last [`HORIZON`] samples from
/// the previous solution moved one sample on (also the prior's centre), each solved by a Cholesky
/// factorisation (`L D Lᵀ`, no square root) and projected onto the box the learning runs cover;
/// `estimate` gives the targets at the newest sample. The paper's on-line observer, which the map
/// replaces: the report gives its accuracy beside the converged MHE's, docs/chip.md its cost.
pub type MheObserver = firmware::mhe::Observer<f32, Mhe, HORIZON, STATES, OUTPUTS, INPUTS, TARGETS>;

