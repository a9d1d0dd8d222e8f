//! What the model-corrected map costs on the chip: a base (the window, the clamps, the blend) plus its
//! predict and steady programs, and the map when the steady program reads it (see
//! [`crate::search::cost`]).

use super::program::CorrectionCode;
use crate::search::cost::{of_program, Cost, BASE};

/// Fixed instructions of the corrected observer's steady sample besides its programs.
pub const CORRECTED_BASE: f64 = 93.0;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plant::program::{Op, Program};
    use crate::search::cost::tests::{close, program};

    #[test]
    fn the_corrected_observer_pays_for_the_map_only_when_its_steady_program_reads_it() {
        let map = Cost {
            instructions: 100.0,
            flash: 0.0,
            first_estimate: 0.0,
        };
        let mut code = CorrectionCode {
            predict: program(),
            start_up: program(),
            steady: Program {
                ops: vec![Op::Number(1.0), Op::Negate(0)],
                results: vec![1],
            },
            steady_reads_map: false,
            parameters: Vec::new(),
        };
        // 93 + 163 (predict) + 1 (steady) = 257; the start-up program is not a steady sample's.
        close(of_corrected(&code, &map), 257.0);
        // Reading the map adds its instructions without the frame it shares: 257 + (100 - 42) = 315.
        code.steady_reads_map = true;
        close(of_corrected(&code, &map), 315.0);
    }
}
