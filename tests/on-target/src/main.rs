//! Runs the observers of one generated design (chosen by `ON_TARGET_DESIGN` at build time, so that
//! the program links that design alone) over its recorded sequence on the emulated Cortex-M4F, one
//! kind after the other (`ON_TARGET_KIND`, comma-separated: any kind the design has by its name,
//! `observer` for its chosen kind, `fixed` for its integer map; the map alone by default), and reports over
//! semihosting (the same program runs on the emulated Cortex-M0, `thumbv6m-none-eabi`, soft float):
//!
//! ```text
//! KIND <kind> <START_UP>                                           for each kind, then
//! E <k> <accepted 0|1> [<value hex> <saturation L|I|H>]…          one line per sample
//! S <size_of the observer>
//! STACK <bytes used by push + estimate>
//! DONE                                                              once, at the end
//! ```
//!
//! A value is printed as its bits: an `f32`'s `to_bits`, the integer observer's `i32` as `u32`
//! (`fixed`, which runs over the raw sequence `RECORDED_RAW_Y`, `RECORDED_RAW_U`).
//!
//! `START_UP` is the number of estimates after the first that take the start-up path (0 for the
//! map; a follower's `Follower::START_UP`; `N − 1` for the restarted EKF, whose estimate number `N`
//! is the one that checks the map).
//!
//! `push` + `estimate` of every sample runs in [`step`], between `measure_start` and `measure_end`:
//! two functions the host finds in the ELF and counts executed instructions between (QEMU `-d exec`
//! with one instruction per translation block). Each kind's samples are counted in order, so the
//! host splits the counts by the `KIND` blocks. Stack: the region below the stack pointer is painted
//! before a kind's samples are run and scanned afterwards; nothing is printed in between, so the
//! deepest word changed is the deepest `step` went.
//!
//! Every kind has its own [`step`] (one instance of it per observer type, called from one place), and
//! everything of `push` and `estimate` that the kinds share (the map's dot products and table, the
//! window) is `#[inline(always)]`: linking several kinds into one program leaves each one's
//! measured code as it is when the kind is linked alone (the report's test compares the two).
#![no_std]
#![no_main]

use core::panic::PanicInfo;

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprint, hprintln};
use firmware::emitted::{Follower, Restart};
use firmware::{Design, Estimate, Saturation};
use generated::firmware;

include!(concat!(env!("OUT_DIR"), "/design.rs"));
include!(concat!(env!("OUT_DIR"), "/kinds.rs"));
include!(concat!(env!("OUT_DIR"), "/board.rs"));

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

const PAINT: u32 = 0xA5A5_5A5A;

type Estimates<T = f32> = Option<[Estimate<T>; d::TARGETS]>;

/// A value an observer estimates, as the runner prints it: its bits.
trait Bits: Copy {
    fn bits(self) -> u32;
}

impl Bits for f32 {
    fn bits(self) -> u32 {
        self.to_bits()
    }
}

impl Bits for i32 {
    fn bits(self) -> u32 {
        self as u32
    }
}

/// What the runner uses of an observer: its `push` and `estimate`, and its start-up.
trait Observe {
    /// What it takes and estimates: `f32`, or `i32` for the integer observer.
    type Value: Bits;
    /// Estimates after the first that take the start-up path.
    const START_UP: usize;
    /// `push`: whether the sample was accepted.
    fn take(&mut self, y: [Self::Value; d::OUTPUTS], u: [Self::Value; d::INPUTS]) -> bool;
    /// `estimate`.
    fn latest(&self) -> Estimates<Self::Value>;
}

/// An observer driven through closures, for the integer observer (`fixed_observer()`, `i32` in and
/// out): its `push` and `estimate`, a map's start-up (none).
#[allow(dead_code)]
struct Driven<T, O, P, E> {
    observer: O,
    push: P,
    estimate: E,
    value: core::marker::PhantomData<T>,
}

#[allow(dead_code)]
impl<T, O, P, E> Driven<T, O, P, E>
where
    P: Fn(&mut O, [T; d::OUTPUTS], [T; d::INPUTS]) -> bool,
    E: Fn(&O) -> Estimates<T>,
{
    fn new(observer: O, push: P, estimate: E) -> Self {
        Driven {
            observer,
            push,
            estimate,
            value: core::marker::PhantomData,
        }
    }
}

impl<T: Bits, O, P, E> Observe for Driven<T, O, P, E>
where
    P: Fn(&mut O, [T; d::OUTPUTS], [T; d::INPUTS]) -> bool,
    E: Fn(&O) -> Estimates<T>,
{
    type Value = T;
    const START_UP: usize = 0;

    #[inline(always)]
    fn take(&mut self, y: [T; d::OUTPUTS], u: [T; d::INPUTS]) -> bool {
        (self.push)(&mut self.observer, y, u)
    }

    #[inline(always)]
    fn latest(&self) -> Estimates<T> {
        (self.estimate)(&self.observer)
    }
}

impl<D, const N: usize> Observe for firmware::Observer<f32, D, N, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>
where
    D: Design<f32, N, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>,
{
    type Value = f32;
    const START_UP: usize = 0;

    #[inline(always)]
    fn take(&mut self, y: [f32; d::OUTPUTS], u: [f32; d::INPUTS]) -> bool {
        self.push(y, u).is_ok()
    }

    #[inline(always)]
    fn latest(&self) -> Estimates {
        self.estimate()
    }
}

impl<F, const NX: usize> Observe for firmware::FilterObserver<f32, F, NX, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>
where
    F: firmware::emitted::Filter<f32, NX, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>,
{
    type Value = f32;
    const START_UP: usize = 0;

    #[inline(always)]
    fn take(&mut self, y: [f32; d::OUTPUTS], u: [f32; d::INPUTS]) -> bool {
        self.push(y, u).is_ok()
    }

    #[inline(always)]
    fn latest(&self) -> Estimates {
        self.estimate()
    }
}

impl<D, F, const N: usize, const NX: usize> Observe
    for firmware::Started<f32, D, F, N, NX, { d::OUTPUTS }, { d::INPUTS }, { d::MAP_ROWS }, { d::TARGETS }>
where
    D: Design<f32, N, { d::OUTPUTS }, { d::INPUTS }, { d::MAP_ROWS }>,
    F: Follower<f32, NX, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>,
{
    type Value = f32;
    const START_UP: usize = F::START_UP;

    #[inline(always)]
    fn take(&mut self, y: [f32; d::OUTPUTS], u: [f32; d::INPUTS]) -> bool {
        self.push(y, u).is_ok()
    }

    #[inline(always)]
    fn latest(&self) -> Estimates {
        self.estimate()
    }
}

impl<D, F, const N: usize, const NX: usize> Observe
    for firmware::Restarted<f32, D, F, N, NX, { d::OUTPUTS }, { d::INPUTS }, { d::MAP_ROWS }, { d::TARGETS }>
where
    D: Design<f32, N, { d::OUTPUTS }, { d::INPUTS }, { d::MAP_ROWS }>,
    F: Restart<f32, NX, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>,
{
    type Value = f32;
    const START_UP: usize = N - 1;

    #[inline(always)]
    fn take(&mut self, y: [f32; d::OUTPUTS], u: [f32; d::INPUTS]) -> bool {
        self.push(y, u).is_ok()
    }

    #[inline(always)]
    fn latest(&self) -> Estimates {
        self.estimate()
    }
}

impl<H, const N: usize, const NX: usize> Observe
    for firmware::mhe::Observer<f32, H, N, NX, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>
where
    H: firmware::emitted::mhe::Horizon<f32, NX, { d::OUTPUTS }, { d::INPUTS }, { d::TARGETS }>,
{
    type Value = f32;
    const START_UP: usize = 0;

    #[inline(always)]
    fn take(&mut self, y: [f32; d::OUTPUTS], u: [f32; d::INPUTS]) -> bool {
        self.push(y, u).is_ok()
    }

    #[inline(always)]
    fn latest(&self) -> Estimates {
        self.estimate()
    }
}

/// One sample: what a user's firmware does every period. Not inlined, and its results are returned
/// and printed, so nothing of `push` and `estimate` can be optimised away.
#[inline(never)]
fn step<O: Observe>(
    observer: &mut O,
    y: &[O::Value; d::OUTPUTS],
    u: &[O::Value; d::INPUTS],
) -> (bool, Estimates<O::Value>) {
    measure_start();
    let accepted = observer.take(*y, *u);
    let estimates = observer.latest();
    measure_end();
    (accepted, estimates)
}

/// Runs `observer` (of kind `kind`) over the recorded sequence (`ys`, `us`) and prints what it
/// estimated.
#[inline(never)]
fn run<O: Observe>(
    kind: &str,
    mut observer: O,
    ys: &[[O::Value; d::OUTPUTS]; d::RECORDED_LEN],
    us: &[[O::Value; d::INPUTS]; d::RECORDED_LEN],
) {
    let mut results: [(bool, Estimates<O::Value>); d::RECORDED_LEN] = [(false, None); d::RECORDED_LEN];
    let top = cortex_m::register::msp::read() as usize;
    for address in (top - PAINTED..top).step_by(4) {
        // SAFETY: below the stack pointer, inside RAM, not in use: nothing runs but this loop.
        unsafe { core::ptr::write_volatile(address as *mut u32, PAINT) };
    }
    for (result, (y, u)) in results.iter_mut().zip(ys.iter().zip(us.iter())) {
        *result = step(&mut observer, y, u);
    }
    let deepest = (top - PAINTED..top)
        .step_by(4)
        // SAFETY: the same painted words, read back.
        .find(|&address| unsafe { core::ptr::read_volatile(address as *const u32) } != PAINT)
        .unwrap_or(top);
    hprintln!("KIND {} {}", kind, O::START_UP);
    for (k, (accepted, estimates)) in results.iter().enumerate() {
        hprint!("E {} {}", k, u8::from(*accepted));
        for e in estimates.iter().flatten() {
            let flag = match e.saturation {
                Saturation::Low => 'L',
                Saturation::Inside => 'I',
                Saturation::High => 'H',
            };
            hprint!(" {:08x} {}", e.value.bits(), flag);
        }
        hprintln!();
    }
    hprintln!("S {}", core::mem::size_of::<O>());
    hprintln!("STACK {}", top - deepest);
}

#[entry]
fn main() -> ! {
    run_all();
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
