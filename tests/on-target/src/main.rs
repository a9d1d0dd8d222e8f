//! Runs one generated observer (chosen by `ON_TARGET_DESIGN` at build time, so that the program
//! links that design alone) over its recorded sequence on the emulated Cortex-M4F and reports over
//! semihosting:
//!
//! ```text
//! E <k> <accepted 0|1> [<value bits hex> <saturation L|I|H>]…     one line per sample
//! S <size_of Observer>
//! STACK <bytes used by push + estimate>
//! DONE
//! ```
//!
//! `push` + `estimate` of every sample runs in [`step`], between `measure_start` and `measure_end`:
//! two functions the host finds in the ELF and counts executed instructions between (QEMU `-d exec`
//! with one instruction per translation block). Stack: the region below the stack pointer is painted
//! before the samples are run and scanned afterwards; nothing is printed in between, so the deepest
//! word changed is the deepest `step` went.
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprint, hprintln};
use firmware::{Estimate, Saturation};

include!(concat!(env!("OUT_DIR"), "/design.rs"));

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

/// Bytes of stack painted below the stack pointer of `main`.
const PAINTED: usize = 4096;
const PAINT: u32 = 0xA5A5_5A5A;

type Estimates = Option<[Estimate<f32>; d::TARGETS]>;

/// One sample: what a user's firmware does every period. Not inlined, and its results are returned
/// and printed, so nothing of `push` and `estimate` can be optimised away.
#[inline(never)]
fn step(observer: &mut Measured, y: &[f32; d::OUTPUTS], u: &[f32; d::INPUTS]) -> (bool, Estimates) {
    measure_start();
    let accepted = observer.push(*y, *u).is_ok();
    let estimates = observer.estimate();
    measure_end();
    (accepted, estimates)
}

#[entry]
fn main() -> ! {
    let mut observer = fresh();
    let mut results: [(bool, Estimates); d::RECORDED_LEN] = [(false, None); d::RECORDED_LEN];
    let top = cortex_m::register::msp::read() as usize;
    for address in (top - PAINTED..top).step_by(4) {
        // SAFETY: below the stack pointer, inside RAM, not in use: nothing runs but this loop.
        unsafe { core::ptr::write_volatile(address as *mut u32, PAINT) };
    }
    for (result, (y, u)) in results.iter_mut().zip(d::RECORDED_Y.iter().zip(d::RECORDED_U.iter())) {
        *result = step(&mut observer, y, u);
    }
    let deepest = (top - PAINTED..top)
        .step_by(4)
        // SAFETY: the same painted words, read back.
        .find(|&address| unsafe { core::ptr::read_volatile(address as *const u32) } != PAINT)
        .unwrap_or(top);
    for (k, (accepted, estimates)) in results.iter().enumerate() {
        hprint!("E {} {}", k, u8::from(*accepted));
        for e in estimates.iter().flatten() {
            let flag = match e.saturation {
                Saturation::Low => 'L',
                Saturation::Inside => 'I',
                Saturation::High => 'H',
            };
            hprint!(" {:08x} {}", e.value.to_bits(), flag);
        }
        hprintln!();
    }
    hprintln!("S {}", core::mem::size_of::<Measured>());
    hprintln!("STACK {}", top - deepest);
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
