//! Writing output files so that a failure never leaves a half-written one behind.

pub mod format;

use std::io::Write;
use std::path::{Path, PathBuf};

pub use format::{number, sha256_hex};

/// Writes `bytes` to a temporary file beside `path`, syncs it to disk, then renames it over `path` (and
/// syncs the folder): a reader never sees a half-written file, a crash leaves the previous one in
/// place, and temporaries left by an interrupted earlier run are removed.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_atomically_with(path, |out| out.write_all(bytes))
}

/// [`write_atomically`] for text produced piece by piece: `write` writes into a buffered temporary
/// file, which replaces `path` only if `write` succeeded.
pub fn write_atomically_with<E: From<std::io::Error>>(
    path: &Path,
    write: impl FnOnce(&mut std::io::BufWriter<std::fs::File>) -> Result<(), E>,
) -> Result<(), E> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let folder = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    remove_stale_temporaries(folder, &format!("{name}.tmp"), "");
    let mut temporary = path.as_os_str().to_owned();
    temporary.push(format!(".tmp{}", std::process::id()));
    let temporary = PathBuf::from(temporary);
    let written = (|| -> Result<(), E> {
        let mut out = std::io::BufWriter::new(std::fs::File::create(&temporary)?);
        write(&mut out)?;
        let file = out.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        std::fs::rename(&temporary, path)?;
        Ok(())
    })();
    if written.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    written?;
    sync_folder(folder);
    Ok(())
}

/// Makes the renames in `folder` durable (best effort: not every platform can sync a folder).
pub fn sync_folder(folder: &Path) {
    if let Ok(dir) = std::fs::File::open(folder) {
        let _ = dir.sync_all();
    }
}

/// Removes the files of `folder` named `<prefix><pid><suffix>`: temporaries this tool names after its
/// process id, left behind when a run was killed. A live process's temporaries are its own (two `gen`
/// into one folder): only those of processes that are gone are removed.
pub fn remove_stale_temporaries(folder: &Path, prefix: &str, suffix: &str) {
    let Ok(entries) = std::fs::read_dir(folder) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let is_stale = name
            .strip_prefix(prefix)
            .and_then(|rest| rest.strip_suffix(suffix))
            .and_then(pid)
            .is_some_and(|pid| !process_is_alive(pid));
        if is_stale {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// A process id written in decimal digits.
fn pid(digits: &str) -> Option<u32> {
    digits
        .bytes()
        .all(|b| b.is_ascii_digit())
        .then(|| digits.parse().ok())?
}

/// Whether `name` is one of [`write_atomically`]'s temporaries (`<file>.tmp<pid>`).
pub fn is_temporary(name: &str) -> bool {
    name.rsplit_once(".tmp")
        .is_some_and(|(_, digits)| pid(digits).is_some())
}

/// Whether process `pid` is running. Where that cannot be known (no `/proc`), it is taken to be:
/// a file that may be another run's is never removed.
pub fn process_is_alive(pid: u32) -> bool {
    let proc = Path::new("/proc");
    !proc.join("self").exists() || proc.join(pid.to_string()).exists()
}

/// Writes `text` to `path` only if it differs from what is there (keeps timestamps, and so cargo's
/// rebuilds, quiet when regeneration changes nothing). Returns whether the file changed.
pub fn write_if_changed(path: &Path, text: &str) -> std::io::Result<bool> {
    if std::fs::read_to_string(path).is_ok_and(|old| old == text) {
        return Ok(false);
    }
    write_atomically(path, text.as_bytes())?;
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn computed_numbers_are_shown_without_rounding_noise() {
        assert_eq!(number(634.0 * 0.1), "63.4");
        assert_eq!(format!("{}", 634.0 * 0.1), "63.400000000000006"); // what was printed
        assert_eq!(number(30.0 * 0.1), "3");
        assert_eq!(number(0.1 + 0.2), "0.3");
        assert_eq!(number(1.0 / 3.0), "0.3333333333");
        assert_eq!(number(2.5e-7), "2.5e-7");
        assert_eq!(number(f64::NAN), "NaN");
    }

    #[test]
    fn replaces_the_file_and_leaves_no_temporary() {
        let dir = std::env::temp_dir().join(format!("host-output-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("a.txt");
        write_atomically(&path, b"one").unwrap();
        assert!(write_if_changed(&path, "two").unwrap());
        assert!(!write_if_changed(&path, "two").unwrap());
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "two");
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        // Temporaries of an interrupted run (this tool's names, of a process that is gone: above the
        // largest pid Linux allows) are cleaned up by the next write; a live process's are its own.
        let live = "a.txt.tmp1"; // process 1 is always running
        std::fs::write(dir.join("a.txt.tmp4194305"), "stale").unwrap();
        std::fs::write(dir.join("a.txt.tmpx"), "not ours").unwrap();
        std::fs::write(dir.join(live), "another run's, live").unwrap();
        write_atomically(&path, b"three").unwrap();
        assert!(!dir.join("a.txt.tmp4194305").exists());
        assert!(dir.join("a.txt.tmpx").exists());
        assert!(is_temporary("a.txt.tmp4194305") && !is_temporary("a.txt.tmpx") && !is_temporary("a.txt.tmp"));
        assert!(dir.join(live).exists());
        std::fs::remove_file(dir.join("a.txt.tmpx")).unwrap();
        std::fs::remove_file(dir.join(live)).unwrap();
        // A failed write (into a missing folder) leaves nothing behind and reports the error.
        assert!(write_atomically(&dir.join("missing").join("b.txt"), b"x").is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
