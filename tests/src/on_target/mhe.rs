//! The chip's moving-horizon estimator (`mhe()` of a design, `tests/on-target/src/bin/mhe.rs`) on the
//! emulated Cortex-M4F: its estimates, instructions and divisions (VDIV, VSQRT) per sample, its size
//! and stack. Not yet a kind of [`super::Kind`]: measured for the designs a test names.

use super::elf::Program;
use super::qemu::run_counted;
use super::unavailable::{failed, require_tools, Unavailable};

/// One design's estimator, as the chip ran it.
#[derive(Clone, Debug)]
pub struct MheMeasurement {
    /// Per sample, the targets' bits when it gave an estimate.
    pub estimates: Vec<Option<Vec<u32>>>,
    /// Instructions of each sample's `push` + `targets`.
    pub instructions: Vec<u64>,
    /// Of them, divisions and square roots.
    pub divisions: Vec<u64>,
    /// `size_of` the estimator (its RAM).
    pub size_bytes: u64,
    /// Stack used by `push` + `targets`.
    pub stack_bytes: u64,
}

/// Builds and runs design `name`'s estimator on the emulated chip.
pub fn measure_mhe(name: &str) -> Result<MheMeasurement, Unavailable> {
    require_tools()?;
    let elf = Program::project()
        .build("mhe", &[("ON_TARGET_DESIGN", name)], &format!("runs/{name}.mhe.elf"))
        .map_err(|e| failed(format!("MHE program of {name}: {e}")))?;
    let (text, counts) = run_counted(&elf)?;
    let mut measured = MheMeasurement {
        estimates: Vec::new(),
        instructions: Vec::new(),
        divisions: Vec::new(),
        size_bytes: 0,
        stack_bytes: 0,
    };
    let number = |word: Option<&str>| -> Result<u64, Unavailable> {
        word.and_then(|w| w.parse().ok())
            .ok_or_else(|| failed(format!("{name} MHE: a malformed line in\n{text}")))
    };
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("K") => {
                let _sample = number(words.next())?;
                let estimated = number(words.next())? == 1;
                let bits: Result<Vec<u32>, _> = words.map(|w| u32::from_str_radix(w, 16)).collect();
                let bits = bits.map_err(|e| failed(format!("{name} MHE: {e} in {line}")))?;
                measured.estimates.push(estimated.then_some(bits));
            }
            Some("S") => measured.size_bytes = number(words.next())?,
            Some("STACK") => measured.stack_bytes = number(words.next())?,
            _ => {}
        }
    }
    if counts.len() != measured.estimates.len() {
        return Err(failed(format!(
            "{name} MHE: {} measured calls for {} samples",
            counts.len(),
            measured.estimates.len()
        )));
    }
    (measured.instructions, measured.divisions) = counts.into_iter().unzip();
    Ok(measured)
}
