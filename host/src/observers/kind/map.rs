//! `map`: the fitted map `F(Z)` alone, nothing tuned.

use super::{Bench, Kind, Needs};
use crate::observers::lost::Track;
use crate::observers::ObserverFigures;
use crate::spec::ObserverKind;

/// See the module's documentation.
pub const KIND: Kind = Kind {
    kind: ObserverKind::Map,
    what: "the map alone",
    short: "map",
    observer_type: "MapObserver",
    measured_as: "`map_observer()`",
    legend: "map F(Z)",
    colour: (214, 39, 40),
    dots: true,
    needs: Needs {
        state_targets: false,
        filter: false,
        reads: &[],
    },
    cost_before_fit: None,
    missing_why: "",
    judged_in: crate::recording::Precision::F64,
    counts_refusals: false,
    fixed: None,
    filter_code: None,
    rust: None,
    c: None,
    tune,
};

/// Judges the map: its estimates are the bench's own (its targets' rows: the helpers' are not its).
fn tune(bench: &mut Bench<'_>) -> Option<ObserverFigures> {
    let targets = bench.design.targets.len();
    Some(bench.judge("map", bench.map_cost.instructions, &|_, map| {
        Track::from(super::bench::first_columns(map, targets))
    }))
}
