//! Publishing a crate whole: a kill at any instant of `gen --spec` leaves, at the crate's path, either
//! the old crate or the new one, never a mix (new tables with an old observer, a README of one run
//! and a report of another).
//!
//! 1. The new crate is written into a staging folder beside it, `<parent>/.<name>.gen-<pid>`, which
//!    nothing else reads: a kill while it is written leaves the old crate untouched (and the stage,
//!    which the next run removes once its process is gone).
//! 2. What the old folder holds that is not the tool's is carried into the stage as hard links (a copy
//!    where a link is refused): the user's `target/`, `.git/`, notes. The tool's own files of the old
//!    crate (listed in its [`super::owned::LIST`] with an unchanged hash) are not: the new crate
//!    replaces them, figures it no longer draws included.
//! 3. One rename publishes the stage. On Linux `renameat2(RENAME_EXCHANGE)` swaps the stage and the
//!    crate atomically; a crate that did not exist is renamed into place. Elsewhere the old crate is
//!    first renamed aside (the one instant a kill leaves no crate at the path; the aside folder holds
//!    it whole).
//! 4. The stage, which now holds the old crate, is removed.
//!
//! The folder is a new one afterwards: a shell whose working directory is inside it sees the old
//! folder until it changes directory again (`gen` says so when its own working directory is there).
//!
//! `GEN_STOP_AFTER_RENAME=k` (for tests) ends the process, as a kill would, right after the `k`-th
//! rename of step 3 (`0`: before the first, with the stage complete); renames inside the stage are not
//! counted, since nothing outside reads it.

use std::path::{Path, PathBuf};

use crate::generate::GenerateError;

/// The prefix of a staging folder's name, before the crate folder's name.
const STAGE: &str = ".gen-";

/// Writes a crate into `folder` as a whole: `build` writes the new crate into the staging folder it is
/// given, then the stage replaces `folder` (see the module's documentation).
pub fn replace<T>(folder: &Path, build: impl FnOnce(&Path) -> Result<T, GenerateError>) -> Result<T, GenerateError> {
    let io = |path: &Path| {
        let path = path.to_owned();
        move |source| GenerateError::Io { path, source }
    };
    let (parent, name) = split(folder).map_err(io(folder))?;
    std::fs::create_dir_all(&parent).map_err(io(&parent))?;
    remove_dead_stages(&parent, &name);
    let stage = parent.join(format!("{STAGE}{name}.{}", std::process::id()));
    if stage.exists() {
        std::fs::remove_dir_all(&stage).map_err(io(&stage))?;
    }
    std::fs::create_dir(&stage).map_err(io(&stage))?;
    let staged = (|| {
        let built = build(&stage)?;
        if folder.is_dir() {
            carry(folder, &stage).map_err(io(folder))?;
            if let Ok(metadata) = std::fs::metadata(folder) {
                let _ = std::fs::set_permissions(&stage, metadata.permissions());
            }
        }
        crate::output::sync_folder(&stage);
        Ok(built)
    })();
    let built = match staged {
        Ok(built) => built,
        Err(e) => {
            let _ = std::fs::remove_dir_all(&stage);
            return Err(e);
        }
    };
    let mut renames = Renames::from_env();
    renames.checkpoint();
    if folder.exists() {
        swap(&stage, folder, &mut renames).map_err(io(folder))?;
        // The stage now holds the old crate.
        std::fs::remove_dir_all(&stage).map_err(io(&stage))?;
    } else {
        std::fs::rename(&stage, folder).map_err(io(folder))?;
        renames.done();
    }
    crate::output::sync_folder(&parent);
    Ok(built)
}

/// Whether the current directory is inside `folder` (whose inode `replace` has changed).
pub fn holds_current_directory(folder: &Path) -> bool {
    let (Ok(here), Ok(folder)) = (std::env::current_dir(), folder.canonicalize()) else {
        return false;
    };
    here.canonicalize().is_ok_and(|here| here.starts_with(&folder))
}

/// The folder's parent and name, from its absolute path (`--out .` has no name of its own).
fn split(folder: &Path) -> std::io::Result<(PathBuf, String)> {
    let absolute = match folder.canonicalize() {
        Ok(path) => path,
        Err(_) => std::path::absolute(folder)?,
    };
    match (absolute.parent(), absolute.file_name()) {
        (Some(parent), Some(name)) => Ok((parent.to_owned(), name.to_string_lossy().into_owned())),
        _ => Err(std::io::Error::other(
            "a crate cannot be the root folder: choose a folder with a parent (--out)",
        )),
    }
}

/// Removes the stages of `name` left by processes that are gone (a live process's stage is its own).
fn remove_dead_stages(parent: &Path, name: &str) {
    let Ok(entries) = std::fs::read_dir(parent) else { return };
    let prefix = format!("{STAGE}{name}.");
    for entry in entries.flatten() {
        let file = entry.file_name().to_string_lossy().into_owned();
        let Some(pid) = file.strip_prefix(&prefix) else {
            continue;
        };
        if pid
            .parse::<u32>()
            .is_ok_and(|pid| !crate::output::process_is_alive(pid))
        {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}

/// Carries into `stage` every entry of the old crate `folder` that is not the tool's and that the new
/// crate (already in `stage`) does not hold: hard links for files, folders recreated, symbolic links
/// copied as links.
fn carry(folder: &Path, stage: &Path) -> std::io::Result<()> {
    let owned = super::owned::Owned::read(folder)?;
    let mut pending = vec![PathBuf::new()];
    while let Some(relative) = pending.pop() {
        for entry in std::fs::read_dir(folder.join(&relative))? {
            let entry = entry?;
            let relative = relative.join(entry.file_name());
            let (from, to) = (folder.join(&relative), stage.join(&relative));
            let kind = entry.file_type()?;
            if kind.is_dir() {
                if !to.exists() {
                    std::fs::create_dir(&to)?;
                    std::fs::set_permissions(&to, std::fs::metadata(&from)?.permissions())?;
                }
                pending.push(relative);
                continue;
            }
            let ours = relative == Path::new(super::owned::LIST)
                || owned.may_replace(folder, &relative).is_ok()
                || crate::output::is_temporary(&entry.file_name().to_string_lossy());
            if ours || to.symlink_metadata().is_ok() {
                continue;
            }
            if kind.is_symlink() {
                link_again(&std::fs::read_link(&from)?, &to)?;
            } else if std::fs::hard_link(&from, &to).is_err() {
                std::fs::copy(&from, &to)?;
            }
        }
    }
    Ok(())
}

#[cfg(unix)]
fn link_again(target: &Path, at: &Path) -> std::io::Result<()> {
    std::os::unix::fs::symlink(target, at)
}

#[cfg(not(unix))]
fn link_again(target: &Path, at: &Path) -> std::io::Result<()> {
    std::fs::copy(target, at).map(|_| ())
}

/// Swaps `stage` and `folder`: one atomic exchange on Linux.
#[cfg(target_os = "linux")]
fn swap(stage: &Path, folder: &Path, renames: &mut Renames) -> std::io::Result<()> {
    use rustix::fs::{renameat_with, RenameFlags, CWD};
    renameat_with(CWD, stage, CWD, folder, RenameFlags::EXCHANGE)?;
    renames.done();
    Ok(())
}

/// Swaps `stage` and `folder`: the old crate aside, then the new one in its place.
#[cfg(not(target_os = "linux"))]
fn swap(stage: &Path, folder: &Path, renames: &mut Renames) -> std::io::Result<()> {
    let mut aside = stage.as_os_str().to_owned();
    aside.push(".old");
    let aside = PathBuf::from(aside);
    std::fs::rename(folder, &aside)?;
    renames.done();
    std::fs::rename(stage, folder)?;
    renames.done();
    std::fs::rename(&aside, stage)
}

/// The publication's renames, counted for `GEN_STOP_AFTER_RENAME`.
struct Renames {
    done: usize,
    stop_after: Option<usize>,
}

impl Renames {
    fn from_env() -> Self {
        Renames {
            done: 0,
            stop_after: std::env::var("GEN_STOP_AFTER_RENAME").ok().and_then(|k| k.parse().ok()),
        }
    }

    /// Ends the process, with no clean-up, as a kill would, when `k` renames are done.
    fn checkpoint(&self) {
        if self.stop_after == Some(self.done) {
            std::process::exit(137);
        }
    }

    fn done(&mut self) {
        self.done += 1;
        self.checkpoint();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("host-publish-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn the_new_crate_replaces_the_tools_files_and_keeps_the_users() {
        let dir = scratch("carry");
        let folder = dir.join("crate");
        std::fs::create_dir_all(folder.join("report")).unwrap();
        std::fs::create_dir_all(folder.join("target/debug")).unwrap();
        std::fs::write(folder.join("README.md"), "old readme").unwrap();
        std::fs::write(folder.join("report/old-figure.svg"), "old figure").unwrap();
        std::fs::write(folder.join("target/debug/build.log"), "the user's build").unwrap();
        std::fs::write(folder.join("notes.txt"), "the user's notes").unwrap();
        let written = [PathBuf::from("README.md"), PathBuf::from("report/old-figure.svg")];
        super::super::owned::Owned::default().record(&folder, &written).unwrap();
        let inode = |p: &Path| std::os::unix::fs::MetadataExt::ino(&std::fs::metadata(p).unwrap());
        let notes_inode = inode(&folder.join("notes.txt"));

        let value = replace(&folder, |stage| {
            assert_ne!(stage, folder);
            std::fs::write(stage.join("README.md"), "new readme").unwrap();
            Ok(7)
        })
        .unwrap();
        assert_eq!(value, 7);
        assert_eq!(std::fs::read_to_string(folder.join("README.md")).unwrap(), "new readme");
        // The old crate's figure was the tool's: gone with the old crate. The user's files are kept,
        // as the same files (hard links), and no stage is left behind.
        assert!(!folder.join("report/old-figure.svg").exists());
        assert_eq!(
            std::fs::read_to_string(folder.join("target/debug/build.log")).unwrap(),
            "the user's build"
        );
        assert_eq!(inode(&folder.join("notes.txt")), notes_inode);
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .flatten()
            .map(|e| e.file_name())
            .collect();
        assert_eq!(left, vec![std::ffi::OsString::from("crate")]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_failed_build_leaves_the_old_crate_and_no_stage() {
        let dir = scratch("failed");
        let folder = dir.join("crate");
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::write(folder.join("README.md"), "old").unwrap();
        let failed: Result<(), _> = replace(&folder, |stage| {
            std::fs::write(stage.join("README.md"), "half").unwrap();
            Err(GenerateError::Failed { failed: 1, total: 1 })
        });
        assert!(failed.is_err());
        assert_eq!(std::fs::read_to_string(folder.join("README.md")).unwrap(), "old");
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        // A stage of a process that is gone is removed by the next run; a new folder is created.
        let dead = dir.join(format!("{STAGE}fresh.4194305"));
        std::fs::create_dir_all(&dead).unwrap();
        replace(&dir.join("fresh"), |stage| {
            std::fs::write(stage.join("a"), "a").unwrap();
            Ok(())
        })
        .unwrap();
        assert!(!dead.exists());
        assert_eq!(std::fs::read_to_string(dir.join("fresh/a")).unwrap(), "a");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
