//! Runs one generated design's extended Kalman filter (chosen by `ON_TARGET_DESIGN` at build time, so
//! that the program links that design alone) over its recorded sequence on the emulated Cortex-M4F,
//! the map observer's peer, measured the same way (see `main.rs`; on the emulated Cortex-M0 too, soft
//! float), and reports over semihosting:
//!
//! ```text
//! K <k> <accepted 0|1> [<target bits hex>…] X <state bits hex>…     one line per sample
//! S <size_of Ekf>
//! STACK <bytes used by push + targets>
//! DONE
//! ```
//!
//! The targets are those of the updated estimate `x̂(k|k)` that `push` returns (none when the sample
//! is refused); the state is the filter's after the sample (the prediction to the next one, which
//! runs on refused samples too), read outside the measured region.
//!
//! `push` + `targets` of every sample runs in [`step`], between `measure_start` and `measure_end`.
//! This file repeats `main.rs`'s markers and stack painting rather than sharing them, so that the map
//! observer's program, and its measured numbers, stay exactly as they were.
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprint, hprintln};
use firmware::rules::Refused;
use generated::firmware;

include!(concat!(env!("OUT_DIR"), "/design.rs"));
include!(concat!(env!("OUT_DIR"), "/board.rs"));

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

const PAINT: u32 = 0xA5A5_5A5A;

type Targets = Result<[f32; d::TARGETS], Refused>;

/// One sample: what a user's firmware does every period. Not inlined, and its results are returned
/// and printed, so nothing of `push` and `targets` can be optimised away.
#[inline(never)]
fn step(filter: &mut d::Ekf, y: &[f32; d::OUTPUTS], u: &[f32; d::INPUTS]) -> Targets {
    measure_start();
    let targets = filter.push(y, u).map(|x| d::targets(&x, u));
    measure_end();
    targets
}

#[entry]
fn main() -> ! {
    let mut filter = d::ekf();
    let mut results: [(Targets, [f32; d::STATES]); d::RECORDED_LEN] =
        [(Err(Refused::Value), [0.0; d::STATES]); d::RECORDED_LEN];
    let top = cortex_m::register::msp::read() as usize;
    for address in (top - EKF_PAINTED..top).step_by(4) {
        // SAFETY: below the stack pointer, inside RAM, not in use: nothing runs but this loop.
        unsafe { core::ptr::write_volatile(address as *mut u32, PAINT) };
    }
    for (result, (y, u)) in results.iter_mut().zip(d::RECORDED_Y.iter().zip(d::RECORDED_U.iter())) {
        let targets = step(&mut filter, y, u);
        *result = (targets, filter.state());
    }
    let deepest = (top - EKF_PAINTED..top)
        .step_by(4)
        // SAFETY: the same painted words, read back.
        .find(|&address| unsafe { core::ptr::read_volatile(address as *const u32) } != PAINT)
        .unwrap_or(top);
    for (k, (targets, state)) in results.iter().enumerate() {
        hprint!("K {} {}", k, u8::from(targets.is_ok()));
        for value in targets.iter().flatten() {
            hprint!(" {:08x}", value.to_bits());
        }
        hprint!(" X");
        for value in state {
            hprint!(" {:08x}", value.to_bits());
        }
        hprintln!();
    }
    hprintln!("S {}", core::mem::size_of::<d::Ekf>());
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
