//! The CSV files the tool writes: simulated runs, and estimates over a recording.

use crate::data::Run;
use crate::spec::Design;

use super::read::Row;
use super::row::{EstimateRow, Status};

/// `k τ` as the shortest decimal that `τ`'s own decimals allow: `0.3`, not `k as f64 * τ`'s
/// `0.30000000000000004`. Exact while `k τ`'s rounding error stays below half the last decimal of `τ`
/// (about `k < 10¹⁴` samples).
pub fn time_text(k: usize, tau: f64) -> String {
    let decimals = format!("{tau}").split_once('.').map_or(0, |(_, d)| d.len());
    let text = format!("{:.decimals$}", k as f64 * tau);
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// The header and lines of an estimates file: `time`, `run` (when the recording has one), `status`
/// (`ok`, `refused`, `no_estimate_yet`), one column per target, then `saturated_<target>` per target
/// (`-1` held at the low end of its range, `0` inside, `1` at the high end). Target cells are empty
/// unless the status is `ok`.
pub struct EstimatesCsv {
    targets: Vec<String>,
    runs: bool,
    tau: f64,
}

impl EstimatesCsv {
    /// The file of `targets` (in order) over a recording sampled every `tau` seconds, with a `run`
    /// column when `runs`.
    pub fn new(targets: &[&str], runs: bool, tau: f64) -> Self {
        EstimatesCsv {
            targets: targets.iter().map(|t| (*t).to_owned()).collect(),
            runs,
            tau,
        }
    }

    /// The header line.
    pub fn header(&self) -> String {
        let mut cells = vec!["time".to_owned()];
        if self.runs {
            cells.push("run".to_owned());
        }
        cells.push("status".to_owned());
        cells.extend(self.targets.iter().cloned());
        cells.extend(self.targets.iter().map(|t| format!("saturated_{t}")));
        cells.join(",") + "\n"
    }

    /// The line of row `k` (counted from 0 in the file): its time is the recording's `time`/`t` cell
    /// as written, else `k τ`.
    pub fn line(&self, k: usize, row: &Row, estimates: &EstimateRow) -> String {
        let mut cells = vec![row.time.clone().unwrap_or_else(|| time_text(k, self.tau))];
        if self.runs {
            cells.push(csv_cell(&row.run));
        }
        cells.push(estimates.status.as_str().to_owned());
        let ok = estimates.status == Status::Ok;
        for t in 0..self.targets.len() {
            cells.push(if ok {
                format!("{}", estimates.targets[t].0)
            } else {
                String::new()
            });
        }
        for t in 0..self.targets.len() {
            cells.push(if ok {
                match estimates.targets[t].1 {
                    firmware::Saturation::Low => "-1",
                    firmware::Saturation::Inside => "0",
                    firmware::Saturation::High => "1",
                }
                .to_owned()
            } else {
                String::new()
            });
        }
        cells.join(",") + "\n"
    }
}

/// A cell as CSV writes it: quoted when it holds a separator, a quote or a line break.
fn csv_cell(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// The whole estimates file of `rows` ([`EstimatesCsv`]).
pub fn estimates_csv(csv: &EstimatesCsv, rows: &[Row], estimates: &[EstimateRow]) -> String {
    let mut text = csv.header();
    for (k, (row, estimate)) in rows.iter().zip(estimates).enumerate() {
        text += &csv.line(k, row, estimate);
    }
    text
}

/// The targets a simulated run writes as `truth_<name>`: those that are not simply the state of the
/// same name (whose column already holds their truth).
fn truth_columns(design: &Design) -> Vec<usize> {
    (0..design.targets.len())
        .filter(|&t| {
            let target = &design.targets[t];
            !(design.model.states.contains(&target.name) && target.expr.text().trim() == target.name)
        })
        .collect()
}

/// CSV text of a simulated run: `time`, the states (true values), the outputs (with noise), the
/// inputs, then `truth_<target>` for each target that is not a state of the same name.
pub fn run_csv(design: &Design, run: &Run) -> String {
    let mut text = Vec::new();
    write_run_csv(design, run, &mut text).expect("writing into memory cannot fail");
    String::from_utf8(text).expect("the CSV is ASCII")
}

/// [`run_csv`], written line by line into `out`.
pub fn write_run_csv(design: &Design, run: &Run, out: &mut impl std::io::Write) -> std::io::Result<()> {
    let truths = truth_columns(design);
    let names: Vec<String> = std::iter::once("time".to_owned())
        .chain(design.model.states.iter().cloned())
        .chain(design.model.outputs.iter().map(|o| o.name.clone()))
        .chain(design.model.inputs.iter().cloned())
        .chain(truths.iter().map(|&t| format!("truth_{}", design.targets[t].name)))
        .collect();
    writeln!(out, "{}", names.join(","))?;
    for k in 0..run.measurements.len() {
        let values: Vec<String> = std::iter::once(time_text(k, design.tau))
            .chain(
                run.states[k]
                    .iter()
                    .chain(&run.measurements[k])
                    .chain(&run.inputs[k])
                    .chain(truths.iter().map(|&t| &run.targets[k][t]))
                    .map(|v| format!("{v}")),
            )
            .collect();
        writeln!(out, "{}", values.join(","))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times_are_written_as_their_decimals() {
        // Each `k as f64 * τ` here prints with float noise; the text must be the exact decimal.
        assert_eq!(format!("{}", 3.0 * 0.1), "0.30000000000000004");
        assert_eq!(time_text(3, 0.1), "0.3");
        assert_eq!(format!("{}", 7.0 * 0.07), "0.49000000000000005");
        assert_eq!(time_text(7, 0.07), "0.49");
        assert_eq!(time_text(0, 0.1), "0");
        assert_eq!(time_text(10, 0.1), "1");
        assert_eq!(time_text(12, 2.0), "24");
        assert_eq!(time_text(3, 0.25), "0.75");
        assert_eq!(time_text(123_456_789, 0.001), "123456.789");
        // Every sample of a long run equals the exact decimal k/10.
        for k in 0..100_000 {
            let text = time_text(k, 0.1);
            let exact = if k % 10 == 0 {
                format!("{}", k / 10)
            } else {
                format!("{}.{}", k / 10, k % 10)
            };
            assert_eq!(text, exact, "k = {k}");
        }
    }

    #[test]
    fn the_estimates_file_names_each_column() {
        let csv = EstimatesCsv::new(&["x1", "energy"], true, 0.5);
        assert_eq!(
            csv.header(),
            "time,run,status,x1,energy,saturated_x1,saturated_energy\n"
        );
        let row = |time: Option<&str>, run: &str| Row {
            time: time.map(str::to_owned),
            run: run.to_owned(),
            y: vec![0.0],
            u: vec![],
        };
        let ok = EstimateRow {
            status: Status::Ok,
            targets: vec![(1.5, firmware::Saturation::High), (-2.0, firmware::Saturation::Inside)],
        };
        assert_eq!(csv.line(3, &row(None, "a,b"), &ok), "1.5,\"a,b\",ok,1.5,-2,1,0\n");
        assert_eq!(
            csv.line(3, &row(Some("12:00:01"), "a"), &EstimateRow::without(Status::Refused)),
            "12:00:01,a,refused,,,,\n"
        );
        let plain = EstimatesCsv::new(&["x1"], false, 0.1);
        let low = EstimateRow {
            status: Status::Ok,
            targets: vec![(0.25, firmware::Saturation::Low)],
        };
        assert_eq!(plain.line(1, &row(None, ""), &low), "0.1,ok,0.25,-1\n");
        assert_eq!(
            plain.line(2, &row(None, ""), &EstimateRow::without(Status::NoEstimateYet)),
            "0.2,no_estimate_yet,,\n"
        );
    }
}
