//! What `plot` reads, found in the two headers before any row: the time, status and run columns,
//! each target's estimate, truth and saturation, and the signals drawn beside them (by the design's
//! names, or every other numeric column without one).

use super::stream::Csv;
use super::RecordedPlotError;
use crate::spec::Design;

const ESTIMATES_FIX: &str =
    "plot the estimates file `estimate` wrote (time, [run,] status, targets, saturated_<target>)";

/// Which file a column is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Side {
    Input,
    Estimates,
}

/// A target's columns: its estimate, its truth in the input (if any), its saturation (if any).
#[derive(Debug, PartialEq)]
pub(super) struct TargetColumns {
    pub(super) name: String,
    pub(super) estimate: usize,
    pub(super) truth: Option<usize>,
    pub(super) saturation: Option<usize>,
}

/// What an input column other than the truth is drawn as.
#[derive(Debug, PartialEq)]
pub(super) enum Role {
    /// A design's output: a panel of its own, dots; every cell must be a number.
    Output { unit: String },
    /// A design's input: a panel of its own, a line; every cell must be a number.
    Input { unit: String },
    /// Without a design: a line in the shared panel, left out if a cell is not a number.
    Other,
}

#[derive(Debug, PartialEq)]
pub(super) struct Signal {
    pub(super) column: usize,
    pub(super) name: String,
    pub(super) role: Role,
}

/// What the figure reads, found in the two headers before any row.
#[derive(Debug, PartialEq)]
pub(super) struct Layout {
    pub(super) headers: [Vec<String>; 2],
    /// The estimates' `time`; the input's `time` (else `t`), when it has one.
    pub(super) time: usize,
    pub(super) input_time: Option<usize>,
    pub(super) status: usize,
    /// The input's `run` (the time spacing restarts at a change).
    pub(super) input_run: Option<usize>,
    /// Where a restart is read: the estimates' `run`, else the input's.
    pub(super) run: Option<(Side, usize)>,
    pub(super) targets: Vec<TargetColumns>,
    pub(super) signals: Vec<Signal>,
}

impl Layout {
    pub(super) fn new(input: &Csv, estimates: &Csv, design: Option<&Design>) -> Result<Self, RecordedPlotError> {
        let time = estimates.require("time", ESTIMATES_FIX)?;
        let status = estimates.require("status", ESTIMATES_FIX)?;
        let run = estimates
            .column("run")
            .map(|c| (Side::Estimates, c))
            .or_else(|| input.column("run").map(|c| (Side::Input, c)));
        let names: Vec<&str> = estimates
            .header
            .iter()
            .map(String::as_str)
            .filter(|h| !matches!(*h, "time" | "run" | "status") && !h.starts_with("saturated_"))
            .collect();
        if names.is_empty() {
            return Err(RecordedPlotError::NoTargets {
                file: estimates.file.clone(),
            });
        }
        if let Some(design) = design {
            let mut found = names.clone();
            let mut expected: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
            found.sort_unstable();
            expected.sort_unstable();
            if found != expected {
                return Err(RecordedPlotError::OtherTargets {
                    file: estimates.file.clone(),
                    design: design.name.clone(),
                    found: found.join(", "),
                    expected: expected.join(", "),
                });
            }
        }
        let mut used: Vec<&str> = vec!["time", "t", "run"];
        let mut targets = Vec::new();
        for (estimate, name) in estimates.header.iter().enumerate() {
            if !names.contains(&name.as_str()) {
                continue;
            }
            let truth = input.column(&format!("truth_{name}")).or_else(|| input.column(name));
            if let Some(t) = truth {
                used.push(input.header[t].as_str());
            }
            targets.push(TargetColumns {
                name: name.clone(),
                estimate,
                truth,
                saturation: estimates.column(&format!("saturated_{name}")),
            });
        }
        let mut signals = Vec::new();
        match design {
            Some(design) => {
                let fix = format!(
                    "the design `{}` reads the outputs {} and the inputs {}: name the input's columns so, or plot without --design/--spec",
                    design.name,
                    design.model.outputs.iter().map(|o| o.name.as_str()).collect::<Vec<_>>().join(", "),
                    if design.model.inputs.is_empty() { "(none)".to_owned() } else { design.model.inputs.join(", ") }
                );
                for output in &design.model.outputs {
                    signals.push(Signal {
                        column: input.require(&output.name, &fix)?,
                        name: output.name.clone(),
                        role: Role::Output {
                            unit: output.unit.clone(),
                        },
                    });
                }
                for (name, unit) in design.model.inputs.iter().zip(&design.input_units) {
                    signals.push(Signal {
                        column: input.require(name, &fix)?,
                        name: name.clone(),
                        role: Role::Input { unit: unit.clone() },
                    });
                }
            }
            None => {
                for (column, name) in input.header.iter().enumerate() {
                    let truth_of_a_target = name.strip_prefix("truth_").is_some_and(|t| names.contains(&t));
                    if used.contains(&name.as_str()) || names.contains(&name.as_str()) || truth_of_a_target {
                        continue;
                    }
                    signals.push(Signal {
                        column,
                        name: name.clone(),
                        role: Role::Other,
                    });
                }
            }
        }
        Ok(Layout {
            headers: [input.header.clone(), estimates.header.clone()],
            time,
            input_time: input.column("time").or_else(|| input.column("t")),
            status,
            input_run: input.column("run"),
            run,
            targets,
            signals,
        })
    }
}
