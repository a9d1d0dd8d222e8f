//! The EKF over the written-out programs ([`crate::plant::kalman::FilterCode`]) in `T`, step for
//! step as the generated code runs it: from the box centre (`Ekf::push`) and started by the map
//! (`StartedEkf`). The mirrors that predict the chip's bits, kept apart from the firmware's own
//! filter in `f64` that tunes and judges ([`super::estimate_run`]).

use crate::data::Run;
use crate::plant::kalman::EkfConstants;
use crate::plant::{Covariance, ModelCode};

/// The EKF from `constants.x0` (the box centre, or the spec's start) over `run`, in `T`, step for step the generated
/// `Ekf::push` (the written-out programs `filter`): per sample the targets of `x̂(k|k)`, or `None`
/// where the sample is refused (a non-finite output or input, or a step whose result is not finite,
/// which is then not taken).
pub fn estimate_box<T: firmware::Scalar + firmware::emitted::Maths>(
    filter: &crate::plant::kalman::FilterCode,
    constants: &EkfConstants,
    run: &Run,
    code: &ModelCode,
) -> Vec<Option<Vec<T>>> {
    let mut observer = BoxStep::new(filter, &constants.x0, &constants.p0, code);
    run.measurements
        .iter()
        .zip(run.inputs.iter())
        .map(|(y, u)| observer.step(y, u))
        .collect()
}

/// [`estimate_box`] one sample at a time: what the filter carries between samples.
pub struct BoxStep<'a, T> {
    filter: &'a crate::plant::kalman::FilterCode,
    code: &'a ModelCode,
    x: Vec<T>,
    p: Vec<T>,
    scratch: Vec<T>,
}

impl<'a, T: firmware::Scalar + firmware::emitted::Maths> BoxStep<'a, T> {
    /// At `x0` with `P = p0`, before the first sample of a run.
    pub fn new(filter: &'a crate::plant::kalman::FilterCode, x0: &[f64], p0: &Covariance, code: &'a ModelCode) -> Self {
        let literal = |v: &f64| T::literal(*v as f32, *v);
        BoxStep {
            filter,
            code,
            x: x0.iter().map(literal).collect(),
            p: p0.upper().iter().map(literal).collect(),
            scratch: Vec::new(),
        }
    }

    /// The targets after the sample with outputs `y` and inputs `u` (`None`: refused).
    pub fn step(&mut self, y: &[f64], u: &[f64]) -> Option<Vec<T>> {
        let finite = |x: &[T], p: &[T]| x.iter().chain(p).all(|v| v.is_finite());
        let u: Vec<T> = u.iter().map(|&v| T::literal(v as f32, v)).collect();
        if !u.iter().all(|v| v.is_finite()) {
            return None;
        }
        let y: Vec<T> = y.iter().map(|&v| T::literal(v as f32, v)).collect();
        let measured = y.iter().all(|v| v.is_finite());
        let (estimate, next_x, next_p) = self.filter.run(
            &self.x,
            &self.p,
            measured.then_some(y.as_slice()),
            &u,
            &mut self.scratch,
        );
        let taken = finite(&next_x, &next_p);
        if taken {
            (self.x, self.p) = (next_x, next_p);
        }
        match estimate {
            Some(estimate) if taken => Some(self.code.targets(&estimate, &u, &mut self.scratch)),
            _ => None,
        }
    }
}

/// The EKF started by the map (the generated `StartedEkf` in `firmware::Started`, step for step,
/// [`started::run`](crate::observers::started::run)) in `T`: at sample `first` the map's estimate, from which `(x, P)` is
/// predicted with `P` = `p0` on the diagonal; then `filter`'s measured samples.
pub fn estimate_started<T: firmware::Scalar + firmware::emitted::Maths>(
    filter: &crate::plant::kalman::FilterCode,
    p0: &[f64],
    state_targets: &[usize],
    first: usize,
    map: &[Vec<T>],
    run: &Run,
    code: &ModelCode,
) -> Vec<Vec<T>> {
    let mut observer = StartedStep::new(filter, p0, state_targets, first, code);
    map.iter()
        .zip(run.measurements.iter().zip(run.inputs.iter()))
        .map(|(row, (y, u))| observer.step(row, y, u))
        .collect()
}

/// [`estimate_started`] one sample at a time.
pub struct StartedStep<'a, T> {
    filter: &'a crate::plant::kalman::FilterCode,
    code: &'a ModelCode,
    /// `P` at the start, its upper triangle.
    upper: Vec<T>,
    scratch: std::cell::RefCell<Vec<T>>,
    shell: crate::observers::started::Shell<T, (Vec<T>, Vec<T>)>,
}

impl<'a, T: firmware::Scalar + firmware::emitted::Maths> StartedStep<'a, T> {
    /// Before the first sample of a run.
    pub fn new(
        filter: &'a crate::plant::kalman::FilterCode,
        p0: &[f64],
        state_targets: &[usize],
        first: usize,
        code: &'a ModelCode,
    ) -> Self {
        StartedStep {
            filter,
            code,
            upper: crate::plant::kalman::diagonal_upper(p0)
                .iter()
                .map(|&v| T::literal(v as f32, v))
                .collect(),
            scratch: std::cell::RefCell::new(Vec::new()),
            shell: crate::observers::started::Shell::new(first, state_targets, code.dimensions.targets),
        }
    }

    /// The targets at the sample with outputs `y` and inputs `u`, the map's estimate there `row`.
    pub fn step(&mut self, row: &[T], y: &[f64], u: &[f64]) -> Vec<T> {
        let StartedStep {
            filter,
            code,
            upper,
            scratch,
            shell,
        } = self;
        let finite = |x: &[T], p: &[T]| x.iter().chain(p).all(|v| v.is_finite());
        shell.step(
            row,
            y,
            u,
            &mut |x, u| {
                let (_, x, p) = filter.run(x, upper, None, u, &mut scratch.borrow_mut());
                finite(&x, &p).then_some((x, p))
            },
            &mut |(x, p): &(Vec<T>, Vec<T>), _, _, y, u| {
                let (estimate, x, p) = filter.run(x, p, Some(y), u, &mut scratch.borrow_mut());
                let estimate = estimate.unwrap_or_else(|| x.clone());
                let targets = code.targets(&estimate, u, &mut scratch.borrow_mut());
                finite(&x, &p).then_some(((x, p), targets))
            },
            // A lost output: the prediction alone (`StartedEkf::predict`).
            &mut |(x, p): &(Vec<T>, Vec<T>), u| {
                let (_, x, p) = filter.run(x, p, None, u, &mut scratch.borrow_mut());
                finite(&x, &p).then_some((x, p))
            },
        )
    }
}
