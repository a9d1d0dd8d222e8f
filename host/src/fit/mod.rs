//! One design end to end: learning and validation data, a fit per target, its evaluation.

pub mod evaluate;
pub mod helpers;
pub mod identify;
pub mod inverse_table;
pub mod maps;
pub mod monotonicity;
pub mod qp;
pub mod streaming_qr;

use indicatif::ProgressBar;

use crate::data::{DataSet, Runs};
use crate::spec::{Design, SpecError};
use evaluate::{evaluate, Evaluation};
use identify::{Fit, FitError};
use qp::QpError;

/// A fitted and judged target (or helper map: [`helpers`]).
#[derive(Clone, Debug)]
pub struct TargetResult {
    /// Index in `design.targets` (of a helper map: the state's index in `design.model.states`).
    pub index: usize,
    /// The fit.
    pub fit: Fit,
    /// Accuracy on the learning windows (noisy regressors, as fitted).
    pub learning: Evaluation,
    /// Accuracy on the validation windows.
    pub validation: Evaluation,
}

/// Everything a design produced: its runs and a fit per target.
#[derive(Clone, Debug)]
pub struct DesignResult {
    /// Every run the design is fitted, tuned and judged on ([`Runs`]).
    pub runs: Runs,
    /// One result per target, in spec order.
    pub targets: Vec<TargetResult>,
    /// One helper map per state that no target is ([`helpers::helper_states`]), in state order;
    /// or why one could not be fitted (the map-started kinds are then left out, saying so).
    pub helpers: Result<Vec<TargetResult>, String>,
}

impl DesignResult {
    /// Every map the map-started kinds read, row by row ([`helpers::state_maps`]): the targets', then
    /// the helpers' (none when a helper could not be fitted).
    pub fn start_maps(&self) -> impl Iterator<Item = &TargetResult> + Clone {
        self.targets.iter().chain(self.helpers.as_deref().unwrap_or(&[]))
    }
}

/// Steps [`run`] reports to its progress bar.
pub fn steps(design: &Design) -> u64 {
    design.targets.len() as u64
}

/// Fits every target of `design` on the learning runs of `runs` and evaluates it on the learning and
/// validation runs; the result keeps the runs for the stages after the fit.
pub fn run(design: &Design, runs: Runs, progress: &ProgressBar) -> Result<DesignResult, SpecError> {
    let odds_ratios = identify::basis_of(&design.map);
    let mut targets = Vec::new();
    for (index, target) in design.targets.iter().enumerate() {
        progress.set_message(format!("{}: fitting {}", design.name, target.name));
        let fit = identify::fit(&runs.learning, index, &target.name, &design.map, &odds_ratios)
            .map_err(|e| explain(design, &runs.learning, index, e))?;
        let result = TargetResult {
            index,
            learning: evaluate(&runs.learning, index, &fit),
            validation: evaluate(&runs.validation, index, &fit),
            fit,
        };
        targets.push(result);
        progress.inc(1);
    }
    let helpers = fit_helpers(design, &runs, &odds_ratios, progress);
    Ok(DesignResult { runs, targets, helpers })
}

/// A map for every state that no target is ([`helpers`]), fitted and judged as a target's.
fn fit_helpers(
    design: &Design,
    runs: &Runs,
    odds_ratios: &std::sync::Arc<[f64]>,
    progress: &ProgressBar,
) -> Result<Vec<TargetResult>, String> {
    let mut fitted = Vec::new();
    for index in helpers::helper_states(design) {
        let name = &design.model.states[index];
        progress.set_message(format!("{}: fitting helper map {name}", design.name));
        let column = crate::data::Column::State(index);
        let fit = identify::fit(&runs.learning, column, name, &design.map, odds_ratios).map_err(|e| {
            format!("the helper map of state `{name}` (no target is it) could not be fitted: {e}; add a target `expr = \"{name}\"` to see why")
        })?;
        fitted.push(TargetResult {
            index,
            learning: evaluate(&runs.learning, column, &fit),
            validation: evaluate(&runs.validation, column, &fit),
            fit,
        });
    }
    Ok(fitted)
}

/// Turns a fit failure on the learning data `learning` into a message about the spec field to change.
pub fn explain(design: &Design, learning: &DataSet, index: usize, error: FitError) -> SpecError {
    let name = &design.targets[index].name;
    let problem = format!("fitting target `{name}`: {error}");
    match error {
        FitError::ConstantTarget { .. } => design.error(
            format!("targets[{index}].expr"),
            problem,
            "a target must vary over the learning data: widen `learning.grid` or estimate another quantity",
        ),
        FitError::DependentRegressor { column } => match dependent_regressor_cause(design, learning, column) {
            Some((field, why, fix)) => design.error(field, format!("{problem}: {why}"), fix),
            None => {
                let (field, fix) = regressor_column_source(design, column);
                design.error(field, problem, fix)
            }
        },
        FitError::NonFinite => design.error(
            format!("targets[{index}].expr"),
            problem,
            "make the model and target finite over the whole state box",
        ),
        FitError::Qp(QpError::Infeasible(_) | QpError::Unbounded(_)) => design.error(
            "map",
            problem,
            "the QP is feasible and bounded by construction (η alone meets every constraint), so this is numerical: lower `map.beta` or `map.nm`, or bring `map.epsilon` closer to the target's range",
        ),
        FitError::Qp(_) => design.error(
            "map.beta",
            problem,
            "the solver lost accuracy on a nearly degenerate basis: lower `map.beta` or `map.nm`",
        ),
        FitError::Table(crate::fit::inverse_table::TableError::TooManySegments { .. }) => design.error(
            "map.beta",
            problem,
            "Γ is too flat somewhere for a certified table of Γ⁻¹: lower `map.beta` (or `map.nm`) so that the basis bends less sharply, or use `normalisation = \"intercept\"`",
        ),
        FitError::Table(_) | FitError::NotMonotone(_) => design.error(
            "map.monotonicity_grid",
            problem,
            "raise `map.monotonicity_grid` (e.g. to 801), or lower `map.beta` so that the basis bends less sharply",
        ),
    }
}

/// Why column `column` of the regressor is a combination of the others when the data, not the spec's
/// outputs, make it so: too few learning windows to tell any columns apart (every column is then
/// dependent), or an output's column constant over the learning data (a plant that settles, saturates
/// or is clipped everywhere in the box). `(field, why, fix)`; `None` for the spec field behind the column
/// ([`regressor_column_source`]).
fn dependent_regressor_cause(design: &Design, learning: &DataSet, column: usize) -> Option<(String, String, String)> {
    let windows = learning.window_count();
    let columns = design.map.horizon * (design.model.outputs.len() + design.model.inputs.len()) + 1;
    if windows <= columns {
        return Some((
            "learning".to_owned(),
            format!("only {windows} learning windows for a regressor of {columns} entries (the intercept included)"),
            "raise `learning.samples` or the points of `learning.grid`, or lower `map.horizon`".to_owned(),
        ));
    }
    let mut z = Vec::new();
    let mut values = learning.windows().map(|w| {
        learning.regressor(w, &mut z);
        z.get(column).copied().unwrap_or(f64::NAN)
    });
    let first = values.next().unwrap_or(f64::NAN);
    // An input's column has its own fix (its learning profile), found by the spec field behind it.
    let output_column = column < design.map.horizon * design.model.outputs.len();
    if output_column && values.all(|v| v == first) {
        let (field, _) = regressor_column_source(design, column);
        return Some((
            field,
            format!(
                "it is {} in every learning window: the learning runs do not move it",
                crate::output::number(first)
            ),
            "check that the plant does not settle, saturate or blow up everywhere in the box: the model, `learning.grid`, `learning.samples`".to_owned(),
        ));
    }
    None
}

/// The spec field behind column `column` of the regressor (with the intercept as column `n_z`), and
/// what to change when that column is a combination of the others.
fn regressor_column_source(design: &Design, column: usize) -> (String, String) {
    let (n_y, n_u, horizon) = (
        design.model.outputs.len(),
        design.model.inputs.len(),
        design.map.horizon,
    );
    if column < horizon * n_y {
        let output = &design.model.outputs[column % n_y].name;
        (
            format!("model.outputs[{}]", column % n_y),
            format!(
                "output `{output}` at lag {} repeats the others: give it measurement noise (`noise_variance` > 0) as the real sensor has, make it depend on the state, or lower `map.horizon`",
                column / n_y
            ),
        )
    } else if column < horizon * (n_y + n_u) {
        let input = &design.model.inputs[(column - horizon * n_y) % n_u];
        (
            format!("learning.inputs.{input}"),
            format!("input `{input}` does not vary enough to be told from the others: give it a range (min < max) and a shorter `hold`"),
        )
    } else {
        (
            "map.normalisation".to_owned(),
            "the intercept is a combination of the regressor: use `normalisation = \"paper\"`".to_owned(),
        )
    }
}
