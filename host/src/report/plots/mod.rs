//! The paper's figures for a design, as PNG and SVG, drawn by the report's drawing module (`draw`):
//!
//! * `measurements`: the scenario's measured outputs against their noise-free values, the noise
//!   (paper Fig. 1 and 5), and the inputs applied;
//! * `identification`: per target, identified against true values on the learning windows, and the
//!   gradient `dΓ/dr` of the identified `Γ` (Fig. 2 left, Fig. 3);
//! * `estimation`: per target, the observer's estimate against the truth along the scenario (Fig. 2
//!   right, Fig. 4);
//! * `validation`: per target, the map's error on every validation run against time and against the
//!   true value (what the report's validation RMSE and max error summarise).
//!
//! Saturated estimates (clamped by `Γ⁻¹` to the learning range) are ringed wherever the map's
//! estimates are drawn.

mod estimation;
mod identification;
mod measurements;
mod search;
mod validation;

use std::path::{Path, PathBuf};

use estimation::estimation;
use identification::identification;
use measurements::measurements;
pub use search::draw_search;
use validation::validation;

pub use super::draw::PlotError;
use super::draw::{Series, Style, SATURATED_COLOR};
use crate::data::{DataSet, Run};
use crate::fit::maps::FittedMap;
use crate::fit::DesignResult;
use crate::observers::Comparison;
use crate::spec::Design;

/// Most dots of one scatter panel.
const MAX_DOTS: usize = 4000;

/// Legend label of the rings around saturated estimates.
pub(crate) const SATURATED_LABEL: &str = "saturated (clamped to the learning range)";

/// The stems of the figures [`draw`] and [`draw_search`] write for a design, in the order the report
/// shows them, each with what it shows.
pub fn figure_stems(mismatch: bool, search: bool) -> Vec<(&'static str, &'static str)> {
    let mut stems = vec![
        (
            "measurements",
            "The scenario's measured outputs against their noise-free values, the noise, and the inputs when the model has any (paper Fig. 1/5)",
        ),
        (
            "identification",
            "Identified against true on the learning windows, and dΓ/dr (paper Fig. 2 left/Fig. 3)",
        ),
        (
            "estimation",
            "Every observer along the scenario against the truth (paper Fig. 2 right/Fig. 4)",
        ),
    ];
    if mismatch {
        stems.push((
            "estimation_mismatch",
            "The same on the plant at the last corner of the uncertain parameters",
        ));
    }
    stems.push((
        "validation",
        "The map's error on every validation run, against time and against the true value",
    ));
    if search {
        stems.push(("search", "The design search's trade-off: the tuning score against the predicted instructions and the delay to the first estimate"));
    }
    stems
}

/// The map's estimate at every window end of `run` (NaN before the first), and whether it saturated.
fn map_along(map: &FittedMap, run: &Run, horizon: usize) -> Vec<(f64, bool)> {
    let set = DataSet {
        runs: vec![run.clone()],
        horizon,
    };
    let mut z = Vec::new();
    let mut out = vec![(f64::NAN, false); run.states.len()];
    for w in set.windows() {
        set.regressor(w, &mut z);
        let e = map.estimate(&z);
        out[w.end] = (e.value, e.saturation.is_saturated());
    }
    out
}

/// Rings at the saturated points of `estimates` (pairs of a point and whether it saturated).
fn saturated_rings(estimates: impl Iterator<Item = ((f64, f64), bool)>) -> Series {
    Series::new(
        SATURATED_LABEL,
        estimates.filter(|e| e.1).map(|e| e.0).collect(),
        SATURATED_COLOR,
        Style::Rings,
    )
}

/// Draws the figures of `design` into `folder` (every figure but `search`); returns the files written.
pub fn draw(
    design: &Design,
    result: &DesignResult,
    comparison: &Comparison,
    folder: &Path,
) -> Result<Vec<PathBuf>, PlotError> {
    std::fs::create_dir_all(folder).map_err(|source| PlotError::Io {
        path: folder.to_owned(),
        source,
    })?;
    let mut files = measurements(design, &result.runs.scenario, folder)?;
    files.extend(identification(design, result, folder)?);
    // Estimation along the scenario, every observer, and on the mismatch plant.
    files.extend(estimation(
        design,
        result,
        comparison,
        &result.runs.scenario,
        false,
        folder,
    )?);
    if let Some(m) = &result.runs.mismatch {
        files.extend(estimation(design, result, comparison, &m.scenario, true, folder)?);
    }
    files.extend(validation(design, result, folder)?);
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_figure_is_listed_once_in_the_report_order() {
        let all = figure_stems(true, true);
        let stems: Vec<&str> = all.iter().map(|s| s.0).collect();
        assert_eq!(
            stems,
            [
                "measurements",
                "identification",
                "estimation",
                "estimation_mismatch",
                "validation",
                "search"
            ]
        );
        assert_eq!(figure_stems(false, false).len(), 4);
    }
}
