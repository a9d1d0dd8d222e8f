//! Runs one generated design's moving-horizon estimator (`mhe()`, chosen by `ON_TARGET_DESIGN` at build
//! time) over its recorded sequence on the emulated Cortex-M4F, measured as the EKF is (`ekf.rs`), and
//! reports over semihosting:
//!
//! ```text
//! K <k> <estimate 0|1> [<target bits hex>…]     one line per sample
//! S <size_of the estimator>
//! STACK <bytes used by push + targets>
//! DONE
//! ```
//!
//! `push` + `targets` of every sample runs in [`step`], between `measure_start` and `measure_end`.
//! This file repeats `ekf.rs`'s markers and stack painting rather than sharing them, so that the other
//! programs, and their measured numbers, stay exactly as they were.
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprint, hprintln};

include!(concat!(env!("OUT_DIR"), "/design.rs"));

/// Marks the start of a measured `push` + `targets`.
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
const PAINTED: usize = 8192;
const PAINT: u32 = 0xA5A5_5A5A;

type Targets = Option<[f32; d::TARGETS]>;

/// One sample: what a user's firmware does every period. Not inlined, and its results are returned
/// and printed, so nothing of `push` and `targets` can be optimised away.
#[inline(never)]
fn step(estimator: &mut d::MheObserver, y: &[f32; d::OUTPUTS], u: &[f32; d::INPUTS]) -> Targets {
    measure_start();
    let targets = match estimator.push(y, u) {
        Ok(Some(x)) => Some(d::targets(&x, u)),
        _ => None,
    };
    measure_end();
    targets
}

#[entry]
fn main() -> ! {
    let mut estimator = d::mhe::<f32>();
    let mut results: [Targets; d::RECORDED_LEN] = [None; d::RECORDED_LEN];
    let top = cortex_m::register::msp::read() as usize;
    for address in (top - PAINTED..top).step_by(4) {
        // SAFETY: below the stack pointer, inside RAM, not in use: nothing runs but this loop.
        unsafe { core::ptr::write_volatile(address as *mut u32, PAINT) };
    }
    for (result, (y, u)) in results.iter_mut().zip(d::RECORDED_Y.iter().zip(d::RECORDED_U.iter())) {
        *result = step(&mut estimator, y, u);
    }
    let deepest = (top - PAINTED..top)
        .step_by(4)
        // SAFETY: the same painted words, read back.
        .find(|&address| unsafe { core::ptr::read_volatile(address as *const u32) } != PAINT)
        .unwrap_or(top);
    for (k, targets) in results.iter().enumerate() {
        hprint!("K {} {}", k, u8::from(targets.is_some()));
        for value in targets.iter().flatten() {
            hprint!(" {:08x}", value.to_bits());
        }
        hprintln!();
    }
    hprintln!("S {}", core::mem::size_of::<d::MheObserver>());
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
