//! What the moving-horizon estimate costs on the chip (see [`crate::search::cost`]).

use crate::plant::ModelCode;
use crate::search::cost::of_program;

/// The moving-horizon observer's instructions per model step of its window that do not depend on the
/// model's arithmetic (the RK4 stages' and the sensitivities' bookkeeping, the window's loads).
pub const MHE_PER_STEP: f64 = 659.0;
/// Its instructions per `n³` (the sensitivities' `n × n` products) of an RK4 step.
pub const MHE_PER_CUBE: f64 = 55.5;
/// Its instructions per operation of the model's programs in a model step ([`of_program`]).
pub const MHE_PER_OPERATION: f64 = 0.902;

/// The moving-horizon observer's steady sample ([`firmware::mhe::Observer`], `iterations` Gauss–Newton
/// steps over windows of `horizon` samples, `substeps` RK4 steps per sample):
///
/// ```text
/// instructions ≈ (iterations + 1)·horizon · (MHE_PER_STEP + MHE_PER_CUBE·n³·substeps + MHE_PER_OPERATION·ops)
/// ops = 4·substeps·(derivative program) + (output program)
/// ```
///
/// `(iterations + 1)·horizon` model steps with their Jacobians: `iterations` passes over the window
/// for the normal equations, and one to carry the solution to the window's end. It is generic code
/// with loops (not written out as the EKF is), so a step costs far more than its arithmetic. The three
/// constants were fitted to the three shipped models (Van der Pol, two tanks, E. coli: one
/// measurement each, one RK4 step per sample); each RK4 step carries the sensitivities' product, so
/// that term scales with the steps (`ecoli_x0_2`, four steps per sample: 113 325 predicted, 117 889
/// measured). `tests/tests/integration/on_target.rs` holds all seven shipped designs, with their
/// different steps and horizons, to [`crate::search::cost::TOLERANCE`].
pub fn of_mhe(code: &ModelCode, horizon: usize, iterations: usize, substeps: usize) -> f64 {
    let n = code.dimensions.states as f64;
    let ops = 4.0 * substeps as f64 * of_program(&code.derivative) + of_program(&code.output);
    let cube = MHE_PER_CUBE * n * n * n * substeps as f64;
    ((iterations + 1) * horizon) as f64 * (MHE_PER_STEP + cube + MHE_PER_OPERATION * ops)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plant::program::{Leaf, Op, Program};
    use crate::search::cost::tests::{close, program};
    use crate::spec::ast::Binary;

    #[test]
    fn the_mhe_costs_every_model_step_of_its_iterations_and_one_more() {
        // Two states; the derivative program costs 163, the output program 1 (one addition).
        let code = crate::plant::ModelCode {
            derivative: program(),
            output: Program {
                ops: vec![
                    Op::Leaf(Leaf::State(0)),
                    Op::Leaf(Leaf::State(1)),
                    Op::Binary(Binary::Add, 0, 1),
                ],
                results: vec![2],
            },
            targets: Program::default(),
            parameters: Vec::new(),
            dimensions: crate::plant::Dimensions {
                states: 2,
                outputs: 1,
                inputs: 0,
                targets: 2,
            },
            bounds: Vec::new(),
            coordinates: crate::plant::Coordinates::plant(2),
            log_coordinates: crate::plant::Coordinates::plant(2),
        };
        // horizon 10, 2 iterations, 3 substeps: (2 + 1)·10 = 30 steps of
        // 659 + 55.5·2³·3 + 0.902·(4·3·163 + 1) = 659 + 1332 + 0.902·1957 = 1991 + 1765.214 = 3756.214,
        // so 112 686.42.
        close(of_mhe(&code, 10, 2, 3), 112_686.42);
        // No iteration: one pass, a third of that over 10 samples.
        close(of_mhe(&code, 10, 0, 3), 37_562.14);
        // One RK4 step per sample: the sensitivities' product once, 659 + 444 + 0.902·(4·163 + 1).
        close(of_mhe(&code, 10, 0, 1), 10.0 * (659.0 + 444.0 + 0.902 * 653.0));
    }
}
