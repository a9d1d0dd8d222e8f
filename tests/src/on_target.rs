//! Running the generated observers on the emulated Cortex-M4F (QEMU `mps2-an386`) and measuring them:
//! estimates over semihosting, instructions per `push` + `estimate` from an execution trace, flash
//! and RAM from the ELF, and the no-panic proof (see `tests/on-target/`). Each design's extended
//! Kalman filter is measured the same way, in its own program ([`measure_ekf`]).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use firmware::{Estimate, Maths, Saturation, Scalar};
use host::emit::precision::compare;

use crate::workspace_root;

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

/// One sample as the target reported it.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetSample {
    /// Whether `push` accepted the sample.
    pub accepted: bool,
    /// `(value bits, saturation flag 'L'|'I'|'H')` per target, when an estimate existed.
    pub estimates: Option<Vec<(u32, char)>>,
}

/// Everything measured for one design.
#[derive(Clone, Debug, Default)]
pub struct DesignMeasurement {
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
    /// Flash (text + data) added by the design's observer over the baseline probe, in bytes.
    pub flash_bytes: u64,
    /// Static RAM (data + bss) added over the baseline probe, in bytes.
    pub static_ram_bytes: u64,
}

impl DesignMeasurement {
    /// Instruction counts of the samples that were accepted and gave an estimate (the steady state:
    /// a full window, the same path every sample).
    pub fn steady_instructions(&self) -> Vec<u64> {
        self.instructions
            .iter()
            .zip(&self.samples)
            .filter(|(_, s)| s.accepted && s.estimates.is_some())
            .map(|(n, _)| *n)
            .collect()
    }

    /// Instructions of the sample that gave the first estimate (the window just became full).
    pub fn first_estimate_instructions(&self) -> Option<u64> {
        self.samples
            .iter()
            .position(|s| s.estimates.is_some())
            .and_then(|k| self.instructions.get(k).copied())
    }
}

/// What a program measures: the map observer, or the design's extended Kalman filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Map,
    Ekf,
}

impl Kind {
    /// The runner binary of the on-target program.
    fn runner(self) -> &'static str {
        match self {
            Kind::Map => "on-target",
            Kind::Ekf => "ekf",
        }
    }

    /// The probe's `PROBE_KIND`.
    fn probe_kind(self) -> &'static str {
        match self {
            Kind::Map => "map",
            Kind::Ekf => "ekf",
        }
    }
}

/// Builds `bin` of the on-target program in release, linking design `design` (a runner's
/// `ON_TARGET_DESIGN`, the probe's `PROBE_DESIGN`, with `PROBE_KIND` from `kind`), into `target_dir`.
fn build(bin: &str, design: &str, kind: Kind, target_dir: &Path) -> Result<PathBuf, String> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let output = Command::new(cargo)
        .current_dir(workspace_root())
        .args(["build", "--release", "--manifest-path", "tests/on-target/Cargo.toml"])
        .args(["--target", "thumbv7em-none-eabihf", "--bin", bin, "--target-dir"])
        .arg(target_dir)
        .env(
            if bin == "probe" {
                "PROBE_DESIGN"
            } else {
                "ON_TARGET_DESIGN"
            },
            design,
        )
        .env("PROBE_KIND", kind.probe_kind())
        .output()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    if !output.status.success() {
        return Err(String::from_utf8_lossy(&output.stderr).into_owned());
    }
    Ok(target_dir.join("thumbv7em-none-eabihf/release").join(bin))
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
/// Output goes to a file, not a pipe (QEMU can hang when a pipe closes early), and a run that does not
/// finish within `timeout` is killed.
fn run_qemu(elf: &Path, trace: &Path, timeout: Duration) -> Result<String, Unavailable> {
    let output_file = trace.with_extension("out");
    let stdout = std::fs::File::create(&output_file).map_err(|e| failed(e.to_string()))?;
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
        .args(one_instruction_per_block()?)
        .args(["-d", "exec,nochain", "-D"])
        .arg(trace)
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
    let text = std::fs::read_to_string(&output_file).map_err(|e| failed(e.to_string()))?;
    if !status.success() || !text.contains("DONE") {
        return Err(failed(format!("the on-target program failed ({status}):\n{text}")));
    }
    Ok(text)
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

/// Parses the program's `E …`, `S …` and `STACK …` lines.
fn parse(text: &str) -> Result<DesignMeasurement, Unavailable> {
    let mut design = DesignMeasurement::default();
    for line in text.lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        match fields.as_slice() {
            ["E", _k, accepted, rest @ ..] => {
                let estimates = (!rest.is_empty()).then(|| {
                    rest.chunks(2)
                        .map(|c| {
                            (
                                u32::from_str_radix(c[0], 16).unwrap_or(0),
                                c.get(1).and_then(|f| f.chars().next()).unwrap_or('?'),
                            )
                        })
                        .collect()
                });
                design.samples.push(TargetSample {
                    accepted: *accepted == "1",
                    estimates,
                });
            }
            ["S", bytes] => design.observer_bytes = bytes.parse().unwrap_or(0),
            ["STACK", bytes] => design.stack_bytes = bytes.parse().unwrap_or(0),
            _ => {}
        }
    }
    if design.samples.is_empty() {
        return Err(failed(format!("no estimate in the output:\n{text}")));
    }
    Ok(design)
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
    /// Per design.
    pub designs: BTreeMap<String, DesignMeasurement>,
    /// Flash added by each family observer (all its members' tables and the selection) over the
    /// baseline probe, in bytes; its probe links, so it has no reachable panic either.
    pub family_flash_bytes: BTreeMap<String, u64>,
}

/// Builds and runs, per design, the on-target program linking that design alone, and the size
/// probes; returns the measurements. `Err(Unavailable::Missing)` when QEMU or binutils are missing.
pub fn measure() -> Result<Measurements, Unavailable> {
    require_tools()?;
    let root = workspace_root().join("target");
    let mut designs = BTreeMap::new();
    for name in design_names() {
        let (text, counts) = run_counted(Kind::Map, name)?;
        let mut design = parse(&text)?;
        if counts.len() != design.samples.len() {
            return Err(failed(format!(
                "{name}: {} measured calls for {} samples",
                counts.len(),
                design.samples.len()
            )));
        }
        (design.instructions, design.divisions) = counts.into_iter().unzip();
        designs.insert(name.to_owned(), design);
    }

    let probes = root.join("on-target-probe");
    let baseline = baseline_sizes(&probes)?;
    for (name, design) in designs.iter_mut() {
        (design.flash_bytes, design.static_ram_bytes) = probe_cost(Kind::Map, name, &probes, baseline)?;
    }
    let mut family_flash_bytes = BTreeMap::new();
    for family in generated::FAMILIES {
        let probe =
            build("probe", family, Kind::Map, &probes).map_err(|e| failed(format!("probe of family {family}: {e}")))?;
        let (text, data, _) = sizes(&probe)?;
        family_flash_bytes.insert(family.to_owned(), (text + data).saturating_sub(baseline.0 + baseline.1));
    }
    Ok(Measurements {
        designs,
        family_flash_bytes,
    })
}

/// QEMU and binutils, or which is missing.
fn require_tools() -> Result<(), Unavailable> {
    require("qemu-system-arm", "qemu-system-arm")?;
    require("arm-none-eabi-size", "binutils-arm-none-eabi")?;
    require("arm-none-eabi-objdump", "binutils-arm-none-eabi")
}

/// Builds the `kind` runner linking design `name` alone, runs it under QEMU with an execution trace
/// and returns what it printed, and the instructions and divisions of each measured call.
fn run_counted(kind: Kind, name: &str) -> Result<(String, Vec<(u64, u64)>), Unavailable> {
    let dir = workspace_root().join("target").join("on-target");
    let elf = build(kind.runner(), name, kind, &dir).map_err(failed)?;
    let trace = dir.join(match kind {
        Kind::Map => format!("{name}.trace"),
        Kind::Ekf => format!("{name}.ekf.trace"),
    });
    let text = run_qemu(&elf, &trace, Duration::from_secs(300))?;
    let counts = count_between(
        &trace,
        symbol(&elf, "measure_start")?,
        symbol(&elf, "measure_end")?,
        &division_addresses(&elf)?,
    )?;
    let _ = std::fs::remove_file(&trace);
    Ok((text, counts))
}

/// `(text, data, bss)` of the baseline probe (no observer), built into `probes`.
fn baseline_sizes(probes: &Path) -> Result<(u64, u64, u64), Unavailable> {
    sizes(&build("probe", "", Kind::Map, probes).map_err(|e| failed(format!("baseline probe: {e}")))?)
}

/// `(flash, static RAM)` added over `baseline` by the probe linking design `name`'s `kind`; the probe
/// failing to link (a reachable panic) is an error.
fn probe_cost(kind: Kind, name: &str, probes: &Path, baseline: (u64, u64, u64)) -> Result<(u64, u64), Unavailable> {
    let what = match kind {
        Kind::Map => "probe",
        Kind::Ekf => "EKF probe",
    };
    let probe = build("probe", name, kind, probes)
        .map_err(|e| failed(format!("{what} of {name} (a panic path would show here): {e}")))?;
    let (text, data, bss) = sizes(&probe)?;
    Ok((
        (text + data).saturating_sub(baseline.0 + baseline.1),
        (data + bss).saturating_sub(baseline.1 + baseline.2),
    ))
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
    /// Instruction counts of the accepted samples (update and prediction; a refused sample only
    /// predicts).
    pub fn accepted_instructions(&self) -> Vec<u64> {
        self.instructions
            .iter()
            .zip(&self.samples)
            .filter(|(_, s)| s.accepted())
            .map(|(n, _)| *n)
            .collect()
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
            ["S", bytes] => filter.filter_bytes = bytes.parse().unwrap_or(0),
            ["STACK", bytes] => filter.stack_bytes = bytes.parse().unwrap_or(0),
            _ => {}
        }
    }
    if filter.samples.is_empty() {
        return Err(failed(format!("no sample in the EKF output:\n{text}")));
    }
    Ok(filter)
}

/// Builds and runs, per design, the program running that design's extended Kalman filter alone, and
/// its size probe (measured against the same baseline as the map observers'); returns the
/// measurements by design. `Err(Unavailable::Missing)` when QEMU or binutils are missing.
pub fn measure_ekf() -> Result<BTreeMap<String, EkfMeasurement>, Unavailable> {
    require_tools()?;
    let mut filters = BTreeMap::new();
    for name in design_names() {
        let (text, counts) = run_counted(Kind::Ekf, name)?;
        let mut filter = parse_ekf(&text)?;
        if counts.len() != filter.samples.len() {
            return Err(failed(format!(
                "{name} EKF: {} measured calls for {} samples",
                counts.len(),
                filter.samples.len()
            )));
        }
        (filter.instructions, filter.divisions) = counts.into_iter().unzip();
        filters.insert(name.to_owned(), filter);
    }
    let probes = workspace_root().join("target").join("on-target-probe");
    let baseline = baseline_sizes(&probes)?;
    for (name, filter) in filters.iter_mut() {
        (filter.flash_bytes, filter.static_ram_bytes) = probe_cost(Kind::Ekf, name, &probes, baseline)?;
    }
    Ok(filters)
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
    if host.len() != measured.samples.len() {
        return Err(format!(
            "{name} EKF: {} samples on the target, {} recorded",
            measured.samples.len(),
            host.len()
        ));
    }
    let mut largest: f64 = 0.0;
    for (k, (sample, (host_targets, _))) in measured.samples.iter().zip(&host).enumerate() {
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
                            "{name} EKF sample {k} target {t}: {on_target} on the target, {h} on the host"
                        ));
                    }
                    largest = largest.max(difference);
                }
            }
            (None, None) => {}
            (target, _) => {
                return Err(format!(
                    "{name} EKF sample {k}: accepted {} on the target, {} on the host",
                    target.is_some(),
                    host_targets.is_some()
                ))
            }
        }
    }
    Ok(largest)
}

/// Builds the probe that indexes out of bounds: it must fail to link, naming the missing symbol.
pub fn panic_check_catches_a_reachable_panic() -> Result<bool, Unavailable> {
    match build(
        "probe",
        "__reachable_panic",
        Kind::Map,
        &workspace_root().join("target").join("on-target-probe"),
    ) {
        Ok(_) => Ok(false),
        Err(stderr) => Ok(stderr.contains("observer_code_can_panic")),
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

/// The recorded sequence of a design as the generated file holds it, rebuilt on the host in f64
/// (the scenario's measurements rounded to f32, with the same refused samples).
fn recorded_rows(result: &host::fit::DesignResult) -> Vec<host::recording::Row> {
    let scenario = &result.scenario;
    let refused = host::emit::refused_samples(scenario.measurements.len());
    scenario
        .measurements
        .iter()
        .zip(&scenario.inputs)
        .enumerate()
        .map(|(k, (y, u))| {
            let mut y: Vec<f64> = y.iter().map(|&v| f64::from(v as f32)).collect();
            match (refused.iter().position(|&r| r == k), y.first_mut()) {
                (Some(0), Some(first)) => *first = f64::NAN,
                (Some(_), Some(first)) => *first = f64::INFINITY,
                _ => {}
            }
            host::recording::Row {
                run: String::new(),
                y,
                u: u.iter().map(|&v| f64::from(v as f32)).collect(),
            }
        })
        .collect()
}

/// Compares the target's estimates of design `name` with the host's f64 library estimates on the
/// same recorded sequence, by [`host::emit::precision::compare`]; returns the largest `|target - host|`.
pub fn compare_with_library(name: &str, measured: &DesignMeasurement) -> Result<f64, String> {
    let path = crate::shipped_specs()
        .into_iter()
        .find(|p| host::spec::load(p).is_ok_and(|d| d.name == name))
        .ok_or_else(|| format!("no shipped spec for {name}"))?;
    let design = host::spec::load(&path).map_err(|e| e.to_string())?;
    let result = crate::build(&design);
    let rows = recorded_rows(&result);
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
