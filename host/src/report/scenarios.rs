//! The spec's scenarios (`[scenario]`, `[[scenario]]`) as the report holds them: each one's start,
//! the observer start it names, and the box filters' figures from that start (every observer's
//! figures per scenario, as the chip starts it, are in its `FiguresReport::scenarios`).

use serde::Serialize;

use crate::observers::Comparison;
use crate::spec::Design;

/// Per target in spec order: the RMSE over a scenario's windows and over its transient (`None`:
/// diverged).
pub type ScenarioFigures = Vec<(Option<f64>, Option<f64>)>;

/// One scenario of the spec.
#[derive(Serialize)]
pub struct ScenarioReport {
    /// Its name.
    pub name: String,
    /// The plant's initial state.
    pub x0: Vec<f64>,
    /// The observer start it names (`observer_x0`), if any.
    pub observer_x0: Option<Vec<f64>>,
    /// Samples.
    pub samples: usize,
    /// Seed of its inputs and noise.
    pub seed: u64,
    /// The box filters started at `observer_x0`: each kind, and per target in spec order the RMSE over
    /// the scenario's windows and over its transient.
    pub from_observer_start: Vec<(&'static str, ScenarioFigures)>,
}

/// The report's scenarios, in the spec's order.
pub fn assemble(design: &Design, comparison: &Comparison) -> Vec<ScenarioReport> {
    let finite = |v: f64| v.is_finite().then_some(v);
    design
        .scenarios
        .iter()
        .enumerate()
        .map(|(i, s)| ScenarioReport {
            name: s.name.clone(),
            x0: s.x0.clone(),
            observer_x0: s.observer_x0.clone(),
            samples: s.samples,
            seed: s.seed,
            from_observer_start: comparison
                .from_observer_start
                .iter()
                .filter(|f| f.scenario == i)
                .map(|f| (f.kind, f.targets.iter().map(|&(r, t)| (finite(r), finite(t))).collect()))
                .collect(),
        })
        .collect()
}
