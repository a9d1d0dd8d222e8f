//! Every kind of bad input ends in a message naming the file, the field and the fix, and the command
//! line exits non-zero without a panic and without touching what an earlier run wrote.

use std::path::{Path, PathBuf};
use std::process::Command;

use host::fit::identify::FitError;
use host::fit::qp::{self, Problem};
use host::spec::{self, SpecError};
use nalgebra::DMatrix;

const EXAMPLE: &str = include_str!("../../specs/vanderpol.toml");

/// The shipped Example 1 with one edit, which must be present.
fn edited(from: &str, to: &str) -> String {
    assert!(EXAMPLE.contains(from), "the example no longer contains {from:?}");
    EXAMPLE.replacen(from, to, 1)
}

fn parse_error(text: &str) -> SpecError {
    spec::parse(Path::new("bad.toml"), text).expect_err("the spec should be refused")
}

/// Asserts the message names the file, the field and gives a fix mentioning `fix_mentions`.
fn assert_names(error: &SpecError, field: &str, fix_mentions: &str) {
    let message = error.to_string();
    assert!(message.starts_with("bad.toml: "), "{message}");
    assert!(
        error.field.contains(field),
        "field {:?} should name {field:?}: {message}",
        error.field
    );
    assert!(
        message.contains("fix: ") && error.fix.contains(fix_mentions),
        "{message}"
    );
}

#[test]
fn toml_syntax_error_names_the_line() {
    let e = parse_error(&edited("tau = 0.1", "tau = = 0.1"));
    let line = 1 + EXAMPLE[..EXAMPLE.find("tau = 0.1").unwrap()].matches('\n').count();
    assert_names(&e, &format!("line {line}"), "TOML");
}

#[test]
fn misspelt_field_is_refused() {
    let e = parse_error(&edited("tau = 0.1", "taux = 0.1"));
    assert!(e.problem.contains("taux"), "{e}");
}

#[test]
fn expression_syntax_error() {
    let e = parse_error(&edited("x1 = \"-x2\"", "x1 = \"-x2 * (\""));
    assert_names(&e, "model.derivatives.x1", "exmex syntax");
}

#[test]
fn minus_before_power_is_refused() {
    let e = parse_error(&edited("expr = \"x1 + x2\"", "expr = \"x1 + -x2^2\""));
    assert_names(&e, "model.outputs[0].expr", "-(x2^");
}

#[test]
fn unknown_variable_in_an_expression() {
    let e = parse_error(&edited("expr = \"x1 + x2\"", "expr = \"x1 + x3\""));
    assert_names(&e, "model.outputs[0].expr", "states");
    assert!(e.problem.contains("x3"), "{e}");
}

#[test]
fn unknown_variable_in_a_target() {
    let e = parse_error(&edited("expr = \"x2\"", "expr = \"speed\""));
    assert_names(&e, "targets[1].expr", "states");
}

#[test]
fn non_positive_sample_time() {
    for tau in ["0.0", "-0.1"] {
        let e = parse_error(&edited("tau = 0.1", &format!("tau = {tau}")));
        assert_names(&e, "sampling.tau", "positive");
    }
}

#[test]
fn horizon_not_below_run_length() {
    let e = parse_error(&edited("horizon = 10", "horizon = 100"));
    assert_names(&e, "map.horizon", "learning.samples");
}

#[test]
fn empty_box() {
    let e = parse_error(&edited("min = -2.0, max = 2.0", "min = 2.0, max = 2.0"));
    assert_names(&e, "learning.grid.x1", "value");
}

#[test]
fn inverted_box() {
    let e = parse_error(&edited("min = -5.0, max = 5.0", "min = 5.0, max = -5.0"));
    assert_names(&e, "learning.grid.x2", "swap");
}

#[test]
fn zero_grid() {
    let e = parse_error(&edited("max = 2.0, points = 4", "max = 2.0, points = 0"));
    assert_names(&e, "learning.grid.x1.points", "2 or more");
}

#[test]
fn negative_variance() {
    let e = parse_error(&edited("noise_variance = 0.2", "noise_variance = -0.2"));
    assert_names(&e, "model.outputs[0].noise_variance", "variance");
}

#[test]
fn trajectory_that_blows_up() {
    // ẋ2 = +x1²·x2 (instead of 1 - x1²) escapes to infinity in finite time from the box.
    let text = edited("x2 = \"4*x1 + (1 - x1^2)*x2\"", "x2 = \"4*x1 + x1^2*x2^3\"");
    let design = spec::parse(Path::new("bad.toml"), &text).unwrap();
    let e = host::data::learning_set(&design).expect_err("must blow up");
    assert_names(&e, "model.derivatives", "sampling.tau");
    assert!(e.problem.contains("non-finite"), "{e}");
}

/// The fit's message for a dependent regressor column `fit::run` gives on `text`.
fn dependent_column_error(text: &str) -> SpecError {
    let design = spec::parse(Path::new("bad.toml"), text).unwrap();
    match host::generate::simulate_and_fit(&design, &indicatif::ProgressBar::hidden()) {
        Err(e) => e,
        Ok(_) => panic!("the fit should fail"),
    }
}

#[test]
fn too_few_learning_windows_are_named_as_such() {
    // 4 runs of 11 samples, N = 10: 8 windows for 11 regressor entries. It used to blame the output
    // for repeating the others and ask for measurement noise it already had.
    let text = edited("samples = 100\nseed = 1", "samples = 11\nseed = 1").replacen("points = 4 }", "points = 2 }", 2);
    let e = dependent_column_error(&text);
    assert_names(&e, "learning", "learning.samples");
    assert!(
        e.problem
            .contains("only 8 learning windows for a regressor of 11 entries"),
        "{e}"
    );
}

#[test]
fn an_output_the_learning_runs_do_not_move_is_named_as_such() {
    // A second, noise-free output y2 = x1 of a state held at 1: constant in every window.
    let text = edited("x1 = \"-x2\"", "x1 = \"0\"")
        .replacen(
            "grid.x1 = { min = -2.0, max = 2.0, points = 4 }",
            "grid.x1 = { value = 1.0 }",
            1,
        )
        .replacen(
            "noise_variance = 0.2\n",
            "noise_variance = 0.2\n[[model.outputs]]\nname = \"y2\"\nexpr = \"x1\"\nnoise_variance = 0.0\n",
            1,
        )
        .replacen("[[targets]]\nname = \"x1\"\nexpr = \"x1\"\n", "", 1);
    let e = dependent_column_error(&text);
    assert_names(&e, "model.outputs[1]", "settle");
    assert!(e.problem.contains("it is 1 in every learning window"), "{e}");
}

#[test]
fn a_unit_with_markup_is_refused_naming_its_field() {
    // `m|<b>&` broke the reports' Markdown tables and left a bare `&` in the SVG figures (not XML).
    for unit in ["m|s", "<b>m</b>", "R&D", "`m`", "m\\\\s"] {
        let e = parse_error(&edited("time_unit = \"s\"", &format!("time_unit = \"{unit}\"")));
        assert_names(&e, "sampling.time_unit", "g/(L h)");
        assert!(e.problem.contains("markup"), "{e}");
    }
    // What units do hold is kept.
    for unit in ["g/(L h)", "m/s^2", "µm", "°C", "1/h"] {
        spec::parse(
            Path::new("ok.toml"),
            &edited("time_unit = \"s\"", &format!("time_unit = \"{unit}\"")),
        )
        .unwrap();
    }
}

#[test]
fn infeasible_qp() {
    // The identification QP is feasible by construction (η alone meets every constraint), so an
    // infeasible answer can only come from the solver; this is the message such a failure gets.
    let problem = Problem {
        p: DMatrix::identity(1, 1),
        q: vec![0.0],
        e_matrix: DMatrix::zeros(0, 1),
        e: vec![],
        g_matrix: DMatrix::from_row_slice(2, 1, &[1.0, -1.0]),
        g: vec![1.0, 0.0],
    };
    let error = qp::solve(&problem).unwrap_err();
    let design = spec::parse(Path::new("bad.toml"), EXAMPLE).unwrap();
    let learning = host::data::learning_set(&design).unwrap();
    let e = host::fit::explain(&design, &learning, 0, FitError::Qp(error));
    assert_names(&e, "map", "map.beta");
    assert!(e.problem.contains("infeasible") && e.problem.contains("`x1`"), "{e}");
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("host-bad-input-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn command_line_exits_non_zero_without_panic_and_keeps_earlier_reports() {
    let dir = scratch("cli");
    let reports = dir.join("reports");
    let earlier = reports.join("vanderpol").join("report.json");
    std::fs::create_dir_all(earlier.parent().unwrap()).unwrap();
    std::fs::write(&earlier, "earlier run").unwrap();
    let spec_path = dir.join("broken.toml");
    std::fs::write(&spec_path, edited("tau = 0.1", "tau = -1")).unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_mho"))
        .args(["gen", "--spec"])
        .arg(&spec_path)
        .arg("--reports")
        .arg(&reports)
        .arg("--generated")
        .arg(dir.join("generated"))
        .env("RUST_BACKTRACE", "1")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success());
    assert!(
        stderr.contains("broken.toml") && stderr.contains("sampling.tau") && stderr.contains("fix:"),
        "{stderr}"
    );
    assert!(
        !stderr.contains("panicked") && !stderr.contains("backtrace"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&earlier).unwrap(), "earlier run");
    let missing = Command::new(env!("CARGO_BIN_EXE_mho"))
        .args(["gen", "--spec", "no/such/spec.toml"])
        .output()
        .unwrap();
    assert!(!missing.status.success());
    assert!(String::from_utf8_lossy(&missing.stderr).contains("no/such/spec.toml"));
    // A runtime path that is not the `firmware` crate (a missing folder, this host crate) is refused
    // before anything is fitted, and no crate folder is made.
    let good_spec = dir.join("good.toml");
    std::fs::write(&good_spec, EXAMPLE).unwrap();
    let host_crate = Path::new(env!("CARGO_MANIFEST_DIR"));
    for (runtime, expected) in [
        (dir.join("no-such-runtime"), "cannot read"),
        (host_crate.to_path_buf(), "the package `host`, not `firmware`"),
    ] {
        let out = dir.join("crate");
        let output = Command::new(env!("CARGO_BIN_EXE_mho"))
            .args(["gen", "--spec"])
            .arg(&good_spec)
            .arg("--out")
            .arg(&out)
            .arg("--runtime-path")
            .arg(&runtime)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            !output.status.success()
                && stderr.contains("--runtime-path")
                && stderr.contains(expected)
                && stderr.contains("fix:"),
            "{stderr}"
        );
        assert!(!out.exists());
    }
}

/// Refusals that need no fit come before it, and every message says each thing once: the spec's path
/// (it used to be printed twice), an OS error (twice too), `--out` a file (an OS error on a file of
/// ours), the spec's `observer.kind` over its budget (refused after fitting before).
#[test]
fn refusals_come_before_the_fit_and_say_each_thing_once() {
    let dir = scratch("once");
    let run = |args: &[&std::ffi::OsStr]| {
        let output = Command::new(env!("CARGO_BIN_EXE_mho")).args(args).output().unwrap();
        assert!(!output.status.success());
        String::from_utf8_lossy(&output.stderr).into_owned()
    };
    let os = std::ffi::OsStr::new;
    // τ below f32's normal range: the spec's error, its path once.
    let tiny = dir.join("tiny_tau.toml");
    std::fs::write(&tiny, edited("tau = 0.1", "tau = 1e-50")).unwrap();
    let stderr = run(&[
        os("gen"),
        os("--spec"),
        tiny.as_os_str(),
        os("--out"),
        dir.join("a").as_os_str(),
    ]);
    assert_eq!(stderr.matches("tiny_tau.toml").count(), 1, "{stderr}");
    assert!(
        stderr.contains("sampling.tau") && stderr.contains("f32") && stderr.contains("fix:"),
        "{stderr}"
    );
    // `--out` names a file.
    let good = dir.join("good.toml");
    std::fs::write(&good, EXAMPLE).unwrap();
    let file = dir.join("a-file");
    std::fs::write(&file, "mine").unwrap();
    let stderr = run(&[os("gen"), os("--spec"), good.as_os_str(), os("--out"), file.as_os_str()]);
    assert!(
        stderr.contains("is a file, not a folder") && stderr.contains("fix:"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "mine");
    // An OS error, once.
    let stderr = run(&[
        os("estimate"),
        os("--spec"),
        good.as_os_str(),
        os("--input"),
        dir.join("missing.csv").as_os_str(),
        os("--output"),
        dir.join("out.csv").as_os_str(),
    ]);
    assert_eq!(stderr.matches("(os error 2)").count(), 1, "{stderr}");
    // An EKF kind over the budget: refused with the kind's count before anything is fitted, nothing
    // written.
    let over = dir.join("over.toml");
    let text = edited("kind = \"auto\"", "kind = \"ekf_box\"").replacen(
        "[observer]",
        "[budget]\ninstructions = 50\n\n[observer]",
        1,
    );
    std::fs::write(&over, text).unwrap();
    let out = dir.join("over-crate");
    let stderr = run(&[os("gen"), os("--spec"), over.as_os_str(), os("--out"), out.as_os_str()]);
    assert!(
        stderr.contains("observer.kind") && stderr.contains("`budget.instructions` = 50") && stderr.contains("ekf_box"),
        "{stderr}"
    );
    assert!(!out.exists(), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bounds_whose_span_overflows() {
    let e = parse_error(&edited("min = -5.0, max = 5.0", "min = -1e308, max = 1e308"));
    assert_names(&e, "learning.grid.x2", "finite");
}

#[test]
fn names_reserved_for_csv_columns() {
    let e = parse_error(&edited("name = \"y\"", "name = \"time\""));
    assert_names(&e, "model.outputs[0].name", "reserved");
    let e = parse_error(&edited("name = \"x2\"", "name = \"run\""));
    assert_names(&e, "targets[1].name", "reserved");
}

#[test]
fn constant_input_is_blamed_on_its_profile() {
    // A model with an input held constant: its regressor columns repeat the intercept.
    let text = edited(
        "states = [\"x1\", \"x2\"]",
        "states = [\"x1\", \"x2\"]\ninputs = [\"u\"]",
    )
    .replacen(
        "grid.x2 = { min = -5.0, max = 5.0, points = 4 }",
        "grid.x2 = { min = -5.0, max = 5.0, points = 4 }\ninputs.u = { min = 0.3, max = 0.3, hold = 1 }",
        1,
    );
    let design = spec::parse(Path::new("bad.toml"), &text).unwrap();
    let e = host::generate::simulate_and_fit(&design, &indicatif::ProgressBar::hidden()).expect_err("must be refused");
    assert_names(&e, "learning.inputs.u", "min < max");
}
