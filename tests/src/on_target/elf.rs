//! Building the on-target programs (cargo for the board's target) and reading their ELFs with
//! binutils: symbol addresses, sizes, and the disassembly (each instruction's mnemonic and size).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Mutex, PoisonError};

use super::board::Board;
use super::timing::{parse_disassembly, Instruction};
use super::unavailable::{failed, Unavailable};
use crate::workspace_root;

/// An on-target program to build: the manifest of its runners and probes (`tests/on-target/`, or
/// one [`standalone`](super::standalone) writes for a user's crate) and the folder cargo builds into.
#[derive(Clone, Debug)]
pub struct Program {
    /// Its `Cargo.toml`.
    pub manifest: PathBuf,
    /// Cargo's `--target-dir`: runners and probes share it, so their dependencies are compiled once.
    pub target_dir: PathBuf,
    /// Where the ELFs are kept (`runs/`, `probes/`).
    pub elves: PathBuf,
}

impl Program {
    /// `tests/on-target/`, linking the project's `generated` crate.
    pub fn project() -> Self {
        let target_dir = workspace_root().join("target").join("on-target");
        Program {
            manifest: workspace_root().join("tests/on-target/Cargo.toml"),
            elves: target_dir.clone(),
            target_dir,
        }
    }

    /// Builds `bin` in release for `board` with `variables` set (the design and kind selections of
    /// `tests/on-target/build.rs`), and copies the ELF to `copy` (under [`Program::elves`] and the
    /// board's [`Board::folder`]), so that the next build (which writes the same file) leaves it as
    /// built.
    pub(super) fn build(
        &self,
        board: Board,
        bin: &str,
        variables: &[(&str, &str)],
        copy: &str,
    ) -> Result<PathBuf, String> {
        // One build and its copy at a time in this process: the tests run in one binary, and two
        // builds of the same `bin` for the same board (other variables, another program in the same
        // target folder) write the same file, which the copy must read as its own build left it.
        static BUILDING: Mutex<()> = Mutex::new(());
        let _building = BUILDING.lock().unwrap_or_else(PoisonError::into_inner);
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let mut command = Command::new(cargo);
        command
            .current_dir(workspace_root())
            .args(["build", "--release", "--manifest-path"])
            .arg(&self.manifest)
            .args(["--target", board.target(), "--bin", bin, "--target-dir"])
            .arg(&self.target_dir);
        for variable in ["ON_TARGET_DESIGN", "ON_TARGET_KIND", "PROBE_DESIGN", "PROBE_KIND"] {
            command.env_remove(variable);
        }
        command.envs(variables.iter().copied());
        let output = command.output().map_err(|e| format!("cannot run cargo: {e}"))?;
        if !output.status.success() {
            return Err(String::from_utf8_lossy(&output.stderr).into_owned());
        }
        let built = self.target_dir.join(board.target()).join("release").join(bin);
        let copy = self.elves.join(board.folder()).join(copy);
        if let Some(folder) = copy.parent() {
            std::fs::create_dir_all(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
        }
        std::fs::copy(&built, &copy)
            .map_err(|e| format!("cannot copy {} to {}: {e}", built.display(), copy.display()))?;
        Ok(copy)
    }
}

/// Address of a symbol in an ELF (`arm-none-eabi-nm`).
pub(super) fn symbol(elf: &Path, name: &str) -> Result<u64, Unavailable> {
    let output = Command::new("arm-none-eabi-nm")
        .arg(elf)
        .output()
        .map_err(|e| failed(e.to_string()))?;
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .find_map(|l| {
            let mut parts = l.split_whitespace();
            let address = parts.next()?;
            (parts.nth(1)? == name).then(|| u64::from_str_radix(address, 16).ok())?
        })
        .ok_or_else(|| failed(format!("no symbol {name} in {}", elf.display())))
}

/// Every defined symbol of an object or an ELF with a size, and its size in bytes
/// (`arm-none-eabi-nm -S --defined-only`).
pub(super) fn symbol_sizes(file: &Path) -> Result<std::collections::BTreeMap<String, u64>, Unavailable> {
    let output = Command::new("arm-none-eabi-nm")
        .args(["-S", "--defined-only"])
        .arg(file)
        .output()
        .map_err(|e| failed(format!("arm-none-eabi-nm: {e}")))?;
    if !output.status.success() {
        return Err(failed(format!(
            "arm-none-eabi-nm {}: {}",
            file.display(),
            String::from_utf8_lossy(&output.stderr)
        )));
    }
    Ok(String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|line| {
            // "00000000 00000010 t is_finite"
            let mut fields = line.split_whitespace();
            let (_, size, _, name) = (fields.next()?, fields.next()?, fields.next()?, fields.next()?);
            Some((name.to_owned(), u64::from_str_radix(size, 16).ok()?))
        })
        .collect())
}

/// `(text, data, bss)` of an ELF (`arm-none-eabi-size`, Berkeley format: text includes rodata).
pub fn sizes(elf: &Path) -> Result<(u64, u64, u64), Unavailable> {
    let output = Command::new("arm-none-eabi-size")
        .arg(elf)
        .output()
        .map_err(|e| failed(e.to_string()))?;
    let text = String::from_utf8_lossy(&output.stdout);
    let numbers: Vec<u64> = text
        .lines()
        .nth(1)
        .unwrap_or("")
        .split_whitespace()
        .take(3)
        .filter_map(|n| n.parse().ok())
        .collect();
    match numbers[..] {
        [text, data, bss] => Ok((text, data, bss)),
        _ => Err(failed(format!("cannot read the sizes of {}: {text}", elf.display()))),
    }
}

/// Every instruction of an ELF by address (`arm-none-eabi-objdump -d`).
pub(super) fn disassembly(elf: &Path) -> Result<BTreeMap<u64, Instruction>, Unavailable> {
    let output = Command::new("arm-none-eabi-objdump")
        .arg("-d")
        .arg(elf)
        .output()
        .map_err(|e| failed(format!("arm-none-eabi-objdump: {e}")))?;
    if !output.status.success() {
        return Err(failed(format!(
            "arm-none-eabi-objdump -d {}: {}",
            elf.display(),
            String::from_utf8_lossy(&output.stderr)
        )));
    }
    Ok(parse_disassembly(&String::from_utf8_lossy(&output.stdout)))
}
