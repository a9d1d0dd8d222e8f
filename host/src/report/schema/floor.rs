//! What `report.json` says of the particle filter: its count, its convergence check, and whether it
//! is a floor for the design.

use serde::Serialize;

/// Whether the particle filter is a floor: converged by doubling and beaten by no observer by more
/// than `report::references::BEATEN_BEYOND` on any target's validation RMSE.
#[derive(Serialize, Clone, Debug, PartialEq)]
pub struct FloorReport {
    /// Whether doubling its count moved no target's validation RMSE by more than 5 %.
    pub converged: bool,
    /// Every observer and target where the observer's validation RMSE is below 0.95 times the
    /// particle filter's.
    pub beaten_by: Vec<BeatenReport>,
    /// Converged and beaten by none: only then is it called the floor and are ratios to it printed.
    pub is_floor: bool,
}

/// An observer that beats the particle filter on a target.
#[derive(Serialize, Clone, Debug, PartialEq)]
pub struct BeatenReport {
    /// The observer's kind.
    pub kind: &'static str,
    /// The target.
    pub target: String,
    /// The observer's validation RMSE on it.
    pub rmse_validation: f64,
    /// The particle filter's.
    pub floor_rmse_validation: f64,
}

/// The particle filter's count and how it was checked.
#[derive(Serialize)]
pub struct ParticlesReport {
    /// Particles.
    pub count: usize,
    /// Validation RMSE per target (spec order) at each count tried.
    pub checked: Vec<(usize, Vec<f64>)>,
    /// Whether the last doubling moved no target's RMSE by more than 5 %.
    pub converged: bool,
}
