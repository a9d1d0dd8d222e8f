//! A C program for the emulated board: built by `arm-none-eabi-gcc` for the Cortex-M4F (hard float,
//! newlib's semihosting, `tests/c/startup.c` and `tests/c/mps2-an386.ld`), run under QEMU with the
//! instructions between its `measure_start` and `measure_end` markers counted, as the Rust runners'.

use std::path::Path;
use std::process::Command;

use super::board::Board;
use super::qemu::{run_counted, Count};
use super::unavailable::{failed, require, require_tools, Unavailable};

/// The Cortex-M4F with its single-precision FPU, as the Rust target `thumbv7em-none-eabihf`.
pub const BOARD_FLAGS: [&str; 4] = ["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16"];

/// Runs `arm-none-eabi-gcc` with `arguments`; its error output when it fails.
fn gcc(arguments: &mut Command) -> Result<(), Unavailable> {
    let built = arguments
        .output()
        .map_err(|e| failed(format!("arm-none-eabi-gcc: {e}")))?;
    if built.status.success() {
        Ok(())
    } else {
        Err(failed(format!(
            "arm-none-eabi-gcc: {}",
            String::from_utf8_lossy(&built.stderr)
        )))
    }
}

/// Compiles the C `source` (with `include` on the include path and `flags`) into `object` for the
/// emulated board by `arm-none-eabi-gcc`.
pub fn compile_for_board(source: &Path, include: &Path, flags: &[&str], object: &Path) -> Result<(), Unavailable> {
    require("arm-none-eabi-gcc", "gcc-arm-none-eabi")?;
    gcc(Command::new("arm-none-eabi-gcc")
        .args(BOARD_FLAGS)
        .args(flags)
        .arg("-I")
        .arg(include)
        .arg("-c")
        .arg(source)
        .arg("-o")
        .arg(object))
}

/// Builds `sources` (each compiled with `include` on the include path and `flags`, then linked with the
/// board's start-up code; an object, `.o`, is linked as it is) into `elf` for the emulated board and
/// runs it: what it printed, and what each measured call executed.
pub fn run_c_counted(
    sources: &[&Path],
    include: &Path,
    flags: &[&str],
    elf: &Path,
) -> Result<(String, Vec<Count>), Unavailable> {
    require_tools()?;
    require("arm-none-eabi-gcc", "gcc-arm-none-eabi")?;
    let mut objects = Vec::new();
    for (i, source) in sources.iter().enumerate() {
        if source.extension().is_some_and(|e| e == "o") {
            objects.push(source.to_path_buf());
            continue;
        }
        let object = elf.with_extension(format!("{i}.o"));
        compile_for_board(source, include, flags, &object)?;
        objects.push(object);
    }
    // The start-up code is the board's, not the code under test: not held to `flags`. With `-flto`
    // the code is compiled at the link, which then takes the observer's optimisation and IEEE flags.
    let board = crate::workspace_root().join("tests/c");
    let link: &[&str] = if flags.contains(&"-flto") {
        &["-flto", "-Os", "-ffp-contract=off", "-fno-fast-math"]
    } else {
        &["-O1"]
    };
    gcc(Command::new("arm-none-eabi-gcc")
        .args(BOARD_FLAGS)
        .args(link)
        .args(["-std=c99", "--specs=rdimon.specs", "-Wl,--gc-sections", "-T"])
        .arg(board.join("mps2-an386.ld"))
        .arg("-o")
        .arg(elf)
        .arg(board.join("startup.c"))
        .args(&objects)
        .arg("-lm"))?;
    run_counted(Board::Mps2An386, elf)
}
