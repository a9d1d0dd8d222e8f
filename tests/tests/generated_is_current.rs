//! The files in `generated/` are exactly what `gen` produces now, and producing them is deterministic.

use host::emit;
use integration_tests::{build, shipped_specs, workspace_root, SEARCHED_FIXTURE_SPEC};

#[test]
fn generated_files_match_a_fresh_generation() {
    let mut names = Vec::new();
    let mut designs = Vec::new();
    for path in shipped_specs() {
        let design = host::spec::load(&path).unwrap();
        let spec_path = emit::portable_spec_path(&path, &workspace_root());
        let first = emit::design_file(&design, &build(&design), &spec_path).unwrap();
        let second = emit::design_file(&design, &build(&design), &spec_path).unwrap();
        assert_eq!(first, second, "generation of {} is not deterministic", design.name);
        let file = workspace_root()
            .join("generated/src")
            .join(format!("{}.rs", design.name));
        let committed = std::fs::read_to_string(&file).unwrap_or_default();
        assert!(
            committed == first,
            "{} is not what `cargo run -p host -- gen` produces now: regenerate and commit it",
            file.display()
        );
        names.push(design.name.clone());
        designs.push(design);
    }
    names.sort();
    let families = emit::families(&designs, &names).unwrap();
    let lib = std::fs::read_to_string(workspace_root().join("generated/src/lib.rs")).unwrap();
    assert_eq!(
        lib,
        emit::lib_file(&names, &families).unwrap(),
        "generated/src/lib.rs must declare exactly the shipped designs: regenerate, and delete files of removed specs"
    );
}

/// The fixture whose tables have searched knots: `tests/fixtures/vanderpol_beta7.rs`, compiled into the
/// `generated_vs_library` and `observer_contract` tests, is what `gen` produces for its spec now.
/// `UPDATE_FIXTURES=1 cargo test -p integration-tests --test generated_is_current` rewrites it.
#[test]
fn the_searched_knot_fixture_is_current() {
    let path = workspace_root().join(SEARCHED_FIXTURE_SPEC);
    let design = host::spec::load(&path).unwrap();
    let text = emit::design_file(&design, &build(&design), SEARCHED_FIXTURE_SPEC).unwrap();
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
