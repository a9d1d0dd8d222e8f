//! Emission of the fitted maps as Rust source (askama templates in `host/templates/`).
//!
//! Each design becomes `generated/src/<design>.rs`: a provenance header, constant `f32` tables and a
//! `const fn` constructor, written only once the f32 tables have been checked against the f64 map on
//! every validation window and the scenario ([`crate::emit::precision`]); `generated/src/lib.rs` declares
//! every design file present. Every literal is
//! printed so that it parses back to the same `f32` bits, non-finite values are refused, and nothing in
//! the output depends on the machine, the time or the way `gen` was invoked: regeneration is byte for
//! byte.
//!
//! One module per piece: `design_file` writes a design's module, `lib_file` the crate's `lib.rs`,
//! [`model`] the design's model and model-based observers, [`mod@families`] the family modules;
//! `doc_text` makes spec text safe for doc comments, `recorded` gives the recorded sequence a design
//! carries, `placement` where a file lives, and [`precision`] checks the f32 tables.

pub mod c;
mod design_file;
mod doc_text;
pub mod families;
pub(crate) mod fixed;
mod lib_file;
pub mod model;
mod placement;
pub mod precision;
mod recorded;
pub mod terms;

pub use design_file::{design_file, within_f32};
pub use doc_text::name_list;
pub(crate) use doc_text::{doc_code, doc_prose};
pub use families::{families, FamilyError, FamilyModule, Member};
pub use lib_file::lib_file;
pub use placement::{portable_spec_path, Placement, STANDALONE_SPEC};
pub use recorded::{recorded_sequence, refused_samples};

/// The licence statement every file `gen` emits carries in its header (the Rust design files and
/// `lib.rs`, the C headers and sources, a crate's manifests and README), one line per entry.
///
/// Why these terms: an emitted file is the user's design output, the tables fitted to their model and
/// their choices, set in code from mho's templates. mho's own licence (MIT OR Apache-2.0, the
/// repository's `LICENSE-MIT` and `LICENSE-APACHE`) asks for its notice to travel with every copy,
/// which a firmware, open or closed, should not owe for its own observer; so, as a compiler's
/// runtime-library exception does, the templates' authors grant the emitted files without conditions:
/// any terms, including mho's own. The `firmware` runtime a crate depends on (or carries) stays under
/// mho's licence.
pub const LICENCE: [&str; 2] = [
    "Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and",
    "distribute it under any terms, including MIT OR Apache-2.0, with or without this notice.",
];

/// [`LICENCE`] as comment lines, each starting with `prefix` (`//! `, ` * `, `# `), no final newline.
pub fn licence_comment(prefix: &str) -> String {
    LICENCE.map(|line| format!("{prefix}{line}")).join("\n")
}

/// Why a design cannot be emitted.
#[derive(Debug, thiserror::Error)]
pub enum EmitError {
    /// A coefficient is NaN, infinite, or beyond the range of `f32`.
    #[error("{what} = {} cannot be stored as a finite f32", crate::spec::readable(*value))]
    NotFinite {
        /// Which coefficient.
        what: String,
        /// Its value.
        value: f64,
    },
    /// A non-zero value that f32 rounds to zero or to a subnormal (losing its precision).
    #[error("{what} = {value:e} is below the normal f32 range (smallest {min:e}): the chip would see 0 or a value without precision; rescale it (e.g. change its units)", min = f32::MIN_POSITIVE)]
    Underflow {
        /// Which value.
        what: String,
        /// Its value.
        value: f64,
    },
    /// Two targets would get the same Rust constant name.
    #[error("targets `{first}` and `{second}` both become the constant `{constant}`")]
    NameClash {
        /// One target.
        first: String,
        /// The other.
        second: String,
        /// The constant both map to.
        constant: String,
    },
    /// A measurement or input of the validation data is beyond the range of f32: the chip could not
    /// hold it.
    #[error("the measurements and inputs reach {}, beyond the range of f32 (±3.4e38): rescale the outputs or inputs (their units) or lower the noise variance", crate::spec::readable(*value))]
    BeyondF32 {
        /// The largest magnitude seen.
        value: f64,
    },
    /// Rounded to f32, the tables do not reproduce the f64 map (see [`crate::emit::precision`]).
    #[error("target `{target}`: {mismatch}; lower `map.beta` or `map.nm`")]
    NotReproducibleInF32 {
        /// The target.
        target: String,
        /// Where it failed.
        mismatch: crate::emit::precision::F32Mismatch,
    },
    /// The map has no table the chip could evaluate.
    #[error("target `{target}`: Γ is so flat somewhere that a certified table of Γ⁻¹ would need more than {max} segments; lower `map.beta` (or `map.nm`), or use `normalisation = \"intercept\"`", max = crate::fit::inverse_table::MAX_SEGMENTS)]
    NoTable {
        /// The target.
        target: String,
    },
    /// The template failed to render.
    #[error("template: {0}")]
    Template(#[from] askama::Error),
}

/// The `f32` nearest `value`, printed so that it parses back to the same bits.
pub fn f32_literal(what: &str, value: f64) -> Result<String, EmitError> {
    let single = value as f32;
    if !single.is_finite() {
        return Err(EmitError::NotFinite {
            what: what.to_owned(),
            value,
        });
    }
    if value != 0.0 && (single == 0.0 || single.is_subnormal()) {
        return Err(EmitError::Underflow {
            what: what.to_owned(),
            value,
        });
    }
    // `{:?}` prints the shortest decimal that round-trips, always with a `.` or an exponent.
    Ok(format!("{single:?}"))
}

/// A watched filter's constants as literals of the emitted language (`firmware::watch`): the mean's
/// start `m`, its gain `1 / W` and its limit `τ m`.
pub(crate) struct WatchLiterals {
    pub(crate) start: String,
    pub(crate) gain: String,
    pub(crate) limit: String,
}

impl WatchLiterals {
    /// Those of `watch` for a filter of `outputs` outputs, each written by `print` (a Rust `T` literal
    /// or a C `float`); `None` where the filter is not watched.
    pub(crate) fn of(
        watch: &crate::plant::kalman::Watch,
        outputs: usize,
        print: impl Fn(&str, f64) -> Result<String, EmitError>,
    ) -> Result<Option<Self>, EmitError> {
        let Some(w) = watch.constants(outputs) else {
            return Ok(None);
        };
        Ok(Some(WatchLiterals {
            start: print("the watch's start", w.start)?,
            gain: print("the watch's gain", w.gain)?,
            limit: print("the watch's limit", w.limit)?,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn literals_round_trip_to_the_same_f32_bits(bits in any::<u32>()) {
            let value = f32::from_bits(bits);
            prop_assume!(value.is_finite() && !value.is_subnormal()); // subnormals are refused
            let literal = f32_literal("x", value as f64).unwrap();
            prop_assert_eq!(literal.parse::<f32>().unwrap().to_bits(), bits, "{}", literal);
            prop_assert!(literal.contains('.') || literal.contains('e'), "{} is not a float literal", literal);
        }
    }

    #[test]
    fn values_that_underflow_in_f32_are_refused_and_zero_and_the_smallest_normal_are_not() {
        for value in [1e-300, -1e-300, 1e-40, f64::from(f32::MIN_POSITIVE) / 2.0] {
            assert!(
                matches!(f32_literal("x", value), Err(EmitError::Underflow { .. })),
                "{value:e}"
            );
        }
        for value in [0.0, -0.0, f64::from(f32::MIN_POSITIVE), 1e-37] {
            assert!(f32_literal("x", value).is_ok(), "{value:e}");
        }
    }

    #[test]
    fn non_finite_and_out_of_range_values_are_refused() {
        for value in [f64::NAN, f64::INFINITY, -f64::INFINITY, 1e39] {
            assert!(matches!(f32_literal("x", value), Err(EmitError::NotFinite { .. })));
        }
    }
}
