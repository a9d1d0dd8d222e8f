//! Fitted maps as the host holds them (owned, `f64`, serialisable), evaluated through the firmware's
//! code so that the host's "library estimate" is the very computation the target runs.

use firmware::{Estimate, Gamma, TargetMap};
use serde::Serialize;

use crate::spec::Normalisation;

/// `r = r_min + (r_max - r_min) Γ⁻¹(Lᵀ Z)` for one target.
#[derive(Clone, Debug, Serialize)]
pub struct FittedMap {
    /// The target's name.
    pub target: String,
    /// How the scale of `Γ` was fixed.
    pub normalisation: Normalisation,
    /// `L` on the raw regressor `Z` (newest first).
    pub gains: Vec<f64>,
    /// Constant `c` of `Lᵀ Z + c` (0 with the paper's normalisation).
    pub intercept: f64,
    /// Coefficient `μ₀` of the constant basis function (0 with `intercept`).
    pub mu_constant: f64,
    /// Coefficients `μ_j` of `B(·; c_j)`.
    pub mu: Vec<f64>,
    /// Odds ratios `c_j` of the basis functions.
    pub odds_ratios: Vec<f64>,
    /// `w_j = μ_j c_j`, what the firmware evaluates.
    pub weights: Vec<f64>,
    /// `Γ(0)` of the firmware form, `μ₀ - c`.
    pub offset: f64,
    /// Smallest target value on the learning windows.
    pub r_min: f64,
    /// Largest target value on the learning windows.
    pub r_max: f64,
}

impl FittedMap {
    /// Assembles a map from the fitted coefficients (the derived fields are computed here).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        target: String,
        normalisation: Normalisation,
        gains: Vec<f64>,
        intercept: f64,
        mu_constant: f64,
        mu: Vec<f64>,
        odds_ratios: Vec<f64>,
        (r_min, r_max): (f64, f64),
    ) -> Self {
        let weights = mu
            .iter()
            .zip(&odds_ratios)
            .map(|(&m, &b)| firmware::gamma::weight(m, b))
            .collect();
        FittedMap {
            target,
            normalisation,
            gains,
            intercept,
            mu_constant,
            mu,
            odds_ratios,
            weights,
            offset: mu_constant - intercept,
            r_min,
            r_max,
        }
    }

    /// `Γ` in the firmware's form (`Γ(η) - c`, so that it is compared with `Lᵀ Z` alone).
    pub fn gamma(&self) -> Gamma<'_, f64> {
        Gamma {
            offset: self.offset,
            weights: &self.weights,
            odds_ratios: &self.odds_ratios,
        }
    }

    /// The firmware's view of this map, in `f64`.
    pub fn as_firmware(&self) -> TargetMap<'_, f64> {
        TargetMap {
            gains: &self.gains,
            gamma: self.gamma(),
            r_min: self.r_min,
            r_span: self.r_max - self.r_min,
        }
    }

    /// The library estimate `F(Z)`.
    pub fn estimate(&self, regressor: &[f64]) -> Estimate<f64> {
        self.as_firmware().estimate(regressor)
    }
}

/// The plain linear least-squares map `r ≈ Lᵀ Z + c`: the floor the method must match or beat.
#[derive(Clone, Debug, Serialize)]
pub struct LinearMap {
    /// `L`.
    pub gains: Vec<f64>,
    /// `c`.
    pub intercept: f64,
}

impl LinearMap {
    /// `Lᵀ Z + c`.
    pub fn estimate(&self, regressor: &[f64]) -> f64 {
        self.intercept + self.gains.iter().zip(regressor).map(|(g, z)| g * z).sum::<f64>()
    }
}
