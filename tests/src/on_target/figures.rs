//! One observer's figures as the reports (`on_target.json`, docs/chip.md) give them, from its
//! measurement and its largest difference from the host.

use super::measurement::{EkfMeasurement, ObserverMeasurement, Phases};

/// One observer's figures as the reports give them.
#[derive(Clone, Debug)]
pub struct Figures {
    /// Its instructions split into start-up and steady state.
    pub phases: Phases,
    /// Its estimated cycles split the same way ([`super::timing`]).
    pub cycles: Phases,
    /// Most `VDIV` + `VSQRT` of a sample.
    pub divisions: u64,
    /// Deepest stack use of a sample, in bytes.
    pub stack_bytes: u64,
    /// Flash added to a program, in bytes.
    pub flash_bytes: u64,
    /// RAM: the observer itself and the static RAM it adds, in bytes.
    pub ram_bytes: u64,
    /// Largest `|chip − host f64|` over the recorded sequence (target units).
    pub largest: f64,
}

impl Figures {
    /// A map or an observer it starts, `largest` from comparing it with the host.
    pub fn of_observer(observer: &ObserverMeasurement, largest: f64) -> Result<Self, String> {
        Ok(Figures {
            phases: observer.phases()?,
            cycles: observer.cycle_phases()?,
            divisions: observer.divisions.iter().copied().max().unwrap_or(0),
            stack_bytes: observer.stack_bytes as u64,
            flash_bytes: observer.flash_bytes,
            ram_bytes: observer.observer_bytes as u64 + observer.static_ram_bytes,
            largest,
        })
    }

    /// The EKF from the box centre, `largest` from comparing it with the host.
    pub fn of_filter(filter: &EkfMeasurement, largest: f64) -> Result<Self, String> {
        Ok(Figures {
            phases: filter.phases()?,
            cycles: filter.cycle_phases()?,
            divisions: filter.divisions.iter().copied().max().unwrap_or(0),
            stack_bytes: filter.stack_bytes as u64,
            flash_bytes: filter.flash_bytes,
            ram_bytes: filter.filter_bytes as u64 + filter.static_ram_bytes,
            largest,
        })
    }

    /// As recorded beside a report.
    pub fn on_target(&self) -> host::report::on_target::OnTarget {
        let (_, median, max) = spread(&self.phases.steady);
        let (_, cycles_median, cycles_max) = spread(&self.cycles.steady);
        host::report::on_target::OnTarget {
            instructions_median: median,
            instructions_max: max,
            cycles_median: Some(cycles_median),
            cycles_max: Some(cycles_max),
            start_up_instructions_max: Some(self.phases.start_up_max),
            start_up_samples: Some(self.phases.start_up_samples as u64),
            divisions: self.divisions,
            flash_bytes: self.flash_bytes,
            ram_bytes: self.ram_bytes,
            stack_bytes: self.stack_bytes,
            // NaN where there is no f64 truth (the integer observer).
            largest_difference: (!self.largest.is_nan()).then_some(self.largest),
        }
    }
}

/// `(min, median, max)`.
pub fn spread(values: &[u64]) -> (u64, u64, u64) {
    let mut sorted = values.to_vec();
    sorted.sort_unstable();
    if sorted.is_empty() {
        return (0, 0, 0);
    }
    (sorted[0], sorted[sorted.len() / 2], sorted[sorted.len() - 1])
}

/// Checks that every sample's estimated cycles lie between its instructions (every instruction takes
/// at least one cycle) and 19 times them (the slowest entry of the tables: an `LDM` of 16 registers
/// that loads the PC); panics naming `what` and the sample otherwise.
pub fn check_cycles(what: &str, instructions: &[u64], cycles: &[u64]) {
    assert_eq!(
        instructions.len(),
        cycles.len(),
        "{what}: one cycle estimate per sample"
    );
    for (k, (&n, &c)) in instructions.iter().zip(cycles).enumerate() {
        assert!(n <= c && c <= 19 * n, "{what} sample {k}: {n} instructions, {c} cycles");
    }
}
