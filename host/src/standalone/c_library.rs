//! The C library of a standalone crate (`<crate>/c/`): a `staticlib` crate of `extern "C"` functions
//! over the design's observer, and its header written by cbindgen.
//!
//! ```c
//! static uint8_t storage[MY_DESIGN_STORAGE_SIZE] __attribute__((aligned(MY_DESIGN_STORAGE_ALIGN)));
//! my_design_init(storage, sizeof storage);               // or to reset
//! my_design_push(storage, y, u);                         // MY_DESIGN_REFUSED for a NaN/inf sample,
//!                                                        // MY_DESIGN_RESTARTED where its filter restarted
//! float x[MY_DESIGN_TARGETS];
//! if (my_design_estimate(storage, x, NULL) == MY_DESIGN_OK) { /* use x */ }
//! ```
//!
//! Its statuses and saturation flags are the C source's (`my_design_status`, `my_design_saturation`,
//! [`crate::emit::c`]): one enum each, with the same names and values in both headers, so that a
//! firmware moves between the two C routes without a change. Rust lays them out as the target's C
//! ABI does (one byte on `arm-none-eabi`, whose compilers use short enums by default).
//!
//! The observer lives in storage the caller provides: `STORAGE_SIZE` bytes aligned to `STORAGE_ALIGN`.
//! The size is a bound the host computes from the design's shape (the window of `N` samples stored
//! twice, the follower's state and covariance); the crate does not compile on a target where the
//! observer would not fit in it, so a header never states too little.

use std::path::Path;

use crate::spec::Design;
use crate::standalone::library_name;

/// The C library's folder inside the standalone crate.
pub const FOLDER: &str = "c";

/// `c/Cargo.toml`.
pub fn manifest(design: &Design) -> String {
    format!(
        "# The C library of the `{name}` observer, emitted by `mho gen --spec`. Do not edit: regenerate.\n\
         {licence}\n\
         # cargo build --release --target thumbv7em-none-eabihf  →  target/thumbv7em-none-eabihf/release/lib{library}_c.a\n\
         [package]\n\
         name = \"{package}-c\"\n\
         version = \"0.1.0\"\n\
         edition = \"2021\"\n\
         rust-version = \"1.95\"\n\
         publish = false\n\
         license = \"MIT OR Apache-2.0\"\n\
         \n\
         [lib]\n\
         name = \"{library}_c\"\n\
         crate-type = [\"staticlib\"]\n\
         \n\
         [dependencies]\n\
         {package} = {{ path = \"..\" }}\n\
         \n\
         [workspace]\n\
         \n\
         # No unwinding across the C boundary; the observer's code has no reachable panic.\n\
         [profile.dev]\n\
         panic = \"abort\"\n\
         \n\
         [profile.release]\n\
         panic = \"abort\"\n\
         opt-level = \"s\"\n\
         lto = true\n\
         codegen-units = 1\n",
        name = design.name,
        licence = crate::emit::licence_comment("# "),
        package = super::package_name(&design.name),
        library = library_name(&design.name),
    )
}

pub use crate::emit::c::{storage_bound, MARK_BYTES};

/// Spec text for a doc comment that cbindgen copies into a C `/* … */` comment: one line, no code
/// span's end, and no `*/` or `/*` (which would end the comment, or open one inside it, and let the
/// rest be read as C).
fn c_comment(text: &str) -> String {
    crate::emit::doc_code(text).replace("*/", "* /").replace("/*", "/ *")
}

/// `c/src/lib.rs`.
pub fn source(design: &Design) -> String {
    let name = &design.name;
    let upper = name.to_uppercase();
    let status = format!("{name}_status");
    let list = crate::emit::name_list;
    // `name (unit)`, as the docs list them.
    let with_unit = |name: &String, unit: &String| {
        if unit.is_empty() {
            name.clone()
        } else {
            format!("{name} ({})", c_comment(unit))
        }
    };
    let outputs: Vec<String> = design
        .model
        .outputs
        .iter()
        .map(|o| with_unit(&o.name, &o.unit))
        .collect();
    let inputs: Vec<String> = design
        .model
        .inputs
        .iter()
        .zip(&design.input_units)
        .map(|(i, unit)| with_unit(i, unit))
        .collect();
    let targets: Vec<String> = design.targets.iter().map(|t| with_unit(&t.name, &t.unit)).collect();
    // The shortest decimal that reads back as the design's f32 period.
    let tau = format!("{:?}", design.tau as f32);
    let saturation = format!("{name}_saturation");
    format!(
        r#"//! C interface of the `{name}` observer: create it in storage the caller provides, push each
//! sample, read the estimates; every call returns a status. Header: `include/{name}.h` (cbindgen).
//! Emitted by `mho gen --spec`. Do not edit: regenerate.
{licence}
#![no_std]

use core::ffi::c_void;
use core::mem::{{align_of, size_of}};

use {library}::{name} as design;

/// Bytes of storage the observer needs at most (checked against its size when this crate compiles).
pub const {upper}_STORAGE_SIZE: usize = {bound};
/// Alignment of the storage, in bytes.
pub const {upper}_STORAGE_ALIGN: usize = 8;
/// Measured outputs per sample (`y`), in this order: {outputs}.
pub const {upper}_OUTPUTS: usize = {ny};
/// Inputs per sample (`u`), in this order: {inputs}.
pub const {upper}_INPUTS: usize = {nu};
/// Estimates, in this order: {targets}.
pub const {upper}_TARGETS: usize = {nt};
/// The map's window, in samples: the map and the observers it starts give no estimate before it (the
/// EKFs from the box centre estimate from the first sample).
pub const {upper}_HORIZON: usize = {horizon};
/// The sample period the design assumes, in {time_unit}. Not `pub`: the header defines
/// `{upper}_SAMPLE_PERIOD` once, as a `float` literal (cbindgen would print it without its `f`).
const {upper}_SAMPLE_PERIOD: f32 = {tau};

/// What `{name}_init` writes into the storage: a mark that an observer of this design is there and
/// the size it was given, then the observer. Every call checks the mark first.
#[repr(C)]
struct Stored {{
    mark: u64,
    size: u64,
    observer: design::Observer,
}}

/// The mark of this design's observer (never 0: zeroed storage holds none).
const MARK: u64 = 0x{mark:016x};

const _: () = assert!(size_of::<Stored>() <= {upper}_STORAGE_SIZE);
const _: () = assert!(align_of::<Stored>() <= {upper}_STORAGE_ALIGN);
const _: () = assert!(
    design::OUTPUTS == {upper}_OUTPUTS
        && design::INPUTS == {upper}_INPUTS
        && design::TARGETS == {upper}_TARGETS
        && design::HORIZON == {upper}_HORIZON
        && design::SAMPLE_PERIOD == {upper}_SAMPLE_PERIOD
);

/// What a call did: the C source's `{status}`, the same names and values.
#[repr(C)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum {status} {{
    /// Done.
    {upper}_OK = 0,
    /// The sample has a NaN or infinite value and was refused; the observer is unchanged.
    {upper}_REFUSED = 1,
    /// No estimate yet (the map and the observers it starts: fewer than `HORIZON` accepted samples since
    /// the start; the EKF from the box centre: no accepted sample yet); nothing was written.
    {upper}_NO_ESTIMATE_YET = 2,
    /// A null pointer, or storage too small or misaligned: nothing was done.
    {upper}_BAD_ARGUMENT = 3,
    /// The storage holds no observer: `{name}_init` was never called on it, or refused it (or it
    /// holds another design's); nothing was done.
    {upper}_NOT_INITIALISED = 4,
    /// The sample's values were finite but the observer's step was not: it restarted (a filter from
    /// its start or from the map, the moving-horizon estimate from its start); the latest estimate is
    /// unchanged.
    {upper}_RESTARTED = 5,
}}

/// Where an estimate lies against its learning range: the C source's `{saturation}`, the same names
/// and values.
#[repr(C)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum {saturation} {{
    /// Inside the range.
    {upper}_INSIDE = 0,
    /// Held at its low end.
    {upper}_LOW = 1,
    /// Held at its high end.
    {upper}_HIGH = 2,
}}

/// The observer in `storage`: `BAD_ARGUMENT` for a null or misaligned pointer, `NOT_INITIALISED`
/// when `{name}_init` did not make one there (the mark is not this design's, or the size it was
/// given is too small).
///
/// # Safety
/// `storage` points to at least 16 readable bytes; when they hold the mark, to an observer made by
/// `{name}_init`, used by nothing else during the call.
unsafe fn observer<'a>(storage: *mut c_void) -> Result<&'a mut design::Observer, {status}> {{
    if storage.is_null() || (storage as usize) % align_of::<Stored>() != 0 {{
        return Err({status}::{upper}_BAD_ARGUMENT);
    }}
    let stored = storage.cast::<Stored>();
    // SAFETY: non-null and aligned; the mark and the size are the storage's first 16 bytes.
    let (mark, size) = unsafe {{ (core::ptr::addr_of!((*stored).mark).read(), core::ptr::addr_of!((*stored).size).read()) }};
    if mark != MARK || size < size_of::<Stored>() as u64 {{
        return Err({status}::{upper}_NOT_INITIALISED);
    }}
    // SAFETY: `{name}_init` wrote a whole `Stored` there (the mark says so).
    Ok(unsafe {{ &mut (*stored).observer }})
}}

/// Creates a fresh observer (no sample yet) in `storage`, `size` bytes aligned to
/// `{upper}_STORAGE_ALIGN`; call it again to reset.
///
/// # Safety
/// `storage` points to `size` writable bytes that nothing else uses while the observer lives.
#[no_mangle]
pub unsafe extern "C" fn {name}_init(storage: *mut c_void, size: usize) -> {status} {{
    if storage.is_null() || size < size_of::<Stored>() || (storage as usize) % align_of::<Stored>() != 0 {{
        return {status}::{upper}_BAD_ARGUMENT;
    }}
    let stored = Stored {{
        mark: MARK,
        size: size as u64,
        observer: design::observer(),
    }};
    // SAFETY: large enough, aligned, and the caller's to write.
    unsafe {{ storage.cast::<Stored>().write(stored) }};
    {status}::{upper}_OK
}}

/// Pushes this instant's sample: `y` points to `{upper}_OUTPUTS` floats and `u` to
/// `{upper}_INPUTS` floats (either may be null when there are none).
///
/// # Safety
/// `storage` was initialised by `{name}_init`; `y` and `u` point to that many floats.
#[no_mangle]
pub unsafe extern "C" fn {name}_push(storage: *mut c_void, y: *const f32, u: *const f32) -> {status} {{
    // SAFETY: the caller's contract.
    let observer = match unsafe {{ observer(storage) }} {{
        Ok(observer) => observer,
        Err(status) => return status,
    }};
    if (y.is_null() && design::OUTPUTS > 0) || (u.is_null() && design::INPUTS > 0) {{
        return {status}::{upper}_BAD_ARGUMENT;
    }}
    let mut outputs = [0.0f32; design::OUTPUTS];
    let mut inputs = [0.0f32; design::INPUTS];
    for (i, value) in outputs.iter_mut().enumerate() {{
        // SAFETY: `y` points to OUTPUTS floats.
        *value = unsafe {{ y.add(i).read_unaligned() }};
    }}
    for (i, value) in inputs.iter_mut().enumerate() {{
        // SAFETY: `u` points to INPUTS floats.
        *value = unsafe {{ u.add(i).read_unaligned() }};
    }}
    let restarts = <design::Observer as {library}::firmware::Estimator>::restarts(observer);
    match observer.push(outputs, inputs) {{
        Ok(()) => {status}::{upper}_OK,
        Err(_) if <design::Observer as {library}::firmware::Estimator>::restarts(observer) != restarts => {{
            {status}::{upper}_RESTARTED
        }}
        Err(_) => {status}::{upper}_REFUSED,
    }}
}}

/// Writes the `{upper}_TARGETS` estimates into `estimates` and, unless `saturation` is null, whether
/// each was held at an end of the learning range into `saturation`.
///
/// # Safety
/// `storage` was initialised by `{name}_init`; `estimates` (and `saturation`, when not null) point
/// to `{upper}_TARGETS` writable values.
#[no_mangle]
pub unsafe extern "C" fn {name}_estimate(storage: *mut c_void, estimates: *mut f32, saturation: *mut {saturation}) -> {status} {{
    // SAFETY: the caller's contract.
    let observer = match unsafe {{ observer(storage) }} {{
        Ok(observer) => observer,
        Err(status) => return status,
    }};
    if estimates.is_null() {{
        return {status}::{upper}_BAD_ARGUMENT;
    }}
    let Some(all) = observer.estimate() else {{
        return {status}::{upper}_NO_ESTIMATE_YET;
    }};
    for (i, estimate) in all.iter().enumerate() {{
        // SAFETY: `estimates` points to TARGETS floats.
        unsafe {{ estimates.add(i).write_unaligned(estimate.value) }};
        if !saturation.is_null() {{
            let flag = match estimate.saturation {{
                {library}::firmware::Saturation::Low => {saturation}::{upper}_LOW,
                {library}::firmware::Saturation::Inside => {saturation}::{upper}_INSIDE,
                {library}::firmware::Saturation::High => {saturation}::{upper}_HIGH,
            }};
            // SAFETY: `saturation` points to TARGETS values.
            unsafe {{ saturation.add(i).write_unaligned(flag) }};
        }}
    }}
    {status}::{upper}_OK
}}

/// Bytes the observer occupies on this target with its mark (at most `{upper}_STORAGE_SIZE`).
#[no_mangle]
pub extern "C" fn {name}_storage_size() -> usize {{
    size_of::<Stored>()
}}

/// The observer's code has no reachable panic (the project's probe proves it for every design);
/// a C program cannot unwind a Rust panic, so one would stop here.
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {{
    loop {{}}
}}
"#,
        library = library_name(name),
        licence = crate::emit::licence_comment("//! "),
        bound = storage_bound(design),
        outputs = list(&outputs),
        inputs = list(&inputs),
        time_unit = c_comment(&design.time_unit),
        tau = tau,
        targets = list(&targets),
        ny = design.model.outputs.len(),
        nu = design.model.inputs.len(),
        nt = design.targets.len(),
        horizon = design.map.horizon,
        mark = crate::emit::c::mark(name),
    )
}

/// The C header of `source` (written at `source_path`), by cbindgen.
pub fn header(design: &Design, source_path: &Path) -> Result<String, cbindgen::Error> {
    let upper = design.name.to_uppercase();
    let guard = format!("{upper}_OBSERVER_H");
    let config = cbindgen::Config {
        language: cbindgen::Language::C,
        include_guard: Some(guard),
        usize_is_size_t: true,
        header: Some(format!(
            "/* C interface of the `{}` observer, written by cbindgen from c/src/lib.rs (mho gen --spec). Do not edit.\n{} */",
            design.name,
            crate::emit::licence_comment(" * ")
        )),
        // The sample period as a `float` literal, once (the Rust constant is not exported).
        after_includes: Some(format!(
            "\n/* The sample period the design assumes, in its time unit: push one sample every period. */\n\
             #define {upper}_SAMPLE_PERIOD {}",
            crate::emit::c::sample_period(design)
        )),
        // `extern "C"` (and the enums' C++ form) for a C++ program that includes the header.
        cpp_compat: true,
        // `typedef enum { … } my_design_status;`, named as the C source's header names it.
        style: cbindgen::Style::Type,
        documentation: true,
        ..Default::default()
    };
    let bindings = cbindgen::Builder::new()
        .with_config(config)
        .with_src(source_path)
        .generate()?;
    let mut text = Vec::new();
    bindings.write(&mut text);
    Ok(String::from_utf8_lossy(&text).into_owned())
}
