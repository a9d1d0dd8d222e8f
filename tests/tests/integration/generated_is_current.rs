//! The files in `generated/` (the Rust design files and their C99 source) are exactly what `gen`
//! produces now, producing them is deterministic, and every shipped design passes the quality gates
//! (what `gen --strict` asks); the README's figure, `docs/figures/vanderpol-estimation.svg`, is the
//! one `gen` draws now, and its headline table shows the figures `gen` computes now.

use host::generate;
use integration_tests::{build, shipped_specs, workspace_root, SEARCHED_FIXTURE_SPEC};

#[test]
fn generated_files_match_a_fresh_generation() {
    let specs = shipped_specs();
    let mut names = Vec::new();
    let mut reports = String::new();
    for path in &specs {
        // `gen`'s own function, shared with the other tests of this binary. Every design's text is
        // compared with the committed files below, written by an earlier run (of `gen`, in another
        // process and on another machine): that is the check that generation is deterministic.
        let first = integration_tests::emitted(path);
        let name = first.design.name.clone();
        // `gen --strict` on the shipped specs: every one passes the quality gates but E. coli's,
        // whose observers lose runs at the substrate's depletion (docs/guide.md), and whose map-started
        // kinds (on helper maps of X and S) drift on P without being chosen: only those gates.
        let gates = host::report::gates::check(&first.design, &first.result, &first.comparison);
        if name.starts_with("ecoli") {
            assert!(
                gates.iter().all(|g| matches!(
                    g,
                    host::report::gates::Gate::LostRuns { .. } | host::report::gates::Gate::Drift { chosen: false, .. }
                )),
                "{name} fails quality gates: {gates:?}"
            );
        } else {
            assert!(gates.is_empty(), "{name} fails quality gates: {gates:?}");
        }
        // Lost runs on validation (`observers::lost`): none for any kind of a Van der Pol or tank
        // design; on E. coli, `observer()` loses the counts docs/guide.md quotes (none on `ecoli_x0_2`).
        let chosen = host::observers::kind::of(first.comparison.chosen.0).kind.name();
        for o in &first.comparison.observers {
            let validation = o.lost.validation;
            assert_eq!(
                validation.runs, first.design.validation.trajectories,
                "{name} {}",
                o.kind
            );
            let expected = match (name.as_str(), o.kind == chosen) {
                ("ecoli_x0_0p5", true) => Some(2),
                ("ecoli_x0_2", true) => Some(0),
                (n, _) if n.starts_with("ecoli") => None,
                _ => Some(0),
            };
            if let Some(expected) = expected {
                assert_eq!(validation.lost, expected, "{name} {}: lost validation runs", o.kind);
            }
            // The floor loses no run at every particle count it tries on a shipped design, so no lost
            // run is excused (docs/guide.md).
            assert_eq!(validation.floor_lost, 0, "{name} {}: lost by the floor too", o.kind);
            // `ecoli_x0_2`'s UKF, in log coordinates, loses no run on any judged set.
            if name == "ecoli_x0_2" && o.kind == chosen {
                assert_eq!(o.lost.judged(), Vec::new(), "{name} {}: lost runs", o.kind);
            }
        }
        let file = workspace_root().join("generated/src").join(format!("{name}.rs"));
        let committed = std::fs::read_to_string(&file).unwrap_or_default();
        assert!(
            committed == first.source,
            "{} is not what `cargo run -p host -- gen` produces now: regenerate and commit it",
            file.display()
        );
        // Its C99 source (`generated/c/`), the same way.
        for (extension, text) in [("h", &first.c_source.header), ("c", &first.c_source.source)] {
            let file = workspace_root().join("generated/c").join(format!("{name}.{extension}"));
            assert!(
                std::fs::read_to_string(&file).unwrap_or_default() == *text,
                "{} is not what `cargo run -p host -- gen` produces now: regenerate and commit it",
                file.display()
            );
        }
        if name == "vanderpol" {
            the_readme_figure_is_current(&first);
            the_readme_table_is_current(&first);
        }
        reports.push_str(&figures_of(&first));
        names.push(name);
    }
    the_docs_numbers_are_current(&reports);
    // `generated/c/` holds the shipped designs' C and nothing else.
    let mut c_files: Vec<String> = std::fs::read_dir(workspace_root().join("generated/c"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    c_files.sort();
    let mut expected: Vec<String> = names
        .iter()
        .flat_map(|n| [format!("{n}.c"), format!("{n}.h")])
        .collect();
    expected.sort();
    assert_eq!(
        c_files, expected,
        "generated/c/ must hold exactly the shipped designs' C: delete files of removed specs"
    );
    let lib = std::fs::read_to_string(workspace_root().join("generated/src/lib.rs")).unwrap();
    assert_eq!(
        lib,
        generate::lib_source(
            &specs.iter().map(|p| host::spec::load(p).unwrap()).collect::<Vec<_>>(),
            &workspace_root().join("generated/src"),
            &names
        )
        .unwrap(),
        "generated/src/lib.rs must declare exactly the shipped designs: regenerate, and delete files of removed specs"
    );
}

/// The figures of `emitted`'s report as `gen` writes it: `report.md`, and `report.json` without the
/// fitted coefficients (thousands of numbers, none quoted, that any figure would match by chance).
fn figures_of(emitted: &generate::Emitted) -> String {
    let mut report = host::report::report(&emitted.design, &emitted.result, &emitted.comparison);
    report.search = emitted.search.as_ref();
    report.taps = emitted.taps.as_deref();
    let (json, markdown) = host::report::texts(&report);
    let mut json: serde_json::Value = serde_json::from_str(&json).unwrap();
    for target in json["targets"].as_array_mut().unwrap() {
        target.as_object_mut().unwrap().remove("fitted");
    }
    format!("{markdown}\n{json}\n")
}

/// Every figure with three decimals or more that the README and `docs/` quote is one of a fresh
/// report (`reports`) or of the on-target table, or is listed as from elsewhere
/// ([`integration_tests::doc_numbers`]).
fn the_docs_numbers_are_current(reports: &str) {
    let read = |name: &str| std::fs::read_to_string(workspace_root().join(name)).unwrap();
    let docs: Vec<(&str, String)> = [
        "README.md",
        "docs/guide.md",
        "docs/method.md",
        "docs/chip.md",
        "docs/benchmarks.md",
    ]
    .into_iter()
    .map(|name| (name, read(name)))
    .collect();
    let computed = integration_tests::doc_numbers::roundings(&format!("{reports}\n{}", read("docs/chip.md")));
    let (unknown, gone) =
        integration_tests::doc_numbers::stale(&docs, &computed, &read("tests/doc-numbers-elsewhere.txt"));
    assert!(
        unknown.is_empty() && gone.is_empty(),
        "numbers the docs quote that no fresh report holds (update the docs from target/designs/*/report.md, or list \
         one from elsewhere in tests/doc-numbers-elsewhere.txt with why): {unknown:?}; listed there but no longer \
         quoted (delete those lines): {gone:?}"
    );
}

/// The README's figure, committed as `docs/figures/vanderpol-estimation.svg`, is byte for byte the
/// `estimation` figure that `gen` draws for the shipped `vanderpol` now: drawn here by `gen`'s own
/// function from the same fit (into a scratch folder: about 0.2 s beside the fit).
fn the_readme_figure_is_current(emitted: &generate::Emitted) {
    let scratch = std::env::temp_dir().join(format!("readme-figure-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&scratch);
    host::report::plots::draw(&emitted.design, &emitted.result, &emitted.comparison, &scratch).unwrap();
    let drawn = std::fs::read_to_string(scratch.join("estimation.svg")).unwrap();
    std::fs::remove_dir_all(&scratch).unwrap();
    let file = workspace_root().join("docs/figures/vanderpol-estimation.svg");
    let committed = std::fs::read_to_string(&file).unwrap_or_default();
    assert!(
        committed == drawn,
        "{} is not the figure `cargo run -p host -- gen` draws now: copy target/designs/vanderpol/estimation.svg \
         there and commit it",
        file.display()
    );
}

/// The README's headline table (Example 1) shows what `gen` computes now and what the chip measures:
/// each observer's validation RMSE and p95, scenario and transient RMSE from the fresh fit (4
/// decimals), and its instructions per sample from the on-target table of `docs/chip.md` (which the
/// on-target test holds against the chip).
fn the_readme_table_is_current(emitted: &generate::Emitted) {
    let readme = std::fs::read_to_string(workspace_root().join("README.md")).unwrap();
    let chip = std::fs::read_to_string(workspace_root().join("docs/chip.md")).unwrap();
    let header = "| observer | RMSE validation x1 / x2 |";
    let rows: Vec<Vec<String>> = readme[readme.find(header).expect("the headline table")..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            l.trim_matches('|')
                .split(" | ")
                .map(|c| c.replace("**", "").trim().to_owned())
                .collect()
        })
        .collect();
    // README row order, the kind, and its observer in the chip's table.
    let kinds = [
        ("map", "`map_observer()`"),
        ("ekf_box", "`ekf()`"),
        ("ukf_box", "`UkfBoxObserver`"),
        ("corrected", "`CorrectedObserver`"),
        ("ekf_map", "`EkfMapObserver`"),
        ("ekf_restart", "`EkfRestartObserver`"),
        ("mhe", "`MheObserver`"),
    ];
    assert_eq!(
        rows.len(),
        kinds.len(),
        "the README's headline table has one row per kind"
    );
    for (row, (kind, on_chip)) in rows.iter().zip(kinds) {
        let figures = emitted
            .comparison
            .observers
            .iter()
            .find(|o| o.kind == kind)
            .unwrap_or_else(|| panic!("no {kind}"));
        let pair = |f: &dyn Fn(&host::observers::Figures) -> f64| {
            format!("{:.4} / {:.4}", f(&figures.targets[0]), f(&figures.targets[1]))
        };
        let expected = [
            pair(&|f| f.rmse_validation),
            pair(&|f| f.p95_validation),
            pair(&|f| f.rmse_scenario),
            pair(&|f| f.rmse_transient),
        ];
        assert_eq!(
            row[1..5],
            expected,
            "README headline table, {kind}: regenerate and copy report.md's figures"
        );
        // Every count the README gives is the chip's steady or start-up count for that observer.
        let chip_row = chip
            .lines()
            .find(|l| l.starts_with("| `vanderpol` |") && l.contains(on_chip))
            .unwrap_or_else(|| panic!("docs/chip.md has no vanderpol {on_chip} row"));
        let cells: Vec<&str> = chip_row.trim_matches('|').split(" | ").collect();
        let measured: Vec<&str> = cells[5..7].iter().flat_map(|c| c.split([' ', '/', ','])).collect();
        for count in row[5].split(|c: char| !c.is_ascii_digit()).filter(|c| !c.is_empty()) {
            assert!(
                measured.contains(&count),
                "README headline table, {kind}: {count} instructions is not in docs/chip.md's {chip_row}"
            );
        }
    }
}

/// The fixture whose tables have searched knots and whose filters have constants its spec fixes:
/// `tests/fixtures/vanderpol_beta7.rs`, compiled into the `generated_vs_library`, `generated_model`,
/// `c_source` and `observer_contract` tests, and its C (`.h`, `.c`, compiled by `c_source`), are what
/// `gen` produces for its spec now.
/// `UPDATE_FIXTURES=1 cargo test -p integration-tests --test integration generated_is_current` rewrites them.
#[test]
fn the_searched_knot_fixture_is_current() {
    let path = workspace_root().join(SEARCHED_FIXTURE_SPEC);
    let design = host::spec::load(&path).unwrap();
    let result = build(&design);
    let (comparison, text, c, _) = generate::design_source(
        &design,
        &result,
        &host::emit::Placement::Generated {
            spec: SEARCHED_FIXTURE_SPEC,
        },
        &path,
        &indicatif::ProgressBar::hidden(),
    )
    .unwrap();
    assert!(
        text.contains("Knots::Searched"),
        "the fixture no longer exercises searched knots"
    );
    the_fixed_constants_are_the_specs_beside_the_tuned_ones(&design, &result, &comparison);
    for (extension, text) in [("rs", &text), ("h", &c.header), ("c", &c.source)] {
        let file = path.with_extension(extension);
        if std::env::var_os("UPDATE_FIXTURES").is_some() {
            std::fs::write(&file, text).unwrap();
        }
        let committed = std::fs::read_to_string(&file).unwrap_or_default();
        assert!(
            committed == *text,
            "{} is out of date: rerun with UPDATE_FIXTURES=1 and commit it",
            file.display()
        );
    }
}

/// The fixture's spec fixes the EKF's `x0`, `q` and `p0` (full) and the UKF's `p0`: those are the
/// filters' constants, the rest tuned around them; the same filters with every constant tuned stand
/// beside them, and the report's section names which are whose.
fn the_fixed_constants_are_the_specs_beside_the_tuned_ones(
    design: &host::spec::Design,
    result: &host::fit::DesignResult,
    comparison: &host::observers::Comparison,
) {
    use host::plant::Covariance;
    let ekf = comparison.tuned.ekf_box().unwrap();
    // Written by hand from tests/fixtures/vanderpol_beta7.toml.
    assert_eq!(ekf.constants.x0, [1.0, 0.7]);
    assert_eq!(
        ekf.constants.q,
        Covariance::Full(vec![vec![3.0e-5, 1.0e-5], vec![1.0e-5, 2.0e-3]])
    );
    assert_eq!(
        ekf.constants.p0,
        Covariance::Full(vec![vec![0.2, 0.05], vec![0.05, 0.5]])
    );
    assert_eq!(ekf.fixed, ["x0", "q", "p0"]);
    let ukf = comparison.tuned.ukf_box().unwrap();
    assert_eq!(ukf.constants.p0, Covariance::Diagonal(vec![0.2, 0.5]));
    assert_eq!(ukf.fixed, ["p0"]);
    assert!(
        matches!(ukf.constants.q, Covariance::Diagonal(_)),
        "the UKF's Q is tuned"
    );
    let kinds: Vec<&str> = comparison.beside.iter().map(|b| b.figures.kind).collect();
    assert_eq!(kinds, ["ekf_box", "ukf_box"]);
    for beside in &comparison.beside {
        assert!(beside.tuned.fixed.is_empty());
        assert!(matches!(beside.tuned.constants.p0, Covariance::Diagonal(_)));
        // The box centre, where a filter whose start is not fixed starts.
        assert_eq!(beside.tuned.constants.x0, [0.0, 0.0]);
    }
    let report = host::report::report(design, result, comparison);
    let markdown = host::report::markdown(&report);
    for line in [
        "### `ekf_box`: the constants the spec fixes",
        "`[observer.ekf]` fixes `x0`, `q` and `p0`; `gen` tuned nothing; the filter starts at the spec's `x0`",
        "| the spec's | (1, 0.7) | [[3.000e-5, 1.000e-5], [1.000e-5, 2.000e-3]] | [[2.000e-1, 5.000e-2], [5.000e-2, 5.000e-1]] |",
        "`[observer.ukf]` fixes `p0`; `gen` tuned `q`; the filter starts at the centre of the state box",
        "| every constant tuned | (0, 0) | diag(",
    ] {
        assert!(markdown.contains(line), "report.md lacks {line:?}:\n{markdown}");
    }
}
