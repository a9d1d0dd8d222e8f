//! Running a program on the emulated board (QEMU `mps2-an386`, semihosting) and counting, from an
//! execution trace, the instructions between the runner's `measure_start` and `measure_end` markers.

use std::ffi::OsStr;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::elf::{division_addresses, symbol};
use super::unavailable::{failed, Unavailable};

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

/// Runs `elf` under QEMU with semihosting and an execution trace in `trace`; returns what it printed.
fn run_qemu(elf: &Path, trace: &Path, timeout: Duration) -> Result<String, Unavailable> {
    let mut tracing: Vec<&OsStr> = one_instruction_per_block()?.into_iter().map(OsStr::new).collect();
    tracing.extend([
        OsStr::new("-d"),
        OsStr::new("exec,nochain"),
        OsStr::new("-D"),
        trace.as_os_str(),
    ]);
    let (status, text) = qemu(elf, &tracing, &trace.with_extension("out"), timeout)?;
    if !status.success() || !text.contains("DONE") {
        return Err(failed(format!("the on-target program failed ({status}):\n{text}")));
    }
    Ok(text)
}

/// Runs `elf` on the emulated board (QEMU `mps2-an386`, semihosting, no trace) until it exits, with
/// its output in `output`; returns what it printed. An error when it exits with a failure (a
/// semihosting `EXIT_FAILURE`, as a panic handler does) or does not finish within `timeout`.
pub fn run_on_emulator(elf: &Path, output: &Path, timeout: Duration) -> Result<String, Unavailable> {
    let (status, text) = qemu(elf, &[], output, timeout)?;
    if !status.success() {
        return Err(failed(format!(
            "{} failed on the emulator ({status}):\n{text}",
            elf.display()
        )));
    }
    Ok(text)
}

/// Runs `elf` under QEMU with semihosting and the `extra` options; returns its exit status and what
/// it printed. Output goes to `output`, a file, not a pipe (QEMU can hang when a pipe closes early),
/// and a run that does not finish within `timeout` is killed.
fn qemu(
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
        .args([
            "-machine",
            "mps2-an386",
            "-cpu",
            "cortex-m4",
            "-nographic",
            "-monitor",
            "none",
            "-serial",
            "none",
        ])
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

/// Instructions, and of them divisions, executed from each entry of `start` to the following entry
/// of `end`, from a QEMU `-d exec` trace with one instruction per block (each `Trace` line is one
/// executed instruction).
fn count_between(
    trace: &Path,
    start: u64,
    end: u64,
    divisions: &std::collections::BTreeSet<u64>,
) -> Result<Vec<(u64, u64)>, Unavailable> {
    use std::io::BufRead;
    let file = std::fs::File::open(trace).map_err(|e| failed(e.to_string()))?;
    let (mut counts, mut current) = (Vec::new(), None);
    for line in std::io::BufReader::new(file).lines() {
        let line = line.map_err(|e| failed(e.to_string()))?;
        let Some(fields) = line.strip_prefix("Trace ").and_then(|l| l.split('[').nth(1)) else {
            continue;
        };
        let Some(pc) = fields.split('/').nth(1).and_then(|pc| u64::from_str_radix(pc, 16).ok()) else {
            continue;
        };
        if pc == start {
            current = Some((0, 0));
        } else if pc == end {
            if let Some(n) = current.take() {
                counts.push(n);
            }
        } else if let Some((n, d)) = current.as_mut() {
            *n += 1;
            *d += u64::from(divisions.contains(&pc));
        }
    }
    Ok(counts)
}

/// Runs `elf` under QEMU with an execution trace beside it and returns what it printed, and the
/// instructions and divisions of each measured call.
pub(super) fn run_counted(elf: &Path) -> Result<(String, Vec<(u64, u64)>), Unavailable> {
    let trace = elf.with_extension("trace");
    let text = run_qemu(elf, &trace, Duration::from_secs(300))?;
    let counts = count_between(
        &trace,
        symbol(elf, "measure_start")?,
        symbol(elf, "measure_end")?,
        &division_addresses(elf)?,
    )?;
    let _ = std::fs::remove_file(&trace);
    Ok((text, counts))
}
