//! The bank of UKFs on the host: its members ([`BankConstants::of`]) and one sample of the bank
//! ([`BankStep`]) in `T` as the emitted `UkfBank::push` runs it: every member by the filters' rules
//! ([`firmware::rules::filter_sample`], each with the box UKF's χ² watch), then the weights and the
//! mean of [`firmware::bank`].

use std::cell::RefCell;

use crate::data::{DataSet, Rows, Run};
use crate::observers::ekf::steps::Watcher;
use crate::observers::lost::{Track, Tracker};
use crate::observers::started::literals;
use crate::plant::kalman::{EkfConstants, FilterCode};
use crate::plant::{Coordinates, ModelCode};
use crate::spec::{Axis, Design};
use firmware::rules::{Refusals, Refused};

/// How a bank's slices of its axis are spaced.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Spacing {
    /// Equal widths in the filter's coordinate (the logarithm for a state bounded below): more
    /// members near the bound.
    Filter,
    /// Equal widths in the plant's coordinate: equal prior masses.
    Plant,
    /// Equal widths in `√(x − a)`, `a` the range's low end: between the two.
    Root,
}

/// A bank's layout: `members` UKFs over `axis`'s range in the state box, sliced by `spacing`, each
/// with `P(0)`'s entry on the axis `scale` times the box UKF's.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Layout {
    /// The state whose range the members split.
    pub axis: usize,
    /// Members, `M ≥ 2`.
    pub members: usize,
    /// How the slices are spaced.
    pub spacing: Spacing,
    /// `P(0)` on the axis, as a multiple of the box UKF's.
    pub scale: f64,
}

/// The bank's own constants: its layout and what it gives each member. It runs on the box UKF's
/// `Q`, `R`, substeps and watch.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BankConstants {
    /// How it was laid out.
    pub layout: Layout,
    /// Each member's start `x̂ₘ(0)`, in the filter's coordinates.
    pub x0: Vec<Vec<f64>>,
    /// Each member's `P(0)` diagonal, in the filter's coordinates.
    pub p0: Vec<Vec<f64>>,
    /// Each member's prior log-weight `ln πₘ`: the log of its slice's share of the box.
    pub prior: Vec<f64>,
}

impl BankConstants {
    /// The bank of `layout` over `design`'s state box around the box UKF `ukf` (its start and `P(0)`
    /// diagonal, in `coordinates`): member `m` starts at the centre, in the filter's coordinate, of
    /// slice `m` of the axis's range and weighs the slice's share of the range in the plant's
    /// coordinate (the box is drawn uniformly); `None` where the axis has no range.
    pub fn of(layout: Layout, design: &Design, coordinates: &Coordinates, ukf: &EkfConstants) -> Option<Self> {
        let Axis::Range { min, max, .. } = design.learning.axes[layout.axis] else {
            return None;
        };
        if max <= min || max.is_nan() || min.is_nan() || layout.members < 2 {
            return None;
        }
        let log = coordinates.0[layout.axis];
        let to_filter = |x: f64| log.map_or(x, |log| log.to_filter(x));
        let to_plant = |z: f64| log.map_or(z, |log| log.to_plant(z));
        // The spacing's coordinate `s(x)` and back: the slices are equal in it, each member starts at
        // its slice's centre in it.
        let (to_spaced, from_spaced): (Map<'_>, Map<'_>) = match layout.spacing {
            Spacing::Plant => (Box::new(|x| x), Box::new(|s| s)),
            Spacing::Filter => (Box::new(to_filter), Box::new(to_plant)),
            Spacing::Root => (
                Box::new(move |x: f64| (x - min).max(0.0).sqrt()),
                Box::new(move |s: f64| min + s * s),
            ),
        };
        let m = layout.members as f64;
        let (low, high) = (to_spaced(min), to_spaced(max));
        let at = |i: f64| from_spaced(low + i / m * (high - low));
        // The slices' edges, in the plant's coordinate.
        let edges: Vec<f64> = (0..=layout.members).map(|i| at(i as f64)).collect();
        let diagonal = ukf.p0.diagonal();
        let mut bank = BankConstants {
            layout,
            x0: Vec::new(),
            p0: Vec::new(),
            prior: Vec::new(),
        };
        for (i, slice) in edges.windows(2).enumerate() {
            let mut x0 = ukf.x0.clone();
            x0[layout.axis] = to_filter(at(i as f64 + 0.5));
            let mut p0 = diagonal.clone();
            p0[layout.axis] *= layout.scale;
            bank.x0.push(x0);
            bank.p0.push(p0);
            bank.prior.push(((slice[1] - slice[0]) / (max - min)).ln());
        }
        Some(bank)
    }
}

/// The bank `bank` over `run` in `T`, step for step the emitted `UkfBank::push` (the members' written-out
/// programs `member`, the box UKF's `constants`): per sample the targets of the weighted mean of
/// the members' `x̂(k|k)`, with the restarts on the run.
pub fn track_run(
    code: &ModelCode,
    member: &FilterCode,
    constants: &EkfConstants,
    bank: &BankConstants,
    run: &Run,
) -> Track {
    let mut step = BankStep::<f32>::new(member, constants, bank, code);
    let mut track = Tracker::new(code.dimensions.targets);
    for (y, u) in run.measurements.iter().zip(run.inputs.iter()) {
        let before = step.restarts();
        match step.step(y, u) {
            Some(targets) => track.estimate(targets.into_iter().map(f64::from)),
            None if step.restarts() > before => track.restarted(),
            None => track.refused(),
        }
    }
    track.finish()
}

/// The bank's estimates of every run of `data`.
pub fn estimates(
    code: &ModelCode,
    member: &FilterCode,
    constants: &EkfConstants,
    bank: &BankConstants,
    data: &DataSet,
) -> Vec<Rows> {
    use rayon::prelude::*;
    data.runs
        .par_iter()
        .map(|run| track_run(code, member, constants, bank, run).rows)
        .collect()
}

/// A coordinate map of one state.
type Map<'a> = Box<dyn Fn(f64) -> f64 + 'a>;

/// One member: `x`, `P`'s upper triangle and its watched mean, as the emitted `Ukf` carries them.
type Carried<T> = (Vec<T>, Vec<T>, T);

/// One sample of the bank at a time (see [`track_run`]).
pub struct BankStep<'a, T> {
    member: &'a FilterCode,
    /// The members as they are, and where each restarts.
    members: Vec<(Carried<T>, Carried<T>)>,
    /// The relative log-weights.
    log: Vec<T>,
    prior: Vec<T>,
    watch: Watcher<T>,
    refusals: Refusals,
    scratch: RefCell<Vec<T>>,
}

impl<'a, T: firmware::Scalar + firmware::emitted::Maths> BankStep<'a, T> {
    /// At the members' starts with their prior weights, before the first sample of a run.
    pub fn new(member: &'a FilterCode, constants: &EkfConstants, bank: &BankConstants, code: &ModelCode) -> Self {
        let watch = Watcher::new(&constants.watch, code.dimensions.outputs);
        let members = bank
            .x0
            .iter()
            .zip(&bank.p0)
            .map(|(x0, p0)| {
                let fresh = (
                    literals(x0),
                    literals(&crate::plant::kalman::diagonal_upper(p0)),
                    watch.start(),
                );
                (fresh.clone(), fresh)
            })
            .collect();
        let prior = literals(&bank.prior);
        BankStep {
            member,
            members,
            log: prior.clone(),
            prior,
            watch,
            refusals: Refusals::NONE,
            scratch: RefCell::new(Vec::new()),
        }
    }

    /// The targets after the sample with outputs `y` and inputs `u` (`None`: refused, or every
    /// member restarted).
    pub fn step(&mut self, y: &[f64], u: &[f64]) -> Option<Vec<T>> {
        let (y, u) = (literals::<T>(y), literals::<T>(u));
        let (inputs, outputs) = (u.iter().all(|v| v.is_finite()), y.iter().all(|v| v.is_finite()));
        let n = self.member.states;
        let count = self.members.len();
        let mut estimates = vec![vec![T::ZERO; n]; count];
        let mut evidence = vec![T::ZERO; count];
        let mut taken = vec![false; count];
        let mut refused = false;
        let (member, watch, scratch) = (self.member, self.watch, &self.scratch);
        for (m, (carried, fresh)) in self.members.iter_mut().enumerate() {
            let result = firmware::rules::filter_sample(
                carried,
                inputs,
                outputs,
                |(x, p, chi)| {
                    let ((estimate, x, p), scalars) = member.run_scored(x, p, &y, &u, &mut scratch.borrow_mut());
                    let e = firmware::bank::evidence(scalars[0], scalars[1]);
                    (
                        (estimate.expect("a measured sample has an estimate"), e),
                        (x, p, watch.watched(*chi, scalars[0])),
                    )
                },
                |(x, p, chi)| {
                    let (_, x, p) = member.run(x, p, None, &u, &mut scratch.borrow_mut());
                    (x, p, *chi)
                },
                |(x, p, chi)| x.iter().chain(p).all(|v| v.is_finite()) && watch.plausible(*chi),
                || fresh.clone(),
            );
            match result {
                Ok((estimate, e)) => {
                    estimates[m] = estimate;
                    evidence[m] = e;
                    taken[m] = true;
                }
                Err(Refused::Value) => refused = true,
                Err(Refused::Restarted) => {}
            }
        }
        let result = if refused {
            Err(Refused::Value)
        } else if !taken.iter().any(|&t| t) {
            self.log.clone_from(&self.prior);
            Err(Refused::Restarted)
        } else {
            firmware::bank::weigh(&mut self.log, &evidence, &taken);
            let mut mixed = vec![T::ZERO; n];
            firmware::bank::mix(&self.log, &taken, &estimates, &mut mixed);
            Ok(mixed)
        };
        let estimate = self.refusals.count(result).ok()?;
        Some(
            self.member
                .targets
                .eval(&self.member.parameters, &estimate, &u, &mut self.scratch.borrow_mut()),
        )
    }

    /// Samples refused so far for a bad value, as the chip counts them.
    pub fn refused(&self) -> u32 {
        self.refusals.get()
    }

    /// Restarts of the whole bank so far (every member at once), as the chip counts them.
    pub fn restarts(&self) -> u32 {
        self.refusals.restarts()
    }

    /// The members' relative log-weights now.
    pub fn log_weights(&self) -> &[T] {
        &self.log
    }
}

#[cfg(test)]
mod tests;
