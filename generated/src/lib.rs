//! Observers emitted by `cargo run -p host -- gen` (host 0.1.0). Do not edit: regenerate.
//!
//! One module per design spec; each holds constant tables, an `Observer` type and `observer()`.
#![no_std]

pub use firmware;

pub mod vanderpol;

/// Invokes `$callback!(design)` for every design module, for code that treats them all alike
/// (the generated-vs-library tests, the on-target runner).
#[macro_export]
macro_rules! for_each_design {
    ($callback:ident) => {
        $callback!(vanderpol);
    };
}
