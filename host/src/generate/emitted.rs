//! One design fitted and emitted, as a value: what `gen` writes its files and tables
//! ([`crate::tables`]) from.

use crate::fit::DesignResult;
use crate::spec::Design;

/// One design fitted and emitted, in memory.
pub struct Emitted {
    /// The design.
    pub design: Design,
    /// Its data, fits and evaluation.
    pub result: DesignResult,
    /// Its observers compared (the map and the EKF).
    pub comparison: crate::observers::Comparison,
    /// The text of `generated/src/<design>.rs`.
    pub source: String,
    /// The design's map in C99 (`generated/c/<design>.h`, `.c`).
    pub c_source: crate::emit::c::CSource,
    /// The design search, when the spec asks for one ([`crate::search`]); `design.map` holds its choice.
    pub search: Option<crate::search::Outcome>,
    /// The map in integers and its figures on the validation runs, when the spec asks for it.
    pub fixed: Option<Fixed>,
    /// Validation accuracy against the taps kept, when the spec prunes `L` ([`crate::search::sparsity`]).
    pub taps: Option<Vec<crate::search::sparsity::Row>>,
}

/// The map in integers ([`crate::fixed_point`]) and how it did on the validation runs.
pub struct Fixed {
    /// The integers, formats and bounds.
    pub point: crate::fixed_point::FixedPoint,
    /// Against the true targets and the f64 map, on every validation window.
    pub validation: crate::fixed_point::Comparison,
}
