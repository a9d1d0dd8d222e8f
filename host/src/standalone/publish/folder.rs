//! Where a crate's folder really is, and what can be done there (for [`super::plan`]): every
//! symbolic link on the way followed, mount points told apart (a folder that cannot be renamed), and
//! whether a stage can be made in a folder.

use std::path::{Component, Path, PathBuf};

use super::STAGE;

/// The folder `path` leads to, absolute, with every symbolic link on the way followed (the last
/// component's too, even where its target does not exist yet). A folder that does not exist is its
/// nearest existing ancestor's real path with the rest appended.
pub(super) fn resolve(path: &Path) -> std::io::Result<PathBuf> {
    let mut path = std::path::absolute(path)?;
    for _ in 0..40 {
        match path.symlink_metadata() {
            Ok(metadata) if metadata.file_type().is_symlink() => {
                let target = std::fs::read_link(&path)?;
                // A relative target is relative to the link's folder.
                path = match path.parent() {
                    Some(parent) => parent.join(target),
                    None => target,
                };
            }
            Ok(_) => return path.canonicalize(),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                let Some((parent, name)) = path.parent().zip(path.file_name()) else {
                    return Ok(path);
                };
                if matches!(path.components().next_back(), Some(Component::ParentDir)) {
                    return Ok(path);
                }
                return Ok(resolve(parent)?.join(name));
            }
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::other("too many symbolic links on the way (a loop?)"))
}

/// Whether `folder` is a mount point: on another device than its parent, or (a bind mount, on the
/// same device) listed as one by the kernel (`/proc/self/mountinfo`, where there is one).
pub(super) fn is_mount_point(folder: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let parent = folder.parent().unwrap_or(folder);
        if let (Ok(here), Ok(above)) = (std::fs::metadata(folder), std::fs::metadata(parent)) {
            if here.dev() != above.dev() {
                return true;
            }
        }
    }
    let Ok(table) = std::fs::read_to_string("/proc/self/mountinfo") else {
        return false;
    };
    table
        .lines()
        .filter_map(|line| line.split(' ').nth(4))
        .any(|point| Path::new(&unescape_mount_point(point)) == folder)
}

/// A mount point as `/proc/self/mountinfo` writes it: space, tab, newline and backslash as `\ooo`.
pub(super) fn unescape_mount_point(field: &str) -> String {
    let mut out = String::with_capacity(field.len());
    let mut rest = field;
    while let Some(at) = rest.find('\\') {
        out.push_str(&rest[..at]);
        let code = rest.get(at + 1..at + 4).and_then(|o| u8::from_str_radix(o, 8).ok());
        match code {
            Some(byte) => {
                out.push(char::from(byte));
                rest = &rest[at + 4..];
            }
            None => {
                out.push('\\');
                rest = &rest[at + 1..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// Whether a stage for `name` can be made in `home`: makes one and removes it.
pub(super) fn probe(home: &Path, name: &str) -> std::io::Result<()> {
    let probe = home.join(format!("{STAGE}{name}.{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&probe);
    std::fs::create_dir(&probe)?;
    std::fs::remove_dir(&probe)
}
