//! `host plot` as a user runs it on a long recording and on what is not a file: the figure's size
//! is bounded by its pixels, not the rows (10⁶ rows used to draw a 291 MB SVG), and a device, a
//! folder or a pipe is refused before anything is read, naming the file and the fix.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn host(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mho")).args(args).output().unwrap()
}

/// A scratch folder of its own per test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plot-long-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn spec() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("specs/vanderpol.toml")
        .display()
        .to_string()
}

/// Rows of the long recording: two runs of Example 1 (τ = 0.1 s), long enough that every-point
/// drawing is far beyond the bounds below, short enough for the dev profile.
const ROWS: usize = 200_000;
/// Every this many rows a sample is refused (its `y` is `nan`) and, at other rows, `x1` saturated.
const REFUSED_EVERY: usize = 997;
const SATURATED_EVERY: usize = 1_009;

/// The recording (`run,time,x1,x2,y`) and its estimates in the format `estimate` writes, computed
/// here: the first 10 rows of each run have no estimate yet.
fn long_recording(dir: &Path) -> (PathBuf, PathBuf) {
    let mut input = String::from("run,time,x1,x2,y\n");
    let mut estimates = String::from("time,run,status,x1,x2,saturated_x1,saturated_x2\n");
    for k in 0..ROWS {
        let (run, j) = if k < ROWS / 2 { ("a", k) } else { ("b", k - ROWS / 2) };
        let time = format!("{}.{}", j / 10, j % 10);
        let t = j as f64 * 0.1;
        let (x1, x2) = ((t / 700.0).sin() * 2.0, (t / 700.0).cos());
        let refused = k % REFUSED_EVERY == 0;
        let y = if refused {
            f64::NAN
        } else {
            x1 + 0.05 * ((k * 7919 % 101) as f64 / 101.0)
        };
        input.push_str(&format!("{run},{time},{x1},{x2},{y}\n"));
        let line = if refused {
            format!("{time},{run},refused,,,,\n")
        } else if j < 10 {
            format!("{time},{run},no_estimate_yet,,,,\n")
        } else {
            let saturated = i32::from(k % SATURATED_EVERY == 0);
            format!("{time},{run},ok,{},{},{saturated},0\n", x1 + 0.01, x2 - 0.01)
        };
        estimates.push_str(&line);
    }
    let (run, est) = (dir.join("run.csv"), dir.join("est.csv"));
    std::fs::write(&run, input).unwrap();
    std::fs::write(&est, estimates).unwrap();
    (run, est)
}

/// The coordinates of every polyline of `stroke` colour in the SVG plotters writes.
fn polyline_points(svg: &str, stroke: &str) -> usize {
    svg.split("<polyline")
        .skip(1)
        .filter(|element| element.contains(&format!("stroke=\"{stroke}\"")))
        .map(|element| {
            let start = element.find("points=\"").unwrap() + 8;
            element[start..].split('"').next().unwrap().split_whitespace().count()
        })
        .sum()
}

#[test]
fn a_long_recording_draws_a_figure_bounded_by_its_pixels_not_its_rows() {
    let dir = scratch("long");
    let (run, est) = long_recording(&dir);
    let out = host(&[
        "plot",
        "--spec",
        &spec(),
        "--input",
        run.to_str().unwrap(),
        "--estimates",
        est.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let svg = std::fs::read_to_string(dir.join("est.svg")).unwrap();
    // Three panels (x1, x2, measured y) of 900 px columns. Drawing every row would take a dot per
    // estimate and per measured sample and a line point per truth row: about 3 × ROWS dots and
    // 2 × ROWS line points. Kept: at most one dot per 2 × 2 px cell of a panel (451 × 161), and per
    // column of each run four line points.
    let dots = svg.matches(r#"r="2" opacity="1""#).count();
    let every_point_dots = 3 * (ROWS - (ROWS / REFUSED_EVERY + 1) - 20);
    assert!(dots <= 3 * 451 * 161, "{dots} dots");
    assert!(
        dots * 2 < 3 * 451 * 161 && 3 * 451 * 161 < every_point_dots,
        "the bound bites"
    );
    let line_points = polyline_points(&svg, "#1F77B4");
    // Two truth lines of two runs, each at most 4 points per column, and a 2-point legend swatch each.
    assert!(line_points <= 2 * (2 * 4 * 900 + 2), "{line_points} line points");
    assert!(
        line_points > 2 * 900,
        "the truth is drawn across the panel: {line_points}"
    );
    // Refused samples, one line per column at most, in each of the three panels (and a swatch).
    let refused_lines = svg.matches(r##"stroke="#F09696""##).count();
    assert!(refused_lines <= 3 * (900 + 1), "{refused_lines}");
    assert!(
        refused_lines >= 3 * 150,
        "the refusals are still marked: {refused_lines}"
    );
    // Saturation rings: at most one per column per side, plus the legend's.
    let rings = svg.matches(r#"r="5" opacity="1" fill="none""#).count();
    assert!((2..=2 * 900 + 1).contains(&rings), "{rings} rings");
    // The old drawing of every point made 291 MB at 10⁶ rows; 20 MB is the limit at any length.
    let svg_bytes = svg.len();
    assert!(svg_bytes < 20_000_000, "{svg_bytes} bytes");
    assert!(std::fs::metadata(dir.join("est.png")).unwrap().len() < 20_000_000);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn plot_refuses_a_device_a_folder_and_a_pipe_naming_the_file_and_the_fix() {
    let dir = scratch("irregular");
    let (run, est) = (dir.join("run.csv"), dir.join("est.csv"));
    std::fs::write(&run, "time,x1,y\n0,1,1\n").unwrap();
    std::fs::write(&est, "time,status,x1,saturated_x1\n0,no_estimate_yet,,\n").unwrap();
    let fifo = dir.join("pipe.csv");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let folder = dir.join("folder.csv");
    std::fs::create_dir(&folder).unwrap();
    let cases: [(&str, &Path, &Path); 4] = [
        // `plot --input /dev/zero` read until it ran out of memory (4 GB).
        ("input", Path::new("/dev/zero"), &est),
        ("estimates", &run, &folder),
        // A pipe with no writer: opening it would wait forever.
        ("input", &fifo, &est),
        ("estimates", &run, Path::new("/dev/zero")),
    ];
    for (option, input, estimates) in cases {
        let out = host(&[
            "plot",
            "--input",
            input.to_str().unwrap(),
            "--estimates",
            estimates.to_str().unwrap(),
            "--out",
            dir.join("figure").to_str().unwrap(),
        ]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        let file = if option == "input" { input } else { estimates };
        assert!(!out.status.success(), "{option} {}", file.display());
        assert!(
            stderr.contains(&format!("{}: --{option} is not a regular file", file.display()))
                && stderr.contains("fix: give --"),
            "{stderr}"
        );
    }
    let mut left: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    assert_eq!(
        left,
        ["est.csv", "folder.csv", "pipe.csv", "run.csv"],
        "nothing written"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
