//! `host simulate` and `host estimate`: the paper's scenario from the command line, runs, refused
//! samples, and clear errors that write nothing.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn host(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mho")).args(args).output().unwrap()
}

/// `host estimate --design vanderpol --input IN --output OUT --kind map`.
fn estimate_vanderpol(input: &Path, output: &Path) -> Output {
    estimate_kind("map", input, output)
}

/// `host estimate --design vanderpol --input IN --output OUT --kind KIND`, by the tables `gen` would
/// save ([`saved_tables`]: fitted and tuned once per test binary, not once per call).
fn estimate_kind(kind: &str, input: &Path, output: &Path) -> Output {
    host(&[
        "estimate",
        "--design",
        "vanderpol",
        "--input",
        s(input),
        "--output",
        s(output),
        "--kind",
        kind,
        "--tables",
        s(saved_tables()),
    ])
}

/// Example 1 fitted and its observers compared, once per test binary.
fn compared() -> &'static (host::spec::Design, host::fit::DesignResult, host::observers::Comparison) {
    static COMPARED: std::sync::OnceLock<(host::spec::Design, host::fit::DesignResult, host::observers::Comparison)> =
        std::sync::OnceLock::new();
    COMPARED.get_or_init(|| {
        let design = host::spec::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml")).unwrap();
        let result = host::generate::simulate_and_fit(&design, &indicatif::ProgressBar::hidden()).unwrap();
        let code = host::plant::ModelCode::new(&design).unwrap();
        let comparison = host::observers::compare(&design, &result, &code, &indicatif::ProgressBar::hidden()).unwrap();
        (design, result, comparison)
    })
}

/// Example 1's tables as `gen` saves them (`design.json`), from [`compared`].
fn saved_tables() -> &'static Path {
    static SAVED: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    SAVED.get_or_init(|| {
        let (design, result, comparison) = compared();
        let path = scratch("saved-tables").join("design.json");
        std::fs::write(
            &path,
            host::tables::Tables::new(design, result, Some(comparison)).to_json(),
        )
        .unwrap();
        path
    })
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("host-estimate-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn rows(text: &str) -> Vec<Vec<String>> {
    text.lines()
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect()
}

/// The cells of the column named `name` below the header.
fn column<'a>(table: &'a [Vec<String>], name: &str) -> Vec<&'a str> {
    let c = table[0]
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name}"));
    table[1..].iter().map(|r| r[c].as_str()).collect()
}

#[test]
fn paper_scenario_round_trip_matches_the_library() {
    let dir = scratch("scenario");
    let (run, estimates) = (dir.join("run.csv"), dir.join("estimates.csv"));
    let out = host(&["simulate", "--design", "vanderpol", "--output", s(&run)]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let recorded = rows(&std::fs::read_to_string(&run).unwrap());
    assert_eq!(recorded[0], ["time", "x1", "x2", "y"]);
    assert_eq!(recorded.len(), 1 + 101);
    assert_eq!((recorded[1][1].as_str(), recorded[1][2].as_str()), ("2", "0.5"));
    // Times are the decimals k τ (τ = 0.1 s), not `3.0 * 0.1` = 0.30000000000000004.
    assert_eq!(column(&recorded, "time")[..4], ["0", "0.1", "0.2", "0.3"]);
    assert_eq!(column(&recorded, "time")[100], "10");

    let out = estimate_vanderpol(&run, &estimates);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let table = rows(&std::fs::read_to_string(&estimates).unwrap());
    assert_eq!(table[0], ["time", "status", "x1", "x2", "saturated_x1", "saturated_x2"]);
    assert_eq!(table.len(), recorded.len());
    // The recording's time, as written.
    assert_eq!(column(&table, "time"), column(&recorded, "time"));
    // No estimate before N = 10 samples (the first correction at t = 0.9 s, as in the paper).
    for row in &table[1..10] {
        assert_eq!(row[1], "no_estimate_yet");
        assert!(row[2..].iter().all(String::is_empty), "{row:?}");
    }
    // From then on, the library estimate on the same window, to the last bit.
    let design = host::spec::load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/specs/vanderpol.toml"))).unwrap();
    let result = host::generate::simulate_and_fit(&design, &indicatif::ProgressBar::hidden()).unwrap();
    let y: Vec<f64> = recorded[1..].iter().map(|r| r[3].parse().unwrap()).collect();
    let mut errors = [0.0f64; 2];
    for k in 9..y.len() {
        let z: Vec<f64> = (0..10).map(|lag| y[k - lag]).collect();
        for t in 0..2 {
            let expected = result.targets[t].fit.map.estimate(&z);
            assert_eq!(table[1 + k][1], "ok");
            assert_eq!(
                table[1 + k][2 + t].parse::<f64>().unwrap(),
                expected.value,
                "row {k} target {t}"
            );
            let flag = match expected.saturation {
                firmware::Saturation::Low => "-1",
                firmware::Saturation::Inside => "0",
                firmware::Saturation::High => "1",
            };
            assert_eq!(table[1 + k][4 + t], flag, "row {k} target {t}");
            let expected = expected.value;
            let truth: f64 = recorded[1 + k][1 + t].parse().unwrap();
            errors[t] = errors[t].max((expected - truth).abs());
        }
    }
    // The scenario starts inside the box: the estimates track the truth within the validation ε_x.
    for (t, error) in errors.iter().enumerate() {
        let bound = result.targets[t].validation.map.max_error;
        assert!(*error <= bound * 1.5, "target {t}: {error} vs ε_x {bound}");
    }
}

#[test]
fn runs_restart_the_observer_and_refused_samples_leave_no_trace() {
    for kind in ["map", "corrected", "ekf_map"] {
        restart_and_refusal(kind);
    }
}

/// Every kind of observer: restarted by each run, no estimate before the N-th accepted sample, and a
/// refused sample changes nothing that follows.
fn restart_and_refusal(kind: &str) {
    let dir = scratch(&format!("runs-{kind}"));
    let (input, output) = (dir.join("in.csv"), dir.join("out.csv"));
    // Two runs of 12 samples, an extra ignored column, and a NaN in the second run at row 16.
    let mut text = String::from("note,run,y\n");
    for k in 0..24 {
        let y = if k == 16 {
            "NaN".to_owned()
        } else {
            format!("{}", (k as f64 * 0.37).sin() * 3.0)
        };
        text += &format!("n{k},{},{y}\n", if k < 12 { "a" } else { "b" });
    }
    std::fs::write(&input, &text).unwrap();
    let out = estimate_kind(kind, &input, &output);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let table = rows(&std::fs::read_to_string(&output).unwrap());
    assert_eq!(
        table[0],
        ["time", "run", "status", "x1", "x2", "saturated_x1", "saturated_x2"]
    );
    // Without a time column, row k is at k τ; the run column is repeated.
    assert_eq!(column(&table, "time")[21], "2.1");
    assert_eq!(column(&table, "run")[11..13], ["a", "b"]);
    // Run b accepts rows 12-15 and 17-23: its 10th accepted sample is row 22.
    let expected: Vec<&str> = (0..24)
        .map(|k| match k {
            16 => "refused",
            9..=11 | 22.. => "ok",
            _ => "no_estimate_yet",
        })
        .collect();
    assert_eq!(
        column(&table, "status"),
        expected,
        "{kind}: estimates from the 10th accepted sample of each run"
    );
    for (k, row) in table[1..].iter().enumerate() {
        assert_eq!(row[3].is_empty(), expected[k] != "ok", "{kind} row {k}");
    }
    // The refused row leaves no trace: the same file without it gives the same last estimates.
    let without: String = text
        .lines()
        .enumerate()
        .filter(|(i, _)| *i != 1 + 16)
        .map(|(_, l)| format!("{l}\n"))
        .collect();
    let (input2, output2) = (dir.join("in2.csv"), dir.join("out2.csv"));
    std::fs::write(&input2, without).unwrap();
    assert!(estimate_kind(kind, &input2, &output2).status.success());
    let table2 = rows(&std::fs::read_to_string(&output2).unwrap());
    // From `status` on (the times differ: the rows moved up by one).
    let tail = |t: &[Vec<String>]| t[t.len() - 2..].iter().map(|r| r[2..].to_vec()).collect::<Vec<_>>();
    assert_eq!(tail(&table), tail(&table2), "{kind}");
}

#[test]
fn bad_recordings_are_refused_with_line_and_column_and_nothing_is_written() {
    let dir = scratch("bad");
    let output = dir.join("out.csv");
    let cases = [
        ("missing.csv", "time,z\n0,1\n", vec!["no column `y`", "missing.csv"]),
        (
            "text.csv",
            "time,y\n0,1\n0.1,abc\n",
            vec!["line 3", "column `y`", "`abc`"],
        ),
        ("empty.csv", "time,y\n0,1\n0.1,\n", vec!["line 3", "column `y`"]),
        // A recording at another sample period than the design's 0.1 s (it used to give 40 times
        // the error, exit 0), a step back in time, and a time that is not a number.
        (
            "fast.csv",
            "time,y\n0,1\n0.05,1.1\n0.1,1.2\n",
            vec!["line 3", "column `time`", "0.05 s after", "every 0.1 s"],
        ),
        (
            "back.csv",
            "t,y\n0,1\n0.1,1.1\n0.05,1.2\n",
            vec!["line 4", "column `t`", "`0.05`"],
        ),
        (
            "clock.csv",
            "time,y\n0,1\n12:00,1.1\n",
            vec!["line 3", "`12:00` is not a finite number"],
        ),
    ];
    for (name, text, expected) in cases {
        let input = dir.join(name);
        std::fs::write(&input, text).unwrap();
        let out = estimate_vanderpol(&input, &output);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success());
        for e in expected {
            assert!(stderr.contains(e), "{name}: {stderr}");
        }
        assert!(!output.exists(), "{name}: an output was written");
    }
    let out = host(&[
        "estimate",
        "--design",
        "nosuch",
        "--input",
        "x.csv",
        "--output",
        s(&output),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && stderr.contains("unknown design `nosuch`") && stderr.contains("vanderpol"),
        "{stderr}"
    );
    assert!(!output.exists());
}

#[test]
fn an_output_that_is_an_input_or_a_folder_is_refused_and_the_input_survives() {
    let dir = scratch("overwrite");
    let recording = dir.join("a.csv");
    std::fs::write(&recording, "y\n0.5\n").unwrap();
    // estimate --input a.csv --output ./a.csv (same file, spelt differently) used to replace the recording.
    let same = dir.join(".").join("a.csv");
    let out = estimate_vanderpol(&recording, &same);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("which writing would destroy") && stderr.contains("--output"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&recording).unwrap(), "y\n0.5\n");
    // simulate --spec v.toml --output v.toml used to replace the spec.
    let spec = dir.join("v.toml");
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml")).unwrap();
    std::fs::write(&spec, &text).unwrap();
    let out = host(&["simulate", "--spec", s(&spec), "--output", s(&spec)]);
    assert!(!out.status.success(), "{}", String::from_utf8_lossy(&out.stdout));
    assert_eq!(std::fs::read_to_string(&spec).unwrap(), text);
    // An output that is a folder.
    let out = host(&["simulate", "--spec", s(&spec), "--output", s(&dir)]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("is a folder"));
    // estimate --tables design.json --output design.json used to replace the saved design with the
    // CSV: refused before anything is read, the file unchanged.
    let tables = dir.join("design.json");
    std::fs::write(&tables, "{\"saved\": true}\n").unwrap();
    let out = host(&[
        "estimate",
        "--design",
        "vanderpol",
        "--input",
        s(&recording),
        "--output",
        s(&tables),
        "--tables",
        s(&tables),
    ]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("design.json") && stderr.contains("which writing would destroy"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&tables).unwrap(), "{\"saved\": true}\n");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_device_as_input_and_a_huge_run_are_refused_at_once() {
    // `estimate --input /dev/zero` read forever; `simulate --samples 10^9` ran out of memory.
    let dir = scratch("bounds");
    let out = estimate_vanderpol(Path::new("/dev/zero"), &dir.join("out.csv"));
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a regular file"));
    let out = host(&[
        "simulate",
        "--design",
        "vanderpol",
        "--samples",
        "1000000000",
        "--output",
        s(&dir.join("run.csv")),
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("above the limit"));
    assert!(!dir.join("out.csv").exists() && !dir.join("run.csv").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The recorded-file reader on the defects found by fuzzing it.
mod reading {
    use std::path::Path;

    use host::recording::{read, RecordingError};

    fn vanderpol() -> host::spec::Design {
        host::spec::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml")).unwrap()
    }

    fn read_bytes(name: &str, bytes: &[u8]) -> Result<Vec<host::recording::Row>, RecordingError> {
        let path = std::env::temp_dir().join(format!("host-reading-{}-{name}.csv", std::process::id()));
        std::fs::write(&path, bytes).unwrap();
        let result = read(&vanderpol(), &path);
        let _ = std::fs::remove_file(&path);
        result
    }

    #[test]
    fn line_numbers_are_true_for_every_line_ending() {
        // The bad cell is on line 3 (the header is line 1); CRLF used to say 2 and CR 1.
        for (ending, name) in [("\n", "lf"), ("\r\n", "crlf"), ("\r", "cr")] {
            let text = ["y", "0.5", "oops", "0.7"].join(ending) + ending;
            match read_bytes(name, text.as_bytes()) {
                Err(RecordingError::NotANumber { line, .. }) => assert_eq!(line, 3, "{name}"),
                other => panic!("{name}: {other:?}"),
            }
        }
    }

    #[test]
    fn a_needed_column_named_twice_is_refused() {
        assert!(matches!(
            read_bytes("duplicate", b"y,y\n1,2\n"),
            Err(RecordingError::DuplicateColumn { column, .. }) if column == "y"
        ));
        assert!(matches!(
            read_bytes("duplicate-run", b"run,y,run\na,1,b\n"),
            Err(RecordingError::DuplicateColumn { column, .. }) if column == "run"
        ));
        // A column the design does not read may repeat.
        assert_eq!(read_bytes("ignored", b"note,y,note\na,1,b\n").unwrap().len(), 1);
    }

    #[test]
    fn an_ignored_column_may_hold_any_bytes() {
        let rows = read_bytes("bytes", b"y,note\n0.5,\xff\xfe\n0.25,ok\n").unwrap();
        assert_eq!(rows.iter().map(|r| r.y[0]).collect::<Vec<_>>(), [0.5, 0.25]);
    }

    #[test]
    fn a_number_beyond_f64_is_an_error_and_a_written_infinity_is_kept() {
        match read_bytes("overflow", b"y\n1e400\n") {
            Err(RecordingError::NotANumber { line: 2, cell, .. }) => assert_eq!(cell, "1e400"),
            other => panic!("{other:?}"),
        }
        let rows = read_bytes("infinity", b"y\ninf\n-Infinity\nNaN\n").unwrap();
        assert!(rows[0].y[0] == f64::INFINITY && rows[1].y[0] == f64::NEG_INFINITY && rows[2].y[0].is_nan());
    }
}

#[test]
fn a_non_finite_initial_state_is_blamed_on_x0() {
    let dir = scratch("x0");
    let out = host(&[
        "simulate",
        "--design",
        "vanderpol",
        "--x0",
        "nan,0",
        "--output",
        s(&dir.join("run.csv")),
    ]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("--x0") && !stderr.contains("derivatives"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn streaming_estimates_equal_the_in_memory_ones() {
    // Two runs, a refused NaN sample and enough rows for windows: `estimate` now streams the file
    // row by row; its text must be what the in-memory path (used by the figures) gives.
    let design = host::spec::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml")).unwrap();
    let result = host::generate::simulate_and_fit(&design, &indicatif::ProgressBar::hidden()).unwrap();
    let maps: Vec<_> = result.targets.iter().map(|t| t.fit.map.clone()).collect();
    let mut text = String::from("run,y\n");
    for k in 0..40 {
        let run = if k < 25 { "a" } else { "b" };
        let y = if k == 17 {
            "nan".to_owned()
        } else {
            format!("{}", (k as f64 * 0.3).sin() * 2.0)
        };
        text += &format!("{run},{y}\n");
    }
    let path = std::env::temp_dir().join(format!("host-stream-{}.csv", std::process::id()));
    std::fs::write(&path, &text).unwrap();
    let rows = host::recording::read(&design, &path).unwrap();
    let names: Vec<&str> = design.targets.iter().map(|t| t.name.as_str()).collect();
    let csv = host::recording::EstimatesCsv::new(&names, true, design.tau);
    for precision in [host::recording::Precision::F64, host::recording::Precision::F32] {
        let maps = host::recording::MapEvaluator::new(&maps, precision).unwrap();
        let estimates = host::recording::estimate(&maps, design.map.horizon, &rows);
        let in_memory = host::recording::estimates_csv(&csv, &rows, &estimates);
        let mut streamed = Vec::new();
        let mut reader = host::recording::RowReader::open(&design, &path).unwrap();
        host::recording::estimate_streaming(&maps, design.map.horizon, &csv, &mut reader, &mut streamed).unwrap();
        assert_eq!(String::from_utf8(streamed).unwrap(), in_memory);
        assert!(
            in_memory.lines().filter(|l| l.contains(",ok,")).count() > 10,
            "{in_memory}"
        );
    }
    let _ = std::fs::remove_file(&path);
}

#[test]
fn the_chosen_observer_on_the_recorded_scenario_is_the_reports() {
    // `estimate` (default `--kind auto`: the kind `gen` chose, Example 1's UKF) over the scenario
    // `simulate` recorded gives, to the last bit, the estimates the report and the figure show for that
    // observer.
    let dir = scratch("chosen");
    let (run, estimates) = (dir.join("run.csv"), dir.join("estimates.csv"));
    assert!(host(&["simulate", "--design", "vanderpol", "--output", s(&run)])
        .status
        .success());
    let (_, _, comparison) = compared();
    // In the arithmetic the report judges the chosen kind in (the UKF's: f32, the chip's). Without
    // `--tables`: `estimate` fits and tunes for the call (no checkout's tables are this binary's),
    // and must give the bits this process computed.
    let precision = match host::observers::kind::of(comparison.chosen.0).judged_in {
        host::recording::Precision::F32 => "f32",
        host::recording::Precision::F64 => "f64",
    };
    let out = host(&[
        "estimate",
        "--design",
        "vanderpol",
        "--input",
        s(&run),
        "--output",
        s(&estimates),
        "--precision",
        precision,
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let table = rows(&std::fs::read_to_string(&estimates).unwrap());

    assert_ne!(
        comparison.chosen.0,
        host::spec::ObserverKind::Map,
        "the case checks a started observer"
    );
    let chosen = host::observers::kind::of(comparison.chosen.0).kind.name();
    let report = comparison.observers.iter().find(|o| o.kind == chosen).unwrap();
    let map = &comparison.observers[0].scenario;
    assert_eq!(table.len(), 1 + report.scenario.len());
    let mut differs_from_map = 0;
    for (k, (row, expected)) in table[1..].iter().zip(report.scenario.iter()).enumerate() {
        for t in 0..2 {
            if expected[t].is_nan() {
                assert!(row[2 + t].is_empty(), "row {k}");
            } else {
                assert_eq!(
                    row[2 + t].parse::<f64>().unwrap().to_bits(),
                    expected[t].to_bits(),
                    "row {k} target {t}"
                );
                differs_from_map += usize::from(expected[t] != map[k][t]);
            }
        }
    }
    // It is not the map: every estimate after the first differs from the map's.
    assert!(differs_from_map >= 2 * (table.len() - 11), "{differs_from_map}");
}
