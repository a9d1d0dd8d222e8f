//! Running a program on an emulated board (QEMU `mps2-an386` or `microbit`, semihosting) and
//! counting, from an execution trace, the instructions between the runner's `measure_start` and
//! `measure_end` markers, and their estimated cycles ([`super::timing`]).

use std::ffi::OsStr;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::board::Board;
use super::elf::{disassembly, symbol};
use super::timing::{Core, Instruction, Timer};
use super::unavailable::{failed, Unavailable};

/// What one measured call executed: instructions, of them `VDIV` + `VSQRT`, and the estimated cycles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Count {
    /// Instructions executed (the markers' included).
    pub instructions: u64,
    /// `VDIV` and `VSQRT` among them.
    pub divisions: u64,
    /// Their estimated cycles on the board's core.
    pub cycles: u64,
}

/// The QEMU option that makes every translation block one instruction (renamed in QEMU 8.1).
fn one_instruction_per_block() -> Result<Vec<&'static str>, Unavailable> {
    let output = Command::new("qemu-system-arm")
        .arg("--version")
        .output()
        .map_err(|e| failed(e.to_string()))?;
    let text = String::from_utf8_lossy(&output.stdout);
    let version: Vec<u32> = text
        .split_whitespace()
        .nth(3)
        .unwrap_or("0")
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|n| n.parse().ok())
        .collect();
    Ok(if version.as_slice() >= [8, 1].as_slice() {
        vec!["-accel", "tcg,one-insn-per-tb=on"]
    } else {
        vec!["-singlestep"]
    })
}

/// Runs `elf` on `board` under QEMU with semihosting and an execution trace in `trace`; returns what
/// it printed.
fn run_qemu(board: Board, elf: &Path, trace: &Path, timeout: Duration) -> Result<String, Unavailable> {
    let mut tracing: Vec<&OsStr> = one_instruction_per_block()?.into_iter().map(OsStr::new).collect();
    tracing.extend([
        OsStr::new("-d"),
        OsStr::new("exec,nochain"),
        OsStr::new("-D"),
        trace.as_os_str(),
    ]);
    let (status, text) = qemu(board, elf, &tracing, &trace.with_extension("out"), timeout)?;
    if !status.success() || !text.contains("DONE") {
        return Err(failed(format!("the on-target program failed ({status}):\n{text}")));
    }
    Ok(text)
}

/// Runs `elf` on the emulated board (QEMU `mps2-an386`, semihosting, no trace) until it exits, with
/// its output in `output`; returns what it printed. An error when it exits with a failure (a
/// semihosting `EXIT_FAILURE`, as a panic handler does) or does not finish within `timeout`.
pub fn run_on_emulator(elf: &Path, output: &Path, timeout: Duration) -> Result<String, Unavailable> {
    let (status, text) = qemu(Board::Mps2An386, elf, &[], output, timeout)?;
    if !status.success() {
        return Err(failed(format!(
            "{} failed on the emulator ({status}):\n{text}",
            elf.display()
        )));
    }
    Ok(text)
}

/// Runs `elf` on `board` under QEMU with semihosting and the `extra` options; returns its exit status
/// and what it printed. Output goes to `output`, a file, not a pipe (QEMU can hang when a pipe closes
/// early), and a run that does not finish within `timeout` is killed.
fn qemu(
    board: Board,
    elf: &Path,
    extra: &[&OsStr],
    output: &Path,
    timeout: Duration,
) -> Result<(std::process::ExitStatus, String), Unavailable> {
    if let Some(folder) = output.parent() {
        std::fs::create_dir_all(folder).map_err(|e| failed(format!("{}: {e}", folder.display())))?;
    }
    let stdout = std::fs::File::create(output).map_err(|e| failed(e.to_string()))?;
    let mut child = Command::new("qemu-system-arm")
        .args(board.machine())
        .args(["-nographic", "-monitor", "none", "-serial", "none"])
        .args(["-semihosting-config", "enable=on,target=native"])
        .args(extra)
        .arg("-kernel")
        .arg(elf)
        .stdin(Stdio::null())
        .stdout(stdout)
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| failed(format!("cannot start qemu-system-arm: {e}")))?;
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| failed(e.to_string()))? {
            break status;
        }
        if started.elapsed() > timeout {
            let _ = child.kill();
            let _ = child.wait();
            return Err(failed(format!("QEMU did not finish within {timeout:?}")));
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let text = std::fs::read_to_string(output).map_err(|e| failed(e.to_string()))?;
    Ok((status, text))
}

/// What each call from an entry of `start` to the following entry of `end` executed ([`Count`]),
/// from a QEMU `-d exec` trace with one instruction per block (each `Trace` line is one executed
/// instruction); `code` is the ELF's disassembly, whose mnemonics give each instruction's cycles on
/// `core`, and the next traced address whether it branched.
pub fn count_between(
    trace: impl std::io::BufRead,
    start: u64,
    end: u64,
    core: Core,
    code: &std::collections::BTreeMap<u64, Instruction>,
) -> Result<Vec<Count>, String> {
    let (mut counts, mut current): (Vec<Count>, Option<Count>) = (Vec::new(), None);
    let mut timer = Timer::new(core, code);
    let (mut trace, mut line) = (trace, String::new());
    loop {
        line.clear();
        if trace.read_line(&mut line).map_err(|e| e.to_string())? == 0 {
            break;
        }
        let Some(fields) = line.strip_prefix("Trace ").and_then(|l| l.split('[').nth(1)) else {
            continue;
        };
        let Some(pc) = fields.split('/').nth(1).and_then(|pc| u64::from_str_radix(pc, 16).ok()) else {
            continue;
        };
        // The instruction before this one, if it was measured, is timed now that its successor shows
        // whether it branched.
        let counted = current.is_some() && pc != start && pc != end;
        let (before, division) = timer.next(pc, counted)?;
        if let Some(count) = current.as_mut() {
            count.cycles += before;
        }
        if pc == start {
            current = Some(Count::default());
        } else if pc == end {
            counts.extend(current.take());
        } else if let Some(count) = current.as_mut() {
            count.instructions += 1;
            count.divisions += u64::from(division);
        }
    }
    Ok(counts)
}

/// Runs `elf` on `board` under QEMU with an execution trace beside it and returns what it printed,
/// and what each measured call executed.
pub(super) fn run_counted(board: Board, elf: &Path) -> Result<(String, Vec<Count>), Unavailable> {
    let trace = elf.with_extension("trace");
    let text = run_qemu(board, elf, &trace, Duration::from_secs(300))?;
    let file = std::fs::File::open(&trace).map_err(|e| failed(format!("{}: {e}", trace.display())))?;
    let counts = count_between(
        std::io::BufReader::new(file),
        symbol(elf, "measure_start")?,
        symbol(elf, "measure_end")?,
        board.core(),
        &disassembly(elf)?,
    )
    .map_err(|e| failed(format!("{}: {e}", elf.display())))?;
    let _ = std::fs::remove_file(&trace);
    Ok((text, counts))
}
