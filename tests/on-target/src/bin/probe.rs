//! Size and panic probe: links exactly one design's observer (chosen by `PROBE_DESIGN` at build
//! time, none for the baseline) and calls every entry point (`push`, `estimate`, `reset`); with
//! `PROBE_KIND=ekf_box`, that design's extended Kalman filter instead (`ekf`, `push`, `targets`, `state`,
//! `covariance`).
//!
//! Its panic handler calls a function that does not exist: if any panic path is reachable from the
//! observer after optimisation, the link fails with `observer_code_can_panic` undefined. The release
//! build of this probe is therefore the no-panic proof, and its size minus the baseline's is the
//! design's flash cost.
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use cortex_m_rt::entry;

include!(concat!(env!("OUT_DIR"), "/probe_design.rs"));

#[entry]
fn main() -> ! {
    probe()
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    extern "Rust" {
        fn observer_code_can_panic() -> !;
    }
    // SAFETY: never executed: the symbol does not exist, so any reachable call fails to link.
    unsafe { observer_code_can_panic() }
}
