//! What the UKF costs on the chip (see [`crate::search::cost`]).

use crate::plant::kalman::{EkfConstants, FilterCode};
use crate::plant::ModelCode;
use crate::search::cost::of_ekf;

/// The UKF's measured sample: its program (the sigma points, both Cholesky factors, the update and
/// the prediction of every sigma point) and the EKF's frame around it (the same `push`).
pub fn of_ukf(filter: &FilterCode) -> f64 {
    of_ekf(filter)
}

/// [`of_ukf`] before the fit (see [`crate::search::cost::ekf_before_fit`]).
pub fn ukf_before_fit(code: &ModelCode, constants: &EkfConstants) -> f64 {
    of_ukf(&super::program::unscented_code(code, constants)) + crate::search::cost::WATCH
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::cost::tests::{close, program};

    #[test]
    fn the_ukf_costs_the_ekfs_frame_and_its_program() {
        let filter = FilterCode {
            measured: program(),
            unmeasured: crate::plant::program::Program::default(),
            targets: crate::plant::program::Program::default(),
            parameters: Vec::new(),
            states: 2,
            scalars: 1,
        };
        // The EKF's frame, 46, and the program, 163.
        close(of_ukf(&filter), 209.0);
    }
}
