//! `generated/src/lib.rs`: the crate root declaring every design and family module present.

use askama::Template;

use crate::emit::{EmitError, FamilyModule};

#[derive(Template)]
#[template(path = "lib.rs", escape = "none")]
struct LibFile<'a> {
    version: &'static str,
    licence: String,
    designs: &'a [String],
    families: &'a [FamilyModule],
}

/// The text of `generated/src/lib.rs` declaring `designs` (sorted by the caller) and `families`.
pub fn lib_file(designs: &[String], families: &[FamilyModule]) -> Result<String, EmitError> {
    LibFile {
        version: env!("CARGO_PKG_VERSION"),
        licence: super::licence_comment("//! "),
        designs,
        families,
    }
    .render()
    .map(|text| text + "\n")
    .map_err(EmitError::from)
}
