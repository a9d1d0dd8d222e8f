//! Observers emitted by `cargo run -p host -- gen`.
//!
//! This crate holds only emitted files. Code emission lands with the next milestone; until then it
//! re-exports the runtime so that the thumbv7em build covers the crate graph users will build.
#![no_std]

pub use firmware;
