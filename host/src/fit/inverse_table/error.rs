//! Why a table could not be certified: the one error of building, proving ([`super::proof`]) and
//! confirming a table, in a module of its own.

use super::RELATIVE_TOLERANCE;

/// Why a table could not be certified.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TableError {
    /// No positive lower bound of `Γ'` could be proven near `eta`.
    #[error("Γ' cannot be proven positive near η = {eta} (lower bound {slope_bound:e})")]
    NotIncreasing {
        /// Where.
        eta: f64,
        /// The best lower bound found there.
        slope_bound: f64,
    },
    /// The proven bound needs more than the allowed segments.
    #[error("the inverse needs more than {limit} segments for a proven error of {RELATIVE_TOLERANCE:e} of the range")]
    TooManySegments {
        /// The limit that was reached.
        limit: usize,
    },
    /// Two knots near `eta` are closer than f64 resolves in `t`: `Γ` is flat there to rounding.
    #[error("Γ is too flat near η = {eta} for its inverse to be tabulated in double precision")]
    Unresolvable {
        /// Where.
        eta: f64,
    },
    /// The dense confirmation found an error above the proven bound: a defect of the proof.
    #[error("the dense check found an error of {sampled:e} above the proven bound {bound:e}")]
    BoundViolated {
        /// The largest error seen.
        sampled: f64,
        /// The proven bound.
        bound: f64,
    },
}
