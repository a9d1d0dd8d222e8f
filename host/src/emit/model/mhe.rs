//! The moving-horizon estimate on the chip (`MheObserver`, `mhe()`): the firmware's
//! [`firmware::mhe::MovingHorizon`] over the design's `Discrete` model, with the constants `gen`
//! chose (`observers::references`): the same code the host runs in `f32` for the report's
//! `mhe_chip` row, so that the chip's estimates are the report's, bit for bit.

use super::rust_text::{list, literal};
use crate::emit::EmitError;
use crate::observers::mhe::ChipConstants;

/// The text of `MheObserver` and `mhe()` with `constants` (`h`: the model's RK4 substep).
pub(super) fn mhe(constants: &ChipConstants, h: f64) -> Result<String, EmitError> {
    let values = |what: &str, values: &[f64]| -> Result<String, EmitError> {
        let items = values
            .iter()
            .enumerate()
            .map(|(i, v)| literal(&format!("chip MHE {what}[{i}]"), *v))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(list(&items))
    };
    Ok(format!(
        "
/// The moving-horizon estimate on the chip ([`firmware::mhe::MovingHorizon`] over [`Discrete`]): at
/// every sample, {iterations} Gauss–Newton step(s) over the last [`HORIZON`] samples from the
/// previous solution moved one sample on (also the prior's centre), each solved by a Cholesky
/// factorisation and projected onto the box the learning runs cover; `push` gives the state at the
/// newest sample. Not `observer()`: the report's `mhe_chip` row gives its accuracy beside the
/// converged MHE, and the on-target tests its cost.
pub type MheObserver = firmware::mhe::MovingHorizon<f32, Discrete<f32>, STATES, OUTPUTS, INPUTS, HORIZON>;

/// A fresh moving-horizon estimator in `T` (`mhe::<f32>()`: an [`MheObserver`]).
pub fn mhe<T: Scalar + Maths>() -> firmware::mhe::MovingHorizon<T, Discrete<T>, STATES, OUTPUTS, INPUTS, HORIZON> {{
    firmware::mhe::MovingHorizon::new(
        firmware::Rk4::new(Plant, {h}),
        firmware::mhe::Settings {{
            weights: {weights},
            prior: {prior},
            lower: {lower},
            upper: {upper},
            start: {start},
            iterations: {iterations},
            damping: {damping},
        }},
    )
}}
",
        iterations = constants.iterations,
        h = literal("chip MHE substep", h)?,
        weights = values("weights", &constants.weights)?,
        prior = values("prior", &constants.prior)?,
        lower = values("lower", &constants.lower)?,
        upper = values("upper", &constants.upper)?,
        start = values("start", &constants.start)?,
        damping = literal("chip MHE damping", constants.damping)?,
    ))
}
