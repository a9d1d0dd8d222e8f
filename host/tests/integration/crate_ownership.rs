//! `gen --spec --out DIR` replaces only files it wrote itself: pointed at a folder holding the user's
//! own files (or files of ours the user edited since), it refuses before fitting anything, names the
//! file and the fix, and leaves every file as it was. And it replaces a crate whole: killed at any
//! instant, it leaves the old crate or the new one.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("host-ownership-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Every file under `dir` with its bytes, sorted by path.
fn files(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else {
                out.push((path.clone(), std::fs::read(&path).unwrap()));
            }
        }
    }
    out.sort();
    out
}

/// `gen --spec <Example 1 as my_oscillator> --out <out>`, with the checkout's runtime.
fn gen_into(spec_dir: &Path, out: &Path, extra: &[&str]) -> Output {
    gen_with(spec_dir, out, extra, "", &[])
}

/// [`gen_into`] with environment `env`; with a `version`, the spec's description ends in it. The
/// validation and tuning runs are 8 (a cheaper fit: these cases are about files, not figures).
fn gen_with(spec_dir: &Path, out: &Path, extra: &[&str], version: &str, env: &[(&str, &str)]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mho"))
        .args(gen_args(spec_dir, out, extra, version))
        .envs(env.iter().copied())
        .output()
        .unwrap()
}

/// The arguments of [`gen_with`] (writes the spec).
fn gen_args(spec_dir: &Path, out: &Path, extra: &[&str], version: &str) -> Vec<String> {
    let spec = spec_dir.join("my_oscillator.toml");
    let mut text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml"))
        .unwrap()
        .replacen("name = \"vanderpol\"", "name = \"my_oscillator\"", 1)
        .replacen("\ntrajectories = 64", "\ntrajectories = 8", 1)
        .replacen("[tuning]", "[tuning]\ntrajectories = 8", 1);
    if !version.is_empty() {
        text = text.replacen("(paper Example 1)\"", &format!("(paper Example 1){version}\""), 1);
    }
    std::fs::write(&spec, text).unwrap();
    let firmware = Path::new(env!("CARGO_MANIFEST_DIR")).join("../firmware");
    let mut args = vec![
        "gen",
        "--spec",
        s(&spec),
        "--out",
        s(out),
        "--runtime-path",
        s(&firmware),
    ];
    args.extend(extra);
    args.into_iter().map(str::to_owned).collect()
}

/// Copies the tree `from` into `to` (a new folder).
fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap().flatten() {
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_tree(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), &target).unwrap();
        }
    }
}

#[test]
fn a_kill_at_every_rename_leaves_the_old_crate_or_the_new_one_whole() {
    let dir = scratch("kill");
    let old = dir.join("old");
    let run = gen_with(&dir, &old, &[], " old", &[]);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    // The user works in the crate: a build folder and notes of their own, which every state keeps.
    std::fs::create_dir_all(old.join("target/release")).unwrap();
    std::fs::write(old.join("target/release/firmware.bin"), "the user's build").unwrap();
    std::fs::write(old.join("NOTES.md"), "the user's notes").unwrap();
    let old_files = files(&old);
    // Every file, relative to the crate, as a run writes it: the report's solver times (which differ
    // from run to run) and their hash in the list set aside; the list is checked by `sha256sum -c`.
    let relative = |dir: &Path, all: Vec<(PathBuf, Vec<u8>)>| -> Vec<(PathBuf, Vec<u8>)> {
        let check = Command::new("sha256sum")
            .args(["--check", "--quiet", ".gen-files"])
            .current_dir(dir)
            .output()
            .unwrap();
        assert!(check.status.success(), "{}", String::from_utf8_lossy(&check.stdout));
        all.into_iter()
            .map(|(p, b)| {
                let p = p.strip_prefix(dir).unwrap().to_owned();
                let text = String::from_utf8_lossy(&b);
                let b = match p.to_str() {
                    Some("report/report.json") => text
                        .lines()
                        .filter(|l| !l.contains("_time_s\""))
                        .collect::<String>()
                        .into_bytes(),
                    Some(".gen-files") => text
                        .lines()
                        .filter(|l| !l.ends_with("  report/report.json"))
                        .collect::<String>()
                        .into_bytes(),
                    _ => b,
                };
                (p, b)
            })
            .collect()
    };
    let old_files = relative(&old, old_files);

    // Killed after the k-th rename that publishes the crate (0: with the new crate staged, before the
    // first), for k = 0, 1, … until a run is not stopped: every state is recorded.
    let mut stopped = Vec::new();
    let new_files = (0..10)
        .find_map(|k| {
            let folder = dir.join(format!("k{k}"));
            copy_tree(&old, &folder);
            let k_text = k.to_string();
            let run = gen_with(&dir, &folder, &[], " new", &[("GEN_STOP_AFTER_RENAME", &k_text)]);
            let state = relative(&folder, files(&folder));
            if run.status.success() {
                return Some(state);
            }
            assert_eq!(run.status.code(), Some(137), "{}", String::from_utf8_lossy(&run.stderr));
            stopped.push((k, state));
            None
        })
        .expect("gen was stopped at every one of 10 renames");
    assert_ne!(new_files, old_files);
    assert!(!stopped.is_empty(), "the hook never stopped gen");
    for (k, state) in &stopped {
        assert!(
            *state == old_files || *state == new_files,
            "stopped after rename {k}, the crate is neither the old one nor the new one"
        );
    }
    // Both ends are seen: before the publishing rename the old crate, after it the new one.
    assert!(stopped.first().is_some_and(|(_, s)| *s == old_files));
    assert!(stopped.last().is_some_and(|(_, s)| *s == new_files));
    assert!(new_files.contains(&(PathBuf::from("NOTES.md"), b"the user's notes".to_vec())));
    // What a killed run leaves beside the crate (its stage) is removed by the next run.
    let litter = |dir: &Path| {
        std::fs::read_dir(dir)
            .unwrap()
            .flatten()
            .filter(|e| e.file_name().to_string_lossy().starts_with(".gen-k0."))
            .count()
    };
    assert!(litter(&dir) > 0);
    let run = gen_with(&dir, &dir.join("k0"), &[], " new", &[]);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    assert_eq!(relative(&dir.join("k0"), files(&dir.join("k0"))), new_files);
    assert_eq!(litter(&dir), 0);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_folder_holding_the_users_project_is_refused_and_left_as_it_was() {
    let dir = scratch("project");
    let project = dir.join("firmware-project");
    std::fs::create_dir_all(project.join("src")).unwrap();
    std::fs::create_dir_all(project.join("report")).unwrap();
    for (file, text) in [
        ("Cargo.toml", "[package]\nname = \"my-firmware\"\n"),
        ("README.md", "# My firmware\n"),
        ("src/lib.rs", "pub fn mine() {}\n"),
        ("report/report.md", "# My own report\n"),
    ] {
        std::fs::write(project.join(file), text).unwrap();
    }
    let before = files(&project);
    let out = gen_into(&dir, &project, &[]);
    assert!(!out.status.success(), "gen replaced the user's files");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(&format!("{}", project.join("Cargo.toml").display()))
            && stderr.contains("did not write")
            && stderr.contains("--force")
            && stderr.contains("another --out folder"),
        "{stderr}"
    );
    // Refused before fitting: nothing written, nothing changed.
    assert_eq!(files(&project), before);
    // With --force the crate replaces them, and lists what it wrote.
    let out = gen_into(&dir, &project, &["--force"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let manifest = std::fs::read_to_string(project.join("Cargo.toml")).unwrap();
    assert!(manifest.contains("my-oscillator-observer"), "{manifest}");
    let list = std::fs::read_to_string(project.join(".gen-files")).unwrap();
    for file in [
        "Cargo.toml",
        "README.md",
        "src/lib.rs",
        "src/my_oscillator.rs",
        "report/report.md",
        "report/design.json",
    ] {
        assert!(
            list.lines().any(|l| l.ends_with(&format!("  {file}"))),
            "{file} not listed:\n{list}"
        );
    }

    // Only the report folder holds a file of the user's: refused, naming it.
    let only_report = dir.join("only-report");
    std::fs::create_dir_all(only_report.join("report")).unwrap();
    std::fs::write(only_report.join("report/notes.txt"), "mine\n").unwrap();
    let out = gen_into(&dir, &only_report, &[]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("notes.txt") && stderr.contains("did not write"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(only_report.join("report/notes.txt")).unwrap(),
        "mine\n"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_file_of_ours_the_user_edited_is_not_replaced() {
    // A crate as `gen` leaves it, as far as the list goes: README.md recorded with the hash of what
    // `gen` wrote (by coreutils' `sha256sum`), then edited by the user.
    let dir = scratch("edited");
    let out = dir.join("crate");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("README.md"), "written by gen\n").unwrap();
    let sum = Command::new("sha256sum")
        .arg("README.md")
        .current_dir(&out)
        .output()
        .unwrap();
    assert!(sum.status.success());
    std::fs::write(out.join(".gen-files"), &sum.stdout).unwrap();
    // Unchanged since: ours to replace (the run goes on to fit; it is not run here). Edited: refused.
    std::fs::write(out.join("README.md"), "written by gen\nand a line of the user's\n").unwrap();
    let run = gen_into(&dir, &out, &[]);
    assert!(!run.status.success());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(
        stderr.contains("README.md") && stderr.contains("changed since") && stderr.contains("--force"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(out.join("README.md")).unwrap(),
        "written by gen\nand a line of the user's\n"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The names in `dir` of stages (`.gen-<crate>.<pid>`, not the list `.gen-files`).
fn stages_in(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".gen-") && n != ".gen-files")
        .collect()
}

#[test]
fn a_link_given_as_out_is_followed_and_a_mount_point_is_written_file_by_file() {
    let dir = scratch("link-mount");
    let real = dir.join("firmware/observer");
    let run = gen_with(&dir, &real, &[], " a", &[]);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    // `ln -s firmware/observer link; gen --out link`: the crate the link points to is replaced, and
    // the link stays a link (it used to become a folder of its own, the old crate left in `real`).
    std::os::unix::fs::symlink("firmware/observer", dir.join("link")).unwrap();
    let run = gen_with(&dir, &dir.join("link"), &[], " b", &[]);
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    assert!(dir.join("link").symlink_metadata().unwrap().file_type().is_symlink());
    let spec = |folder: &Path| std::fs::read_to_string(folder.join("spec.toml")).unwrap();
    assert!(spec(&real).contains("(paper Example 1) b"));
    assert!(stages_in(&dir).is_empty() && stages_in(&dir.join("firmware")).is_empty());

    // `--out` on a mount point (a Docker volume, a tmpfs): a bind mount of the crate's folder onto
    // itself, in a mount namespace of the run's own. It used to fail after the whole fit with
    // "Device or resource busy" and leave a stage of several MB beside the folder on every run.
    std::fs::write(real.join("NOTES.md"), "the user's notes").unwrap();
    let args = gen_args(&dir, &real, &[], " c");
    let mut unshare = Command::new("unshare");
    if !is_root() {
        unshare.arg("--map-root-user");
    }
    let run = unshare
        .args(["--mount", "sh", "-c", "mount --bind \"$0\" \"$0\" && exec \"$@\""])
        .arg(&real)
        .arg(env!("CARGO_BIN_EXE_mho"))
        .args(&args)
        .output();
    let run = match run {
        Ok(run) if run.status.success() || String::from_utf8_lossy(&run.stderr).contains("gen:") => run,
        other => {
            let why = format!("no mount namespace here (unshare --mount): {other:?}");
            assert!(std::env::var_os("CI").is_none(), "{why}");
            eprintln!("skipped the mount point: {why}");
            return;
        }
    };
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(
        stderr.contains("mount point") && stderr.contains("file by file"),
        "{stderr}"
    );
    assert!(spec(&real).contains("(paper Example 1) c"));
    assert_eq!(
        std::fs::read_to_string(real.join("NOTES.md")).unwrap(),
        "the user's notes"
    );
    assert!(stages_in(&real).is_empty() && stages_in(&dir.join("firmware")).is_empty());
    // The list is whole again (one content per file) and matches the files.
    let check = Command::new("sha256sum")
        .args(["--check", "--quiet", ".gen-files"])
        .current_dir(&real)
        .output()
        .unwrap();
    assert!(check.status.success(), "{}", String::from_utf8_lossy(&check.stdout));
    let _ = std::fs::remove_dir_all(&dir);
}

fn is_root() -> bool {
    Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
}
