//! Every error the spec validator can return, reached from TOML text by one table.
//!
//! PLACEHOLDER: summary written after the run.

use std::collections::HashSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use host::spec::{self, SpecError};

const VANDERPOL: &str = include_str!("../specs/vanderpol.toml");
const ECOLI_X0_0P5: &str = include_str!("../specs/ecoli_x0_0p5.toml");
const ECOLI_X0_2: &str = include_str!("../specs/ecoli_x0_2.toml");

/// The shipped spec a case edits.
#[derive(Clone, Copy, Debug)]
enum Base {
    Vdp,
    E05,
    E2,
    /// No text: `spec::load` of a path that does not exist.
    NoFile,
}

impl Base {
    fn text(self) -> &'static str {
        match self {
            Base::Vdp => VANDERPOL,
            Base::E05 => ECOLI_X0_0P5,
            Base::E2 => ECOLI_X0_2,
            Base::NoFile => "",
        }
    }
}

/// One edit of the base text.
enum Edit {
    /// Replace the only occurrence of the first string by the second.
    Swap(&'static str, &'static str),
    /// Append text at the end of the file.
    Append(&'static str),
}

/// The field the error must name.
enum Field {
    Exact(&'static str),
    Prefix(&'static str),
}

struct Case {
    /// Unique; also the file name the spec is parsed as (`<name>.toml`).
    name: &'static str,
    base: Base,
    edits: &'static [Edit],
    field: Field,
    /// A substring the fix must contain.
    fix: &'static str,
}

use Base::*;
use Edit::*;
use Field::*;

const fn case(name: &'static str, base: Base, edits: &'static [Edit], field: Field, fix: &'static str) -> Case {
    Case {
        name,
        base,
        edits,
        field,
        fix,
    }
}

#[rustfmt::skip]
const CASES: &[Case] = &[
    case("scratch", Vdp, &[Swap("tau = 0.1", "tau = 0.0")], Exact("sampling.tau"), "positive"),
];

/// Applies the case's edits; each find-string must occur exactly once in the text it edits.
fn edited(case: &Case) -> Result<String, String> {
    let mut text = case.base.text().to_owned();
    for edit in case.edits {
        match *edit {
            Swap(find, with) => {
                let count = text.matches(find).count();
                if count != 1 {
                    return Err(format!(
                        "the edit's find-string {find:?} occurs {count} times (must be once)"
                    ));
                }
                if find == with {
                    return Err(format!("the edit of {find:?} changes nothing"));
                }
                text = text.replacen(find, with, 1);
            }
            Append(more) => text.push_str(more),
        }
    }
    Ok(text)
}

/// `Ok` when the case's spec is refused with the expected field and fix, else what went wrong.
fn check(case: &Case) -> Result<(), String> {
    let (path, result) = match case.base {
        NoFile => {
            let path = std::env::temp_dir()
                .join(format!("host-spec-errors-{}", std::process::id()))
                .join(format!("{}.toml", case.name));
            let result = catch_unwind(AssertUnwindSafe(|| spec::load(&path)));
            (path, result)
        }
        _ => {
            let text = edited(case)?;
            let path = PathBuf::from(format!("{}.toml", case.name));
            let result = catch_unwind(AssertUnwindSafe(|| spec::parse(&path, &text)));
            (path, result)
        }
    };
    let error: SpecError = match result {
        Err(_) => return Err("the validator panicked".into()),
        Ok(Ok(_)) => return Err("the spec was accepted".into()),
        Ok(Err(e)) => e,
    };
    let message = error.to_string();
    let file = path.display().to_string();
    let (field_ok, wanted) = match case.field {
        Exact(f) => (error.field == f, format!("field {f:?}")),
        Prefix(f) => (error.field.starts_with(f), format!("a field starting with {f:?}")),
    };
    let mut problems = Vec::new();
    if !field_ok {
        problems.push(format!("names field {:?}, expected {wanted}", error.field));
    }
    if error.file != file || !message.contains(&file) {
        problems.push(format!("does not name the file {file:?}"));
    }
    if !message.contains(&format!("`{}`", error.field)) {
        problems.push("the message does not name the field".into());
    }
    if !message.contains("fix:") || error.fix.trim().is_empty() || error.problem.trim().is_empty() {
        problems.push("the message has an empty problem or no fix".into());
    }
    if !error.fix.contains(case.fix) {
        problems.push(format!("the fix does not mention {:?}", case.fix));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "{}\n      message: {}",
            problems.join("; "),
            message.replace('\n', "\n      ")
        ))
    }
}

#[test]
fn every_validator_error_names_its_field_and_a_fix() {
    let mut names = HashSet::new();
    let mut failures = Vec::new();
    for case in CASES {
        assert!(names.insert(case.name), "two cases are named {:?}", case.name);
        if let Err(why) = check(case) {
            failures.push(format!("  {} ({:?}): {why}", case.name, case.base));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        CASES.len(),
        failures.join("\n")
    );
}

#[test]
fn the_shipped_specs_are_valid() {
    for (name, text) in [
        ("vanderpol.toml", VANDERPOL),
        ("ecoli_x0_0p5.toml", ECOLI_X0_0P5),
        ("ecoli_x0_2.toml", ECOLI_X0_2),
    ] {
        if let Err(e) = spec::parse(Path::new(name), text) {
            panic!("the base of the table must be valid: {e}");
        }
    }
    // Every spec shipped in host/specs, so a new one joins the check.
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("specs");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            count += 1;
            if let Err(e) = spec::load(&path) {
                panic!("{e}");
            }
        }
    }
    assert!(count >= 3, "{count} specs in {}", dir.display());
}
