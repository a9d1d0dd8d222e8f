//! Accuracy against taps (sparse `L`): the chosen `(N, n_m, β)` refitted at every tap count the spec
//! offers and judged on the validation runs, which neither the fits nor the search saw. What the
//! report shows beside the search's tuning scores.

use serde::Serialize;

use crate::data::DataSet;
use crate::fit::identify::{self, FitError};
use crate::fit::maps::{FittedMap, Tabulation};
use crate::search::cost;
use crate::spec::{Design, Taps};

/// One tap count at the chosen `N`, `n_m` and `β`.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    /// Non-zero gains per target.
    pub taps: usize,
    /// Entries of the regressor (every tap).
    pub regressor_len: usize,
    /// Predicted instructions per sample ([`cost`]).
    pub instructions: f64,
    /// Validation RMSE per target, in the spec's order.
    pub rmse: Vec<f64>,
    /// Whether this is the design's count.
    pub chosen: bool,
}

/// The rows for `design` (its `map` settled), or `None` when the spec does not prune `L`.
pub fn accuracy_vs_taps(
    design: &Design,
    learning: &DataSet,
    validation: &DataSet,
) -> Result<Option<Vec<Row>>, FitError> {
    let regressor_len = learning.regressor_len();
    let offered = design.search.as_ref().map_or(Taps::All, |s| s.taps.clone());
    let chosen = design.map.taps.unwrap_or(regressor_len).min(regressor_len);
    let mut counts = offered.for_regressor(regressor_len);
    if counts == [regressor_len] && chosen == regressor_len {
        return Ok(None);
    }
    counts.extend([regressor_len, chosen]);
    counts.sort_unstable_by(|a, b| b.cmp(a));
    counts.dedup();
    let odds_ratios = identify::basis_of(&design.map);
    // maps[target][count]
    let maps: Vec<Vec<FittedMap>> = design
        .targets
        .iter()
        .enumerate()
        .map(|(index, target)| {
            let fits = identify::fit_counts(
                learning,
                index,
                &target.name,
                &design.map,
                &odds_ratios,
                &counts,
                Tabulation::Sketched,
            )?;
            Ok(fits.into_iter().map(|fit| fit.map).collect())
        })
        .collect::<Result<_, FitError>>()?;
    let rmse = super::rmse_per_count(&maps, validation, 0);
    Ok(Some(
        counts
            .iter()
            .enumerate()
            .map(|(c, &taps)| {
                let refs: Vec<&FittedMap> = maps.iter().map(|m| &m[c]).collect();
                Row {
                    taps,
                    regressor_len,
                    instructions: cost::of_maps(&refs, design.map.horizon, design.tau).instructions,
                    rmse: rmse[c].clone(),
                    chosen: taps == chosen,
                }
            })
            .collect(),
    ))
}
