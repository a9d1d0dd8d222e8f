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
//! Cortex-M4F measures them (`on-target-report`); `tests/tests/integration/on_target.rs` checks the instructions
//! against QEMU on every shipped design within [`TOLERANCE`] (`vanderpol_searched`, out of the
//! calibration set: predicted 149.2, measured 147). All shipped designs have two targets, so `BASE`
//! and `PER_TARGET` are not separated by the data: the split follows the code (one table look-up with
//! its clamps per target).
//!
//! Flash is a lower bound, not a prediction within 10 %: the constants are counted exactly, but the
//! code a map links measured from 630 B (`ecoli_*`) to 1830 B (`two_tanks`), depending on
//! what else the design's module links, not on the map's shape alone; [`CODE_BYTES`] is the smallest.
//! The test checks that the bound holds and is within [`CODE_SPREAD`] of the measurement.
//!
//! # The observers with the model on the chip
//!
//! The corrected observer and the EKF run the model's straight-line programs
//! ([`crate::plant::program`]) every sample, so their cost follows the programs' operations:
//!
//! ```text
//! instructions ≈ KIND_BASE + PER_OPERATION·(+, −, ×, ÷, negations) + Σ CALL(f) over the calls
//! ```
//!
//! with [`CORRECTED_BASE`] (the window, the clamps, the blend) plus the predict and steady programs
//! (and the map when the steady program reads it), [`EKF_BASE`] plus the measured-sample program, and
//! the map-started EKF [`STARTED_EXTRA`] above the EKF. The call costs ([`call`]) are those of the
//! functions the shipped models use (`sqrt`, `abs`, `signum`, `exp`); every other function is
//! given [`UNMEASURED_CALL`], a deliberate over-estimate until a shipped model measures it. These
//! constants were fitted to the same shipped designs the test checks them on (five measurements of
//! five models' kinds): the test guards the model against drift of the code, it is not an
//! out-of-sample validation.

use serde::Serialize;

use crate::fit::maps::FittedMap;
use crate::plant::correction::CorrectionCode;
use crate::plant::kalman::FilterCode;
use crate::plant::program::{Op, Program};

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

/// Instructions per arithmetic operation of a model program (the operation and its share of moves).
pub const PER_OPERATION: f64 = 1.0;
/// Fixed instructions of the corrected observer's steady sample besides its programs.
pub const CORRECTED_BASE: f64 = 93.0;
/// Fixed instructions of the EKF's measured sample besides its program.
pub const EKF_BASE: f64 = 46.0;
/// What the map-started EKF adds to the EKF in steady state (the window it keeps for its start).
pub const STARTED_EXTRA: f64 = 8.0;
/// Instructions of a state's projection onto one bound (a compare, the flags' move and a select).
pub const PER_SELECT: f64 = 3.0;
/// Instructions assumed for a function no shipped model calls yet (an over-estimate).
pub const UNMEASURED_CALL: f64 = 150.0;

/// Instructions of one call of the expression language's function `name` on the chip.
pub fn call(name: &str) -> f64 {
    match name {
        "abs" => 1.0,
        "signum" => 14.0,
        // The FPU's `VSQRT.F32` and the moves around it (`firmware::emitted::sqrt_f32`).
        "sqrt" => 7.0,
        "exp" => 101.0,
        _ => UNMEASURED_CALL,
    }
}

/// Instructions of one run of `program`: its arithmetic and its calls (numbers and names are loads
/// folded into the operations).
pub fn of_program(program: &Program) -> f64 {
    program
        .ops
        .iter()
        .map(|op| match op {
            Op::Number(_) | Op::Leaf(_) => 0.0,
            Op::Negate(_) | Op::Binary(..) => PER_OPERATION,
            Op::Call(name, _) => call(name),
            Op::AtLeast(..) | Op::AtMost(..) => PER_SELECT,
        })
        .sum()
}

/// The corrected observer's steady sample; `map` is the map's cost, paid when the steady program
/// reads the map.
pub fn of_corrected(code: &CorrectionCode, map: &Cost) -> f64 {
    let reads_map = if code.steady_reads_map {
        map.instructions - BASE
    } else {
        0.0
    };
    CORRECTED_BASE + of_program(&code.predict) + of_program(&code.steady) + reads_map
}

/// The EKF's measured sample.
pub fn of_ekf(filter: &FilterCode) -> f64 {
    EKF_BASE + of_program(&filter.measured)
}

/// The UKF's measured sample: its program (the sigma points, both Cholesky factors, the update and
/// the prediction of every sigma point) and the EKF's frame around it (the same `push`).
pub fn of_ukf(filter: &FilterCode) -> f64 {
    of_ekf(filter)
}

/// [`of_ekf`] of the EKF of `code` with `constants` (any non-zero constants give the same count):
/// the cost before the fit of the kinds over the EKF.
pub fn ekf_before_fit(code: &crate::plant::ModelCode, constants: &crate::plant::kalman::EkfConstants) -> f64 {
    of_ekf(&crate::plant::kalman::filter_code(code, constants))
}

/// [`of_started`] before the fit (see [`ekf_before_fit`]).
pub fn started_before_fit(code: &crate::plant::ModelCode, constants: &crate::plant::kalman::EkfConstants) -> f64 {
    of_started(&crate::plant::kalman::filter_code(code, constants))
}

/// [`of_ukf`] before the fit (see [`ekf_before_fit`]).
pub fn ukf_before_fit(code: &crate::plant::ModelCode, constants: &crate::plant::kalman::EkfConstants) -> f64 {
    of_ukf(&crate::plant::unscented::unscented_code(code, constants))
}

/// The map-started EKF's steady sample.
pub fn of_started(filter: &FilterCode) -> f64 {
    of_ekf(filter) + STARTED_EXTRA
}

/// The box-started EKF checked by the map (`firmware::Restarted`): its steady sample, the EKF's (the
/// check's flag is a compare and a branch, which the EKF's own finiteness tests pay for; measured
/// equal to `ekf()` on every shipped design).
pub fn of_restarted(filter: &FilterCode) -> f64 {
    of_ekf(filter)
}

/// The moving-horizon observer's instructions per model step of its window that do not depend on the
/// model's arithmetic (the RK4 stages' and the sensitivities' bookkeeping, the window's loads).
pub const MHE_PER_STEP: f64 = 659.0;
/// Its instructions per `n³` (the sensitivities' `n × n` products) of a model step.
pub const MHE_PER_CUBE: f64 = 55.5;
/// Its instructions per operation of the model's programs in a model step ([`of_program`]).
pub const MHE_PER_OPERATION: f64 = 0.902;

/// The moving-horizon observer's steady sample ([`firmware::mhe::Observer`], `iterations` Gauss–Newton
/// steps over windows of `horizon` samples, `substeps` RK4 steps per sample):
///
/// ```text
/// instructions ≈ (iterations + 1)·horizon · (MHE_PER_STEP + MHE_PER_CUBE·n³ + MHE_PER_OPERATION·ops)
/// ops = 4·substeps·(derivative program) + (output program)
/// ```
///
/// `(iterations + 1)·horizon` model steps with their Jacobians: `iterations` passes over the window
/// for the normal equations, and one to carry the solution to the window's end. It is generic code
/// with loops (not written out as the EKF is), so a step costs far more than its arithmetic. The three
/// constants were fitted to the three shipped models (Van der Pol, two tanks, E. coli: one
/// measurement each); `tests/tests/integration/on_target.rs` holds all seven shipped designs, with their
/// different steps and horizons, to [`TOLERANCE`].
pub fn of_mhe(code: &crate::plant::ModelCode, horizon: usize, iterations: usize, substeps: usize) -> f64 {
    let n = code.dimensions.states as f64;
    let ops = 4.0 * substeps as f64 * of_program(&code.derivative) + of_program(&code.output);
    ((iterations + 1) * horizon) as f64 * (MHE_PER_STEP + MHE_PER_CUBE * n * n * n + MHE_PER_OPERATION * ops)
}

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
        instructions += PER_SEARCH_STEP * firmware::emitted::search_halves(knots).count() as f64;
        constants += taps + 2.0 * segments as f64 + knots as f64 + 4.0;
    }
    Cost {
        instructions,
        flash: CODE_BYTES + CONSTANT_BYTES * constants,
        first_estimate: horizon.saturating_sub(1) as f64 * tau,
    }
}
