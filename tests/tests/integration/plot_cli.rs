//! `plot` (the function the CLI's `plot` command calls) on a recorded run and estimates written by
//! hand in the estimates format: what is drawn is counted in the SVG against the files' own cells
//! (one ring per saturated estimate, one line per refused sample in every panel), the PNG and the SVG
//! are the same figure, and an error writes nothing.

use std::path::{Path, PathBuf};

use host::report::recorded::{plot, RecordedPlotError};

/// A scratch folder of its own per test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("plot-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn vanderpol() -> host::spec::Design {
    host::spec::load(&integration_tests::specs_folder().join("vanderpol.toml")).unwrap()
}

/// Two runs of six samples of Example 1's output `y`, with the states as truth; sample 3 is NaN.
const INPUT: &str = "\
run,time,x1,x2,y
a,0,2,0.5,2.1
a,0.1,1.9,0.9,2.2
a,0.2,1.8,1.3,2.3
a,0.3,1.6,1.6,nan
a,0.4,1.4,1.9,2.4
a,0.5,1.1,2.2,2.6
b,0,-1,0,-1.1
b,0.1,-1.1,-0.3,-1.2
b,0.2,-1.2,-0.6,-1.3
b,0.3,-1.3,-0.9,-1.5
b,0.4,-1.4,-1.2,-1.6
b,0.5,-1.5,-1.5,-1.7
";

/// The estimates of [`INPUT`] as `estimate` writes them: the first two samples of each run have none,
/// sample 3 is refused; three estimates saturated.
const ESTIMATES: &str = "\
time,run,status,x1,x2,saturated_x1,saturated_x2
0,a,no_estimate_yet,,,,
0.1,a,no_estimate_yet,,,,
0.2,a,ok,1.7,1.2,0,0
0.3,a,refused,,,,
0.4,a,ok,1.45,1.8,1,0
0.5,a,ok,1.2,2.1,0,0
0,b,no_estimate_yet,,,,
0.1,b,no_estimate_yet,,,,
0.2,b,ok,-1.25,-0.5,0,0
0.3,b,ok,-1.3,-1.0,1,0
0.4,b,ok,-1.35,-1.3,0,-1
0.5,b,ok,-1.5,-1.4,0,0
";

/// `(width, height)` of a PNG, from its IHDR chunk.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let word = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    (word(16), word(20))
}

/// `(width, height)` of the SVG plotters writes.
fn svg_size(text: &str) -> (u32, u32) {
    let attribute = |name: &str| -> u32 {
        let start = text.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
        text[start..].split('"').next().unwrap().parse().unwrap()
    };
    (attribute("width"), attribute("height"))
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_recorded_run_is_drawn_with_its_truth_refusals_restarts_and_saturation() {
    let dir = scratch("drawn");
    let input = write(&dir, "run.csv", INPUT);
    let estimates = write(&dir, "est.csv", ESTIMATES);
    let files = plot(&input, &estimates, Some(&vanderpol()), None).unwrap();
    // The default prefix: the estimates' path without its extension.
    assert_eq!(files, [dir.join("est.png"), dir.join("est.svg")]);
    let png = std::fs::read(&files[0]).unwrap();
    let svg = std::fs::read_to_string(&files[1]).unwrap();
    assert_eq!(png_size(&png), svg_size(&svg), "the PNG and the SVG are one figure");
    // A panel per target, then one per output of the design by its name (Example 1 has no input).
    for title in ["run: estimating x1", "run: estimating x2", "run: measured y"] {
        assert!(svg.contains(title), "no panel `{title}`");
    }
    assert!(!svg.contains("recorded signals"));
    let count = |needle: &str| svg.matches(needle).count();
    // A ring per saturated cell of the file (3), and a legend swatch in each of the two panels with one.
    let saturated = ESTIMATES
        .lines()
        .flat_map(|l| l.split(',').skip(5))
        .filter(|c| *c == "1" || *c == "-1")
        .count();
    assert_eq!(saturated, 3);
    assert_eq!(count(r#"r="5" opacity="1" fill="none""#), saturated + 2);
    // The refused sample: a line across each of the three panels, and its legend swatch in each.
    let refused = ESTIMATES.matches(",refused,").count();
    assert_eq!(count(r##"stroke="#F09696""##), 3 * refused + 3);
    // The restart of run b: 24 dashes across each panel, and a three-dash swatch in each legend.
    assert_eq!(count(r##"stroke="#3C3C3C""##), 3 * 24 + 3 * 3);
    for label in [
        "true (x1)",
        "true (x2)",
        "refused sample (NaN or infinite)",
        "observer restarted (new run)",
    ] {
        assert_eq!(count(label), 3 - usize::from(label.starts_with("true")) * 2, "{label}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn without_a_design_the_other_columns_share_one_panel() {
    let dir = scratch("signals");
    let input = write(&dir, "run.csv", INPUT);
    let estimates = write(&dir, "est.csv", ESTIMATES);
    let files = plot(&input, &estimates, None, Some(&dir.join("figure"))).unwrap();
    assert_eq!(files, [dir.join("figure.png"), dir.join("figure.svg")]);
    let svg = std::fs::read_to_string(&files[1]).unwrap();
    assert!(svg.contains("run: recorded signals"));
    assert!(!svg.contains("measured y"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every file in `dir`, sorted.
fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn an_error_writes_nothing_and_the_inputs_are_never_overwritten() {
    let dir = scratch("errors");
    let input = write(&dir, "run.csv", INPUT);
    // A saturation cell that is not -1, 0 or 1, on the last line: found before anything is drawn.
    let bad = ESTIMATES.replace("-1.5,-1.4,0,0", "-1.5,-1.4,0,2");
    let estimates = write(&dir, "est.csv", &bad);
    let error = plot(&input, &estimates, Some(&vanderpol()), None).unwrap_err();
    assert!(
        error.to_string().contains("line 13, column `saturated_x2`: `2`"),
        "{error}"
    );
    assert_eq!(listing(&dir), ["est.csv", "run.csv"]);
    // The design reads `y`: an input without it is refused, naming the column and the fix.
    let renamed = write(&dir, "renamed.csv", &INPUT.replacen(",y\n", ",y_measured\n", 1));
    let estimates = write(&dir, "est.csv", ESTIMATES);
    let error = plot(&renamed, &estimates, Some(&vanderpol()), None).unwrap_err();
    assert!(
        matches!(&error, RecordedPlotError::MissingColumn { column, .. } if column == "y"),
        "{error}"
    );
    assert!(error.to_string().contains("fix:"));
    assert_eq!(listing(&dir), ["est.csv", "renamed.csv", "run.csv"]);
    // An input recorded at 0.05 s for the design's 0.1 s, as `estimate` refuses it: named by line.
    let fast = write(&dir, "fast.csv", &INPUT.replacen("a,0.1,", "a,0.05,", 1));
    let error = plot(&fast, &estimates, Some(&vanderpol()), None)
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("line 3, column `time`") && error.contains("every 0.1"),
        "{error}"
    );
    assert_eq!(listing(&dir), ["est.csv", "fast.csv", "renamed.csv", "run.csv"]);
    // A prefix whose SVG would be the input itself.
    let named_svg = write(&dir, "run.svg", INPUT);
    let error = plot(&named_svg, &estimates, None, Some(&dir.join("run"))).unwrap_err();
    assert!(matches!(error, RecordedPlotError::WouldOverwrite { .. }), "{error}");
    assert_eq!(std::fs::read_to_string(&named_svg).unwrap(), INPUT);
    assert!(!dir.join("run.png").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
