//! A recording's time column against the design's sample period. An observer fitted for `τ` reads
//! its window as samples `τ` apart: fed a recording at another period it estimates wrongly and says
//! nothing (at 0.05 s, Example 1's map is 40 times off). So within each run, every time must be a
//! number and follow the previous one by `τ`, within [`TOLERANCE`].

/// How far a step between two successive times may be from `τ`, relative to `τ`: times rounded to
/// a logger's resolution or a sampling clock's jitter pass; another sample period (half or twice
/// `τ`: 50 % or 100 % off), a gap, a repeated or a decreasing time do not.
pub const TOLERANCE: f64 = 0.05;

/// What is wrong with a time.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpacingError {
    /// The cell is not a finite number.
    #[error("time `{cell}` is not a finite number")]
    NotATime {
        /// The cell.
        cell: String,
    },
    /// The step from the previous time of the run is not `τ`.
    #[error(
        "time `{cell}` is {step} {unit} after the previous sample's `{previous}`, but the design samples every {tau} {unit} (±{percent} %); record at that period (a gap: start a new run in the `run` column), or fit a design for this one (`tau` in its spec)",
        percent = TOLERANCE * 100.0
    )]
    Step {
        /// The cell.
        cell: String,
        /// The previous time of the same run, as written.
        previous: String,
        /// The step, printed to `f32`'s shortest digits.
        step: f32,
        /// The design's sample period.
        tau: f64,
        /// The spec's time unit.
        unit: String,
    },
}

/// The check of successive times, row by row (memory independent of the recording's length).
#[derive(Clone, Debug)]
pub struct Spacing {
    tau: f64,
    unit: String,
    /// The run and time (as written, and its value) of the previous row.
    previous: Option<(String, String, f64)>,
}

impl Spacing {
    /// For a design sampled every `tau` (in `unit`).
    pub fn new(tau: f64, unit: &str) -> Self {
        Spacing {
            tau,
            unit: unit.to_owned(),
            previous: None,
        }
    }

    /// Checks the time `cell` of the next row, in run `run`: a finite number, `τ` after the previous
    /// row's when that row is of the same run (the first row of a run may have any time).
    pub fn check(&mut self, run: &str, cell: &str) -> Result<(), SpacingError> {
        let time = cell
            .parse::<f64>()
            .ok()
            .filter(|t| t.is_finite())
            .ok_or_else(|| SpacingError::NotATime { cell: cell.to_owned() })?;
        let previous = self.previous.replace((run.to_owned(), cell.to_owned(), time));
        if let Some((previous_run, previous_cell, previous_time)) = previous {
            let step = time - previous_time;
            // Both times are finite, so the step is a number (an overflow to infinity is refused).
            if previous_run == run && (step - self.tau).abs() > TOLERANCE * self.tau {
                return Err(SpacingError::Step {
                    cell: cell.to_owned(),
                    previous: previous_cell,
                    step: step as f32,
                    tau: self.tau,
                    unit: self.unit.clone(),
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check_all(tau: f64, rows: &[(&str, &str)]) -> Result<(), (usize, SpacingError)> {
        let mut spacing = Spacing::new(tau, "s");
        for (i, (run, cell)) in rows.iter().enumerate() {
            spacing.check(run, cell).map_err(|e| (i, e))?;
        }
        Ok(())
    }

    #[test]
    fn times_tau_apart_pass_and_another_period_a_gap_or_a_step_back_do_not() {
        // The decimals `simulate` writes, and times rounded to the millisecond with 2 % jitter.
        assert!(check_all(0.1, &[("", "0"), ("", "0.1"), ("", "0.2"), ("", "0.30000000000000004")]).is_ok());
        assert!(check_all(0.1, &[("", "1.000"), ("", "1.102"), ("", "1.199")]).is_ok());
        // Just beyond the tolerance, on either side: 0.1 ± 5.1 %.
        assert_eq!(check_all(0.1, &[("", "0"), ("", "0.1051")]).unwrap_err().0, 1);
        assert_eq!(check_all(0.1, &[("", "0"), ("", "0.0949")]).unwrap_err().0, 1);
        // A recording at 0.05 s for a 0.1 s design: refused at its second row, saying both periods.
        let (row, error) = check_all(0.1, &[("", "0"), ("", "0.05"), ("", "0.1")]).unwrap_err();
        assert_eq!(row, 1);
        let message = error.to_string();
        assert!(
            message.contains("0.05 s after") && message.contains("every 0.1 s"),
            "{message}"
        );
        // Repeated, decreasing, missing or not-a-number times.
        for bad in [["0", "0"], ["0.2", "0.1"], ["0", ""], ["0", "nan"], ["0", "inf"]] {
            assert!(check_all(0.1, &[("", bad[0]), ("", bad[1])]).is_err(), "{bad:?}");
        }
        // A new run starts afresh, at any time.
        assert!(check_all(0.1, &[("a", "5"), ("a", "5.1"), ("b", "0"), ("b", "0.1")]).is_ok());
    }
}
