//! What the restarted EKF costs on the chip (see [`crate::search::cost`]).

use crate::plant::kalman::FilterCode;
use crate::search::cost::of_ekf;

/// Instructions per state of the map's check at every sample (the distance's term with its division,
/// the map's states copied, the start's compare): 62 for two states on every shipped design,
/// measured as `EkfRestartObserver` − `ekf()` − `map_observer()`.
pub const CHECK_PER_STATE: f64 = 31.0;

/// The box-started EKF watched by the map (`firmware::Restarted`): its steady sample is the EKF's,
/// the map's (`map`: the map observer's instructions, window included) and the check.
pub fn of_restarted(filter: &FilterCode, map: f64) -> f64 {
    of_ekf(filter) + map + CHECK_PER_STATE * filter.states as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::cost::tests::{close, program};

    #[test]
    fn the_restarted_ekf_costs_the_ekf_the_map_and_the_check() {
        let filter = FilterCode {
            measured: program(),
            unmeasured: crate::plant::program::Program::default(),
            targets: crate::plant::program::Program::default(),
            parameters: Vec::new(),
            states: 2,
            scalars: 1,
        };
        // The EKF's frame, 46, and the program, 163; the map's 124; the check, 2 × 31.
        close(of_restarted(&filter, 124.0), 209.0 + 124.0 + 62.0);
    }
}
