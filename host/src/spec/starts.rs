//! Every start a spec gives, by the field that gives it: the filters' fixed `x0` and each scenario's
//! `x0` (the plant's) and `observer_x0`. The validation (inside `[model.bounds]`) and the quality
//! gate (inside the learning box) read the same list.

use super::{FixedFilters, Scenario};

/// One start the spec gives.
pub struct Start<'a> {
    /// The spec's field (`observer.ekf.x0`, `scenario.observer_x0`, `scenario[1].x0`).
    pub field: String,
    /// The start, in state order.
    pub values: &'a [f64],
    /// Whether the plant starts there (a scenario's `x0`) rather than an observer.
    pub plant: bool,
}

/// A scenario's section as the spec names it: `scenario` when there is one, `scenario[i]` among
/// several.
pub fn scenario_section(i: usize, scenarios: usize) -> String {
    if scenarios > 1 {
        format!("scenario[{i}]")
    } else {
        "scenario".to_owned()
    }
}

/// Every start: the filters' (`[observer.<filter>] x0`), then each scenario's `x0` and
/// `observer_x0`, in the spec's order.
pub fn starts<'a>(filters: &'a FixedFilters, scenarios: &'a [Scenario]) -> Vec<Start<'a>> {
    let mut starts = Vec::new();
    for (section, fixed) in filters.iter() {
        if let Some(x0) = &fixed.x0 {
            starts.push(Start {
                field: format!("{section}.x0"),
                values: x0,
                plant: false,
            });
        }
    }
    for (i, scenario) in scenarios.iter().enumerate() {
        let section = scenario_section(i, scenarios.len());
        starts.push(Start {
            field: format!("{section}.x0"),
            values: &scenario.x0,
            plant: true,
        });
        if let Some(x0) = &scenario.observer_x0 {
            starts.push(Start {
                field: format!("{section}.observer_x0"),
                values: x0,
                plant: false,
            });
        }
    }
    starts
}
