//! What `gen --spec` may replace in a crate folder: the files it wrote itself, unchanged since.
//!
//! A crate folder may be anywhere a user points `--out`, their own project's folder included. Every
//! crate `gen` writes lists the files it wrote in [`LIST`] (written last): one line per file,
//! `<SHA-256 of its content>  <path relative to the crate>`, as `sha256sum` prints them (a path may be
//! listed twice, with the old and the new content, while a crate is published file by file:
//! [`super::publish`]). Before
//! anything is fitted or written, every file the run would replace must be listed there with the hash
//! of what it holds now; a file that is not (the user's own, or one of ours the user edited) stops the
//! run, naming the file and the fix, unless `--force` says to replace it anyway.
//!
//! Which files a run replaces: the crate's fixed files ([`fixed_files`]) and every file in its
//! `report/` folder (the report's texts, tables and figures, whose names depend on the design: the
//! folder is the tool's as a whole).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

pub use crate::generate::NotOurs;
use crate::output::sha256_hex as sha256;

/// The list's file name in a crate folder.
pub const LIST: &str = ".gen-files";

/// The report's folder in a crate.
pub const REPORT: &str = "report";

/// The files `gen` wrote in a crate folder, by path relative to it, with their content's SHA-256
/// (one, or two while a crate is published file by file).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Owned(BTreeMap<PathBuf, BTreeSet<String>>);

impl Owned {
    /// The list in `folder` (empty when there is none).
    pub fn read(folder: &Path) -> std::io::Result<Self> {
        let text = match std::fs::read_to_string(folder.join(LIST)) {
            Ok(text) => text,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Owned::default()),
            Err(e) => return Err(e),
        };
        let mut owned = Owned::default();
        for (hash, path) in text.lines().filter_map(|line| line.split_once("  ")) {
            owned.0.entry(PathBuf::from(path)).or_default().insert(hash.to_owned());
        }
        Ok(owned)
    }

    /// The files listed, relative to the crate.
    pub fn paths(&self) -> impl Iterator<Item = &Path> {
        self.0.keys().map(PathBuf::as_path)
    }

    /// Whether `relative` is listed.
    pub fn lists(&self, relative: &Path) -> bool {
        self.0.contains_key(relative)
    }

    /// Both lists in one: every file with every content either gives it.
    pub fn merged(mut self, other: &Owned) -> Owned {
        for (path, hashes) in &other.0 {
            self.0.entry(path.clone()).or_default().extend(hashes.iter().cloned());
        }
        self
    }

    /// Writes the list into `folder` (atomically).
    pub fn write(&self, folder: &Path) -> std::io::Result<()> {
        let text: String = self
            .0
            .iter()
            .flat_map(|(path, hashes)| {
                hashes
                    .iter()
                    .map(move |hash| format!("{hash}  {}\n", path.to_string_lossy()))
            })
            .collect();
        crate::output::write_atomically(&folder.join(LIST), text.as_bytes())
    }

    /// Whether `relative` (in `folder`) may be replaced: it does not exist, or it is listed with the
    /// hash of what it holds now. `Err` says why not.
    pub fn may_replace(&self, folder: &Path, relative: &Path) -> Result<(), NotOurs> {
        let path = folder.join(relative);
        let not_ours = |why| NotOurs {
            path: path.clone(),
            why,
        };
        let Ok(bytes) = std::fs::read(&path) else {
            return if path.symlink_metadata().is_ok() {
                Err(not_ours("it exists and cannot be read as a file"))
            } else {
                Ok(())
            };
        };
        match self.0.get(relative) {
            None => Err(not_ours("it exists and `gen` did not write it")),
            Some(hashes) if !hashes.contains(&sha256(&bytes)) => Err(not_ours("it was changed since `gen` wrote it")),
            Some(_) => Ok(()),
        }
    }

    /// Records `written` (paths relative to `folder`, as they are now on disk) and keeps the entries
    /// of files still there unchanged; writes the list last, atomically.
    pub fn record(mut self, folder: &Path, written: &[PathBuf]) -> std::io::Result<()> {
        self.0.retain(|relative, hashes| {
            let now = std::fs::read(folder.join(relative)).map(|b| sha256(&b));
            hashes.retain(|hash| now.as_ref().is_ok_and(|now| now == hash));
            !hashes.is_empty()
        });
        for relative in written {
            let bytes = std::fs::read(folder.join(relative))?;
            self.0.insert(relative.clone(), BTreeSet::from([sha256(&bytes)]));
        }
        self.write(folder)
    }
}

/// The files every crate of design `name` with `runtime` has besides its report, relative to the crate.
pub fn fixed_files(name: &str, runtime: &super::Runtime) -> Vec<PathBuf> {
    let c = Path::new(super::c_library::FOLDER);
    let embedded = match runtime {
        super::Runtime::Embedded => super::runtime::files().into_iter().map(|(path, _)| path).collect(),
        _ => Vec::new(),
    };
    let mut files = vec![
        PathBuf::from("Cargo.toml"),
        PathBuf::from(crate::emit::STANDALONE_SPEC),
        PathBuf::from("README.md"),
        PathBuf::from("src/lib.rs"),
        PathBuf::from(format!("src/{name}.rs")),
        c.join("Cargo.toml"),
        c.join("src/lib.rs"),
        c.join("include").join(format!("{name}.h")),
        Path::new(super::C_SOURCE_FOLDER).join(format!("{name}.h")),
        Path::new(super::C_SOURCE_FOLDER).join(format!("{name}.c")),
    ];
    files.extend(embedded);
    files
}

/// Checks, before anything is fitted, that writing design `name`'s crate into `folder` replaces no
/// file `gen` did not write there ([`Owned::may_replace`]): its fixed files and every file of its
/// report folder. With `force`, nothing is checked.
pub fn check(
    folder: &Path,
    name: &str,
    runtime: &super::Runtime,
    force: bool,
) -> Result<(), crate::generate::GenerateError> {
    if force {
        return Ok(());
    }
    let owned = Owned::read(folder).map_err(|source| crate::generate::GenerateError::Io {
        path: folder.join(LIST),
        source,
    })?;
    let mut files = fixed_files(name, runtime);
    if let Ok(entries) = std::fs::read_dir(folder.join(REPORT)) {
        let mut report: Vec<PathBuf> = entries
            .flatten()
            .filter(|e| !e.file_name().to_string_lossy().starts_with('.')) // our temporaries
            .map(|e| Path::new(REPORT).join(e.file_name()))
            .collect();
        report.sort();
        files.extend(report);
    }
    for relative in &files {
        owned.may_replace(folder, relative)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_listed_unchanged_files_may_be_replaced() {
        let folder = std::env::temp_dir().join(format!("host-owned-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&folder);
        std::fs::create_dir_all(folder.join("src")).unwrap();
        let (ours, theirs) = (PathBuf::from("src/a.rs"), PathBuf::from("README.md"));
        std::fs::write(folder.join(&ours), "ours").unwrap();
        std::fs::write(folder.join(&theirs), "theirs").unwrap();
        // Nothing recorded: every existing file is the user's; a missing one may be written.
        let none = Owned::read(&folder).unwrap();
        assert!(none.may_replace(&folder, &ours).is_err());
        assert!(none.may_replace(&folder, Path::new("missing.txt")).is_ok());
        Owned::default().record(&folder, std::slice::from_ref(&ours)).unwrap();
        let owned = Owned::read(&folder).unwrap();
        assert!(owned.may_replace(&folder, &ours).is_ok());
        let error = owned.may_replace(&folder, &theirs).unwrap_err().to_string();
        assert!(
            error.contains("README.md") && error.contains("did not write") && error.contains("--force"),
            "{error}"
        );
        // Edited by the user since: no longer ours to replace.
        std::fs::write(folder.join(&ours), "edited").unwrap();
        let error = owned.may_replace(&folder, &ours).unwrap_err().to_string();
        assert!(error.contains("changed since"), "{error}");
        // The list is `sha256sum`'s format: `echo -n ours | sha256sum`.
        let list = std::fs::read_to_string(folder.join(LIST)).unwrap();
        assert_eq!(
            list,
            "ae0bec9e9d33c56354bd612c8a6010840324fc5b9786ce0a18b696b304b09397  src/a.rs\n"
        );
        std::fs::remove_dir_all(&folder).unwrap();
    }
}
