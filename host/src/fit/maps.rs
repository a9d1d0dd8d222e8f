//! Fitted maps as the host holds them (owned, `f64`, serialisable), evaluated through the firmware's
//! code so that the host's "library estimate" is the very computation the target runs: the certified
//! table ([`InverseTable`]). The exact `Γ` and its bisection stay beside it as the reference.

use std::sync::Arc;

use firmware::{Estimate, Gamma, Saturation, TargetMap};
use serde::{Deserialize, Serialize};

use crate::fit::inverse_table::{InverseTable, TableError, RELATIVE_TOLERANCE};
use crate::spec::Normalisation;

/// How a fit tabulates `Γ⁻¹`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tabulation {
    /// [`InverseTable::certify`]: proven, what is emitted.
    Certified,
    /// [`InverseTable::sketch`]: unproven, ten times cheaper; for ranking search candidates only.
    Sketched,
}

/// `r = r_min + (r_max - r_min) Γ⁻¹(Lᵀ Z)` for one target.
#[derive(Clone, Debug, Serialize, Deserialize)]
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
    pub odds_ratios: Arc<[f64]>,
    /// Smallest target value on the learning windows.
    pub r_min: f64,
    /// Largest target value on the learning windows.
    pub r_max: f64,
    /// The certified table of `Γ⁻¹` and the scaled gains: what the library estimate and the chip use.
    /// `None` when a table with knots uniform in `Lᵀ Z` would need more than
    /// [`crate::fit::inverse_table::MAX_SEGMENTS`] segments (a very flat stretch of `Γ`): such a map is
    /// estimated by the exact bisection on the host and refused at emission.
    pub table: Option<InverseTable>,
}

impl FittedMap {
    /// Assembles a map from the fitted coefficients (the derived fields are computed here) and
    /// tabulates `Γ⁻¹` as `tabulation` says; a certified table fails when `Γ` cannot be proven increasing.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        target: String,
        normalisation: Normalisation,
        gains: Vec<f64>,
        intercept: f64,
        mu_constant: f64,
        mu: Vec<f64>,
        odds_ratios: Arc<[f64]>,
        (r_min, r_max): (f64, f64),
        tabulation: Tabulation,
    ) -> Result<Self, TableError> {
        let exact = Gamma {
            offset: mu_constant - intercept,
            mu: &mu,
            odds_ratios: &odds_ratios,
        };
        let range = (r_min, r_max);
        let table = match tabulation {
            Tabulation::Sketched => Some(InverseTable::sketch(&exact, &gains, range, RELATIVE_TOLERANCE)),
            Tabulation::Certified => match InverseTable::certify(&exact, &gains, range, RELATIVE_TOLERANCE) {
                Ok(table) => Some(table),
                Err(TableError::TooManySegments { .. }) => None,
                Err(e) => return Err(e),
            },
        };
        Ok(FittedMap {
            target,
            normalisation,
            gains,
            intercept,
            mu_constant,
            mu,
            odds_ratios,
            r_min,
            r_max,
            table,
        })
    }

    /// `Γ` in the firmware's form (`Γ(η) - c`, so that it is compared with `Lᵀ Z` alone).
    pub fn gamma(&self) -> Gamma<'_, f64> {
        Gamma {
            offset: self.mu_constant - self.intercept,
            mu: &self.mu,
            odds_ratios: &self.odds_ratios,
        }
    }

    /// The firmware's view of this map, in `f64`: the scaled gains and the table (if it has one).
    pub fn as_firmware(&self) -> Option<TargetMap<'_, f64>> {
        let table = self.table.as_ref()?;
        Some(TargetMap {
            gains: &table.gains,
            offset: table.offset,
            inverse: table.as_firmware(),
        })
    }

    /// The library estimate `F(Z)`: the certified table, as on the chip; the exact bisection for a
    /// map without a table (which is never emitted).
    pub fn estimate(&self, regressor: &[f64]) -> Estimate<f64> {
        match self.as_firmware() {
            Some(map) => map.estimate(regressor),
            None => self.exact_estimate(regressor),
        }
    }

    /// `r_min + (r_max - r_min) Γ⁻¹(Lᵀ Z)` by the exact bisection: the reference the table is proven
    /// against (within `table.proven_bound`).
    pub fn exact_estimate(&self, regressor: &[f64]) -> Estimate<f64> {
        let v: f64 = self.gains.iter().zip(regressor).map(|(g, z)| g * z).sum();
        let inverse = self.gamma().inverse(v);
        let value = match inverse.saturation {
            Saturation::Inside => self.r_min + (self.r_max - self.r_min) * inverse.eta,
            Saturation::Low => self.r_min,
            Saturation::High => self.r_max,
        };
        Estimate {
            value,
            saturation: inverse.saturation,
        }
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
