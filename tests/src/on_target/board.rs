//! The emulated boards the on-target programs run on: which Rust target builds for each, how QEMU
//! emulates it, whose timing estimates its cycles, and at what clock a sample's time is given.

use super::timing::Core;

/// An emulated board.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Board {
    /// QEMU `mps2-an386`: a Cortex-M4 with its FPU (`thumbv7em-none-eabihf`, hard float), 4 MiB of
    /// memory at 0 and at `0x2000_0000`. The project's reference chip.
    #[default]
    Mps2An386,
    /// QEMU `microbit` (nRF51822): a Cortex-M0 (`thumbv6m-none-eabi`, no FPU: `f32` in software),
    /// 256 KiB of flash at 0 and 16 KiB of RAM at `0x2000_0000`. Its cycles are estimated for the
    /// Cortex-M0+, which runs the same ARMv6-M instructions.
    Microbit,
}

impl Board {
    /// The Rust target the programs are built for.
    pub fn target(self) -> &'static str {
        match self {
            Board::Mps2An386 => "thumbv7em-none-eabihf",
            Board::Microbit => "thumbv6m-none-eabi",
        }
    }

    /// QEMU's options that select the board (the micro:bit's CPU is its machine's, a Cortex-M0).
    pub fn machine(self) -> &'static [&'static str] {
        match self {
            Board::Mps2An386 => &["-machine", "mps2-an386", "-cpu", "cortex-m4"],
            Board::Microbit => &["-machine", "microbit"],
        }
    }

    /// The core whose published timing the cycles are estimated with ([`super::timing`]).
    pub fn core(self) -> Core {
        match self {
            Board::Mps2An386 => Core::CortexM4F,
            Board::Microbit => Core::CortexM0Plus,
        }
    }

    /// The clock a sample's time is stated at, in MHz: a common top speed of each class of part
    /// (STM32L4/G4-class Cortex-M4F at 80 MHz, SAMD21/RP2040-class Cortex-M0+ at 48 MHz).
    pub fn clock_mhz(self) -> f64 {
        match self {
            Board::Mps2An386 => 80.0,
            Board::Microbit => 48.0,
        }
    }

    /// The core as the reports name it.
    pub fn name(self) -> &'static str {
        match self {
            Board::Mps2An386 => "Cortex-M4F",
            Board::Microbit => "Cortex-M0",
        }
    }

    /// The folder, under a program's ELF folder, of this board's ELFs (none for the reference board,
    /// whose files keep their names).
    pub fn folder(self) -> &'static str {
        match self {
            Board::Mps2An386 => "",
            Board::Microbit => "m0/",
        }
    }

    /// Microseconds that `cycles` take at [`Board::clock_mhz`].
    pub fn microseconds(self, cycles: u64) -> f64 {
        cycles as f64 / self.clock_mhz()
    }
}
