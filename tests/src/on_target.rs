//! Running the generated observers on the emulated Cortex-M4F (QEMU `mps2-an386`) and measuring them:
//! estimates over semihosting, instructions per `push` + `estimate` from an execution trace, flash
//! and RAM from the ELF, and the no-panic proof (see `tests/on-target/`).
//!
//! Every kind of observer a design has is measured ([`Kind`]): the map, the observers the map starts
//! (the model-corrected map, the map-started EKF: one program per design runs them one after the
//! other over the recorded sequence, [`ObserverMeasurement`]) and the EKF from the box centre (a
//! program of its own, [`EkfMeasurement`]: it shares the filter's code with the map-started EKF, which
//! linked together could change what the compiler inlines). [`measure`] builds each program once
//! per design and runs QEMU on one while cargo builds the next.

use std::any::TypeId;
use std::collections::BTreeMap;
use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use firmware::{Estimate, Follower, Maths, Saturation, Scalar, Started};
use host::emit::precision::compare;

use crate::workspace_root;

pub mod standalone;

include!(concat!(env!("OUT_DIR"), "/started_observers.rs"));

/// Why the on-target measurements could not be made.
#[derive(Debug)]
pub enum Unavailable {
    /// A tool is missing: its name and the Debian package that provides it.
    Missing {
        /// The command.
        tool: &'static str,
        /// The package to install.
        package: &'static str,
    },
    /// Something failed that should not have.
    Failed(String),
}

impl std::fmt::Display for Unavailable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unavailable::Missing { tool, package } => {
                write!(
                    f,
                    "`{tool}` is not installed (Debian package `{package}`: apt-get install {package})"
                )
            }
            Unavailable::Failed(message) => f.write_str(message),
        }
    }
}

fn failed(message: impl Into<String>) -> Unavailable {
    Unavailable::Failed(message.into())
}

fn require(tool: &'static str, package: &'static str) -> Result<(), Unavailable> {
    match Command::new(tool)
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
    {
        Ok(status) if status.success() => Ok(()),
        _ => Err(Unavailable::Missing { tool, package }),
    }
}

/// A kind of observer a generated design may have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kind {
    /// The paper's map (`map_observer()`, every design).
    Map,
    /// The model-corrected map (`CorrectedObserver`).
    Corrected,
    /// The EKF started by the map (`StartedEkfObserver`).
    StartedEkf,
    /// The EKF from the box centre, restarted by the map (`RestartedEkfObserver`).
    RestartedEkf,
    /// The EKF from the centre of the state box (`ekf()`, every design).
    Ekf,
}

impl Kind {
    /// Every kind, in the order the report lists them.
    pub const ALL: [Kind; 5] = [
        Kind::Map,
        Kind::Corrected,
        Kind::StartedEkf,
        Kind::RestartedEkf,
        Kind::Ekf,
    ];

    /// Its name for the on-target program (`ON_TARGET_KIND`, `PROBE_KIND`).
    pub fn chip_name(self) -> &'static str {
        match self {
            Kind::Map => "map",
            Kind::Corrected => "corrected",
            Kind::StartedEkf => "started_ekf",
            Kind::RestartedEkf => "restarted_ekf",
            Kind::Ekf => "ekf",
        }
    }

    /// Its name in `report.json` (`observers[].kind`) and `on_target.json`.
    pub fn report_name(self) -> &'static str {
        match self {
            Kind::Map => "map",
            Kind::Corrected => "corrected",
            Kind::StartedEkf => "ekf_map",
            Kind::RestartedEkf => "ekf_restart",
            Kind::Ekf => "ekf_box",
        }
    }

    /// How firmware makes one.
    pub fn api(self) -> &'static str {
        match self {
            Kind::Map => "map_observer()",
            Kind::Corrected => "CorrectedObserver::new()",
            Kind::StartedEkf => "StartedEkfObserver::new()",
            Kind::RestartedEkf => "RestartedEkfObserver::new()",
            Kind::Ekf => "ekf()",
        }
    }

    fn from_chip_name(name: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.chip_name() == name)
    }
}

/// Every kind design `name` has, in [`Kind::ALL`]'s order: the map, the observers the map starts
/// that its generated file declares, and the EKF from the centre. Empty for an unknown design.
pub fn kinds(name: &str) -> Vec<Kind> {
    let mut kinds = Vec::new();
    if design_names().contains(&name) {
        kinds.push(Kind::Map);
    }
    macro_rules! started {
        ($design:ident, $kind:ident, $type:ident) => {
            if stringify!($design) == name {
                kinds.push(Kind::$kind);
            }
        };
    }
    for_each_started_observer!(started);
    if !kinds.is_empty() {
        kinds.push(Kind::Ekf);
    }
    kinds.sort();
    kinds
}

/// The kind of design `name`'s `observer()` (its type compared with each kind's); `None` for an
/// unknown design, or an `Observer` that is none of the kinds.
pub fn chosen_kind(name: &str) -> Option<Kind> {
    let mut chosen = None;
    macro_rules! map {
        ($design:ident) => {
            if stringify!($design) == name
                && TypeId::of::<generated::$design::Observer>() == TypeId::of::<generated::$design::MapObserver>()
            {
                chosen = Some(Kind::Map);
            }
        };
    }
    generated::for_each_design!(map);
    macro_rules! started {
        ($design:ident, $kind:ident, $type:ident) => {
            if stringify!($design) == name
                && TypeId::of::<generated::$design::Observer>() == TypeId::of::<generated::$design::$type>()
            {
                chosen = Some(Kind::$kind);
            }
        };
    }
    for_each_started_observer!(started);
    // The EKF from the box centre, which every design the host can filter has.
    macro_rules! boxed {
        ($design:ident) => {
            if stringify!($design) == name && generated::$design::KIND == "ekf_box" {
                chosen = Some(Kind::Ekf);
            }
        };
    }
    generated::for_each_design!(boxed);
    chosen
}

/// One sample as the target reported it (or the host computed it).
#[derive(Clone, Debug, PartialEq)]
pub struct TargetSample {
    /// Whether `push` accepted the sample.
    pub accepted: bool,
    /// `(value bits, saturation flag 'L'|'I'|'H')` per target, when an estimate existed.
    pub estimates: Option<Vec<(u32, char)>>,
}

/// Everything measured for one observer of a design that estimates through `push` + `estimate`:
/// the map, or an observer the map starts.
#[derive(Clone, Debug)]
pub struct ObserverMeasurement {
    /// Which.
    pub kind: Kind,
    /// Estimates after the first that take the start-up path, as the chip reported it (0 for the
    /// map, `Follower::START_UP` for the others).
    pub start_up: usize,
    /// Samples in the recorded sequence order.
    pub samples: Vec<TargetSample>,
    /// Instructions executed by `push` + `estimate` per sample (markers included).
    pub instructions: Vec<u64>,
    /// `VDIV` and `VSQRT` instructions executed per sample.
    pub divisions: Vec<u64>,
    /// Deepest stack use of `push` + `estimate` (the call to them included), in bytes.
    pub stack_bytes: usize,
    /// `size_of` the observer on the target, in bytes.
    pub observer_bytes: usize,
    /// Flash (text + data) added by this observer over the baseline probe, in bytes.
    pub flash_bytes: u64,
    /// Static RAM (data + bss) added over the baseline probe, in bytes.
    pub static_ram_bytes: u64,
}

impl ObserverMeasurement {
    /// The instructions split into start-up and steady state ([`phases`]).
    pub fn phases(&self) -> Result<Phases, String> {
        let accepted: Vec<bool> = self.samples.iter().map(|s| s.accepted).collect();
        let estimated: Vec<bool> = self
            .samples
            .iter()
            .map(|s| s.accepted && s.estimates.is_some())
            .collect();
        phases(&self.instructions, &accepted, &estimated, self.start_up)
    }
}

/// A run's instructions per sample, split at the end of the start-up.
///
/// The start-up is every sample up to and including the one that gives estimate number
/// `start_up + 1`, counting only samples that were accepted and gave an estimate: the samples before
/// the first estimate (the window filling), the first estimate, and the `start_up` estimates after
/// it that take a follower's start-up path (`Follower::START_UP`; 0 for the map and the EKF, whose
/// start-up is their first estimate). Refused samples in between count with the start-up. The
/// steady state is every later sample.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Phases {
    /// Samples in the start-up (the index of the first steady sample).
    pub start_up_samples: usize,
    /// Largest instructions of one start-up sample.
    pub start_up_max: u64,
    /// Instructions of the sample that gave the first estimate.
    pub first_estimate: u64,
    /// Instructions of every accepted sample of the steady state, in order.
    pub steady: Vec<u64>,
    /// Instructions of every refused sample of the steady state, in order.
    pub steady_refused: Vec<u64>,
}

/// Splits `instructions` ([`Phases`]); `accepted` and `estimated` say, per sample, whether `push`
/// accepted it and whether it then gave an estimate. An error when the lengths differ, or when the
/// run does not reach the steady state.
pub fn phases(instructions: &[u64], accepted: &[bool], estimated: &[bool], start_up: usize) -> Result<Phases, String> {
    if instructions.len() != accepted.len() || accepted.len() != estimated.len() {
        return Err(format!(
            "{} instruction counts for {} samples ({} estimate flags)",
            instructions.len(),
            accepted.len(),
            estimated.len()
        ));
    }
    let estimates: Vec<usize> = (0..estimated.len()).filter(|&k| estimated[k]).collect();
    let (Some(&first), Some(&last)) = (estimates.first(), estimates.get(start_up)) else {
        return Err(format!(
            "{} estimates in {} samples: the start-up takes {}",
            estimates.len(),
            estimated.len(),
            start_up + 1
        ));
    };
    let after = last + 1;
    let steady: Vec<u64> = (after..instructions.len())
        .filter(|&k| accepted[k])
        .map(|k| instructions[k])
        .collect();
    if steady.is_empty() {
        return Err(format!(
            "no accepted sample after the start-up ({after} of {} samples)",
            instructions.len()
        ));
    }
    Ok(Phases {
        start_up_samples: after,
        start_up_max: instructions[..after].iter().copied().max().unwrap_or(0),
        first_estimate: instructions[first],
        steady,
        steady_refused: (after..instructions.len())
            .filter(|&k| !accepted[k])
            .map(|k| instructions[k])
            .collect(),
    })
}

/// An on-target program to build: the manifest of its runners and probes (`tests/on-target/`, or
/// one [`standalone`] writes for a user's crate) and the folder cargo builds into.
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

    /// Builds `bin` in release with `variables` set (the design and kind selections of
    /// `tests/on-target/build.rs`), and copies the ELF to `copy` (under [`Program::elves`]), so that
    /// the next build (which writes the same file) leaves it as built.
    fn build(&self, bin: &str, variables: &[(&str, &str)], copy: &str) -> Result<PathBuf, String> {
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let mut command = Command::new(cargo);
        command
            .current_dir(workspace_root())
            .args(["build", "--release", "--manifest-path"])
            .arg(&self.manifest)
            .args(["--target", "thumbv7em-none-eabihf", "--bin", bin, "--target-dir"])
            .arg(&self.target_dir);
        for variable in ["ON_TARGET_DESIGN", "ON_TARGET_KIND", "PROBE_DESIGN", "PROBE_KIND"] {
            command.env_remove(variable);
        }
        command.envs(variables.iter().copied());
        let output = command.output().map_err(|e| format!("cannot run cargo: {e}"))?;
        if !output.status.success() {
            return Err(String::from_utf8_lossy(&output.stderr).into_owned());
        }
        let built = self.target_dir.join("thumbv7em-none-eabihf/release").join(bin);
        let copy = self.elves.join(copy);
        if let Some(folder) = copy.parent() {
            std::fs::create_dir_all(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
        }
        std::fs::copy(&built, &copy)
            .map_err(|e| format!("cannot copy {} to {}: {e}", built.display(), copy.display()))?;
        Ok(copy)
    }
}

/// Address of a symbol in an ELF (`arm-none-eabi-nm`).
fn symbol(elf: &Path, name: &str) -> Result<u64, Unavailable> {
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

/// Addresses of the division and square-root instructions (`VDIV`, `VSQRT`) in an ELF, from
/// `arm-none-eabi-objdump -d`.
fn division_addresses(elf: &Path) -> Result<std::collections::BTreeSet<u64>, Unavailable> {
    let output = Command::new("arm-none-eabi-objdump")
        .arg("-d")
        .arg(elf)
        .output()
        .map_err(|e| failed(format!("arm-none-eabi-objdump: {e}")))?;
    let text = String::from_utf8_lossy(&output.stdout);
    Ok(text
        .lines()
        .filter_map(|line| {
            // "     1a4:\teec0 7a80 \tvdiv.f32\ts15, s1, s0"
            let (address, rest) = line.trim_start().split_once(':')?;
            let mnemonic = rest.split('\t').nth(2)?.trim();
            (mnemonic.starts_with("vdiv") || mnemonic.starts_with("vsqrt"))
                .then(|| u64::from_str_radix(address.trim(), 16).ok())?
        })
        .collect())
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

/// Parses the runner's output: per `KIND` block its `E …`, `S …` and `STACK …` lines (the costs
/// measured elsewhere are left at zero).
fn parse(text: &str) -> Result<Vec<ObserverMeasurement>, Unavailable> {
    let mut observers: Vec<ObserverMeasurement> = Vec::new();
    let number = |field: &str, line: &str| -> Result<usize, Unavailable> {
        field.parse().map_err(|e| failed(format!("{field:?} in {line:?}: {e}")))
    };
    for line in text.lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        if let ["KIND", name, start_up] = fields.as_slice() {
            let kind = Kind::from_chip_name(name).ok_or_else(|| failed(format!("unknown kind in {line:?}")))?;
            observers.push(ObserverMeasurement {
                kind,
                start_up: number(start_up, line)?,
                samples: Vec::new(),
                instructions: Vec::new(),
                divisions: Vec::new(),
                stack_bytes: 0,
                observer_bytes: 0,
                flash_bytes: 0,
                static_ram_bytes: 0,
            });
            continue;
        }
        let Some(observer) = observers.last_mut() else {
            continue;
        };
        match fields.as_slice() {
            ["E", _k, accepted, rest @ ..] => {
                if rest.len() % 2 != 0 {
                    return Err(failed(format!("an estimate without its flag in {line:?}")));
                }
                let estimates = rest
                    .chunks(2)
                    .map(|c| {
                        let bits = u32::from_str_radix(c[0], 16)
                            .map_err(|e| failed(format!("{:?} in {line:?}: {e}", c[0])))?;
                        match c[1] {
                            "L" | "I" | "H" => Ok((bits, c[1].chars().next().unwrap_or('?'))),
                            other => Err(failed(format!("saturation flag {other:?} in {line:?}"))),
                        }
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                observer.samples.push(TargetSample {
                    accepted: *accepted == "1",
                    estimates: (!estimates.is_empty()).then_some(estimates),
                });
            }
            ["S", bytes] => observer.observer_bytes = number(bytes, line)?,
            ["STACK", bytes] => observer.stack_bytes = number(bytes, line)?,
            _ => {}
        }
    }
    if observers.is_empty() || observers.iter().any(|o| o.samples.is_empty()) {
        return Err(failed(format!("no estimate in the output:\n{text}")));
    }
    Ok(observers)
}

/// The generated design modules.
pub fn design_names() -> Vec<&'static str> {
    let mut names = Vec::new();
    macro_rules! push_name {
        ($name:ident) => {
            names.push(stringify!($name));
        };
    }
    generated::for_each_design!(push_name);
    names
}

/// Everything measured on the target.
#[derive(Clone, Debug, Default)]
pub struct Measurements {
    /// Per design, its map and the observers the map starts, by kind.
    pub observers: BTreeMap<String, BTreeMap<Kind, ObserverMeasurement>>,
    /// Per design, its EKF from the box centre.
    pub filters: BTreeMap<String, EkfMeasurement>,
    /// Flash added by each family observer (all its members' tables and the selection) over the
    /// baseline probe, in bytes; its probe links, so it has no reachable panic either.
    pub family_flash_bytes: BTreeMap<String, u64>,
}

/// A program built and waiting for QEMU: the design, whether it is the EKF's, and its ELF.
type Built = (String, bool, PathBuf);

/// What QEMU reported for a [`Built`] program: the design, whether it is the EKF's, what the program
/// printed and the instructions and divisions of each measured call.
type Ran = (String, bool, String, Vec<(u64, u64)>);

/// Builds and runs, per design, two programs on the emulated chip: one that runs the map and every
/// observer the map starts ([`kinds`]) one after the other, and one that runs the EKF from the box
/// centre; then the size probes (one per design and kind, the families, a baseline). QEMU runs on a
/// second thread while cargo builds the next program. `Err(Unavailable::Missing)` when QEMU or
/// binutils are missing.
pub fn measure() -> Result<Measurements, Unavailable> {
    let designs: Vec<(String, Vec<Kind>)> = design_names()
        .into_iter()
        .map(|name| (name.to_owned(), kinds(name)))
        .collect();
    measure_designs(&Program::project(), &designs, &generated::FAMILIES)
}

/// [`measure`] of `designs` (each with its kinds, the EKF from the centre among them) and
/// `families` (probes only) as `program` links them.
pub fn measure_designs(
    program: &Program,
    designs: &[(String, Vec<Kind>)],
    families: &[&str],
) -> Result<Measurements, Unavailable> {
    require_tools()?;
    let (ran, probes) = std::thread::scope(|scope| {
        let (send, receive) = std::sync::mpsc::channel::<Built>();
        let qemu = scope.spawn(move || -> Result<Vec<Ran>, Unavailable> {
            receive
                .into_iter()
                .map(|(name, ekf, elf)| {
                    let (text, counts) = run_counted(&elf)?;
                    Ok((name, ekf, text, counts))
                })
                .collect()
        });
        let built = (|| -> Result<Probes, Unavailable> {
            for (name, kinds) in designs {
                let name = name.as_str();
                for (group, suffix) in programs(kinds) {
                    let kinds: Vec<&str> = group.iter().map(|k| k.chip_name()).collect();
                    let elf = program
                        .build(
                            "on-target",
                            &[("ON_TARGET_DESIGN", name), ("ON_TARGET_KIND", &kinds.join(","))],
                            &format!("runs/{name}{suffix}.elf"),
                        )
                        .map_err(|e| failed(format!("on-target program of {name}: {e}")))?;
                    // The QEMU thread has stopped only after an error, which its result reports.
                    let _ = send.send((name.to_owned(), false, elf));
                }
                let elf = program
                    .build("ekf", &[("ON_TARGET_DESIGN", name)], &format!("runs/{name}.ekf.elf"))
                    .map_err(|e| failed(format!("EKF program of {name}: {e}")))?;
                let _ = send.send((name.to_owned(), true, elf));
            }
            drop(send);
            probe_all(program, designs, families)
        })();
        let ran = qemu
            .join()
            .unwrap_or_else(|_| Err(failed("the thread running QEMU panicked")));
        (ran, built)
    });
    let (ran, probes) = (ran?, probes?);

    let mut all = Measurements {
        family_flash_bytes: probes.families,
        ..Measurements::default()
    };
    for (name, ekf, text, counts) in ran {
        let cost = |kind: Kind| {
            probes
                .kinds
                .get(&(name.clone(), kind))
                .copied()
                .ok_or_else(|| failed(format!("{name}: no size probe of {kind:?}")))
        };
        if ekf {
            let mut filter = parse_ekf(&text)?;
            if counts.len() != filter.samples.len() {
                return Err(failed(format!(
                    "{name} EKF: {} measured calls for {} samples",
                    counts.len(),
                    filter.samples.len()
                )));
            }
            (filter.instructions, filter.divisions) = counts.into_iter().unzip();
            (filter.flash_bytes, filter.static_ram_bytes) = cost(Kind::Ekf)?;
            all.filters.insert(name, filter);
        } else {
            let observers = parse(&text)?;
            let samples: usize = observers.iter().map(|o| o.samples.len()).sum();
            if counts.len() != samples {
                return Err(failed(format!(
                    "{name}: {} measured calls for {samples} samples of {} observers",
                    counts.len(),
                    observers.len()
                )));
            }
            let mut counts = counts.into_iter();
            let by_kind = all.observers.entry(name.clone()).or_default();
            for mut observer in observers {
                (observer.instructions, observer.divisions) = counts.by_ref().take(observer.samples.len()).unzip();
                (observer.flash_bytes, observer.static_ram_bytes) = cost(observer.kind)?;
                if by_kind.insert(observer.kind, observer).is_some() {
                    return Err(failed(format!("{name}: one kind ran twice")));
                }
            }
        }
    }
    Ok(all)
}

/// The `on-target` programs that measure `kinds` (the EKF from the box centre has a program of its
/// own, `ekf`), each with its file name's suffix: the map and the observers it starts together, and
/// the restarted EKF alone, since it shares the filter's code with the map-started EKF and linked
/// together the compiler would inline it differently ([`same_alone`] checks that it does not).
fn programs(kinds: &[Kind]) -> Vec<(Vec<Kind>, &'static str)> {
    let started: Vec<Kind> = kinds
        .iter()
        .copied()
        .filter(|&k| k != Kind::Ekf && k != Kind::RestartedEkf)
        .collect();
    let mut programs = vec![(started, "")];
    if kinds.contains(&Kind::RestartedEkf) {
        programs.push((vec![Kind::RestartedEkf], ".restarted_ekf"));
    }
    programs
}

/// What the size probes measured: `(flash, static RAM)` added over the baseline per design and
/// kind, and the families' flash.
struct Probes {
    kinds: BTreeMap<(String, Kind), (u64, u64)>,
    families: BTreeMap<String, u64>,
}

/// Builds the baseline probe, one probe per design and kind, and one per family.
fn probe_all(program: &Program, designs: &[(String, Vec<Kind>)], families: &[&str]) -> Result<Probes, Unavailable> {
    let baseline = sizes(
        &program
            .build("probe", &[], "probes/baseline.elf")
            .map_err(|e| failed(format!("baseline probe: {e}")))?,
    )?;
    let mut kinds = BTreeMap::new();
    for (name, design_kinds) in designs {
        for &kind in design_kinds {
            let probe = program
                .build(
                    "probe",
                    &[("PROBE_DESIGN", name), ("PROBE_KIND", kind.chip_name())],
                    &format!("probes/{name}.{}.elf", kind.chip_name()),
                )
                .map_err(|e| {
                    failed(format!(
                        "probe of {name}'s {} (a panic path would show here): {e}",
                        kind.api()
                    ))
                })?;
            let (text, data, bss) = sizes(&probe)?;
            let cost = (
                (text + data).saturating_sub(baseline.0 + baseline.1),
                (data + bss).saturating_sub(baseline.1 + baseline.2),
            );
            kinds.insert((name.clone(), kind), cost);
        }
    }
    let mut family_flash = BTreeMap::new();
    for &family in families {
        let probe = program
            .build("probe", &[("PROBE_DESIGN", family)], &format!("probes/{family}.elf"))
            .map_err(|e| failed(format!("probe of family {family}: {e}")))?;
        let (text, data, _) = sizes(&probe)?;
        family_flash.insert(family.to_owned(), (text + data).saturating_sub(baseline.0 + baseline.1));
    }
    Ok(Probes {
        kinds,
        families: family_flash,
    })
}

/// QEMU and binutils, or which is missing.
fn require_tools() -> Result<(), Unavailable> {
    require_emulator()?;
    require("arm-none-eabi-objdump", "binutils-arm-none-eabi")
}

/// QEMU (to run a program, [`run_on_emulator`]) and `arm-none-eabi-size` (to measure it, [`sizes`]),
/// or which is missing.
pub fn require_emulator() -> Result<(), Unavailable> {
    require("qemu-system-arm", "qemu-system-arm")?;
    require("arm-none-eabi-size", "binutils-arm-none-eabi")
}

/// Runs `elf` under QEMU with an execution trace beside it and returns what it printed, and the
/// instructions and divisions of each measured call.
fn run_counted(elf: &Path) -> Result<(String, Vec<(u64, u64)>), Unavailable> {
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

/// Builds the runner of design `name` with `kind` alone and returns the instructions of each of its
/// measured calls: the report checks that running several kinds in one program ([`measure`]) counts
/// what each kind counts when linked alone ([`same_alone`]).
pub fn instructions_alone(program: &Program, name: &str, kind: Kind) -> Result<Vec<u64>, Unavailable> {
    require_tools()?;
    if kind == Kind::Ekf {
        return Err(failed("the EKF from the box centre runs alone already"));
    }
    let elf = program
        .build(
            "on-target",
            &[("ON_TARGET_DESIGN", name), ("ON_TARGET_KIND", kind.chip_name())],
            &format!("runs/{name}.{}.elf", kind.chip_name()),
        )
        .map_err(|e| failed(format!("on-target program of {name}'s {} alone: {e}", kind.api())))?;
    let (_, counts) = run_counted(&elf)?;
    Ok(counts.into_iter().map(|(n, _)| n).collect())
}

/// Checks that every kind of every design that ran with others counts, built alone, the same
/// instructions: the program that runs them together measures what a firmware with one kind runs.
pub fn same_alone(program: &Program, all: &Measurements) -> Result<(), String> {
    for (name, observers) in &all.observers {
        let kinds: Vec<Kind> = observers.keys().copied().collect();
        let shared: Vec<Kind> = programs(&kinds)
            .into_iter()
            .filter(|(group, _)| group.len() > 1)
            .flat_map(|(group, _)| group)
            .collect();
        for (&kind, observer) in observers.iter().filter(|(k, _)| shared.contains(k)) {
            let alone = instructions_alone(program, name, kind).map_err(|e| e.to_string())?;
            if alone != observer.instructions {
                return Err(format!(
                    "{name} {}: linked with the other kinds it counts {:?}, alone {alone:?}: the program that runs them together does not measure what a firmware with this kind alone runs",
                    kind.api(),
                    observer.instructions
                ));
            }
        }
    }
    Ok(())
}

/// One sample of a design's extended Kalman filter as the target reported it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EkfSample {
    /// The bits of the targets of the updated estimate `push` returned, in `TARGET_NAMES` order;
    /// `None` when `push` refused the sample.
    pub targets: Option<Vec<u32>>,
    /// The bits of the filter's state after the sample (`state()`: the prediction to the next one).
    pub state: Vec<u32>,
}

impl EkfSample {
    /// Whether `push` accepted the sample.
    pub fn accepted(&self) -> bool {
        self.targets.is_some()
    }
}

/// Everything measured for one design's extended Kalman filter.
#[derive(Clone, Debug, Default)]
pub struct EkfMeasurement {
    /// Samples in the recorded sequence order.
    pub samples: Vec<EkfSample>,
    /// Instructions executed by `push` + `targets` per sample (markers included).
    pub instructions: Vec<u64>,
    /// `VDIV` and `VSQRT` instructions executed per sample.
    pub divisions: Vec<u64>,
    /// Deepest stack use of `push` + `targets` (the call to them included), in bytes.
    pub stack_bytes: usize,
    /// `size_of` the filter on the target, in bytes.
    pub filter_bytes: usize,
    /// Flash (text + data) added by the filter over the baseline probe, in bytes.
    pub flash_bytes: u64,
    /// Static RAM (data + bss) added over the baseline probe, in bytes.
    pub static_ram_bytes: u64,
}

impl EkfMeasurement {
    /// The instructions split into start-up and steady state ([`phases`]): the filter estimates
    /// from its first accepted sample, which is its whole start-up.
    pub fn phases(&self) -> Result<Phases, String> {
        let accepted: Vec<bool> = self.samples.iter().map(EkfSample::accepted).collect();
        phases(&self.instructions, &accepted, &accepted, 0)
    }
}

/// Parses the EKF program's `K …`, `S …` and `STACK …` lines.
fn parse_ekf(text: &str) -> Result<EkfMeasurement, Unavailable> {
    let mut filter = EkfMeasurement::default();
    let bits = |fields: &[&str]| -> Result<Vec<u32>, Unavailable> {
        fields
            .iter()
            .map(|f| u32::from_str_radix(f, 16).map_err(|e| failed(format!("{f:?} in the EKF output: {e}"))))
            .collect()
    };
    for line in text.lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        match fields.as_slice() {
            ["K", _k, accepted, rest @ ..] => {
                let marker = rest
                    .iter()
                    .position(|&f| f == "X")
                    .ok_or_else(|| failed(format!("no state in {line:?}")))?;
                let (targets, state) = (&rest[..marker], &rest[marker + 1..]);
                filter.samples.push(EkfSample {
                    targets: (*accepted == "1").then(|| bits(targets)).transpose()?,
                    state: bits(state)?,
                });
            }
            ["S", bytes] => {
                filter.filter_bytes = bytes.parse().map_err(|e| failed(format!("{line:?}: {e}")))?;
            }
            ["STACK", bytes] => {
                filter.stack_bytes = bytes.parse().map_err(|e| failed(format!("{line:?}: {e}")))?;
            }
            _ => {}
        }
    }
    if filter.samples.is_empty() {
        return Err(failed(format!("no sample in the EKF output:\n{text}")));
    }
    Ok(filter)
}

/// One sample of an extended Kalman filter run on the host: the targets of the estimate `push`
/// returned (`None` when refused) and the state after the sample.
pub type HostEkfSample<T> = (Option<Vec<T>>, Vec<T>);

/// Runs design `name`'s extended Kalman filter (`Ekf::<T>::new()`, the written-out one) on the host over the recorded
/// sequence the chip runs (`RECORDED_Y`, `RECORDED_U`, each value taken exactly into `T`); `None` for
/// an unknown design.
pub fn host_ekf<T: Scalar + Maths>(name: &str) -> Option<Vec<HostEkfSample<T>>> {
    let mut samples = None;
    macro_rules! run {
        ($design:ident) => {
            if generated::$design::NAME == name {
                use generated::$design as d;
                let exact = |v: f32| T::literal(v, f64::from(v));
                let mut filter = d::Ekf::<T>::new();
                samples = Some(
                    d::RECORDED_Y
                        .iter()
                        .zip(&d::RECORDED_U)
                        .map(|(y, u)| {
                            let (y, u) = (y.map(exact), u.map(exact));
                            let targets = filter.push(&y, &u).ok().map(|x| d::targets(&x, &u).to_vec());
                            (targets, filter.state().to_vec())
                        })
                        .collect(),
                );
            }
        };
    }
    generated::for_each_design!(run);
    samples
}

/// The largest `|target − host|` over the targets of design `name`'s extended Kalman filter, the chip
/// (f32) against the same filter in f64 on the host over the same recorded sequence; an error when the
/// two do not refuse the same samples.
pub fn compare_ekf_with_f64(name: &str, measured: &EkfMeasurement) -> Result<f64, String> {
    let host = host_ekf::<f64>(name).ok_or_else(|| format!("no generated design {name}"))?;
    let targets: Vec<Option<Vec<f64>>> = host.into_iter().map(|(targets, _)| targets).collect();
    ekf_largest_difference(&format!("{name} EKF"), measured, &targets)
}

/// The largest `|chip − host|` of an EKF's targets, `host` giving per sample the f64 filter's targets
/// (`None` where it refused the sample); an error when the two do not refuse the same samples or a
/// difference is NaN (one side NaN, the other not).
pub fn ekf_largest_difference(what: &str, measured: &EkfMeasurement, host: &[Option<Vec<f64>>]) -> Result<f64, String> {
    if host.len() != measured.samples.len() {
        return Err(format!(
            "{what}: {} samples on the target, {} recorded",
            measured.samples.len(),
            host.len()
        ));
    }
    let mut largest: f64 = 0.0;
    for (k, (sample, host_targets)) in measured.samples.iter().zip(host).enumerate() {
        match (&sample.targets, host_targets) {
            (Some(target), Some(host)) => {
                for (t, (&bits, &h)) in target.iter().zip(host).enumerate() {
                    let on_target = f64::from(f32::from_bits(bits));
                    if on_target.is_nan() && h.is_nan() {
                        continue;
                    }
                    let difference = (on_target - h).abs();
                    if difference.is_nan() {
                        return Err(format!(
                            "{what} sample {k} target {t}: {on_target} on the target, {h} on the host"
                        ));
                    }
                    largest = largest.max(difference);
                }
            }
            (None, None) => {}
            (target, _) => {
                return Err(format!(
                    "{what} sample {k}: accepted {} on the target, {} on the host",
                    target.is_some(),
                    host_targets.is_some()
                ))
            }
        }
    }
    Ok(largest)
}

/// Estimates as the chip prints them: per target the value's bits and the saturation flag.
pub fn bits_and_flags<T: Scalar>(estimates: &[Estimate<T>], bits: impl Fn(T) -> u32) -> Vec<(u32, char)> {
    estimates
        .iter()
        .map(|e| (bits(e.value), chip_flag(e.saturation)))
        .collect()
}

/// The saturation flag as the chip prints it.
pub fn chip_flag(saturation: Saturation) -> char {
    match saturation {
        Saturation::Low => 'L',
        Saturation::Inside => 'I',
        Saturation::High => 'H',
    }
}

/// Runs design `name`'s observer of `kind` on the host in f32, over the recorded sequence the chip
/// runs (`RECORDED_Y`, `RECORDED_U`): per sample whether `push` accepted it and what `estimate`
/// gave, as the chip reports them. `None` for the EKF from the box centre (see [`host_ekf`]), an
/// unknown design or a kind the design does not have.
pub fn host_samples(name: &str, kind: Kind) -> Option<Vec<TargetSample>> {
    let mut samples = None;
    macro_rules! run {
        ($design:ident, $fresh:expr) => {{
            use generated::$design as d;
            let mut observer = $fresh;
            d::RECORDED_Y
                .iter()
                .zip(&d::RECORDED_U)
                .map(|(y, u)| TargetSample {
                    accepted: observer.push(*y, *u).is_ok(),
                    estimates: observer.estimate().map(|e| bits_and_flags(&e, f32::to_bits)),
                })
                .collect::<Vec<_>>()
        }};
    }
    macro_rules! map {
        ($design:ident) => {
            if kind == Kind::Map && stringify!($design) == name {
                samples = Some(run!($design, generated::$design::map_observer()));
            }
        };
    }
    generated::for_each_design!(map);
    macro_rules! started {
        ($design:ident, $kind:ident, $type:ident) => {
            if kind == Kind::$kind && stringify!($design) == name {
                samples = Some(run!($design, generated::$design::$type::new()));
            }
        };
    }
    for_each_started_observer!(started);
    samples
}

/// The estimates after the first that take the start-up path of an observer the map starts or checks.
trait StartUp {
    /// `Follower::START_UP` of a started observer's follower; `N − 1` for the restarted EKF, whose
    /// estimate number `N` checks the map.
    const START_UP: usize;
}

impl<D, F, const N: usize, const NY: usize, const NU: usize, const NT: usize, const NX: usize> StartUp
    for Started<f32, D, F, N, NY, NU, NT, NX>
where
    F: Follower<f32, NX, NY, NU, NT>,
{
    const START_UP: usize = F::START_UP;
}

impl<D, F, const N: usize, const NY: usize, const NU: usize, const NT: usize, const NX: usize> StartUp
    for firmware::Restarted<f32, D, F, N, NY, NU, NT, NX>
where
    F: firmware::Restart<f32, NX, NY, NU, NT>,
{
    const START_UP: usize = N - 1;
}

fn follower_start_up<O: StartUp>(_: &O) -> usize {
    O::START_UP
}

/// The estimates after the first that take the start-up path, for design `name`'s observer of
/// `kind`, from the generated code (0 for the map and the EKF); `None` for a kind it does not have.
pub fn start_up(name: &str, kind: Kind) -> Option<usize> {
    if !kinds(name).contains(&kind) {
        return None;
    }
    let mut start_up = Some(0);
    macro_rules! started {
        ($design:ident, $kind:ident, $type:ident) => {
            if kind == Kind::$kind && stringify!($design) == name {
                start_up = Some(follower_start_up(&generated::$design::$type::new()));
            }
        };
    }
    for_each_started_observer!(started);
    start_up
}

/// Every difference between what the chip reported (`chip`) and what the host computed (`host`),
/// sample by sample, one line each naming `what`, the sample and the target; empty when the two
/// are equal bit for bit (acceptance, the presence of an estimate, each value's bits and flag).
pub fn differences(what: &str, chip: &[TargetSample], host: &[TargetSample]) -> Vec<String> {
    let mut found = Vec::new();
    if chip.len() != host.len() {
        found.push(format!(
            "{what}: {} samples on the chip, {} on the host",
            chip.len(),
            host.len()
        ));
    }
    for (k, (chip, host)) in chip.iter().zip(host).enumerate() {
        if chip.accepted != host.accepted {
            found.push(format!(
                "{what} sample {k}: accepted {} on the chip, {} on the host",
                chip.accepted, host.accepted
            ));
        }
        match (&chip.estimates, &host.estimates) {
            (Some(on_chip), Some(on_host)) => {
                if on_chip.len() != on_host.len() {
                    found.push(format!(
                        "{what} sample {k}: {} targets on the chip, {} on the host",
                        on_chip.len(),
                        on_host.len()
                    ));
                }
                for (t, (c, h)) in on_chip.iter().zip(on_host).enumerate() {
                    if c != h {
                        found.push(format!(
                            "{what} sample {k} target {t}: chip {:08x} {} ({:e}), host {:08x} {} ({:e})",
                            c.0,
                            c.1,
                            f32::from_bits(c.0),
                            h.0,
                            h.1,
                            f32::from_bits(h.0)
                        ));
                    }
                }
            }
            (None, None) => {}
            (on_chip, on_host) => found.push(format!(
                "{what} sample {k}: an estimate on the chip: {}, on the host: {}",
                on_chip.is_some(),
                on_host.is_some()
            )),
        }
    }
    found
}

/// [`differences`] for an extended Kalman filter: the targets of every estimate `push` returned
/// (`None` when refused) and the state after every sample.
pub fn ekf_differences(what: &str, chip: &[EkfSample], host: &[HostEkfSample<f32>]) -> Vec<String> {
    let mut found = Vec::new();
    if chip.len() != host.len() {
        found.push(format!(
            "{what}: {} samples on the chip, {} on the host",
            chip.len(),
            host.len()
        ));
    }
    let bits = |values: &[f32]| values.iter().map(|v| v.to_bits()).collect::<Vec<u32>>();
    for (k, (chip, (targets, state))) in chip.iter().zip(host).enumerate() {
        let targets = targets.as_deref().map(bits);
        if chip.targets != targets {
            found.push(format!(
                "{what} sample {k}: targets {:x?} on the chip, {targets:x?} on the host",
                chip.targets
            ));
        }
        if chip.state != bits(state) {
            found.push(format!(
                "{what} sample {k}: state {:x?} on the chip, {:x?} on the host",
                chip.state,
                bits(state)
            ));
        }
    }
    found
}

/// The largest `|target − host|` of design `name`'s observer that the map starts, measured on the
/// chip (f32), against the host's mirror of the same observer in f64 (`host::observers`) started by
/// the library's f64 map, over the same recorded sequence (the mirror runs the accepted samples: a
/// refused one changes nothing). An error for a kind the design does not have, or when the two do
/// not estimate at the same samples.
pub fn compare_started_with_f64(name: &str, measured: &ObserverMeasurement) -> Result<f64, String> {
    use host::data::{Rows, Run};
    use host::observers::{corrected, ekf};
    use host::plant::correction::correction_code;
    use host::plant::kalman::filter_code;
    use host::plant::ModelCode;

    let path = crate::shipped_specs()
        .into_iter()
        .find(|p| host::spec::load(p).is_ok_and(|d| d.name == name))
        .ok_or_else(|| format!("no shipped spec for {name}"))?;
    let design = crate::settled(host::spec::load(&path).map_err(|e| e.to_string())?);
    let result = crate::build(&design);
    let code = ModelCode::new(&design).map_err(|e| e.to_string())?;
    let state_targets = corrected::state_targets(&design)?;
    let first = design.map.horizon - 1;
    let widen = |values: &[f32]| values.iter().map(|&v| f64::from(v)).collect::<Vec<f64>>();
    let mut host: Option<Vec<Vec<f64>>> = None;
    macro_rules! mirror {
        ($design:ident, $kind:ident, $type:ident) => {
            if measured.kind == Kind::$kind && stringify!($design) == name {
                use generated::$design as d;
                // Every sample, the refused ones included: over them the observer carries its state
                // one period (`Follower::predict`).
                let all: Vec<(Vec<f64>, Vec<f64>)> = d::RECORDED_Y
                    .iter()
                    .zip(&d::RECORDED_U)
                    .map(|(y, u)| (widen(y), widen(u)))
                    .collect();
                let rows: Vec<host::recording::Row> = all
                    .iter()
                    .map(|(y, u)| host::recording::Row {
 time: None,
                        run: String::new(),
                        y: y.clone(),
                        u: u.clone(),
                    })
                    .collect();
                let maps: Vec<Vec<f64>> = host::recording::regressors(design.map.horizon, &rows)
                    .iter()
                    .map(|z| match z {
                        Some(z) => result.targets.iter().map(|t| t.fit.map.estimate(z).value).collect(),
                        None => vec![f64::NAN; d::TARGETS],
                    })
                    .collect();
                let run = Run {
                    states: Rows::from(vec![vec![0.0; d::STATES]; all.len()]),
                    inputs: Rows::from(all.iter().map(|(_, u)| u.clone()).collect::<Vec<_>>()),
                    measurements: Rows::from(all.iter().map(|(y, _)| y.clone()).collect::<Vec<_>>()),
                    targets: Rows::from(vec![vec![0.0; d::TARGETS]; all.len()]),
                    parameters: Vec::new(),
                };
                let estimates: Vec<Vec<f64>> = mirror!(@ $kind, d, design, code, state_targets, first, maps, run);
                host = Some(
                    estimates
                        .into_iter()
                        .zip(&all)
                        .filter(|(_, (y, u))| y.iter().chain(u).all(|v| v.is_finite()))
                        .map(|(estimate, _)| estimate)
                        .collect(),
                );
            }
        };
        (@ Corrected, $d:ident, $design:ident, $code:ident, $targets:ident, $first:ident, $maps:ident, $run:ident) => {{
            let (constants, _) = crate::emitted_constants!($d, &$design);
            let setting = corrected::Setting {
                code: &$code,
                h: constants.h,
                substeps: constants.substeps,
                state_targets: &$targets,
                first: $first,
                lower: constants.lower.clone(),
                upper: constants.upper.clone(),
            };
            corrected::estimate_run::<f64>(&setting, &correction_code(&$code, &constants), &constants, &$maps, &$run)
        }};
        (@ StartedEkf, $d:ident, $design:ident, $code:ident, $targets:ident, $first:ident, $maps:ident, $run:ident) => {{
            let (_, ekf_constants) = crate::emitted_constants!($d, &$design);
            let filter = filter_code(&$code, &ekf_constants);
            ekf::estimate_started::<f64>(&filter, &$d::STARTED_P0, &$targets, $first, &$maps, &$run, &$code)
        }};
        (@ RestartedEkf, $d:ident, $design:ident, $code:ident, $targets:ident, $first:ident, $maps:ident, $run:ident) => {{
            let (_, mut ekf_constants) = crate::emitted_constants!($d, &$design);
            // The filter's start as emitted: the box centre and P(0)'s diagonal.
            let (x0, upper) = <$d::StartedEkf as firmware::Restart<
                f64,
                { $d::STATES },
                { $d::OUTPUTS },
                { $d::INPUTS },
                { $d::TARGETS },
            >>::FRESH;
            ekf_constants.x0 = x0.to_vec();
            ekf_constants.p0 = (0..$d::STATES)
                .map(|i| upper[host::plant::kalman::upper($d::STATES, i, i)])
                .collect();
            let filter = filter_code(&$code, &ekf_constants);
            let restart = host::observers::restart::RestartConstants {
                threshold: $d::RESTART_THRESHOLD,
                variances: $d::RESTART_VARIANCES.to_vec(),
            };
            host::observers::restart::estimate::<f64>(
                &filter,
                &ekf_constants,
                &$d::STARTED_P0,
                &restart,
                &$targets,
                &$maps,
                &$run,
                &$code,
            )
        }};
    }
    for_each_started_observer!(mirror);
    let host = host.ok_or_else(|| format!("{name} has no {:?} observer", measured.kind))?;
    let chip: Vec<&TargetSample> = measured.samples.iter().filter(|s| s.accepted).collect();
    if chip.len() != host.len() {
        return Err(format!(
            "{name} {:?}: {} accepted samples on the chip, {} on the host",
            measured.kind,
            chip.len(),
            host.len()
        ));
    }
    let mut largest: f64 = 0.0;
    for (k, (sample, host)) in chip.iter().zip(&host).enumerate() {
        let before_first = host.iter().all(|v| v.is_nan());
        match &sample.estimates {
            None if before_first => {}
            Some(estimates) if !before_first => {
                for (t, (&(bits, _), &h)) in estimates.iter().zip(host).enumerate() {
                    let difference = (f64::from(f32::from_bits(bits)) - h).abs();
                    if difference.is_nan() {
                        return Err(format!(
                            "{name} {:?} accepted sample {k} target {t}: {} on the chip, {h} on the host",
                            measured.kind,
                            f32::from_bits(bits)
                        ));
                    }
                    largest = largest.max(difference);
                }
            }
            estimates => {
                return Err(format!(
                    "{name} {:?} accepted sample {k}: an estimate on the chip: {}, on the host: {}",
                    measured.kind,
                    estimates.is_some(),
                    !before_first
                ))
            }
        }
    }
    Ok(largest)
}

/// Builds the probe that indexes out of bounds: it must fail to link, naming the missing symbol.
pub fn panic_check_catches_a_reachable_panic() -> Result<bool, Unavailable> {
    match Program::project().build(
        "probe",
        &[("PROBE_DESIGN", "__reachable_panic")],
        "probes/reachable_panic.elf",
    ) {
        Ok(_) => Ok(false),
        Err(stderr) => Ok(stderr.contains("observer_code_can_panic")),
    }
}

/// One observer's figures as the reports give them.
#[derive(Clone, Debug)]
pub struct Figures {
    /// Its instructions split into start-up and steady state.
    pub phases: Phases,
    /// Most `VDIV` + `VSQRT` of a sample.
    pub divisions: u64,
    /// Deepest stack use of a sample, in bytes.
    pub stack_bytes: u64,
    /// Flash added to a program, in bytes.
    pub flash_bytes: u64,
    /// RAM: the observer itself and the static RAM it adds, in bytes.
    pub ram_bytes: u64,
    /// Largest `|chip − host f64|` over the recorded sequence (target units).
    pub largest: f64,
}

impl Figures {
    /// A map or an observer it starts, `largest` from comparing it with the host.
    pub fn of_observer(observer: &ObserverMeasurement, largest: f64) -> Result<Self, String> {
        Ok(Figures {
            phases: observer.phases()?,
            divisions: observer.divisions.iter().copied().max().unwrap_or(0),
            stack_bytes: observer.stack_bytes as u64,
            flash_bytes: observer.flash_bytes,
            ram_bytes: observer.observer_bytes as u64 + observer.static_ram_bytes,
            largest,
        })
    }

    /// The EKF from the box centre, `largest` from comparing it with the host.
    pub fn of_filter(filter: &EkfMeasurement, largest: f64) -> Result<Self, String> {
        Ok(Figures {
            phases: filter.phases()?,
            divisions: filter.divisions.iter().copied().max().unwrap_or(0),
            stack_bytes: filter.stack_bytes as u64,
            flash_bytes: filter.flash_bytes,
            ram_bytes: filter.filter_bytes as u64 + filter.static_ram_bytes,
            largest,
        })
    }

    /// As recorded beside a report.
    pub fn on_target(&self) -> host::report::on_target::OnTarget {
        let (_, median, max) = spread(&self.phases.steady);
        host::report::on_target::OnTarget {
            instructions_median: median,
            instructions_max: max,
            start_up_instructions_max: Some(self.phases.start_up_max),
            start_up_samples: Some(self.phases.start_up_samples as u64),
            divisions: self.divisions,
            flash_bytes: self.flash_bytes,
            ram_bytes: self.ram_bytes,
            stack_bytes: self.stack_bytes,
            largest_difference: Some(self.largest),
        }
    }
}

/// `(min, median, max)`.
pub fn spread(values: &[u64]) -> (u64, u64, u64) {
    let mut sorted = values.to_vec();
    sorted.sort_unstable();
    if sorted.is_empty() {
        return (0, 0, 0);
    }
    (sorted[0], sorted[sorted.len() / 2], sorted[sorted.len() - 1])
}

/// Compares the target's estimates of design `name` with the host's f64 library estimates on the
/// same recorded sequence, by [`host::emit::precision::compare`]; returns the largest `|target - host|`.
pub fn compare_with_library(name: &str, measured: &ObserverMeasurement) -> Result<f64, String> {
    let path = crate::shipped_specs()
        .into_iter()
        .find(|p| host::spec::load(p).is_ok_and(|d| d.name == name))
        .ok_or_else(|| format!("no shipped spec for {name}"))?;
    let design = crate::settled(host::spec::load(&path).map_err(|e| e.to_string())?);
    let result = crate::build(&design);
    let rows = host::emit::recorded_sequence(&result.scenario);
    if rows.len() != measured.samples.len() {
        return Err(format!(
            "{name}: {} samples on the target, {} recorded",
            measured.samples.len(),
            rows.len()
        ));
    }
    let horizon = design.map.horizon;
    let regressors = host::recording::regressors(horizon, &rows);
    let mut largest: f64 = 0.0;
    for (k, ((row, sample), z)) in rows.iter().zip(&measured.samples).zip(&regressors).enumerate() {
        let finite = row.y.iter().chain(&row.u).all(|v| v.is_finite());
        if finite != sample.accepted {
            return Err(format!(
                "{name} sample {k}: accepted {} on the target, finite = {finite}",
                sample.accepted
            ));
        }
        let (Some(estimates), Some(z)) = (&sample.estimates, z) else {
            if z.is_some() {
                return Err(format!(
                    "{name} sample {k}: no estimate on the target after {horizon} samples"
                ));
            }
            continue;
        };
        for (t, ((bits, flag), fitted)) in estimates
            .iter()
            .zip(result.targets.iter().map(|t| &t.fit.map))
            .enumerate()
        {
            let table = fitted
                .table
                .as_ref()
                .ok_or_else(|| format!("{name}: target {t} has no table"))?;
            let saturation = match flag {
                'L' => Saturation::Low,
                'I' => Saturation::Inside,
                'H' => Saturation::High,
                other => {
                    return Err(format!(
                        "{name} sample {k} target {t}: unknown saturation flag {other:?}"
                    ))
                }
            };
            let on_target = Estimate {
                value: f32::from_bits(*bits),
                saturation,
            };
            let difference = compare(table, z, on_target, fitted.estimate(z))
                .map_err(|mismatch| format!("{name} sample {k} target {t}: target vs host: {mismatch}"))?
                .difference;
            largest = largest.max(difference);
        }
    }
    Ok(largest)
}
