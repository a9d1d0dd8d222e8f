//! What the restarted EKF costs on the chip (see [`crate::search::cost`]).

use crate::plant::kalman::FilterCode;
use crate::search::cost::of_ekf;

/// The box-started EKF checked by the map (`firmware::Restarted`): its steady sample, the EKF's (the
/// check's flag is a compare and a branch, which the EKF's own finiteness tests pay for; measured
/// equal to `ekf()` on every shipped design).
pub fn of_restarted(filter: &FilterCode) -> f64 {
    of_ekf(filter)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::cost::tests::{close, program};

    #[test]
    fn the_restarted_ekf_costs_the_ekfs_steady_sample() {
        let filter = FilterCode {
            measured: program(),
            unmeasured: crate::plant::program::Program::default(),
            parameters: Vec::new(),
            states: 2,
        };
        // The EKF's frame, 46, and the program, 163.
        close(of_restarted(&filter), 209.0);
    }
}
