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
//! calibration set: predicted 149.2, measured 145). All shipped designs have two targets, so `BASE`
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
//! with [`EKF_BASE`] plus the measured-sample program, and the map-started EKF [`STARTED_EXTRA`] above
//! the EKF. A kind with a cost of its own has it in its folder (`observers/kind/<kind>/cost.rs`: its
//! model over [`of_program`] and [`of_ekf`] here. The call costs ([`call`]) are those of the
//! functions the shipped models use (`sqrt`, `abs`, `signum`, `exp`); every other function is
//! given [`UNMEASURED_CALL`], a deliberate over-estimate until a shipped model measures it. These
//! constants were fitted to the same shipped designs the test checks them on (five measurements of
//! five models' kinds): the test guards the model against drift of the code, it is not an
//! out-of-sample validation.

use serde::Serialize;

use crate::fit::maps::FittedMap;
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
/// Fixed instructions of the EKF's measured sample besides its program.
pub const EKF_BASE: f64 = 46.0;
/// What a box filter's χ² watch adds to its sample (`firmware::watch`) beyond the normalised
/// innovation's operations, which its program counts: the mean's multiply-add, the compare, the loads
/// and stores. Measured on Example 1: its EKF 237 → 257 and its UKF 435 → 447 instructions with the
/// watch, 14 each above the programs' count.
pub const WATCH: f64 = 14.0;
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
        // libm's `logf`, from the E. coli UKF in log coordinates: 3467 → 6535 instructions per
        // sample for 18 `ln` and 39 `exp` more (with `exp` at 101 above, an upper bound).
        "ln" => 60.0,
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

/// The EKF's measured sample.
pub fn of_ekf(filter: &FilterCode) -> f64 {
    EKF_BASE + of_program(&filter.measured)
}

/// What the watch `watch` of a box filter costs per sample: [`WATCH`] where it watches, else 0.
pub fn of_watch(watch: &crate::plant::kalman::Watch) -> f64 {
    if watch.threshold.is_finite() {
        WATCH
    } else {
        0.0
    }
}

/// [`of_ekf`] of the EKF of `code` with `constants` (any non-zero constants give the same count) and
/// its watch (which tuning keeps on every shipped filter but one; a filter left unwatched costs
/// [`WATCH`] fewer after the fit): the box EKF's cost before the fit.
pub fn ekf_before_fit(code: &crate::plant::ModelCode, constants: &crate::plant::kalman::EkfConstants) -> f64 {
    of_ekf(&crate::plant::kalman::filter_code(code, constants)) + WATCH
}

/// [`of_started`] before the fit with the box EKF's watch, which it carries (see [`ekf_before_fit`]).
pub fn started_before_fit(code: &crate::plant::ModelCode, constants: &crate::plant::kalman::EkfConstants) -> f64 {
    of_started(&crate::plant::kalman::filter_code(code, constants)) + WATCH
}

/// The map-started EKF's steady sample, its watch ([`of_watch`]) apart.
pub fn of_started(filter: &FilterCode) -> f64 {
    of_ekf(filter) + STARTED_EXTRA
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

#[cfg(test)]
pub(crate) mod tests {
    //! The cost model on hand-made programs and maps: each expected count is the module's formula
    //! worked out by hand in the comment beside it, with the constants' values written out.

    use std::sync::Arc;

    use super::*;
    use crate::fit::inverse_table::InverseTable;
    use crate::plant::program::Leaf;
    use crate::spec::ast::Binary;
    use crate::spec::Normalisation;

    pub(crate) fn close(got: f64, want: f64) {
        assert!((got - want).abs() < 1e-9, "{got} != {want}");
    }

    /// `-(x0 + 2) · sqrt(x1)`, then `tanh(x0)` and `x0` projected onto a lower bound of 0.
    pub(crate) fn program() -> Program {
        let ops = vec![
            Op::Leaf(Leaf::State(0)),      // 0: a load, free
            Op::Number(2.0),               // 1: free
            Op::Binary(Binary::Add, 0, 1), // 2: 1
            Op::Negate(2),                 // 3: 1
            Op::Leaf(Leaf::State(1)),      // 4: free
            Op::Call("sqrt", 4),           // 5: 7
            Op::Binary(Binary::Mul, 3, 5), // 6: 1
            Op::Call("tanh", 0),           // 7: 150, no shipped model measured it
            Op::Number(0.0),               // 8: free
            Op::AtLeast(0, 8),             // 9: 3
        ];
        Program {
            ops,
            results: vec![6, 7, 9],
        }
    }

    #[test]
    fn a_program_costs_its_operations_calls_and_selects() {
        // 1 + 1 + 7 + 1 + 150 + 3 = 163.
        close(of_program(&program()), 163.0);
        close(of_program(&Program::default()), 0.0);
        assert_eq!((call("abs"), call("signum"), call("exp")), (1.0, 14.0, 101.0));
    }

    #[test]
    fn the_filters_cost_their_base_and_their_program() {
        let filter = FilterCode {
            measured: program(),
            unmeasured: Program::default(),
            targets: crate::plant::program::Program::default(),
            parameters: Vec::new(),
            states: 2,
            scalars: 1,
        };
        // EKF: 46 + 163 = 209; the started one 8 more, 217 (the other kinds: their `cost.rs`).
        close(of_ekf(&filter), 209.0);
        close(of_started(&filter), 217.0);
    }

    /// A map with `gains` and, if `segments > 0`, a table of that many segments (searched knots
    /// when `searched`).
    fn map(gains: &[f64], segments: usize, searched: bool) -> FittedMap {
        let table = (segments > 0).then(|| InverseTable {
            gains: gains.to_vec(),
            offset: 0.0,
            starts: searched.then(|| (0..segments).map(|k| k as f64 / segments as f64).collect()),
            segments: vec![[0.0, 1.0]; segments],
            r_min: 0.0,
            r_max: 1.0,
            proven_bound: 0.0,
            sampled_error: 0.0,
        });
        FittedMap {
            target: "x".to_owned(),
            normalisation: Normalisation::Intercept,
            gains: gains.to_vec(),
            intercept: 0.0,
            mu_constant: 0.0,
            mu: Vec::new(),
            odds_ratios: Arc::from(Vec::new()),
            r_min: 0.0,
            r_max: 1.0,
            table,
        }
    }

    #[test]
    fn a_map_costs_its_taps_tables_and_search_steps() {
        // No table (one segment, no knots), 3 non-zero gains of 4 (the pruned one is not emitted):
        // 42 + 12 + 2.6·3 = 61.8 instructions; constants 3 + 2·1 + 0 + 4 = 9, flash 630 + 4·9 = 666.
        let plain = map(&[0.5, 0.0, -0.25, 1.0], 0, false);
        let cost = of_maps(&[&plain], 10, 0.1);
        close(cost.instructions, 61.8);
        close(cost.flash, 666.0);
        close(cost.first_estimate, 0.9);
        // One uniform segment: no table step, as without a table.
        close(
            of_maps(&[&map(&[0.5, 0.0, -0.25, 1.0], 1, false)], 10, 0.1).instructions,
            61.8,
        );
        // Five uniform segments, two gains: 12 + 5.2 + 8 = 25.2 more; constants 2 + 10 + 0 + 4 = 16.
        // Eight searched segments (eight knots, ⌈log₂ 8⌉ = 3 steps), one gain: 12 + 2.6 + 8 + 3·5 =
        // 37.6 more; constants 1 + 16 + 8 + 4 = 29.
        let uniform = map(&[1.0, 2.0], 5, false);
        let searched = map(&[3.0], 8, true);
        let cost = of_maps(&[&plain, &uniform, &searched], 1, 0.1);
        close(cost.instructions, 61.8 + 25.2 + 37.6);
        close(cost.flash, 630.0 + 4.0 * (9.0 + 16.0 + 29.0));
        close(cost.first_estimate, 0.0);
        // Five knots need ⌈log₂ 5⌉ = 3 steps as well, two knots one: 12 + 2.6 + 8 + 15 and + 5.
        close(of_maps(&[&map(&[3.0], 5, true)], 1, 0.1).instructions, 42.0 + 37.6);
        close(of_maps(&[&map(&[3.0], 2, true)], 1, 0.1).instructions, 42.0 + 27.6);
    }
}
