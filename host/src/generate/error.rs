//! Why `gen` failed: one error type for the whole job, in a module of its own so that the parts of
//! the job that fail with it (the standalone crate's file list, [`crate::standalone::owned`]) need not
//! import the job itself; with it the one error of that list ([`NotOurs`]), so that it need not import
//! them either.

use std::path::PathBuf;

use crate::emit::{EmitError, FamilyError};
use crate::report::plots::PlotError;
use crate::spec::SpecError;

/// Why `gen` failed for a design, or as a whole.
#[derive(Debug, thiserror::Error)]
pub enum GenerateError {
    /// The spec is invalid, or its data or fit failed (the message names the spec field to change).
    #[error(transparent)]
    Spec(#[from] SpecError),
    /// `--runtime-path` is not the folder of the `firmware` crate.
    #[error("{}: --runtime-path: {why}\n  fix: pass the folder of the `firmware` runtime crate (the checkout's firmware/), or --runtime-version <version>", path.display())]
    Runtime {
        /// The path given.
        path: PathBuf,
        /// What is wrong.
        why: String,
    },
    /// `gen --spec` would replace a file it did not write (see [`crate::standalone::owned`]).
    #[error(transparent)]
    NotOurs(#[from] NotOurs),
    /// The fitted design cannot be emitted.
    #[error("{}: cannot emit design `{design}`: {source}", file.display())]
    Emit {
        /// The spec.
        file: PathBuf,
        /// The design.
        design: String,
        /// Why.
        source: EmitError,
    },
    /// The family modules of `lib.rs` cannot be emitted.
    #[error(transparent)]
    Family(#[from] FamilyError),
    /// A figure could not be drawn or written.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// cbindgen could not write the C header of a standalone crate's C library.
    #[error("{}: cbindgen could not write the C header: {message}", path.display())]
    Header {
        /// The C library's source it read.
        path: PathBuf,
        /// cbindgen's message.
        message: String,
    },
    /// A file or folder could not be listed, created or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The crate's folder can be neither swapped whole nor written file by file (see
    /// [`crate::standalone::publish`]); said before anything is fitted.
    #[error("{}: cannot publish the crate there: {why}\n  fix: {fix}", folder.display())]
    CannotPublish {
        /// The crate's folder, links followed.
        folder: PathBuf,
        /// What was tried and what the system said.
        why: String,
        /// What to change.
        fix: &'static str,
    },
    /// `--out` (or a design's folder in it) is a file.
    #[error("{}: is a file, not a folder: `gen --spec` writes a crate into the folder --out names\n  fix: choose a folder for --out (a new or empty one)", path.display())]
    NotAFolder {
        /// The file.
        path: PathBuf,
    },
    /// No checkout around the current folder (needed for the defaults: shipped specs, `generated/`).
    #[error("{}: not inside a checkout (no folder upward holds host/specs/ and generated/Cargo.toml); run from the checkout, or give the paths (--spec FILE instead of --design; for gen also --reports and --generated)", from.display())]
    NoWorkspace {
        /// Where the search started.
        from: PathBuf,
    },
    /// No shipped spec names the design asked for.
    #[error("unknown design `{name}`; the shipped designs are: {known}{broken} (or pass --spec FILE)")]
    UnknownDesign {
        /// The name asked for.
        name: String,
        /// The shipped designs that loaded.
        known: String,
        /// The shipped specs that did not load, if any.
        broken: String,
    },
    /// Two specs of one run name the same design.
    #[error("{} and {}: both specs name the design `{name}`: rename one", first.display(), second.display())]
    DuplicateName {
        /// The design name.
        name: String,
        /// One spec.
        first: PathBuf,
        /// The other.
        second: PathBuf,
    },
    /// Two specs of one run name designs whose C names would clash ([`crate::emit::c::c_name_clash`]).
    #[error(
        "{} (`name = \"{first_name}\"`) and {} (`name = \"{second_name}\"`): field `name`: the C interface of one design appends `_{word}…` to its name, which is how the other's begins, so both would declare names such as `{shorter}_{word}_init` and one C program could not hold both; rename one so that neither is the other followed by `_{word}` (e.g. `{suggestion}`)",
        first.display(),
        second.display(),
        word = crate::emit::c::c_name_clash(first_name, second_name).unwrap_or_default(),
        shorter = if first_name.len() <= second_name.len() { first_name } else { second_name },
        suggestion = if first_name.len() <= second_name.len() { second_name.replacen('_', "", 1) } else { first_name.replacen('_', "", 1) }
    )]
    CNameClash {
        /// One design's name.
        first_name: String,
        /// Its spec.
        first: PathBuf,
        /// The other's.
        second_name: String,
        /// Its spec.
        second: PathBuf,
    },
    /// `--strict`: some designs fail quality gates (each was reported); nothing was written.
    #[error("{designs} fail(s) the quality gates above (--strict); nothing was written: change the spec as each warning says, or run without --strict")]
    Gates {
        /// The designs, comma separated.
        designs: String,
    },
    /// Some designs failed (each was reported); nothing was written.
    #[error("{failed} of {total} design(s) failed; nothing was written")]
    Failed {
        /// Designs that failed.
        failed: usize,
        /// Designs asked for.
        total: usize,
    },
}

/// A file the run would replace but did not write (or that changed since).
#[derive(Debug, thiserror::Error)]
#[error(
    "{}: {why}; `gen` would replace it\n  fix: choose another --out folder (an empty or new one), or pass --force to replace it",
    path.display()
)]
pub struct NotOurs {
    /// The file.
    pub path: PathBuf,
    /// Why it is not ours to replace.
    pub why: &'static str,
}
