//! `mho gen` end to end: the report files and the summary a user sees.

use std::process::Command;

/// `mho gen --verbose` of Example 1 into a temporary folder, once per process: the folder, what it
/// printed and its `report.json`.
struct Generated {
    reports: std::path::PathBuf,
    stdout: String,
    json: serde_json::Value,
}

fn generated() -> &'static Generated {
    static GENERATED: std::sync::OnceLock<Generated> = std::sync::OnceLock::new();
    GENERATED.get_or_init(|| {
        let reports = std::env::temp_dir().join(format!("host-cli-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&reports);
        let spec = concat!(env!("CARGO_MANIFEST_DIR"), "/specs/vanderpol.toml");
        let output = Command::new(env!("CARGO_BIN_EXE_mho"))
            .args(["gen", "--verbose", "--spec", spec, "--reports"])
            .arg(&reports)
            .arg("--generated")
            .arg(reports.join("generated"))
            .output()
            .unwrap();
        assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
        let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
        let json =
            serde_json::from_str(&std::fs::read_to_string(reports.join("vanderpol/report.json")).unwrap()).unwrap();
        Generated { reports, stdout, json }
    })
}

#[test]
fn gen_verbose_prints_the_reports_tables() {
    let stdout = &generated().stdout;
    // With --verbose, the report's tables.
    assert!(
        stdout.contains("n_E = 1456") && stdout.contains("| x1 |") && stdout.contains("| x2 |"),
        "{stdout}"
    );
}

#[test]
fn gen_prints_a_summary_of_report_json() {
    let Generated { reports, stdout, json } = generated();
    // The summary: the chosen observer with its validation RMSE as report.json records them, the
    // map's beside it, and where the report is.
    let chosen = json["observer"][0].as_str().unwrap();
    let rmse = |kind: &str| {
        let observer = json["observers"]
            .as_array()
            .unwrap()
            .iter()
            .find(|o| o["kind"] == kind)
            .unwrap();
        let of = |t: &str| observer["targets"][t]["rmse_validation"].as_f64().unwrap();
        format!("validation RMSE x1 {:.4}, x2 {:.4}", of("x1"), of("x2"))
    };
    let mut lines = stdout.lines();
    assert!(
        lines.next().unwrap().starts_with("vanderpol: Van der Pol oscillator"),
        "{stdout}"
    );
    let observer = lines.next().unwrap();
    assert!(
        observer.starts_with(&format!("  observer: {chosen} (N = 10), ~")) && observer.ends_with(&rmse(chosen)),
        "{observer}"
    );
    assert_eq!(lines.next().unwrap(), format!("  the map alone: {}", rmse("map")));
    // Then where the observers stand (issue 32): the best embeddable one against the particle floor,
    // as report.json's figures give it (each target's RMSE over the floor's, averaged).
    let validation = |list: &str, key: &str, name: &str| -> Vec<f64> {
        let entry = json[list].as_array().unwrap().iter().find(|o| o[key] == name).unwrap();
        ["x1", "x2"]
            .iter()
            .map(|t| entry["targets"][*t]["rmse_validation"].as_f64().unwrap())
            .collect()
    };
    let floor = validation("references", "name", "floor");
    let (best, ratio) = json["observers"]
        .as_array()
        .unwrap()
        .iter()
        .map(|o| {
            let kind = o["kind"].as_str().unwrap();
            let v = validation("observers", "kind", kind);
            (kind, (v[0] / floor[0] + v[1] / floor[1]) / 2.0)
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    assert_eq!(
        lines.next().unwrap(),
        format!("  Best embeddable observer on the validation runs: `{best}`, {ratio:.2}× the floor's RMSE (mean over targets).")
    );
    for name in ["mhe_host", "mhe_host_prior"] {
        let line = lines.next().unwrap();
        assert!(
            line.starts_with(&format!(
                "  The map against `{name}`, the on-line estimate it replaces: "
            )),
            "{line}"
        );
    }
    let line = lines.next().unwrap();
    assert!(line.starts_with("  The MHE as the chip runs it (`mhe`"), "{line}");
    // What the map saves: the two kinds' predicted counts in report.json, and their ratio.
    let predicted = |kind: &str| -> f64 {
        json["observers"]
            .as_array()
            .unwrap()
            .iter()
            .find(|o| o["kind"] == kind)
            .unwrap()["predicted_instructions"]
            .as_f64()
            .unwrap()
    };
    let (map, mhe) = (predicted("map"), predicted("mhe"));
    assert!(mhe > 50.0 * map, "{map} {mhe}");
    assert_eq!(
        lines.next().unwrap(),
        format!(
            "  What the map saves on the chip: ~{map:.0} instructions per estimate against the chip MHE's ~{mhe:.0} ({:.0}× fewer; predicted by the cost model, measured in docs/chip.md).",
            mhe / map
        )
    );
    assert_eq!(
        lines.next().unwrap(),
        format!("  report: {}", reports.join("vanderpol/report.md").display())
    );
}

#[test]
fn report_json_holds_the_fits_figures() {
    let json = &generated().json;
    assert_eq!(json["learning"]["windows"], 1456);
    for target in json["targets"].as_array().unwrap() {
        for key in ["rmse_learning", "rmse_validation", "max_error_validation"] {
            assert!(target[key].as_f64().unwrap() > 0.0, "{key}");
            assert!(target["linear"][key].as_f64().unwrap() > 0.0, "linear {key}");
        }
        // The empirical ε_x bounds the RMSE.
        assert!(target["max_error_validation"].as_f64() >= target["rmse_validation"].as_f64());
        let qp = &target["qp"];
        assert!(qp["status"] == "Solved" || qp["status"] == "AlmostSolved");
        assert!(qp["iterations"].as_u64().unwrap() > 0 && qp["solve_time_s"].as_f64().unwrap() > 0.0);
        assert!(qp["active_constraints"].as_u64().unwrap() <= qp["constraints"].as_u64().unwrap());
        assert!(qp["collapsed"].is_boolean());
    }
}

#[test]
fn gen_draws_the_papers_figures_titled_and_labelled() {
    let reports = &generated().reports;
    // The paper's figures, as PNG and SVG, titled with the design and labelled with names and units.
    for figure in ["measurements", "identification", "estimation"] {
        let png = std::fs::read(reports.join(format!("vanderpol/{figure}.png"))).unwrap();
        assert!(
            png.starts_with(b"\x89PNG\r\n\x1a\n") && png.len() > 10_000,
            "{figure}.png"
        );
        let svg = std::fs::read_to_string(reports.join(format!("vanderpol/{figure}.svg"))).unwrap();
        assert!(
            svg.contains("<svg") && svg.contains("vanderpol:") && svg.contains("x1"),
            "{figure}.svg"
        );
    }
    let svg = std::fs::read_to_string(reports.join("vanderpol/measurements.svg")).unwrap();
    assert!(svg.contains("time [s]") && svg.contains("noise variance 0.2"));
}

#[test]
fn gen_emits_the_observer_and_report_md_where_asked_and_no_temporary_file() {
    let reports = &generated().reports;
    let markdown = std::fs::read_to_string(reports.join("vanderpol/report.md")).unwrap();
    // The observer is emitted where it was asked for, with a lib.rs declaring it.
    let emitted = std::fs::read_to_string(reports.join("generated/src/vanderpol.rs")).unwrap();
    assert!(emitted.contains("pub const MAP_X1: TargetMap<'static, f32>"));
    assert!(std::fs::read_to_string(reports.join("generated/src/lib.rs"))
        .unwrap()
        .contains("pub mod vanderpol;"));
    assert!(markdown.contains("| x1 |") && markdown.contains("n_E = 1456"));
    // No temporary file is left behind.
    let leftovers: Vec<_> = std::fs::read_dir(reports.join("vanderpol"))
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains(".tmp"))
        .collect();
    assert!(leftovers.is_empty());
}

/// A fresh folder holding just what `gen` needs of a checkout: the Van der Pol spec in `host/specs/`
/// and `generated/Cargo.toml`.
fn minimal_checkout(name: &str) -> std::path::PathBuf {
    let copy = std::env::temp_dir().join(format!("host-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&copy);
    std::fs::create_dir_all(copy.join("host/specs")).unwrap();
    std::fs::create_dir_all(copy.join("generated/src")).unwrap();
    let here = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // Example 1 on 8 validation and 8 tuning runs (of 64): these cases are about where gen looks
    // and what it writes, not about a figure.
    let spec = std::fs::read_to_string(here.join("specs/vanderpol.toml"))
        .unwrap()
        .replacen("\ntrajectories = 64", "\ntrajectories = 8", 1)
        .replacen("[tuning]", "[tuning]\ntrajectories = 8", 1);
    assert!(spec.contains("\ntrajectories = 8"));
    std::fs::write(copy.join("host/specs/vanderpol.toml"), spec).unwrap();
    std::fs::copy(here.join("../generated/Cargo.toml"), copy.join("generated/Cargo.toml")).unwrap();
    copy
}

#[test]
fn gen_finds_the_checkout_from_the_current_folder_not_from_where_it_was_built() {
    // A copied checkout (just what gen needs) used to be ignored: the defaults pointed into the
    // checkout the binary was compiled in.
    let copy = minimal_checkout("copy");
    let inside = copy.join("host/specs");
    let output = Command::new(env!("CARGO_BIN_EXE_mho"))
        .arg("gen")
        .current_dir(&inside)
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains(&format!("observers into {}", copy.join("generated").display())),
        "{stderr}"
    );
    assert!(copy.join("generated/src/vanderpol.rs").is_file());
    assert!(copy.join("generated/src/lib.rs").is_file());
    assert!(copy.join("target/designs/vanderpol/report.md").is_file());
    // Outside any checkout, the defaults are an error that says what to do.
    let outside = std::env::temp_dir();
    let output = Command::new(env!("CARGO_BIN_EXE_mho"))
        .arg("gen")
        .current_dir(&outside)
        .output()
        .unwrap();
    assert!(!output.status.success());
    assert!(String::from_utf8_lossy(&output.stderr).contains("not inside a checkout"));
    let _ = std::fs::remove_dir_all(&copy);
}

#[test]
fn one_broken_shipped_spec_does_not_stop_the_others() {
    // A broken spec in host/specs/ used to make `--design` fail for every design.
    let copy = minimal_checkout("broken");
    std::fs::write(
        copy.join("host/specs/broken.toml"),
        "name = \"broken\"\nthis is not toml\n",
    )
    .unwrap();
    let run = |design: &str| {
        Command::new(env!("CARGO_BIN_EXE_mho"))
            .args(["simulate", "--design", design, "--output", "run.csv"])
            .current_dir(&copy)
            .output()
            .unwrap()
    };
    let ok = run("vanderpol");
    assert!(ok.status.success(), "{}", String::from_utf8_lossy(&ok.stderr));
    // Asking for the broken one gives its own error; an unknown name lists what loaded and what did not.
    let broken = run("broken");
    assert!(!broken.status.success() && String::from_utf8_lossy(&broken.stderr).contains("broken.toml"));
    let unknown = String::from_utf8_lossy(&run("nothing").stderr).into_owned();
    assert!(
        unknown.contains("vanderpol") && unknown.contains("did not load"),
        "{unknown}"
    );
    let _ = std::fs::remove_dir_all(&copy);
}
