//! Design-time side of the off-line moving-horizon observer.
//!
//! From a design spec ([`spec`]) the host simulates learning data ([`data`], [`simulate`]), fits for
//! every target a map `r = Γ⁻¹(Lᵀ Z)` by constrained least squares ([`identify`], solved by Clarabel
//! through [`qp`]), judges it on fresh validation runs beside a plain linear least-squares floor
//! ([`evaluate`]) and writes a report ([`report`]). The fitted maps are evaluated through the
//! `firmware` crate's code, in `f64` ([`maps`]).
#![warn(missing_docs)]

pub mod data;
pub mod emit;
pub mod fit;
pub mod generate;
pub mod output;
pub mod recording;
pub mod report;
pub mod spec;
