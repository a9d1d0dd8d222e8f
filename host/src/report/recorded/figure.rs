//! The figure of a recorded run and its estimates: a panel per target (estimate against truth),
//! then per output and input (or one of the other signals), each marking refusals and restarts.

use std::path::Path;

use super::columns::Role;
use super::decimate::{Dots, Extent, Grid, Line, PerColumn, Point, PANEL_WIDTH, ROW_HEIGHT};
use super::rows::{open, scan, Status};
use super::RecordedPlotError;
use crate::report::draw::{
    with_unit, Figure, Panel, Series, Style, ESTIMATE_COLOR, MARK_COLOR, PALETTE, REFUSED_COLOR, SATURATED_COLOR,
    TRUE_COLOR,
};
use crate::spec::Design;

/// How a signal's values are kept.
enum Drawn {
    Dots(Dots),
    Line(Line),
}

impl Drawn {
    /// The points, and the bands of dots.
    fn points(&self) -> (Vec<Point>, Vec<(f64, f64, f64)>) {
        match self {
            Drawn::Dots(dots) => dots.finish(),
            Drawn::Line(line) => (line.points(), Vec::new()),
        }
    }
}

/// The figure of a recorded run and its estimates: both files are read twice, first to check every
/// row and find the time axis and each dotted series' values, then to keep what is drawn.
pub(super) fn figure(input: &Path, estimates: &Path, design: Option<&Design>) -> Result<Figure, RecordedPlotError> {
    let (input_csv, estimates_csv, layout) = open(input, estimates, design)?;
    let mut times = Extent::default();
    let mut estimate_values = vec![Extent::default(); layout.targets.len()];
    let mut signal_values = vec![Extent::default(); layout.signals.len()];
    let numeric = scan(input_csv, estimates_csv, &layout, design, |row| {
        times.add(row.time);
        for (extent, target) in estimate_values.iter_mut().zip(&row.targets) {
            extent.add(target.estimate);
        }
        for (extent, &value) in signal_values.iter_mut().zip(&row.signals) {
            extent.add(value);
        }
    })?;
    let grid = Grid::new(times);

    let (input_csv, estimates_csv, again) = open(input, estimates, design)?;
    if again != layout {
        return Err(RecordedPlotError::Csv {
            file: input.to_owned(),
            message: format!(
                "{} or this file changed while plot read them; plot again",
                estimates.display()
            ),
        });
    }
    let mut truths: Vec<Line> = layout.targets.iter().map(|_| Line::default()).collect();
    let mut estimate_dots: Vec<Dots> = estimate_values.iter().map(|&e| Dots::new(e)).collect();
    let mut rings: Vec<[PerColumn<Point>; 2]> = layout
        .targets
        .iter()
        .map(|_| [PerColumn::new(), PerColumn::new()])
        .collect();
    let mut signals: Vec<Drawn> = layout
        .signals
        .iter()
        .zip(&signal_values)
        .map(|(signal, &values)| match signal.role {
            Role::Output { .. } => Drawn::Dots(Dots::new(values)),
            Role::Input { .. } | Role::Other => Drawn::Line(Line::default()),
        })
        .collect();
    let mut refused = PerColumn::new();
    let mut restarted = PerColumn::new();
    scan(input_csv, estimates_csv, &layout, design, |row| {
        let (t, column) = (row.time, grid.column(row.time));
        if row.status == Status::Refused {
            refused.put(column, t);
        }
        if row.restart || row.status == Status::Restarted {
            restarted.put(column, t);
        }
        for (i, target) in row.targets.iter().enumerate() {
            truths[i].push(&grid, t, target.truth, row.restart);
            estimate_dots[i].push(&grid, t, target.estimate);
            if target.saturation != 0 && target.estimate.is_finite() {
                rings[i][usize::from(target.saturation > 0)].put(column, (t, target.estimate));
            }
        }
        for (drawn, &value) in signals.iter_mut().zip(&row.signals) {
            match drawn {
                Drawn::Dots(dots) => dots.push(&grid, t, value),
                Drawn::Line(line) => line.push(&grid, t, value, row.restart),
            }
        }
    })?;

    let title = input
        .file_stem()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    let time_label = design.map_or("time".to_owned(), |d| with_unit("time", &d.time_unit));
    let (refused, restarted) = (refused.values(), restarted.values());
    let marked = |panel: Panel| {
        panel
            .marked(
                "refused sample (NaN or infinite)",
                refused.clone(),
                REFUSED_COLOR,
                Style::Rule,
            )
            .marked(
                "observer restarted (new run)",
                restarted.clone(),
                MARK_COLOR,
                Style::Dashes,
            )
    };
    let mut panels = Vec::new();
    for (i, target) in layout.targets.iter().enumerate() {
        let name = target.name.as_str();
        let unit = design
            .and_then(|d| d.targets.iter().find(|t| t.name == name))
            .map_or("", |t| t.unit.as_str());
        let mut panel = Panel::new(
            format!("{title}: estimating {name}"),
            time_label.clone(),
            with_unit(name, unit),
        );
        if let Some(truth) = target.truth {
            let label = &layout.headers[0][truth];
            panel = panel.with(Series::new(
                format!("true ({label})"),
                truths[i].points(),
                TRUE_COLOR,
                Style::Line,
            ));
        }
        let (dots, bands) = estimate_dots[i].finish();
        panel = panel.with(Series::new("estimate", dots, ESTIMATE_COLOR, Style::Dots).with_bands(bands));
        if target.saturation.is_some() {
            let [low, high] = &rings[i];
            let mut points = low.values();
            points.extend(high.values());
            panel = panel.with(Series::new(
                crate::report::plots::SATURATED_LABEL,
                points,
                SATURATED_COLOR,
                Style::Rings,
            ));
        }
        panels.push(marked(panel));
    }
    let mut others = Panel::new(format!("{title}: recorded signals"), time_label.clone(), "value");
    let mut colors = PALETTE.iter().cycle();
    for ((signal, drawn), numeric) in layout.signals.iter().zip(&signals).zip(numeric) {
        let name = signal.name.as_str();
        match &signal.role {
            Role::Output { unit } => panels.push(marked(
                Panel::new(
                    format!("{title}: measured {name}"),
                    time_label.clone(),
                    with_unit(name, unit),
                )
                .with({
                    let (dots, bands) = drawn.points();
                    Series::new("measured", dots, ESTIMATE_COLOR, Style::Dots).with_bands(bands)
                }),
            )),
            Role::Input { unit } => panels.push(marked(
                Panel::new(
                    format!("{title}: input {name}"),
                    time_label.clone(),
                    with_unit(name, unit),
                )
                .with(Series::new(name, drawn.points().0, PALETTE[1], Style::Line)),
            )),
            // A column of text is left out.
            Role::Other if numeric => {
                let color = *colors.next().unwrap_or(&PALETTE[0]);
                others = others.with(Series::new(name, drawn.points().0, color, Style::Line));
            }
            Role::Other => {}
        }
    }
    if !others.series.is_empty() {
        panels.push(marked(others));
    }
    Ok(Figure {
        rows: panels.into_iter().map(|p| vec![p]).collect(),
        panel_width: PANEL_WIDTH,
        row_height: ROW_HEIGHT,
    })
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;

    /// `input` and `estimates` written as `<name>-<pid>/run.csv` and `est.csv` in the temporary folder.
    fn files(name: &str, input: &str, estimates: &str) -> (PathBuf, PathBuf) {
        let dir = std::env::temp_dir().join(format!("recorded-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (run, est) = (dir.join("run.csv"), dir.join("est.csv"));
        std::fs::write(&run, input).unwrap();
        std::fs::write(&est, estimates).unwrap();
        (run, est)
    }

    fn figure_of(name: &str, input: &str, estimates: &str) -> Result<Figure, RecordedPlotError> {
        let (run, est) = files(name, input, estimates);
        let figure = figure(&run, &est, None);
        std::fs::remove_dir_all(run.parent().unwrap()).unwrap();
        figure
    }

    const INPUT: &str = "time,x1,y,u\n0,1,1.1,0\n0.1,2,2.1,0\n0.2,3,nan,1\n0.3,4,4.1,1\n";
    const ESTIMATES: &str =
        "time,status,x1,saturated_x1\n0,no_estimate_yet,,\n0.1,ok,2.5,1\n0.2,refused,,\n0.3,ok,3.9,0\n";

    fn panel<'f>(figure: &'f Figure, title_end: &str) -> &'f Panel {
        figure
            .rows
            .iter()
            .flatten()
            .find(|p| p.title.ends_with(title_end))
            .unwrap_or_else(|| panic!("no panel `{title_end}`"))
    }

    #[test]
    fn the_estimates_are_drawn_against_the_truth_with_refusals_and_saturation_marked() {
        let figure = figure_of("drawn", INPUT, ESTIMATES).unwrap();
        let x1 = panel(&figure, "estimating x1");
        let truth = x1.series.iter().find(|s| s.label == "true (x1)").unwrap();
        assert_eq!(truth.points, [(0.0, 1.0), (0.1, 2.0), (0.2, 3.0), (0.3, 4.0)]);
        let estimate = x1.series.iter().find(|s| s.label == "estimate").unwrap();
        let finite: Vec<_> = estimate.points.iter().filter(|p| p.1.is_finite()).copied().collect();
        assert_eq!(finite, [(0.1, 2.5), (0.3, 3.9)]);
        let rings = x1.series.iter().find(|s| s.style == Style::Rings).unwrap();
        assert_eq!(rings.points, [(0.1, 2.5)]);
        assert_eq!(x1.marks[0].at, [0.2]);
        // Without the design the other numeric columns share one panel; the truth is not repeated.
        let signals = panel(&figure, "recorded signals");
        let names: Vec<&str> = signals.series.iter().map(|s| s.label.as_str()).collect();
        assert_eq!(names, ["y", "u"]);
    }

    #[test]
    fn a_truth_column_is_preferred_and_runs_break_lines_and_are_marked() {
        let input = "run,truth_x1,x1,y\na,10,1,0\na,11,2,0\nb,12,3,0\nb,13,4,0\n";
        let estimates = "time,run,status,x1,saturated_x1\n0,a,ok,1,0\n0.1,a,ok,2,0\n0.2,b,ok,3,-1\n0.3,b,ok,4,0\n";
        let figure = figure_of("runs", input, estimates).unwrap();
        let x1 = panel(&figure, "estimating x1");
        let truth = &x1.series[0];
        assert_eq!(truth.label, "true (truth_x1)");
        assert_eq!(truth.points.len(), 5);
        assert!(truth.points[2].0.is_nan(), "a restart breaks the line");
        assert_eq!(x1.marks[0].label, "observer restarted (new run)");
        assert_eq!(x1.marks[0].at, [0.2]);
        let rings = x1.series.iter().find(|s| s.style == Style::Rings).unwrap();
        assert_eq!(rings.points, [(0.2, 3.0)]);
        // A column named after a target is never a recorded signal, even when truth_x1 is the truth.
        let signals = panel(&figure, "recorded signals");
        assert_eq!(
            signals.series.iter().map(|s| s.label.as_str()).collect::<Vec<_>>(),
            ["y"]
        );
    }

    #[test]
    fn estimates_of_another_input_are_refused() {
        let shifted = ESTIMATES.replace("0.3,ok", "0.4,ok");
        let error = figure_of("shifted", INPUT, &shifted).err().unwrap();
        assert!(
            matches!(error, RecordedPlotError::OtherTimes { line: 5, .. }),
            "{error}"
        );
        let short: String = ESTIMATES.lines().take(3).map(|l| format!("{l}\n")).collect();
        let error = figure_of("short", INPUT, &short).err().unwrap();
        assert!(matches!(
            error,
            RecordedPlotError::RowCount {
                input_rows: 4,
                estimate_rows: 2,
                ..
            }
        ));
        let bad = ESTIMATES.replace("refused", "maybe");
        let error = figure_of("bad", INPUT, &bad).err().unwrap();
        assert!(
            error.to_string().contains("line 4, column `status`: `maybe`"),
            "{error}"
        );
    }

    /// Deterministic noise in [0, 1) for row `k` (a multiplicative hash; the test's own truth).
    fn noise(k: usize) -> f64 {
        ((k as u64).wrapping_mul(6_364_136_223_846_793_005) >> 40) as f64 / (1u64 << 24) as f64
    }
    #[test]
    fn a_long_line_keeps_each_columns_first_last_lowest_and_highest_row_and_dots_stay_within_2_px() {
        // Times 0, 1, …, ROWS − 1 over 900 columns of 222.5 each: no time lies on a border, so the
        // column of row k is ⌊k / 222.5⌋ by plain arithmetic.
        const ROWS: usize = 200_251;
        let width = (ROWS - 1) as f64 / 900.0;
        assert_eq!(width, 222.5);
        let column = |t: f64| ((t / width).floor() as usize).min(899);
        let value = |k: usize| (k as f64 / 3000.0).sin() + 0.3 * noise(k);
        let (mut input, mut estimates) = (String::from("x1\n"), String::from("time,status,x1\n"));
        for k in 0..ROWS {
            input.push_str(&format!("{}\n", value(k)));
            estimates.push_str(&format!("{k},ok,{}\n", value(k)));
        }
        let figure = figure_of("long", &input, &estimates).unwrap();
        let x1 = panel(&figure, "estimating x1");

        // The line: per column, brute force over every row.
        let truth = &x1.series.iter().find(|s| s.label == "true (x1)").unwrap().points;
        assert!(truth.len() <= 4 * 900, "{} points for 900 columns", truth.len());
        let mut expected: Vec<Option<[(f64, f64); 4]>> = vec![None; 900]; // first, last, lowest, highest
        for k in 0..ROWS {
            let p = (k as f64, value(k));
            let e = expected[column(p.0)].get_or_insert([p; 4]);
            e[1] = p;
            if p.1 < e[2].1 {
                e[2] = p;
            }
            if p.1 > e[3].1 {
                e[3] = p;
            }
        }
        for (c, e) in expected.iter().enumerate() {
            let [first, last, low, high] = e.unwrap();
            let drawn: Vec<(f64, f64)> = truth.iter().copied().filter(|p| column(p.0) == c).collect();
            assert_eq!(drawn.first(), Some(&first), "column {c}");
            assert_eq!(drawn.last(), Some(&last), "column {c}");
            assert!(drawn.contains(&low) && drawn.contains(&high), "column {c}");
            // Every point drawn is a row of the file, in the file's order (one unbroken line).
            assert!(drawn.iter().all(|p| p.1 == value(p.0 as usize)));
        }
        assert!(truth.windows(2).all(|w| w[0].0 <= w[1].0), "in row order, never broken");

        // The dots: far fewer than the rows, and every row's dot within one 2-column by
        // (range / 160) cell of a drawn dot or band: under 2 px, as the plotting area is under
        // 900 × 320 px.
        let estimate = x1.series.iter().find(|s| s.label == "estimate").unwrap();
        let (dots, bands) = (&estimate.points, &estimate.bands);
        assert!(
            dots.len() + bands.len() < ROWS / 10,
            "{} dots, {} bands",
            dots.len(),
            bands.len()
        );
        let (low, high) = (0..ROWS)
            .map(value)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
        let cell_height = (high - low) / 160.0;
        let mut by_column: Vec<Vec<(f64, f64)>> = vec![Vec::new(); 900];
        for &(t, v) in dots {
            by_column[column(t)].push((v, v));
        }
        for &(t, from, to) in bands {
            assert!(from < to, "a band runs up");
            by_column[column(t)].push((from, to));
        }
        for k in 0..ROWS {
            let (c, v) = (column(k as f64), value(k));
            let near = (c.saturating_sub(2)..=(c + 2).min(899))
                .flat_map(|c| &by_column[c])
                .any(|&(from, to)| from - cell_height <= v && v <= to + cell_height);
            assert!(near, "row {k}: nothing drawn within 2 px");
        }
    }
}
