//! The Rust static library's C interface (`c/include/<name>.h` of a crate `gen --spec` writes,
//! `crate::standalone::c_library`) over the C source's chosen kind: the same calls, statuses, storage
//! mark and checks, so that a firmware moves between the two C routes without changing a line.

use askama::Template;

use crate::spec::Design;

/// Bytes the observer of `design` needs at most on any target: the window (`N` samples of `f32`
/// outputs and inputs, twice, and two indices), the follower's state, covariance and start-up
/// constants, and slack for indices and padding. Both routes state it as `<NAME>_STORAGE_SIZE`; each
/// checks when it compiles that its observer fits.
pub fn storage_bound(design: &Design) -> usize {
    let (n, ny, nu) = (
        design.map.horizon,
        design.model.outputs.len(),
        design.model.inputs.len(),
    );
    let (nx, nt) = (design.model.states.len(), design.targets.len());
    let window = 2 * 4 * n * (ny + nu) + 2 * 8;
    let follower = 4 * (nx * (nx + 7) + 4 * nt) + 64;
    // The storage's mark and size before the observer.
    (MARK_BYTES + window + follower).div_ceil(8) * 8
}

/// Bytes before the observer in the C storage: the mark that `init` made an observer there, and the
/// size it was given.
pub const MARK_BYTES: usize = 16;

/// The mark of an observer of design `name` in C storage: FNV-1a of the name, never 0, so that
/// zeroed storage, storage `init` refused, or another design's observer are told apart.
pub fn mark(name: &str) -> u64 {
    let hash = name.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    });
    hash | 1
}

/// The header's and the source's parts of the interface for `design`.
pub(super) fn storage_interface(design: &Design) -> (String, String) {
    let name = design.name.as_str();
    let inputs = design.model.inputs.len();
    let upper = name.to_uppercase();
    let bound = storage_bound(design);
    let header = super::text::render(&StorageH {
        name,
        upper: &upper,
        bound,
    });
    let source = super::text::render(&StorageC {
        name,
        upper: &upper,
        inputs: inputs > 0,
        mark: &format!("{:016x}", mark(name)),
    });
    (header, source)
}

/// The interface's part of the header (`bound`: `<NAME>_STORAGE_SIZE`).
#[derive(Template)]
#[template(path = "c/storage.h", escape = "none")]
struct StorageH<'a> {
    name: &'a str,
    upper: &'a str,
    bound: usize,
}

/// The interface's part of the source (`mark`: the design's mark, 16 hex digits).
#[derive(Template)]
#[template(path = "c/storage.c", escape = "none")]
struct StorageC<'a> {
    name: &'a str,
    upper: &'a str,
    inputs: bool,
    mark: &'a str,
}

/// The design's sample period as a C `float` literal (`0.1f`): the shortest decimal that reads back
/// as its f32, as the Rust design file's `SAMPLE_PERIOD`; both C headers define it with this text.
pub fn sample_period(design: &Design) -> String {
    format!("{:?}f", design.tau as f32)
}
