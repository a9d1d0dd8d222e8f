//! Runs every generated observer over its recorded sequence on the emulated Cortex-M4F and reports
//! over semihosting, one line per sample:
//!
//! ```text
//! E <design> <k> <accepted 0|1> [<value bits hex> <saturation L|I|H>]…
//! ```
//!
//! `push` + `estimate` of every sample runs between `measure_start` and `measure_end`, two functions
//! the host finds in the ELF and counts executed instructions between (QEMU `-d exec` with one
//! instruction per translation block). Finally `S <design> <size_of Observer>` and `DONE`.
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprint, hprintln};
use firmware::{Estimate, Saturation};

/// Marks the start of a measured `push` + `estimate`.
#[inline(never)]
#[no_mangle]
pub extern "C" fn measure_start() {
    cortex_m::asm::nop();
}

/// Marks its end.
#[inline(never)]
#[no_mangle]
pub extern "C" fn measure_end() {
    // Two instructions, so that the linker cannot fold it into `measure_start`.
    cortex_m::asm::nop();
    cortex_m::asm::nop();
}

fn print_estimates(estimates: &[Estimate<f32>]) {
    for e in estimates {
        let flag = match e.saturation {
            Saturation::Low => 'L',
            Saturation::Inside => 'I',
            Saturation::High => 'H',
        };
        hprint!(" {:08x} {}", e.value.to_bits(), flag);
    }
}

macro_rules! run_design {
    ($name:ident) => {{
        use generated::$name as d;
        let mut observer = d::observer();
        for (k, (y, u)) in d::RECORDED_Y.iter().zip(d::RECORDED_U.iter()).enumerate() {
            measure_start();
            let accepted = core::hint::black_box(observer.push(*y, *u)).is_ok();
            let estimates = core::hint::black_box(observer.estimate());
            measure_end();
            hprint!("E {} {} {}", d::NAME, k, u8::from(accepted));
            if let Some(estimates) = estimates {
                print_estimates(&estimates);
            }
            hprintln!();
        }
        hprintln!("S {} {}", d::NAME, core::mem::size_of::<d::Observer>());
    }};
}

#[entry]
fn main() -> ! {
    generated::for_each_design!(run_design);
    hprintln!("DONE");
    debug::exit(debug::EXIT_SUCCESS);
    loop {}
}

#[panic_handler]
fn panic(info: &PanicInfo) -> ! {
    hprintln!("PANIC {}", info);
    debug::exit(debug::EXIT_FAILURE);
    loop {}
}
