//! The sensor. On a real board `read` would start an ADC conversion and scale the result into the
//! design's units; here it replays a run recorded by the design tool, so that the program prints the
//! same numbers on any board and on the emulator. `data/run.csv` was made by
//!
//! ```sh
//! cargo run -q -p host -- simulate --design vanderpol --samples 60 --output examples/board/data/run.csv
//! ```
//!
//! and `build.rs` turns it into [`ROWS`] at build time.

use crate::design::{INPUTS, INPUT_NAMES, OUTPUTS, OUTPUT_NAMES};

include!(concat!(env!("OUT_DIR"), "/recorded.rs"));

/// Samples in the recording.
pub const SAMPLES: usize = ROWS.len();

/// Where each output and input of the design is in [`ROWS`]; a column the CSV lacks stops the build.
const Y_COLUMNS: [usize; OUTPUTS] = columns(&OUTPUT_NAMES);
const U_COLUMNS: [usize; INPUTS] = columns(&INPUT_NAMES);

/// The recorded run, one sample per `read`.
pub struct Replay {
    next: usize,
}

impl Replay {
    /// At the first sample.
    pub const fn new() -> Self {
        Replay { next: 0 }
    }

    /// The next sample's outputs and inputs, in the design's order; `None` at the end of the
    /// recording (an ADC would never end).
    pub fn read(&mut self) -> Option<([f32; OUTPUTS], [f32; INPUTS])> {
        let row = ROWS.get(self.next)?;
        self.next += 1;
        Some((Y_COLUMNS.map(|c| row[c]), U_COLUMNS.map(|c| row[c])))
    }
}

/// The index in [`COLUMNS`] of each of `names` (evaluated by the compiler: a missing name is a build
/// error).
const fn columns<const N: usize>(names: &[&str; N]) -> [usize; N] {
    let mut found = [0; N];
    let mut n = 0;
    while n < N {
        let mut c = 0;
        while c < COLUMNS.len() && !same(COLUMNS[c], names[n]) {
            c += 1;
        }
        assert!(c < COLUMNS.len(), "data/run.csv lacks a column of the design");
        found[n] = c;
        n += 1;
    }
    found
}

/// `a == b`, in a `const fn`.
const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}
