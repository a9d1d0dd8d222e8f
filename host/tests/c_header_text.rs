//! Spec text that reaches the C header is inert there: a unit or time unit holding `*/ … /*` (which
//! once ended cbindgen's comment and declared `int broken;`) stays inside its comment, checked by the
//! C compiler itself.

use std::path::Path;
use std::process::Command;

#[test]
fn a_unit_cannot_inject_a_declaration_into_the_c_header() {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("specs/vanderpol.toml"))
        .unwrap()
        .replacen(
            "noise_variance = 0.2",
            "noise_variance = 0.2\nunit = \"V */ int broken; /*\"",
            1,
        )
        .replacen("time_unit = \"s\"", "time_unit = \"s */ int x; /*\"", 1);
    let design = host::spec::parse(Path::new("injected.toml"), &text).expect("units are labels: accepted");
    assert_eq!(design.model.outputs[0].unit, "V */ int broken; /*");
    let dir = std::env::temp_dir().join(format!("host-c-header-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let source = dir.join("lib.rs");
    std::fs::write(&source, host::standalone::c_library::source(&design)).unwrap();
    let header = host::standalone::c_library::header(&design, &source).unwrap();
    assert!(header.contains("V * / int broken; / *"), "{header}");
    // The C compiler reads the header with a use of each name the injection would declare: both
    // must be undeclared (an error), and the header alone must compile.
    let path = dir.join("check.c");
    let compile = |body: &str| {
        std::fs::write(
            &path,
            format!("#include <stddef.h>\n#include <stdint.h>\n#include <stdbool.h>\n{header}\n{body}\n"),
        )
        .unwrap();
        Command::new("cc")
            .args(["-std=c99", "-fsyntax-only", "-x", "c"])
            .arg(&path)
            .output()
    };
    let Ok(clean) = compile("") else {
        assert!(std::env::var_os("CI").is_none(), "no C compiler (cc)");
        println!("no C compiler: the header was checked as text only");
        return;
    };
    assert!(clean.status.success(), "{}", String::from_utf8_lossy(&clean.stderr));
    for name in ["broken", "x"] {
        let used = compile(&format!("int use_{name}(void) {{ return {name}; }}")).unwrap();
        assert!(!used.status.success(), "`{name}` is declared by the header:\n{header}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
