//! The EKF over the written-out programs ([`crate::plant::kalman::FilterCode`]) in `T`, by the
//! firmware's own rules ([`firmware::rules`]) as the generated code runs them: from the box centre
//! (`Ekf::push`) and started by the map (`StartedEkf`). They predict the chip's bits; the programs
//! are interpreted, the rules are the chip's.

use std::cell::RefCell;

use crate::data::Run;
use crate::observers::lost::Track;
use crate::observers::started::{literal, literals, Shell};
use crate::plant::kalman::{EkfConstants, Watch};
use crate::plant::ModelCode;
use firmware::rules::Refusals;

/// The EKF from `constants.x0` (the box centre, or the spec's start) over `run`, in `T`, step for step the generated
/// `Ekf::push` (the written-out programs `filter`): per sample the targets of `x̂(k|k)`, or `None`
/// where the sample is refused (a non-finite output or input) or the filter restarted (a step whose
/// result is not finite, which is then not taken, or whose watch found its innovations implausible:
/// the filter starts again from `constants.x0`).
pub fn estimate_box<T: firmware::Scalar + firmware::emitted::Maths>(
    filter: &crate::plant::kalman::FilterCode,
    constants: &EkfConstants,
    run: &Run,
    code: &ModelCode,
) -> Vec<Option<Vec<T>>> {
    let mut observer = BoxStep::new(filter, &constants.x0, constants, code);
    run.measurements
        .iter()
        .zip(run.inputs.iter())
        .map(|(y, u)| observer.step(y, u))
        .collect()
}

/// [`estimate_box`] one sample at a time: the firmware's rule ([`firmware::rules::filter_sample`])
/// over the written-out programs.
pub struct BoxStep<'a, T> {
    filter: &'a crate::plant::kalman::FilterCode,
    /// `x`, the upper triangle of `P` and the watched mean of the normalised innovations squared.
    carried: (Vec<T>, Vec<T>, T),
    /// Where a restart goes: the start.
    fresh: (Vec<T>, Vec<T>, T),
    watch: Watcher<T>,
    refusals: Refusals,
    scratch: RefCell<Vec<T>>,
}

impl<'a, T: firmware::Scalar + firmware::emitted::Maths> BoxStep<'a, T> {
    /// At `x0` with `P = constants.p0` and `constants.watch`, before the first sample of a run.
    pub fn new(
        filter: &'a crate::plant::kalman::FilterCode,
        x0: &[f64],
        constants: &EkfConstants,
        code: &ModelCode,
    ) -> Self {
        let watch = Watcher::new(&constants.watch, code.dimensions.outputs);
        let fresh = (literals(x0), literals(&constants.p0.upper()), watch.start());
        BoxStep {
            filter,
            carried: fresh.clone(),
            fresh,
            watch,
            refusals: Refusals::NONE,
            scratch: RefCell::new(Vec::new()),
        }
    }

    /// The targets after the sample with outputs `y` and inputs `u` (`None`: refused).
    pub fn step(&mut self, y: &[f64], u: &[f64]) -> Option<Vec<T>> {
        let (y, u) = (literals::<T>(y), literals::<T>(u));
        let BoxStep {
            filter,
            scratch,
            fresh,
            watch,
            ..
        } = self;
        let watch = *watch;
        let result = firmware::rules::filter_sample(
            &mut self.carried,
            u.iter().all(|v| v.is_finite()),
            y.iter().all(|v| v.is_finite()),
            |(x, p, chi)| {
                let ((estimate, x, p), nis) = filter.run_watched(x, p, Some(&y), &u, &mut scratch.borrow_mut());
                let nis = nis.expect("a measured sample has one");
                (
                    estimate.expect("a measured sample has an estimate"),
                    (x, p, watch.watched(*chi, nis)),
                )
            },
            |(x, p, chi)| {
                let (_, x, p) = filter.run(x, p, None, &u, &mut scratch.borrow_mut());
                (x, p, *chi)
            },
            |(x, p, chi)| finite(x, p) && watch.plausible(*chi),
            || fresh.clone(),
        );
        let estimate = self.refusals.count(result).ok()?;
        let filter = self.filter;
        Some(
            filter
                .targets
                .eval(&filter.parameters, &estimate, &u, &mut self.scratch.borrow_mut()),
        )
    }

    /// Samples refused so far for a bad value, as the chip counts them.
    pub fn refused(&self) -> u32 {
        self.refusals.get()
    }

    /// Restarts so far, as the chip counts them.
    pub fn restarts(&self) -> u32 {
        self.refusals.restarts()
    }
}

/// A filter's χ² watch in `T` as the emitted code runs it (`firmware::watch`): the watched mean's
/// start `m` (the outputs), and its gain and limit where the filter is watched. The host's filters
/// (`BoxStep`, `StartedStep`, the restarted EKF's step) share it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Watcher<T> {
    start: T,
    constants: Option<(T, T)>,
}

impl<T: firmware::Scalar> Watcher<T> {
    /// `watch` over a filter of `outputs` outputs.
    pub(crate) fn new(watch: &Watch, outputs: usize) -> Self {
        Watcher {
            start: literal(outputs as f64),
            constants: watch.constants(outputs).map(|w| (literal(w.gain), literal(w.limit))),
        }
    }

    /// The mean at the start and after a restart, `m`.
    pub(crate) fn start(&self) -> T {
        self.start
    }

    /// The mean `chi` after a measured sample of normalised innovation squared `nis` (unchanged where
    /// the filter is not watched).
    pub(crate) fn watched(&self, chi: T, nis: T) -> T {
        self.constants
            .map_or(chi, |(gain, _)| firmware::watch::watched(chi, nis, gain))
    }

    /// Whether `chi` is plausible (always, where the filter is not watched).
    pub(crate) fn plausible(&self, chi: T) -> bool {
        self.constants
            .is_none_or(|(_, limit)| firmware::watch::plausible(chi, limit))
    }
}

/// Whether every entry of `x` and `p` is finite (the generated `finite`).
fn finite<T: firmware::Scalar>(x: &[T], p: &[T]) -> bool {
    x.iter().chain(p).all(|v| v.is_finite())
}

/// What a sample of the filter carries on, `(x, P)`, when it is finite (what the generated
/// `finite(&x, &p).then_some((x, p))` keeps).
pub fn kept<T: firmware::Scalar>((_, x, p): crate::plant::kalman::Sampled<T>) -> Option<(Vec<T>, Vec<T>)> {
    finite(&x, &p).then_some((x, p))
}

/// The EKF started by the map (the generated `StartedEkf` in `firmware::Started`, step for step,
/// [`Shell`]) in `T`: at sample `first` the map's estimate, from which `(x, P)` is
/// predicted with `P` = `p0` on the diagonal; then `filter`'s measured samples, watched by `watch`
/// (the box EKF's: a sample whose innovations leave it implausible ends the filter, which the map's
/// next estimate starts again). With the restarts on the run.
#[allow(clippy::too_many_arguments)]
pub fn estimate_started<T: firmware::Scalar + firmware::emitted::Maths>(
    filter: &crate::plant::kalman::FilterCode,
    p0: &[f64],
    watch: &Watch,
    state_targets: &[usize],
    first: usize,
    map: &[Vec<T>],
    run: &Run,
    code: &ModelCode,
) -> Track<Vec<Vec<T>>> {
    let mut observer = StartedStep::new(filter, p0, watch, state_targets, first, code);
    let rows = map
        .iter()
        .zip(run.measurements.iter().zip(run.inputs.iter()))
        .map(|(row, (y, u))| observer.step(row, y, u))
        .collect();
    Track {
        rows,
        restarts: observer.restarts(),
    }
}

/// [`estimate_started`] one sample at a time: `firmware::Started`'s rule ([`Shell`]) over the
/// written-out programs.
pub struct StartedStep<'a, T> {
    filter: &'a crate::plant::kalman::FilterCode,
    code: &'a ModelCode,
    /// `P` at the start, its upper triangle.
    upper: Vec<T>,
    watch: Watcher<T>,
    scratch: RefCell<Vec<T>>,
    /// `x`, the upper triangle of `P` and the watched mean (`m` where not watched: never read).
    shell: Shell<T, (Vec<T>, Vec<T>, T)>,
}

impl<'a, T: firmware::Scalar + firmware::emitted::Maths> StartedStep<'a, T> {
    /// Before the first sample of a run.
    pub fn new(
        filter: &'a crate::plant::kalman::FilterCode,
        p0: &[f64],
        watch: &Watch,
        state_targets: &[usize],
        first: usize,
        code: &'a ModelCode,
    ) -> Self {
        StartedStep {
            filter,
            code,
            upper: literals(&crate::plant::kalman::diagonal_upper(p0)),
            watch: Watcher::new(watch, code.dimensions.outputs),
            scratch: RefCell::new(Vec::new()),
            // `StartedEkf`: no start-up, the map read at the start only.
            shell: Shell::new(first, state_targets, code.dimensions.targets, (0, false)),
        }
    }

    /// The targets at the sample with outputs `y` and inputs `u`, the map's estimate there `row`.
    pub fn step(&mut self, row: &[T], y: &[f64], u: &[f64]) -> Vec<T> {
        let StartedStep {
            filter,
            code,
            upper,
            watch,
            scratch,
            shell,
        } = self;
        let watch = *watch;
        shell.step(
            row,
            y,
            u,
            // `StartedEkf::start`: `(x, P)` predicted from the map's states with `P` = `p0`.
            &mut |x, u| {
                kept(filter.run(x, upper, None, u, &mut scratch.borrow_mut())).map(|(x, p)| (x, p, watch.start()))
            },
            &mut |(x, p, chi): &(Vec<T>, Vec<T>, T), _, _, y, u| {
                let ((estimate, x, p), nis) = filter.run_watched(x, p, Some(y), u, &mut scratch.borrow_mut());
                let estimate = estimate.expect("a measured sample has an estimate");
                let nis = nis.expect("a measured sample has one");
                let chi = watch.watched(*chi, nis);
                let targets = code.targets(&estimate, u, &mut scratch.borrow_mut());
                (finite(&x, &p) && watch.plausible(chi)).then_some(((x, p, chi), targets))
            },
            // A lost output: the prediction alone (`StartedEkf::predict`).
            &mut |(x, p, chi): &(Vec<T>, Vec<T>, T), u| {
                kept(filter.run(x, p, None, u, &mut scratch.borrow_mut())).map(|(x, p)| (x, p, *chi))
            },
        )
    }

    /// Samples refused so far for a bad value, as the chip counts them.
    pub fn refused(&self) -> u32 {
        self.shell.refused()
    }

    /// Restarts so far, as the chip counts them.
    pub fn restarts(&self) -> u32 {
        self.shell.restarts()
    }
}
