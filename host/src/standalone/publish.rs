//! Publishing a crate: decided before anything is fitted ([`plan`]), carried out once the new crate is
//! written ([`Plan::replace`]).
//!
//! **The crate's folder is the one `--out` leads to**: a symbolic link given as `--out` (or met on the
//! way) is followed, so that the crate the user's build reads is the one replaced and the link stays
//! a link.
//!
//! **Whole (the swap), wherever it can work**: a kill at any instant of `gen --spec` leaves, at the
//! crate's path, either the old crate or the new one, never a mix (new tables with an old observer, a
//! README of one run and a report of another).
//!
//! 1. The new crate is written into a staging folder beside it, `<parent>/.gen-<name>.<pid>`, which
//!    nothing else reads: a kill while it is written leaves the old crate untouched (and the stage,
//!    which the next run removes once its process is gone; a run that fails removes its own).
//! 2. What the old folder holds that is not the tool's is carried into the stage as hard links (a copy
//!    where a link is refused): the user's `target/`, `.git/`, notes. The tool's own files of the old
//!    crate (listed in its [`super::owned::LIST`] with an unchanged hash) are not: the new crate
//!    replaces them, figures it no longer draws included.
//! 3. One rename publishes the stage. On Linux `renameat2(RENAME_EXCHANGE)` swaps the stage and the
//!    crate atomically; a crate that did not exist is renamed into place. Elsewhere (or where the file
//!    system has no exchange) the old crate is first renamed aside (the one instant a kill leaves no
//!    crate at the path; the aside folder holds it whole).
//! 4. The stage, which now holds the old crate, is removed.
//!
//! The folder is a new one afterwards: a shell whose working directory is inside it sees the old
//! folder until it changes directory again (`gen` says so when its own working directory is there).
//!
//! **File by file, where a swap cannot work**: a folder that is a mount point (a Docker volume, a
//! tmpfs, a shared folder) cannot be renamed, and one whose parent the user may not write has no room
//! for a stage beside it. There the stage is made inside the crate's folder, `<folder>/.gen-<name>.<pid>`,
//! and each file moves into place by its own rename: **every file is whole, the old one or the new
//! one, but a kill during the moves (a few milliseconds) can leave a crate whose files come from two
//! runs**; the list of the tool's files then names both contents of each, so the next `gen` replaces
//! them all. Files of the old crate that the new one no longer has are removed, then the new list moves
//! in last. `gen` says when a crate was published this way.
//!
//! Where neither can work (the folder cannot be created or written), `gen` refuses before fitting,
//! naming the folder and the fix.
//!
//! `GEN_STOP_AFTER_RENAME=k` (for tests) ends the process, as a kill would, right after the `k`-th
//! rename that publishes (`0`: before the first, with the stage complete); renames inside a stage are
//! not counted, since nothing outside reads it.

mod folder;

use std::path::{Path, PathBuf};

use crate::generate::GenerateError;
use folder::{is_mount_point, probe, resolve};

/// The prefix of a staging folder's name, before the crate folder's name.
const STAGE: &str = ".gen-";

/// An I/O error at `path` as `gen`'s error.
fn io(path: &Path) -> impl FnOnce(std::io::Error) -> GenerateError {
    let path = path.to_owned();
    move |source| GenerateError::Io { path, source }
}

/// How a crate will be published, decided by [`plan`] before anything is fitted.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Publication {
    /// Written beside the folder and swapped in whole.
    Swap,
    /// Written inside the folder and moved into place file by file (the folder is a mount point,
    /// or its parent cannot be written).
    InPlace {
        /// Why the swap cannot work there.
        why: String,
    },
}

/// Where and how one crate is published.
#[derive(Clone, Debug)]
pub struct Plan {
    /// The crate's folder, every symbolic link followed.
    folder: PathBuf,
    /// Its parent and name.
    parent: PathBuf,
    name: String,
    /// How.
    publication: Publication,
}

/// Decides, before anything is fitted, how the crate at `folder` (`--out`, or a design's folder in
/// it) will be published: follows links, then tries the parent (for a stage beside the folder) and,
/// where that cannot work, the folder itself. Creates nothing that stays: the folder's missing
/// parents are created (the crate goes there anyway), the probe stages are removed at once.
pub fn plan(folder: &Path) -> Result<Plan, GenerateError> {
    let folder = resolve(folder).map_err(io(folder))?;
    let (parent, name) = match (folder.parent(), folder.file_name()) {
        (Some(parent), Some(name)) => (parent.to_owned(), name.to_string_lossy().into_owned()),
        _ => {
            return Err(GenerateError::CannotPublish {
                folder,
                why: "a crate cannot be the root folder".to_owned(),
                fix: "choose a folder with a parent (--out)",
            })
        }
    };
    if folder.exists() && !folder.is_dir() {
        return Err(GenerateError::NotAFolder { path: folder });
    }
    std::fs::create_dir_all(&parent).map_err(io(&parent))?;
    let beside = if is_mount_point(&folder) {
        Err("it is a mount point, which cannot be renamed".to_owned())
    } else {
        probe(&parent, &name).map_err(|e| format!("no stage can be made beside it in {} ({e})", parent.display()))
    };
    let publication = match beside {
        Ok(()) => Publication::Swap,
        Err(why) => {
            let inside = std::fs::create_dir_all(&folder).and_then(|()| probe(&folder, &name));
            if let Err(e) = inside {
                return Err(GenerateError::CannotPublish {
                    folder,
                    why: format!("{why}, and none inside it either ({e})"),
                    fix: "choose a folder you may write (--out), or make this one writable",
                });
            }
            Publication::InPlace { why }
        }
    };
    Ok(Plan {
        folder,
        parent,
        name,
        publication,
    })
}

impl Plan {
    /// The crate's folder, links followed.
    pub fn folder(&self) -> &Path {
        &self.folder
    }

    /// How the crate will be published.
    pub fn publication(&self) -> &Publication {
        &self.publication
    }

    /// Writes the crate: `build` writes the new crate into the staging folder it is given, then the
    /// stage replaces the folder (see the module's documentation). A failure at any step removes the
    /// stage.
    pub fn replace<T>(&self, build: impl FnOnce(&Path) -> Result<T, GenerateError>) -> Result<T, GenerateError> {
        let home = match self.publication {
            Publication::Swap => &self.parent,
            Publication::InPlace { .. } => &self.folder,
        };
        std::fs::create_dir_all(home).map_err(io(home))?;
        remove_dead_stages(&self.parent, &self.name);
        remove_dead_stages(&self.folder, &self.name);
        let stage = home.join(format!("{STAGE}{}.{}", self.name, std::process::id()));
        if stage.exists() {
            std::fs::remove_dir_all(&stage).map_err(io(&stage))?;
        }
        std::fs::create_dir(&stage).map_err(io(&stage))?;
        let published = (|| {
            let built = build(&stage)?;
            match self.publication {
                Publication::Swap => self.swap_in(&stage)?,
                Publication::InPlace { .. } => self.move_in(&stage).map_err(io(&self.folder))?,
            }
            Ok(built)
        })();
        // Gone whatever happened: after a swap it holds the old crate; after a failure, half a new one.
        let _ = std::fs::remove_dir_all(&stage);
        crate::output::sync_folder(home);
        published
    }

    /// Publishes the complete stage beside the folder by one rename (steps 2 to 3).
    fn swap_in(&self, stage: &Path) -> Result<(), GenerateError> {
        let folder = &self.folder;
        if folder.is_dir() {
            carry(folder, stage).map_err(io(folder))?;
            if let Ok(metadata) = std::fs::metadata(folder) {
                let _ = std::fs::set_permissions(stage, metadata.permissions());
            }
        }
        crate::output::sync_folder(stage);
        let mut renames = Renames::from_env();
        renames.checkpoint();
        if folder.exists() {
            swap(stage, folder, &mut renames).map_err(io(folder))
        } else {
            std::fs::rename(stage, folder).map_err(io(folder))?;
            renames.done();
            Ok(())
        }
    }

    /// Moves the complete stage inside the folder into place, file by file (see the module's
    /// documentation): the merged list first, then each file, then the old files the new crate no
    /// longer has are removed, and the new list moves in last.
    fn move_in(&self, stage: &Path) -> std::io::Result<()> {
        let folder = &self.folder;
        let list = Path::new(super::owned::LIST);
        let old = super::owned::Owned::read(folder)?;
        let new = super::owned::Owned::read(stage)?;
        old.clone().merged(&new).write(folder)?;
        crate::output::sync_folder(stage);
        let mut renames = Renames::from_env();
        renames.checkpoint();
        for relative in files_under(stage)? {
            if relative == list {
                continue;
            }
            let to = folder.join(&relative);
            if let Some(parent) = to.parent() {
                std::fs::create_dir_all(parent)?;
            }
            std::fs::rename(stage.join(&relative), &to)?;
            renames.done();
        }
        for relative in old.paths().filter(|p| !new.lists(p)) {
            // Only what is still the tool's, as the old list says.
            if old.may_replace(folder, relative).is_ok() {
                let _ = std::fs::remove_file(folder.join(relative));
            }
        }
        std::fs::rename(stage.join(list), folder.join(list))?;
        renames.done();
        crate::output::sync_folder(folder);
        Ok(())
    }
}

/// Whether the current directory is inside `folder` (whose inode a swap has changed).
pub fn holds_current_directory(folder: &Path) -> bool {
    let (Ok(here), Ok(folder)) = (std::env::current_dir(), folder.canonicalize()) else {
        return false;
    };
    here.canonicalize().is_ok_and(|here| here.starts_with(&folder))
}

/// Every file (and symbolic link) under `folder`, relative to it.
fn files_under(folder: &Path) -> std::io::Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let mut pending = vec![PathBuf::new()];
    while let Some(relative) = pending.pop() {
        for entry in std::fs::read_dir(folder.join(&relative))? {
            let entry = entry?;
            let relative = relative.join(entry.file_name());
            if entry.file_type()?.is_dir() {
                pending.push(relative);
            } else {
                files.push(relative);
            }
        }
    }
    files.sort();
    Ok(files)
}

/// Removes the stages of `name` in `home` left by processes that are gone (a live process's stage is
/// its own).
fn remove_dead_stages(home: &Path, name: &str) {
    let Ok(entries) = std::fs::read_dir(home) else { return };
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
/// copied as links. Stages of other runs inside the folder are not carried.
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
                // Another run's stage inside the folder (published file by file) is not the user's.
                let stage_of = format!("{STAGE}{}.", folder.file_name().unwrap_or_default().to_string_lossy());
                if relative.parent() == Some(Path::new(""))
                    && entry.file_name().to_string_lossy().starts_with(&stage_of)
                {
                    continue;
                }
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

/// Swaps `stage` and `folder`: one atomic exchange on Linux, where the file system has it.
#[cfg(target_os = "linux")]
fn swap(stage: &Path, folder: &Path, renames: &mut Renames) -> std::io::Result<()> {
    use rustix::fs::{renameat_with, RenameFlags, CWD};
    match renameat_with(CWD, stage, CWD, folder, RenameFlags::EXCHANGE) {
        Ok(()) => {
            renames.done();
            Ok(())
        }
        // No exchange on this file system (EINVAL): the two renames below.
        Err(rustix::io::Errno::INVAL) => swap_aside(stage, folder, renames),
        Err(e) => Err(e.into()),
    }
}

/// Swaps `stage` and `folder` by renames (no atomic exchange here).
#[cfg(not(target_os = "linux"))]
fn swap(stage: &Path, folder: &Path, renames: &mut Renames) -> std::io::Result<()> {
    swap_aside(stage, folder, renames)
}

/// Swaps `stage` and `folder`: the old crate aside, then the new one in its place.
fn swap_aside(stage: &Path, folder: &Path, renames: &mut Renames) -> std::io::Result<()> {
    let mut aside = stage.as_os_str().to_owned();
    aside.push(".old");
    let aside = PathBuf::from(aside);
    std::fs::rename(folder, &aside)?;
    renames.done();
    if let Err(e) = std::fs::rename(stage, folder) {
        // The old crate back in its place.
        let _ = std::fs::rename(&aside, folder);
        return Err(e);
    }
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
    use super::folder::unescape_mount_point;
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

        let value = plan(&folder)
            .unwrap()
            .replace(|stage| {
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
        let failed: Result<(), _> = plan(&folder).unwrap().replace(|stage| {
            std::fs::write(stage.join("README.md"), "half").unwrap();
            Err(GenerateError::Failed { failed: 1, total: 1 })
        });
        assert!(failed.is_err());
        assert_eq!(std::fs::read_to_string(folder.join("README.md")).unwrap(), "old");
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        // A stage of a process that is gone is removed by the next run; a new folder is created.
        let dead = dir.join(format!("{STAGE}fresh.4194305"));
        std::fs::create_dir_all(&dead).unwrap();
        plan(&dir.join("fresh"))
            .unwrap()
            .replace(|stage| {
                std::fs::write(stage.join("a"), "a").unwrap();
                Ok(())
            })
            .unwrap();
        assert!(!dead.exists());
        assert_eq!(std::fs::read_to_string(dir.join("fresh/a")).unwrap(), "a");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// Writes a crate of one file `README.md` holding `text` and records it as the tool's.
    fn publish_readme(folder: &Path, text: &str) -> Publication {
        let plan = plan(folder).unwrap();
        plan.replace(|stage| {
            std::fs::write(stage.join("README.md"), text).unwrap();
            super::super::owned::Owned::default()
                .record(stage, &[PathBuf::from("README.md")])
                .unwrap();
            Ok(())
        })
        .unwrap();
        plan.publication().clone()
    }

    #[test]
    fn a_link_given_as_the_folder_is_followed_and_stays_a_link() {
        let dir = scratch("link");
        let real = dir.join("firmware/observer");
        std::fs::create_dir_all(&real).unwrap();
        std::fs::write(real.join("notes.txt"), "the user's").unwrap();
        assert_eq!(publish_readme(&real, "a"), Publication::Swap);
        // `link` -> firmware/observer, relative, as `ln -s` makes it; and a link on the way.
        std::os::unix::fs::symlink("firmware/observer", dir.join("link")).unwrap();
        std::os::unix::fs::symlink("firmware", dir.join("way")).unwrap();
        publish_readme(&dir.join("link"), "b");
        assert!(dir.join("link").symlink_metadata().unwrap().file_type().is_symlink());
        assert_eq!(std::fs::read_to_string(real.join("README.md")).unwrap(), "b");
        publish_readme(&dir.join("way/observer"), "c");
        assert!(dir.join("way").symlink_metadata().unwrap().file_type().is_symlink());
        assert_eq!(std::fs::read_to_string(real.join("README.md")).unwrap(), "c");
        assert_eq!(std::fs::read_to_string(real.join("notes.txt")).unwrap(), "the user's");
        // A link to a folder not made yet: the crate is made where it points.
        std::os::unix::fs::symlink(dir.join("later"), dir.join("dangling")).unwrap();
        publish_readme(&dir.join("dangling"), "d");
        assert!(dir
            .join("dangling")
            .symlink_metadata()
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read_to_string(dir.join("later/README.md")).unwrap(), "d");
        // No stage anywhere.
        for folder in [&dir, &dir.join("firmware")] {
            for entry in std::fs::read_dir(folder).unwrap().flatten() {
                assert!(!entry.file_name().to_string_lossy().starts_with(STAGE), "{entry:?}");
            }
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn mount_points_are_read_from_the_kernels_escaped_table() {
        assert_eq!(unescape_mount_point("/mnt/my\\040disk"), "/mnt/my disk");
        assert_eq!(unescape_mount_point("/a\\134b"), "/a\\b");
        assert_eq!(unescape_mount_point("/plain"), "/plain");
        // The root of this process's file system is one; a fresh folder in the temporary one is not.
        if Path::new("/proc/self/mountinfo").exists() {
            assert!(is_mount_point(Path::new("/")));
            let dir = scratch("not-a-mount");
            assert!(!is_mount_point(&dir));
            std::fs::remove_dir_all(&dir).unwrap();
        }
    }

    #[test]
    fn in_place_the_files_move_one_by_one_and_the_old_tool_files_go() {
        let dir = scratch("in-place");
        let folder = dir.join("crate");
        std::fs::create_dir_all(folder.join("report")).unwrap();
        std::fs::write(folder.join("report/old.svg"), "old figure").unwrap();
        std::fs::write(folder.join("README.md"), "old").unwrap();
        std::fs::write(folder.join("notes.txt"), "the user's").unwrap();
        super::super::owned::Owned::default()
            .record(&folder, &[PathBuf::from("README.md"), PathBuf::from("report/old.svg")])
            .unwrap();
        let plan = Plan {
            folder: folder.clone(),
            parent: dir.clone(),
            name: "crate".to_owned(),
            publication: Publication::InPlace {
                why: "a test".to_owned(),
            },
        };
        let inode = |p: &Path| std::os::unix::fs::MetadataExt::ino(&std::fs::metadata(p).unwrap());
        let folder_inode = inode(&folder);
        plan.replace(|stage| {
            assert!(stage.starts_with(&folder));
            std::fs::create_dir_all(stage.join("src")).unwrap();
            std::fs::write(stage.join("README.md"), "new").unwrap();
            std::fs::write(stage.join("src/lib.rs"), "lib").unwrap();
            let written = [PathBuf::from("README.md"), PathBuf::from("src/lib.rs")];
            super::super::owned::Owned::default().record(stage, &written).unwrap();
            Ok(())
        })
        .unwrap();
        assert_eq!(inode(&folder), folder_inode, "the folder itself is kept");
        assert_eq!(std::fs::read_to_string(folder.join("README.md")).unwrap(), "new");
        assert_eq!(std::fs::read_to_string(folder.join("src/lib.rs")).unwrap(), "lib");
        assert_eq!(std::fs::read_to_string(folder.join("notes.txt")).unwrap(), "the user's");
        assert!(!folder.join("report/old.svg").exists());
        let list = super::super::owned::Owned::read(&folder).unwrap();
        let listed: Vec<_> = list.paths().map(Path::to_owned).collect();
        assert_eq!(listed, [PathBuf::from("README.md"), PathBuf::from("src/lib.rs")]);
        let names: Vec<_> = std::fs::read_dir(&folder)
            .unwrap()
            .flatten()
            .map(|e| e.file_name())
            .collect();
        assert!(
            !names.iter().any(|n| n.to_string_lossy().starts_with(".gen-crate.")),
            "{names:?}"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_failure_while_swapping_leaves_no_stage() {
        // A swap across two file systems fails (EXDEV) as one on a mount point does (EBUSY): a plan
        // whose stage is made on another file system than the folder's stands in for that.
        use std::os::unix::fs::MetadataExt;
        let dir = scratch("swap-fails");
        let elsewhere = Path::new("/dev/shm").join(format!("host-publish-{}", std::process::id()));
        std::fs::create_dir_all(&elsewhere).unwrap();
        let device = |p: &Path| std::fs::metadata(p).unwrap().dev();
        if device(&elsewhere) == device(&dir) {
            eprintln!("skipped: /dev/shm is on the file system of {}", dir.display());
            return;
        }
        let folder = dir.join("crate");
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::write(folder.join("README.md"), "old").unwrap();
        let plan = Plan {
            folder: folder.clone(),
            parent: elsewhere.clone(),
            name: "crate".to_owned(),
            publication: Publication::Swap,
        };
        let failed = plan.replace(|stage| {
            std::fs::write(stage.join("README.md"), "new").unwrap();
            Ok(())
        });
        assert!(failed.is_err());
        assert_eq!(std::fs::read_to_string(folder.join("README.md")).unwrap(), "old");
        assert_eq!(std::fs::read_dir(&elsewhere).unwrap().count(), 0, "a stage was left");
        std::fs::remove_dir_all(&elsewhere).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
