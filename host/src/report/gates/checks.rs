//! The gates that read the spec, the learning runs or every kind's figures rather than one target's
//! (see the parent module's list).

use super::{Gate, OUTSIDE_FRACTION};
use crate::observers::lost::Lost;
use crate::observers::{kind, Comparison};
use crate::spec::Design;

/// How much larger an observer's RMSE over the last window of the long runs may be than over the
/// first before [`Gate::Drift`].
pub const DRIFT_RATIO: f64 = 2.0;

/// Every observer's drift over the long runs above [`DRIFT_RATIO`] ([`Gate::Drift`]).
pub fn drifts(design: &Design, comparison: &Comparison) -> Vec<Gate> {
    let chosen = kind::of(comparison.chosen.0).kind.name();
    let mut gates = Vec::new();
    for o in &comparison.observers {
        for (t, figures) in o.targets.iter().enumerate() {
            let plants = [
                ("", Some(figures.drift)),
                (" at the last corner", figures.drift_mismatch),
            ];
            for (plant, drift) in plants {
                let Some(drift) = drift else { continue };
                if drift.last > DRIFT_RATIO * drift.first {
                    gates.push(Gate::Drift {
                        kind: o.kind,
                        target: design.targets[t].name.clone(),
                        plant,
                        first: drift.first,
                        last: drift.last,
                        chosen: o.kind == chosen,
                    });
                }
            }
        }
    }
    gates
}

/// Every observer's lost runs on the sets it is judged on ([`Gate::LostRuns`]), with, for
/// `observer()`'s, the other kinds that lost none of that set's runs.
pub fn lost_runs(comparison: &Comparison) -> Vec<Gate> {
    let chosen = kind::of(comparison.chosen.0).kind.name();
    // The other kinds judged on `set`, and of those the ones that lost none of its runs.
    let lost_none = |set: &str| -> Option<Vec<&'static str>> {
        let judged: Vec<(&'static str, Lost)> = (comparison.observers.iter())
            .filter(|o| o.kind != chosen)
            .filter_map(|o| {
                let (_, lost) = o.lost.judged_sets().into_iter().find(|(s, _)| *s == set)?;
                Some((o.kind, lost?))
            })
            .collect();
        (!judged.is_empty()).then(|| {
            (judged.into_iter())
                .filter(|(_, l)| l.beyond_floor() == 0)
                .map(|(kind, _)| kind)
                .collect()
        })
    };
    comparison
        .observers
        .iter()
        .flat_map(|o| {
            o.lost.judged().into_iter().map(move |(set, l)| Gate::LostRuns {
                kind: o.kind,
                set,
                lost: l.beyond_floor(),
                floor_lost: l.floor_lost,
                runs: l.runs,
                chosen: o.kind == chosen,
                lost_none: if o.kind == chosen { lost_none(set) } else { None },
            })
        })
        .collect()
}

/// The chip's model too far from the simulated plant over one period ([`Gate::CoarseChipModel`]).
pub fn coarse_chip_model(design: &Design, learning: &crate::data::DataSet) -> Option<Gate> {
    let d = crate::plant::discretisation::check(design, learning);
    (!d.passes()).then(|| Gate::CoarseChipModel {
        substeps: d.substeps,
        state: design.model.states[d.state].clone(),
        error: d.error,
        fewest: d.fewest,
    })
}

/// The starts the spec gives a filter outside the learning box ([`Gate::StartOutsideBox`]).
pub fn starts_outside_box(design: &Design) -> Vec<Gate> {
    let mut outside = Vec::new();
    // The observers' starts (a scenario's plant start may lie anywhere within the bounds).
    let starts = crate::spec::starts::starts(&design.filters, &design.scenarios);
    for start in starts.iter().filter(|s| !s.plant) {
        for ((state, axis), &value) in design.model.states.iter().zip(&design.learning.axes).zip(start.values) {
            let range = match *axis {
                crate::spec::Axis::Range { min, max, .. } => (min, max),
                crate::spec::Axis::Fixed(held) => (held, held),
            };
            if !(range.0..=range.1).contains(&value) {
                outside.push(Gate::StartOutsideBox {
                    field: start.field.clone(),
                    state: state.clone(),
                    value,
                    range,
                });
            }
        }
    }
    outside
}

/// The signals whose declared raw range (`[chip.raw.<signal>]`) the learning runs leave
/// ([`Gate::RawRangeShort`]).
pub fn raw_ranges_short(design: &Design, learning: &crate::data::DataSet) -> Vec<Gate> {
    let Some(fixed) = &design.fixed else { return Vec::new() };
    let model = &design.model;
    let outputs = fixed
        .outputs
        .iter()
        .enumerate()
        .map(|(i, s)| (model.outputs[i].name.clone(), s, true, i));
    let inputs = fixed
        .inputs
        .iter()
        .enumerate()
        .map(|(i, s)| (model.inputs[i].clone(), s, false, i));
    let mut short = Vec::new();
    for (signal, scale, output, i) in outputs.chain(inputs) {
        let Some(scale) = scale else { continue };
        let ends = (
            scale.offset + scale.scale * f64::from(scale.min),
            scale.offset + scale.scale * f64::from(scale.max),
        );
        let covered = (ends.0.min(ends.1), ends.0.max(ends.1));
        let (mut outside, mut samples) = (0usize, 0usize);
        let mut seen = (f64::INFINITY, f64::NEG_INFINITY);
        for run in &learning.runs {
            let rows = if output { &run.measurements } else { &run.inputs };
            for row in rows {
                let value = row[i];
                seen = (seen.0.min(value), seen.1.max(value));
                outside += usize::from(!(covered.0..=covered.1).contains(&value));
                samples += 1;
            }
        }
        let fraction = outside as f64 / samples.max(1) as f64;
        if fraction > OUTSIDE_FRACTION {
            short.push(Gate::RawRangeShort {
                signal,
                covered,
                seen,
                fraction,
            });
        }
    }
    short
}
