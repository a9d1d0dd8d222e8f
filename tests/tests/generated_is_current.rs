//! The files in `generated/` are exactly what `gen` produces now, producing them is deterministic, and
//! every shipped design passes the quality gates (what `gen --strict` asks); the README's figure,
//! `docs/figures/vanderpol-estimation.svg`, is the one `gen` draws now.

use host::generate;
use indicatif::ProgressBar;
use integration_tests::{build, shipped_specs, workspace_root, SEARCHED_FIXTURE_SPEC};

#[test]
fn generated_files_match_a_fresh_generation() {
    let specs = shipped_specs();
    let mut names = Vec::new();
    for path in &specs {
        // `gen`'s own function, twice: the text must not depend on the run.
        let emit = || {
            let design = host::spec::load(path).unwrap();
            generate::emit_design(design, path, None, &ProgressBar::hidden()).unwrap()
        };
        let (first, second) = (emit(), emit());
        let name = first.design.name.clone();
        // `gen --strict` on the shipped specs: every one passes the quality gates.
        let gates = host::report::gates::check(&first.design, &first.result, &first.comparison);
        assert!(gates.is_empty(), "{name} fails quality gates: {gates:?}");
        assert_eq!(first.source, second.source, "generation of {name} is not deterministic");
        let file = workspace_root().join("generated/src").join(format!("{name}.rs"));
        let committed = std::fs::read_to_string(&file).unwrap_or_default();
        assert!(
            committed == first.source,
            "{} is not what `cargo run -p host -- gen` produces now: regenerate and commit it",
            file.display()
        );
        if name == "vanderpol" {
            the_readme_figure_is_current(&first);
        }
        names.push(name);
    }
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

/// The fixture whose tables have searched knots: `tests/fixtures/vanderpol_beta7.rs`, compiled into the
/// `generated_vs_library` and `observer_contract` tests, is what `gen` produces for its spec now.
/// `UPDATE_FIXTURES=1 cargo test -p integration-tests --test generated_is_current` rewrites it.
#[test]
fn the_searched_knot_fixture_is_current() {
    let path = workspace_root().join(SEARCHED_FIXTURE_SPEC);
    let design = host::spec::load(&path).unwrap();
    let (_, text) = generate::design_source(
        &design,
        &build(&design),
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
    let file = path.with_extension("rs");
    if std::env::var_os("UPDATE_FIXTURES").is_some() {
        std::fs::write(&file, &text).unwrap();
    }
    let committed = std::fs::read_to_string(&file).unwrap_or_default();
    assert!(
        committed == text,
        "{} is out of date: rerun with UPDATE_FIXTURES=1 and commit it",
        file.display()
    );
}
