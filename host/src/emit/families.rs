//! Family modules of `generated/src/lib.rs`: designs that differ only in a known value (e.g. an
//! initial condition) share one observer type, and `observer()` picks the member nearest the first
//! measured value of the selecting output.

use std::path::{Path, PathBuf};

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

/// A design's place in a family, as its spec gives it ([`Member::of`]) or as its emitted file declares
/// it ([`Member::declared`]): what `lib.rs` needs to group the members and to check that one observer
/// type serves them all. A design file declares it so that regenerating one member of a family keeps
/// the members whose specs are not in the run.
#[derive(Clone, Debug, PartialEq)]
pub struct Member {
    /// The design (its module).
    pub design: String,
    /// The family (its module).
    pub family: String,
    /// Index of the selecting output.
    pub output: usize,
    /// This member's value of it, as the `f32` literal `lib.rs` holds.
    pub value: String,
    /// The horizon `N`.
    pub horizon: usize,
    /// Output names.
    pub outputs: Vec<String>,
    /// Input names.
    pub inputs: Vec<String>,
    /// Target names.
    pub targets: Vec<String>,
    /// Its spec, or its design file: what an error names.
    pub file: PathBuf,
}

impl Member {
    /// The member a design's spec makes it (`None` outside a family).
    pub fn of(design: &Design) -> Result<Option<Member>, EmitError> {
        let Some(family) = &design.family else {
            return Ok(None);
        };
        let value = f32_literal("family.value", family.value)?;
        Ok(Some(Member {
            design: design.name.clone(),
            family: family.name.clone(),
            output: family.output,
            value,
            horizon: design.map.horizon,
            outputs: design.model.outputs.iter().map(|o| o.name.clone()).collect(),
            inputs: design.model.inputs.clone(),
            targets: design.targets.iter().map(|t| t.name.clone()).collect(),
            file: design.file.clone(),
        }))
    }

    /// The `FAMILY` constant of the member's design file (a line of its own after the unit constants).
    pub fn declaration(&self) -> String {
        format!(
            "/// Member of family `{family}`: `{family}::observer()` in `lib.rs` runs the member whose value of output\n\
             /// `{output}` is nearest its first measured value; this one's is {value}. (`gen` reads this line when it\n\
             /// rebuilds `lib.rs`, so that regenerating one member keeps the others.)\n\
             pub const FAMILY: (&str, usize, f32) = (\"{family}\", {index}, {value});\n",
            family = self.family,
            output = self.outputs[self.output],
            index = self.output,
            value = self.value,
        )
    }

    /// The member design file `source` (at `file`, module `design`) declares, read from its
    /// `FAMILY`, `HORIZON` and name constants; `None` when it declares none (or not legibly: a file
    /// `gen` did not write, or wrote before members declared their family).
    pub fn declared(design: &str, source: &str, file: &Path) -> Option<Member> {
        let constant = |name: &str| {
            source
                .lines()
                .find_map(|line| line.strip_prefix(&format!("pub const {name}: ")))
                .and_then(|rest| rest.split_once(" = "))
                .and_then(|(_, value)| value.strip_suffix(';'))
        };
        let names = |name: &str| -> Option<Vec<String>> {
            let list = constant(name)?.strip_prefix('[')?.strip_suffix(']')?;
            list.split(", ")
                .filter(|item| !item.is_empty())
                .map(|item| Some(item.strip_prefix('"')?.strip_suffix('"')?.to_owned()))
                .collect()
        };
        let tuple = constant("FAMILY")?.strip_prefix('(')?.strip_suffix(')')?;
        let mut parts = tuple.split(", ");
        let family = parts.next()?.strip_prefix('"')?.strip_suffix('"')?.to_owned();
        let output = parts.next()?.parse().ok()?;
        let value = parts.next()?.to_owned();
        value.parse::<f32>().ok()?;
        let outputs = names("OUTPUT_NAMES")?;
        (output < outputs.len()).then_some(Member {
            design: design.to_owned(),
            family,
            output,
            value,
            horizon: constant("HORIZON")?.parse().ok()?,
            outputs,
            inputs: names("INPUT_NAMES")?,
            targets: names("TARGET_NAMES")?,
            file: file.to_owned(),
        })
    }
}

/// The family modules of the `members` whose design files are `present`: members of one family must
/// share the horizon, the outputs, the inputs, the targets and the selecting output (one observer type
/// serves them all).
pub fn families(members: &[Member], present: &[String]) -> Result<Vec<FamilyModule>, FamilyError> {
    let mut members: Vec<&Member> = members.iter().filter(|m| present.contains(&m.design)).collect();
    let value = |m: &Member| m.value.parse::<f32>().unwrap_or(f32::NAN);
    members.sort_by(|a, b| a.family.cmp(&b.family).then(value(a).total_cmp(&value(b))));
    let mut modules = Vec::new();
    for group in members.chunk_by(|a, b| a.family == b.family) {
        let first = group[0];
        let mut module = FamilyModule {
            name: first.family.clone(),
            output: first.output,
            output_name: first.outputs[first.output].clone(),
            members: Vec::new(),
        };
        for member in group {
            let same = first.horizon == member.horizon
                && first.outputs == member.outputs
                && first.inputs == member.inputs
                && first.targets == member.targets
                && first.output == member.output;
            if !same {
                return Err(FamilyError::Mismatch {
                    file: member.file.clone(),
                    design: member.design.clone(),
                    family: module.name.clone(),
                    first: first.design.clone(),
                });
            }
            module.members.push((member.design.clone(), member.value.clone()));
        }
        if present.contains(&module.name) {
            return Err(FamilyError::NameClash { family: module.name });
        }
        modules.push(module);
    }
    Ok(modules)
}
