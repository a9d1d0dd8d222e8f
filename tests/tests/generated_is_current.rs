//! The files in `generated/` are exactly what `gen` produces now, and producing them is deterministic.

use host::emit;
use integration_tests::{build, shipped_specs, workspace_root};

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
