//! The `{{ name }}` observer: {{ description }}
//!
//! Emitted by `mho gen --spec` from `{{ spec }}` (mho {{ version }}); its accuracy and cost are in
//! README.md. Do not edit: change the spec and regenerate.
{{ licence }}
#![no_std]

pub use firmware;

// Kept as `gen` writes it (regeneration is compared byte for byte).
#[rustfmt::skip]
pub mod {{ name }};

