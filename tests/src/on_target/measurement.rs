//! What the chip measured, as plain data: per sample what it reported, per call the instructions,
//! and the start-up and steady phases they split into. Filled by [`measure`](super::measure), read by
//! the reports and the tests.

use std::collections::BTreeMap;

use super::board::Board;
use super::kind::Kind;

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
    /// Estimated cycles of `push` + `estimate` per sample ([`super::timing`]).
    pub cycles: Vec<u64>,
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
        self.split(&self.instructions)
    }

    /// The estimated cycles split the same way.
    pub fn cycle_phases(&self) -> Result<Phases, String> {
        self.split(&self.cycles)
    }

    fn split(&self, per_sample: &[u64]) -> Result<Phases, String> {
        let accepted: Vec<bool> = self.samples.iter().map(|s| s.accepted).collect();
        let estimated: Vec<bool> = self
            .samples
            .iter()
            .map(|s| s.accepted && s.estimates.is_some())
            .collect();
        phases(per_sample, &accepted, &estimated, self.start_up)
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

/// Everything measured on both emulated boards.
#[derive(Clone, Debug, Default)]
pub struct Boards {
    /// On the Cortex-M4F (QEMU `mps2-an386`): every kind of every design.
    pub m4f: Measurements,
    /// On the Cortex-M0 (QEMU `microbit`, software floating point): each design's map and EKF
    /// from the box centre (and its integer observer, where it has one).
    pub m0: Measurements,
}

/// Everything measured on one target.
#[derive(Clone, Debug, Default)]
pub struct Measurements {
    /// The board it ran on.
    pub board: Board,
    /// Per design, its map and the observers the map starts, by kind.
    pub observers: BTreeMap<String, BTreeMap<Kind, ObserverMeasurement>>,
    /// Per design, its EKF from the box centre.
    pub filters: BTreeMap<String, EkfMeasurement>,
    /// Flash added by each family observer (all its members' tables and the selection) over the
    /// baseline probe, in bytes; its probe links, so it has no reachable panic either.
    pub family_flash_bytes: BTreeMap<String, u64>,
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
    /// Estimated cycles of `push` + `targets` per sample ([`super::timing`]).
    pub cycles: Vec<u64>,
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

    /// The estimated cycles split the same way.
    pub fn cycle_phases(&self) -> Result<Phases, String> {
        let accepted: Vec<bool> = self.samples.iter().map(EkfSample::accepted).collect();
        phases(&self.cycles, &accepted, &accepted, 0)
    }
}
