//! What a map costs on the chip, predicted from its shape: the design search ranks and budgets
//! candidates with it before anything is emitted or built.
//!
//! The model follows the code the chip runs for `push` + `estimate` of the map:
//!
//! ```text
//! instructions ≈ BASE + PER_TARGET·targets + PER_TAP·Σ taps + PER_TABLE·(targets with > 1 segment)
//!                + PER_SEARCH_STEP·Σ ⌈log₂ knots⌉          (searched knots only)
//! flash        ≳ CODE_BYTES + 4·(Σ taps + 2·Σ segments + Σ knots + 4·targets)   (f32 constants)
//! ```
//!
//! The constants are calibrated on the designs shipped before `vanderpol_searched` as the emulated
//! Cortex-M4F measures them (`on-target-report`); `tests/tests/on_target.rs` checks the instructions
//! against QEMU on every shipped design within [`TOLERANCE`] (`vanderpol_searched`, out of the
//! calibration set: predicted 149.2, measured 147). All shipped designs have two targets, so `BASE`
//! and `PER_TARGET` are not separated by the data: the split follows the code (one table look-up with
//! its clamps per target).
//!
//! Flash is a lower bound, not a prediction within 10 %: the constants are counted exactly, but the
//! code a map links measured from 630 B (`ecoli_*`) to 1830 B (`two_tanks`), depending on
//! what else the design's module links, not on the map's shape alone; [`CODE_BYTES`] is the smallest.
//! The test checks that the bound holds and is within [`CODE_SPREAD`] of the measurement.

use serde::Serialize;

use crate::fit::maps::FittedMap;

/// Fixed instructions of a sample: the ring buffer, the call and the returns.
pub const BASE: f64 = 42.0;
/// Instructions of one target's table look-up with a single segment (projection start, the clamps).
pub const PER_TARGET: f64 = 12.0;
/// Instructions per non-zero gain of the projection (load, load, fused multiply-add); pruned gains
/// (exactly 0) are not emitted.
pub const PER_TAP: f64 = 2.6;
/// Extra instructions of a table with more than one uniform segment (the index, its clamp, the row).
pub const PER_TABLE: f64 = 8.0;
/// Instructions per step of the branch-free search over searched knots.
pub const PER_SEARCH_STEP: f64 = 5.0;
/// The smallest code a map was measured to link besides its constants (`ecoli_x0_0p5`), in bytes.
pub const CODE_BYTES: f64 = 630.0;
/// How far above the flash bound the measurement may be: the spread of the measured code sizes.
pub const CODE_SPREAD: f64 = 1300.0;
/// Bytes per emitted constant (`f32`).
const CONSTANT_BYTES: f64 = 4.0;
/// How far the prediction may be from the emulated chip on the shipped designs (relative).
pub const TOLERANCE: f64 = 0.10;

/// A map's predicted cost per sample and in flash.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Cost {
    /// Instructions of `push` + `estimate` in steady state.
    pub instructions: f64,
    /// Bytes of flash the map adds, at least (see the module's documentation).
    pub flash: f64,
    /// Delay from the first sample to the first estimate, `(N − 1) τ`, in the spec's time unit.
    pub first_estimate: f64,
}

/// The predicted cost of the maps `maps` (one per target) over a horizon `horizon` sampled every `tau`.
pub fn of_maps(maps: &[&FittedMap], horizon: usize, tau: f64) -> Cost {
    let mut instructions = BASE;
    let mut constants = 0.0;
    for map in maps {
        let taps = map.gains.iter().filter(|&&g| g != 0.0).count() as f64;
        instructions += PER_TARGET + PER_TAP * taps;
        let (segments, knots) = match &map.table {
            Some(table) => (table.segments.len(), table.starts.as_ref().map_or(0, Vec::len)),
            None => (1, 0),
        };
        if segments > 1 {
            instructions += PER_TABLE;
        }
        instructions += PER_SEARCH_STEP * firmware::inverse::search_halves(knots).count() as f64;
        constants += taps + 2.0 * segments as f64 + knots as f64 + 4.0;
    }
    Cost {
        instructions,
        flash: CODE_BYTES + CONSTANT_BYTES * constants,
        first_estimate: horizon.saturating_sub(1) as f64 * tau,
    }
}
