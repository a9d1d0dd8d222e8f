//! The tuning set: the runs every tunable constant and `auto` are chosen on, never what accuracy is
//! reported on. Random starts as the validation set's, the scenarios' starts, and the learning box's
//! edges and corners, where rare failures hide.

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

use super::{random_runs, random_state, simulate_plant, uncertain, DataSet};
use crate::spec::{Axis, Design, SpecError};

/// Runs from the scenario's initial state in the tuning set ([`tuning_set`]).
pub const SCENARIO_TUNING_RUNS: usize = 16;

/// Corners of the learning box among the tuning set's edge starts: all of them up to 4 states, else
/// this many drawn ([`edge_starts`]).
pub const MAX_CORNER_STARTS: usize = 16;

/// The tuning set's starts on the learning box's boundary, where a filter from the box centre starts
/// farthest from its guess and a state sits on its bound when the box reaches it: for each state
/// with a range, one start at its minimum and one at its maximum (the other states drawn uniformly),
/// then the box's corners (all `2ⁿ` of them up to [`MAX_CORNER_STARTS`], else that many drawn):
/// `2 n + min(2ⁿ, 16)` starts for `n` states with a range, so rare failures grow with the state.
pub fn edge_starts(design: &Design, rng: &mut ChaCha8Rng) -> Vec<Vec<f64>> {
    let axes = &design.learning.axes;
    let ranged: Vec<usize> = (0..axes.len())
        .filter(|&i| matches!(axes[i], Axis::Range { .. }))
        .collect();
    let end = |i: usize, high: bool| match axes[i] {
        Axis::Range { min, max, .. } => {
            if high {
                max
            } else {
                min
            }
        }
        Axis::Fixed(value) => value,
    };
    let mut starts = Vec::new();
    for &i in &ranged {
        for high in [false, true] {
            let mut x0 = random_state(design, rng);
            x0[i] = end(i, high);
            starts.push(x0);
        }
    }
    let n = ranged.len();
    let corners: Vec<u64> = if n <= 4 {
        (0..1u64 << n).collect()
    } else {
        (0..MAX_CORNER_STARTS).map(|_| rng.random_range(0..u64::MAX)).collect()
    };
    for corner in corners {
        let mut x0 = random_state(design, rng);
        for (bit, &i) in ranged.iter().enumerate() {
            x0[i] = end(i, corner >> (bit % 64) & 1 == 1);
        }
        starts.push(x0);
    }
    starts
}

/// The random stream of the tuning seed the edge starts read (the random runs read 0, scenario `i`
/// reads `1 + i`).
pub(crate) const EDGE_STREAM: u64 = 1 << 32;

/// The tuning set: runs drawn as the validation set's, from `[tuning]`'s own seed; then, for every
/// scenario the spec declares, [`SCENARIO_TUNING_RUNS`] more from its initial state (its samples,
/// other inputs, noise and drawn plants than the reported scenario's, from stream `1 + i` of the
/// tuning seed for scenario `i`), so that every tuning criterion and `auto` see the starts the spec
/// names, where a filter from the box centre may converge slowly, and not only the random ones; then
/// one run from each of the box's [`edge_starts`], where rare failures hide (stream `2³²`).
pub fn tuning_set(design: &Design) -> Result<DataSet, SpecError> {
    let mut set = random_runs(design, &design.tuning, "tuning", None)?;
    for (i, scenario) in design.scenarios.iter().enumerate() {
        let mut rng = ChaCha8Rng::seed_from_u64(design.tuning.seed);
        rng.set_stream(1 + i as u64); // the random runs read stream 0
        for _ in 0..SCENARIO_TUNING_RUNS {
            let drawn = uncertain::draw_plant(&design.model, &mut rng);
            let plant = drawn.as_ref().unwrap_or(&design.model);
            set.runs.push(simulate_plant(
                design,
                plant,
                &scenario.x0,
                scenario.samples,
                &mut rng,
                "tuning",
            )?);
        }
    }
    let mut rng = ChaCha8Rng::seed_from_u64(design.tuning.seed);
    rng.set_stream(EDGE_STREAM);
    for x0 in edge_starts(design, &mut rng) {
        let drawn = uncertain::draw_plant(&design.model, &mut rng);
        let plant = drawn.as_ref().unwrap_or(&design.model);
        set.runs.push(simulate_plant(
            design,
            plant,
            &x0,
            design.tuning.samples,
            &mut rng,
            "tuning",
        )?);
    }
    Ok(set)
}
