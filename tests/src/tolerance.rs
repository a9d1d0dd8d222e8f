//! The f32-against-f64 tolerance lives in the host ([`host::emit::precision`]), which also checks every map
//! against it before emitting; the tests use the same bound.

pub use host::emit::precision::{tolerance, U};
