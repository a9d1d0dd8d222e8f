//! Family modules of `generated/src/lib.rs`: designs that differ only in a known value (e.g. an
//! initial condition) share one observer type, and `observer()` picks the member nearest the first
//! measured value of the selecting output.

use std::path::PathBuf;

use super::{f32_literal, EmitError};
use crate::spec::Design;

/// Why the designs' families cannot be emitted.
#[derive(Debug, thiserror::Error)]
pub enum FamilyError {
    /// A member does not share the observer type of its family.
    #[error("{}: `family`: design `{design}` cannot join family `{family}` of `{first}`: members must share the horizon, outputs, inputs, targets and selecting output", file.display())]
    Mismatch {
        /// The member's spec.
        file: PathBuf,
        /// The member.
        design: String,
        /// The family.
        family: String,
        /// Its first member.
        first: String,
    },
    /// A member's value has no f32 literal.
    #[error("{}: {source}", file.display())]
    Value {
        /// The member's spec.
        file: PathBuf,
        /// Why.
        source: EmitError,
    },
    /// The family's module would shadow a design's.
    #[error("family `{family}` has the name of a design: rename one of them")]
    NameClash {
        /// The family.
        family: String,
    },
}

/// A family module of `lib.rs`: its members, sorted by their value of the selecting output.
#[derive(Clone, Debug, PartialEq)]
pub struct FamilyModule {
    /// Module name.
    pub name: String,
    /// Index of the selecting output.
    pub output: usize,
    /// Its name.
    pub output_name: String,
    /// `(design module, value literal)`, by increasing value.
    pub members: Vec<(String, String)>,
}

/// The family modules of the designs whose files are `present`: members of one family must share
/// the horizon, the outputs, the inputs and the targets (one observer type serves them all).
pub fn families(designs: &[Design], present: &[String]) -> Result<Vec<FamilyModule>, FamilyError> {
    let mut members: Vec<(&Design, &crate::spec::Family)> = designs
        .iter()
        .filter(|d| present.contains(&d.name))
        .filter_map(|d| d.family.as_ref().map(|f| (d, f)))
        .collect();
    members.sort_by(|a, b| a.1.name.cmp(&b.1.name).then(a.1.value.total_cmp(&b.1.value)));
    let outputs = |d: &Design| d.model.outputs.iter().map(|o| o.name.clone()).collect::<Vec<_>>();
    let targets = |d: &Design| d.targets.iter().map(|t| t.name.clone()).collect::<Vec<_>>();
    let mut modules = Vec::new();
    for group in members.chunk_by(|a, b| a.1.name == b.1.name) {
        let (first, family) = group[0];
        let mut module = FamilyModule {
            name: family.name.clone(),
            output: family.output,
            output_name: first.model.outputs[family.output].name.clone(),
            members: Vec::new(),
        };
        for &(design, member) in group {
            let same = first.map.horizon == design.map.horizon
                && outputs(first) == outputs(design)
                && first.model.inputs == design.model.inputs
                && targets(first) == targets(design)
                && member.output == family.output;
            if !same {
                return Err(FamilyError::Mismatch {
                    file: design.file.clone(),
                    design: design.name.clone(),
                    family: family.name.clone(),
                    first: first.name.clone(),
                });
            }
            let value = f32_literal("family.value", member.value).map_err(|source| FamilyError::Value {
                file: design.file.clone(),
                source,
            })?;
            module.members.push((design.name.clone(), value));
        }
        if present.contains(&module.name) {
            return Err(FamilyError::NameClash { family: module.name });
        }
        modules.push(module);
    }
    Ok(modules)
}
