//! Any observer kind over recorded measurements, as the chip runs it: the map over the window of
//! accepted samples ([`crate::recording::estimate`]), and the observers it starts through the
//! chip's own rules (`firmware::rules`, [`super::started::Shell`]), in `f64` or, bit for bit as the
//! chip, in `f32`. A sample with a NaN or infinite output or input is refused (no estimate on its row;
//! the map's window skips it, a started observer takes the model's period over it when the input is
//! finite); every change of the `run` column restarts the observer.

use crate::plant::ModelCode;
use crate::recording::{self, EstimateRow, MapEvaluator, NoTable, Precision, Row, Status, Window};
use crate::spec::{Design, ObserverKind};
use crate::tables::Tables;

use firmware::Saturation;

use super::ekf;
use super::kind::corrected::run as corrected;
use super::started::literal;

/// Why a kind cannot run on this design.
#[derive(Debug, thiserror::Error)]
pub enum RecordedError {
    /// The design has no observer of that kind (see the report's observers).
    #[error(
        "the design `{design}` has no `{kind}` observer: {why}; ask for --kind map, or for a kind its report lists"
    )]
    Unavailable {
        /// The design.
        design: String,
        /// The kind asked for.
        kind: &'static str,
        /// Why (from the comparison).
        why: String,
    },
    /// `--precision f32` without the emitted tables.
    #[error(transparent)]
    NoTable(#[from] NoTable),
}

/// `kind`'s estimates over `rows` (one row out per row in) by the fitted design `tables`, in
/// `precision`. `ObserverKind::Auto` is the kind `gen` chose (`observer()`).
pub fn estimate(
    design: &Design,
    tables: &Tables,
    code: &ModelCode,
    kind: ObserverKind,
    precision: Precision,
    rows: &[Row],
) -> Result<Vec<EstimateRow>, RecordedError> {
    let mut out = Vec::with_capacity(rows.len());
    let mut rows = rows.iter();
    stream(
        design,
        tables,
        code,
        kind,
        precision,
        || Ok::<_, RecordedError>(rows.next().cloned()),
        |_, estimate| {
            out.push(estimate);
            Ok(())
        },
    )?;
    Ok(out)
}

/// [`estimate`] over rows as `next` reads them, each row's estimate given to `emit` as soon as it is
/// known: memory of `N` rows and the observer's state, whatever the recording's length.
pub fn stream<E: From<RecordedError>>(
    design: &Design,
    tables: &Tables,
    code: &ModelCode,
    kind: ObserverKind,
    precision: Precision,
    next: impl FnMut() -> Result<Option<Row>, E>,
    emit: impl FnMut(&Row, EstimateRow) -> Result<(), E>,
) -> Result<(), E> {
    let kind = match kind {
        ObserverKind::Auto => tables.chosen,
        other => other,
    };
    let setup = Setup::new(design, tables, code, kind)?;
    match precision {
        Precision::F64 => setup.stream::<f64, E>(precision, next, emit),
        Precision::F32 => setup.stream::<f32, E>(precision, next, emit),
    }
}

/// What a kind needs besides the map, checked and built once per recording.
struct Setup<'a> {
    design: &'a Design,
    tables: &'a Tables,
    code: &'a ModelCode,
    kind: ObserverKind,
    /// The written-out programs of the filter the kind runs (its own, or the one it reads).
    filter: Option<crate::plant::kalman::FilterCode>,
    /// The correction's programs (`corrected`).
    programs: Option<crate::observers::kind::corrected::program::CorrectionCode>,
    /// The map target of each state (the kinds the map starts or checks).
    state_targets: Vec<usize>,
}

/// One run's observer, one sample at a time.
enum Follower<'s, T> {
    Map,
    Box(ekf::BoxStep<'s, T>),
    Started(ekf::StartedStep<'s, T>),
    Corrected(corrected::CorrectedStep<'s, T>, Vec<(usize, T, T)>),
    Restarted(super::kind::ekf_restart::run::RestartStep<'s, T>),
    Mhe(Box<dyn super::kind::mhe::run::chip::ChipStep + 's>),
}

impl<'a> Setup<'a> {
    fn new(
        design: &'a Design,
        tables: &'a Tables,
        code: &'a ModelCode,
        kind: ObserverKind,
    ) -> Result<Self, RecordedError> {
        let name = kind.name();
        let unavailable = |why: &str| RecordedError::Unavailable {
            design: design.name.clone(),
            kind: name,
            why: why.to_owned(),
        };
        if let Some(missing) = tables.missing(kind) {
            return Err(unavailable(super::kind::of(missing).missing_why));
        }
        let entry = super::kind::of(kind);
        let state_targets = if entry.needs.state_targets {
            crate::fit::helpers::state_maps(design)
        } else {
            Vec::new()
        };
        let reads = |kind: ObserverKind| entry.needs.reads.contains(&kind);
        let constants = &tables.constants;
        Ok(Setup {
            design,
            tables,
            code,
            kind,
            filter: entry.needs.reads.iter().find_map(|&read| {
                let filter_code = super::kind::of(read).filter_code?;
                Some(filter_code(code, constants.filter(read)?))
            }),
            programs: constants
                .corrected()
                .filter(|_| reads(ObserverKind::Corrected))
                .map(|constants| crate::observers::kind::corrected::program::correction_code(code, constants)),
            state_targets,
        })
    }

    /// Runs over the rows `next` reads, in `T` (`precision` for the map's tables).
    fn stream<T: firmware::Scalar + firmware::emitted::Maths + Into<f64>, E: From<RecordedError>>(
        &self,
        precision: Precision,
        mut next: impl FnMut() -> Result<Option<Row>, E>,
        mut emit: impl FnMut(&Row, EstimateRow) -> Result<(), E>,
    ) -> Result<(), E> {
        // The targets' maps, then the helpers' (read by the map-started kinds only).
        let start_maps = self.tables.start_maps();
        let maps = MapEvaluator::new(&start_maps, precision).map_err(RecordedError::from)?;
        let setting = corrected::Setting::for_maps(
            self.design,
            self.tables.horizon,
            &start_maps,
            self.code,
            &self.state_targets,
        );
        let mut window = Window::new(self.tables.horizon);
        let mut run: Option<String> = None;
        let mut follower = self.follower::<T>(&setting);
        while let Some(row) = next()? {
            // Every change of the `run` column restarts the observer (the window restarts itself).
            if run.as_deref() != Some(row.run.as_str()) {
                follower = self.follower::<T>(&setting);
                run = Some(row.run.clone());
            }
            let map = recording::map_row(&maps, window.push(&row));
            let estimate = follower.step(map, &row, (start_maps.len(), self.tables.maps.len()));
            emit(&row, estimate)?;
        }
        Ok(())
    }

    /// A fresh observer for a new run.
    fn follower<'s, T: firmware::Scalar + firmware::emitted::Maths>(
        &'s self,
        setting: &'s corrected::Setting<'s>,
    ) -> Follower<'s, T> {
        let (tables, constants) = (self.tables, &self.tables.constants);
        // `Setup::new` refused a kind whose constants the tables lack (`Tables::missing`).
        const CHECKED: &str = "Setup::new checked the kind's constants";
        // A kind whose constants are one filter's runs that filter from its start.
        if let (Some(own), Some(filter)) = (constants.filter(self.kind), &self.filter) {
            return Follower::Box(ekf::BoxStep::new(filter, &own.x0, own, self.code));
        }
        match (self.kind, &self.filter, &self.programs) {
            (ObserverKind::EkfMap, Some(filter), _) => Follower::Started(ekf::StartedStep::new(
                filter,
                &constants.ekf_map().expect(CHECKED).p0,
                &constants.ekf_box().expect(CHECKED).watch,
                &self.state_targets,
                tables.horizon - 1,
                self.code,
            )),
            (ObserverKind::EkfRestart, Some(filter), _) => {
                Follower::Restarted(super::kind::ekf_restart::run::RestartStep::new(
                    filter,
                    constants.ekf_box().expect(CHECKED),
                    &constants.ekf_map().expect(CHECKED).p0,
                    constants.ekf_restart().expect(CHECKED),
                    &self.state_targets,
                    self.code,
                ))
            }
            (ObserverKind::Corrected, _, Some(programs)) => {
                let constants = constants.corrected().expect(CHECKED);
                let clamps = self
                    .state_targets
                    .iter()
                    .zip(constants.lower.iter().zip(&constants.upper))
                    .map(|(&t, (&lo, &hi))| (t, literal(lo), literal(hi)))
                    .collect();
                Follower::Corrected(corrected::CorrectedStep::new(setting, programs, constants), clamps)
            }
            (ObserverKind::Mhe, _, _) => Follower::Mhe(super::kind::mhe::run::chip::chip_stepper::<T>(
                self.code,
                tables.horizon,
                constants.mhe().expect(CHECKED),
            )),
            _ => Follower::Map,
        }
    }
}

impl<T: firmware::Scalar + firmware::emitted::Maths + Into<f64>> Follower<'_, T> {
    /// Restarts so far, as the chip counts them (0 for the map, which carries nothing).
    fn restarts(&self) -> u32 {
        match self {
            Follower::Map => 0,
            Follower::Box(observer) => observer.restarts(),
            Follower::Started(observer) => observer.restarts(),
            Follower::Corrected(observer, _) => observer.restarts(),
            Follower::Restarted(observer) => observer.restarts(),
            Follower::Mhe(observer) => observer.restarts(),
        }
    }

    /// The observer's row for `sample`, the map's row there `map` (of `width` targets): `restarted`
    /// where the sample restarted the observer.
    fn step(&mut self, map: EstimateRow, sample: &Row, widths: (usize, usize)) -> EstimateRow {
        let before = self.restarts();
        let row = self.row(map, sample, widths);
        if self.restarts() != before {
            return EstimateRow::without(Status::Restarted);
        }
        row
    }

    /// [`step`](Self::step) but for the restarts.
    /// `widths`: the map's rows (the targets', then the helpers') and the targets.
    fn row(&mut self, map: EstimateRow, sample: &Row, (width, targets): (usize, usize)) -> EstimateRow {
        let (y, u) = (sample.y.as_slice(), sample.u.as_slice());
        // NaN where the map has no estimate; an f32 estimate converts back to itself exactly.
        let map_values = || -> Vec<T> {
            match map.status {
                Status::Ok => map.targets.iter().map(|&(v, _)| literal(v)).collect(),
                _ => vec![T::literal(f32::NAN, f64::NAN); width],
            }
        };
        // The map's own estimate: its targets' rows.
        let own = EstimateRow {
            status: map.status,
            targets: map.targets.iter().take(targets).copied().collect(),
        };
        let (row, clamps): (Vec<T>, &[(usize, T, T)]) = match self {
            Follower::Map => return own,
            Follower::Box(observer) => {
                return match observer.step(y, u) {
                    Some(values) => EstimateRow {
                        status: Status::Ok,
                        targets: values.into_iter().map(|v| (v.into(), Saturation::Inside)).collect(),
                    },
                    None => EstimateRow::without(Status::Refused),
                };
            }
            Follower::Mhe(observer) => {
                return match observer.step(y, u) {
                    Some(values) => EstimateRow {
                        status: Status::Ok,
                        targets: values.into_iter().map(|v| (v, Saturation::Inside)).collect(),
                    },
                    None if y.iter().chain(u).any(|v| !v.is_finite()) => EstimateRow::without(Status::Refused),
                    None => EstimateRow::without(Status::NoEstimateYet),
                };
            }
            Follower::Started(observer) => (observer.step(&map_values(), y, u), &[]),
            Follower::Restarted(observer) => (observer.step(&map_values(), y, u), &[]),
            Follower::Corrected(observer, clamps) => (observer.step(&map_values(), y, u), clamps),
        };
        if y.iter().chain(u).any(|v| !v.is_finite()) {
            return EstimateRow::without(Status::Refused);
        }
        if row.iter().any(|v| !v.is_finite()) {
            return EstimateRow::without(Status::NoEstimateYet);
        }
        let values: Vec<f64> = row.into_iter().map(Into::into).collect();
        // The first estimate is the map's, with its flags.
        if own.status == Status::Ok && own.targets.iter().map(|t| t.0).eq(values.iter().copied()) {
            return own;
        }
        // Later, the corrected map's clamp sets a state exactly to an end of its box.
        let saturation = |t: usize| match clamps.iter().find(|&&(s, _, _)| s == t) {
            Some(&(_, lo, _)) if values[t] == lo.into() => Saturation::Low,
            Some(&(_, _, hi)) if values[t] == hi.into() => Saturation::High,
            _ => Saturation::Inside,
        };
        EstimateRow {
            status: Status::Ok,
            targets: values.iter().enumerate().map(|(t, &v)| (v, saturation(t))).collect(),
        }
    }
}
