//! A generated observer on a Cortex-M4F board: every sample period it reads the sensor, pushes the
//! sample into the Van der Pol design's observer (`generated::vanderpol`, the paper's Example 1) and
//! prints the estimate over semihosting, one line per sample:
//!
//! ```text
//! 0 no estimate yet            before the first estimate (the map and the observers it starts:
//!                              until HORIZON samples have arrived; the EKFs from the box centre
//!                              estimate from the first sample)
//! 9 x1=0.3654424 x2=3.9929113  one name=value per target, (low) or (high) after a value clamped
//!                              to the design's learning range
//! <k> refused                  a NaN or infinite sample: the observer is unchanged
//! ```
//!
//! The board is a cargo feature: `nucleo-f401re` (the default) or `qemu-mps2-an386` (the emulator;
//! see README.md). At the end of the recording the program ends the emulator's or probe-rs's run.
#![no_std]
#![no_main]

mod sensor;

use core::panic::PanicInfo;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprint, hprintln};
use generated::firmware::Saturation;
use generated::vanderpol as design;

#[entry]
fn main() -> ! {
    let mut clock = SampleClock::start();
    let mut sensor = sensor::Replay::new();
    // Fixed memory, no allocation: the observer is a plain value.
    let mut observer = design::observer();
    hprintln!(
        "{} observer ({}), {} recorded samples",
        design::NAME,
        design::KIND,
        sensor::SAMPLES
    );
    let mut k = 0;
    while let Some((y, u)) = sensor.read() {
        hprint!("{}", k);
        if observer.push(y, u).is_err() {
            hprint!(" refused");
        } else if let Some(estimates) = observer.estimate() {
            for (name, estimate) in design::TARGET_NAMES.iter().zip(estimates) {
                // `{}` prints the shortest decimal that reads back as the same f32.
                hprint!(" {}={}", name, estimate.value);
                match estimate.saturation {
                    Saturation::Inside => {}
                    Saturation::Low => hprint!("(low)"),
                    Saturation::High => hprint!("(high)"),
                }
            }
        } else {
            hprint!(" no estimate yet");
        }
        hprintln!();
        k += 1;
        clock.wait();
    }
    hprintln!("end of the recording");
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

/// Keeps the design's sample period with SysTick: the STM32F401 runs from its 16 MHz internal
/// oscillator after reset (this example sets up no PLL), and one period must fit SysTick's 24 bits.
#[cfg(feature = "nucleo-f401re")]
struct SampleClock(cortex_m::peripheral::SYST);

#[cfg(feature = "nucleo-f401re")]
impl SampleClock {
    const CORE_HZ: f32 = 16e6;
    const CYCLES: u32 = (design::SAMPLE_PERIOD * Self::CORE_HZ) as u32;

    /// Starts counting the first period.
    fn start() -> Self {
        const { assert!(Self::CYCLES >= 1 && Self::CYCLES <= 1 << 24) };
        let mut systick = cortex_m::Peripherals::take()
            .expect("the core peripherals, taken once")
            .SYST;
        systick.set_clock_source(cortex_m::peripheral::syst::SystClkSource::Core);
        systick.set_reload(Self::CYCLES - 1);
        systick.clear_current();
        systick.enable_counter();
        SampleClock(systick)
    }

    /// Waits for the end of the current period, however long the sample took.
    fn wait(&mut self) {
        while !self.0.has_wrapped() {}
    }
}

/// The emulator replays the recording as fast as it can: there is no real time to keep.
#[cfg(feature = "qemu-mps2-an386")]
struct SampleClock;

#[cfg(feature = "qemu-mps2-an386")]
impl SampleClock {
    fn start() -> Self {
        SampleClock
    }

    fn wait(&mut self) {}
}

#[panic_handler]
fn panic(info: &PanicInfo) -> ! {
    hprintln!("panic: {}", info);
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::wfi();
    }
}
