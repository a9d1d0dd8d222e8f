//! One observer's figures on every set of runs, from its estimates ([`Bench::judge`]): the errors
//! per target, the drift over the long runs, and the lost and restarted runs per set.

use super::{Bench, Estimates};
use crate::data::{Rows, Run};
use crate::observers::figures::{Drift, Figures, ObserverFigures};
use crate::observers::kind::corrected::run as corrected;
use crate::observers::lost::{self, LostRuns, LostWhich};
use crate::observers::score::{self, errors};

impl Bench<'_> {
    /// The figures of one observer's estimates on every set.
    pub(super) fn figures(
        &self,
        kind: &'static str,
        instructions: f64,
        estimates: Estimates,
        tuned: bool,
    ) -> ObserverFigures {
        let runs = &self.result.runs;
        let horizon = self.design.map.horizon;
        let windows = self.windows();
        let Estimates {
            validation,
            scenario,
            scenarios,
            tuning: on_tuning,
            draws: on_draws,
            mismatch,
            long: on_long,
            restarts,
        } = estimates;
        let (on_mismatch, mismatch_scenario) = match mismatch {
            Some((sets, scenario)) => (Some(sets), Some(scenario)),
            None => (None, None),
        };
        let long_samples = Drift::long_samples(self.design);
        let start_up = horizon - 1 + corrected::START_UP_HORIZONS * horizon;
        let window = self.design.validation.samples;
        let drift = |runs: &[Run], estimates: &[Rows], t: usize| Drift {
            first: errors(runs, estimates, t, |_| start_up..start_up + window).0,
            last: errors(runs, estimates, t, |_| long_samples - window..long_samples).0,
        };
        // Per target, (whole, transient) on the headline scenario and on each named one.
        let headline = self.scenario_errors(&runs.scenario, &scenario);
        let named: Vec<Vec<(f64, f64)>> = (scenarios.iter().enumerate())
            .map(|(i, rows)| self.on_scenario(i, rows))
            .collect();
        let targets = (0..self.design.targets.len())
            .map(|t| {
                let (rmse_validation, max_error_validation) = errors(&runs.validation.runs, &validation, t, windows);
                let (rmse_mismatch, rmse_corners, rmse_nominal, drift_mismatch) = match (&runs.mismatch, &on_mismatch) {
                    (Some(m), Some([estimates, on_nominal, on_long])) => (
                        Some(errors(&m.corners_set.runs, estimates, t, windows).0),
                        m.corners_set
                            .runs
                            .chunks(self.design.validation.trajectories)
                            .zip(estimates.chunks(self.design.validation.trajectories))
                            .map(|(runs, estimates)| errors(runs, estimates, t, windows).0)
                            .collect(),
                        Some(errors(&m.nominal_set.runs, on_nominal, t, windows).0),
                        Some(drift(&m.long.runs, on_long, t)),
                    ),
                    _ => (None, Vec::new(), None, None),
                };
                let p95 = |runs: &[Run], estimates: &[Rows]| {
                    score::percentile_95(&score::per_run_rmse(runs, estimates, t, windows))
                };
                Figures {
                    scenarios: named.iter().map(|per_target| per_target[t]).collect(),
                    rmse_validation,
                    max_error_validation,
                    p95_validation: p95(&runs.validation.runs, &validation),
                    p95_tuning: p95(&runs.tuning.runs, &on_tuning),
                    rmse_scenario: headline[t].0,
                    rmse_transient: headline[t].1,
                    rmse_tuning: errors(&runs.tuning.runs, &on_tuning, t, windows).0,
                    scenario_draws: runs
                        .scenario_draws
                        .as_ref()
                        .zip(on_draws.as_ref())
                        .map(|(d, on)| (errors(&d.runs, on, t, windows).0, p95(&d.runs, on))),
                    rmse_mismatch,
                    rmse_corners,
                    rmse_nominal,
                    drift: drift(&runs.long.runs, &on_long, t),
                    drift_mismatch,
                }
            })
            .collect();
        // Lost runs per set, on the targets of weight above 0; a reference (`tuned` false) is not run
        // on the tuning and long runs.
        let counted = self.scoring.lost_spreads();
        let lost = |runs: &[Run], estimates: &[Rows], restarts: &[u32]| {
            lost::count(runs, estimates, restarts, windows, &counted)
        };
        let lost = LostRuns {
            validation: lost(&runs.validation.runs, &validation, &restarts.validation),
            tuning: tuned.then(|| lost(&runs.tuning.runs, &on_tuning, &restarts.tuning)),
            scenario_draws: runs
                .scenario_draws
                .as_ref()
                .zip(on_draws.as_ref())
                .map(|(d, on)| lost(&d.runs, on, &restarts.draws)),
            mismatch: runs
                .mismatch
                .as_ref()
                .zip(on_mismatch.as_ref())
                .map(|(m, [on_corners, _, _])| lost(&m.corners_set.runs, on_corners, &restarts.corners)),
            long: tuned.then(|| lost(&runs.long.runs, &on_long, &restarts.long)),
        };
        let which = |runs: &[Run], estimates: &[Rows]| lost::which(runs, estimates, windows, &counted);
        let lost_which = LostWhich {
            validation: which(&runs.validation.runs, &validation),
            scenario_draws: (runs.scenario_draws.as_ref().zip(on_draws.as_ref()))
                .map_or_else(Vec::new, |(d, on)| which(&d.runs, on)),
            mismatch: (runs.mismatch.as_ref().zip(on_mismatch.as_ref()))
                .map_or_else(Vec::new, |(m, [on_corners, _, _])| {
                    which(&m.corners_set.runs, on_corners)
                }),
        };
        // The score's terms on the tuning runs, regime by regime (a reference is not run on them).
        let tuning_terms = if tuned {
            self.scoring.terms(&runs.tuning.runs, &on_tuning)
        } else {
            Vec::new()
        };
        ObserverFigures {
            kind,
            instructions,
            targets,
            tuning_terms,
            tuning_estimates: if tuned { on_tuning } else { Vec::new() },
            mismatch_scenario,
            scenario,
            lost,
            lost_which,
        }
    }
}
