//! Running the generated observers on the emulated Cortex-M4F (QEMU `mps2-an386`) and Cortex-M0 (QEMU
//! `microbit`, [`Board`]) and measuring them: estimates over semihosting, instructions per `push` +
//! `estimate` from an execution trace and their estimated cycles ([`timing`]), flash and RAM from the
//! ELF, and the no-panic proof (see `tests/on-target/`).
//!
//! Every kind of observer a design has is measured ([`Kind`]): the map, the observers the map starts
//! (the model-corrected map, the map-started EKF: one program per design runs them one after the
//! other over the recorded sequence, [`ObserverMeasurement`]) and the EKF from the box centre (a
//! program of its own, [`EkfMeasurement`]: it shares the filter's code with the map-started EKF, which
//! linked together could change what the compiler inlines). [`measure`] builds each program once
//! per design and runs QEMU on one while cargo builds the next.
//!
//! The modules below split the harness by concern: [`Program`] builds the programs and reads their
//! ELFs, QEMU runs them and counts instructions, the semihosting output is parsed into
//! [`Measurements`], and the chip's estimates are compared with the host's, bit for bit in f32 and
//! against f64 ([`Figures`] gathers what the reports give).

mod accuracy;
mod bit_exact;
mod board;
mod c_build;
mod c_cases;
mod c_observers;
mod elf;
mod figures;
mod kind;
mod measure;
mod measurement;
mod qemu;
mod semihosting;
pub mod standalone;
pub mod timing;
mod unavailable;

pub use accuracy::{
    compare_ekf_with_f64, compare_started_with_f64, compare_ukf_with_f64, compare_with_library, ekf_largest_difference,
};
pub use bit_exact::{bits_and_flags, chip_flag, differences, ekf_differences, host_ekf, host_samples, HostEkfSample};
pub use board::Board;
pub use c_build::{run_c_counted, BOARD_FLAGS};
pub use c_cases::{
    c_table, compare, extended, inexact, run_shipped_on_board, shipped_cases, Case, INEXACT, LIBM_TOLERANCE,
};
pub use c_observers::{
    c_harness, counts_refusals, run_c_observer, rust_lines, sample_lines, status, CBoardRun, CValue, STRICT_C_FLAGS,
};
pub use elf::{sizes, Program};
pub use figures::{check_cycles, spread, Figures};
pub use kind::{chosen_kind, design_names, has_fixed, kinds, m0_kinds, start_up, Kind, ObserverKind};
pub use measure::{
    instructions_alone, measure, measure_board, measure_designs, panic_check_catches_a_reachable_panic, same_alone,
};
pub use measurement::{
    phases, Boards, EkfMeasurement, EkfSample, Measurements, ObserverMeasurement, Phases, TargetSample,
};
pub use qemu::{count_between, run_on_emulator, Count};
pub use unavailable::{require_emulator, Unavailable};
