//! `gen --spec --out DIR` replaces only files it wrote itself: pointed at a folder holding the user's
//! own files (or files of ours the user edited since), it refuses before fitting anything, names the
//! file and the fix, and leaves every file as it was.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn host(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_host")).args(args).output().unwrap()
}

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
    let spec = spec_dir.join("my_oscillator.toml");
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml"))
        .unwrap()
        .replacen("name = \"vanderpol\"", "name = \"my_oscillator\"", 1);
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
    host(&args)
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
