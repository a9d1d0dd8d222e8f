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

/// The `NAME = value` of every enum constant in C `text` whose name starts with `prefix`.
fn enum_values(text: &str, prefix: &str) -> Vec<(String, String)> {
    let mut values: Vec<(String, String)> = text
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with(prefix) && l.contains(" = "))
        .map(|l| {
            let (name, value) = l.trim_end_matches(',').split_once(" = ").unwrap();
            (name.to_owned(), value.to_owned())
        })
        .collect();
    values.sort();
    values
}

/// Issue 48: the Rust static library's header (cbindgen) declares the C source's one status enum and
/// one saturation enum, with the same names and values (no `<Name>Status`, no `int8_t` flags), the
/// sample period once as a `float` literal, the licence statement, and C linkage for C++: a C++
/// unit calling it refers to the library's unmangled symbols.
#[test]
fn the_librarys_header_has_the_c_sources_enums_and_c_linkage() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let design = host::spec::load(&manifest.join("specs/vanderpol.toml")).unwrap();
    let dir = std::env::temp_dir().join(format!("host-c-header-cpp-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let source = dir.join("lib.rs");
    std::fs::write(&source, host::standalone::c_library::source(&design)).unwrap();
    let header = host::standalone::c_library::header(&design, &source).unwrap();
    assert!(header.contains("extern \"C\" {"), "{header}");
    for line in host::emit::LICENCE {
        assert!(header.contains(line), "{header}");
    }
    assert_eq!(
        header.matches("#define VANDERPOL_SAMPLE_PERIOD 0.1f\n").count(),
        1,
        "{header}"
    );
    assert_eq!(header.matches("SAMPLE_PERIOD").count(), 1, "{header}");
    assert!(
        !header.contains("int8_t") && !header.contains("VanderpolStatus"),
        "{header}"
    );
    let words = header.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        words.contains(
            "vanderpol_status vanderpol_estimate(void *storage, float *estimates, vanderpol_saturation *saturation)"
        ),
        "{header}"
    );
    // The C source's header, as `gen` wrote it for the shipped Example 1: the same enums.
    let c_source = std::fs::read_to_string(manifest.join("../generated/c/vanderpol.h")).unwrap();
    let library = enum_values(&header, "VANDERPOL_");
    assert_eq!(library, enum_values(&c_source, "VANDERPOL_"));
    assert_eq!(library.len(), 9, "{library:?}");
    // A C++ unit that calls the library: its references are the C names.
    let unit = dir.join("firmware.cpp");
    std::fs::write(
        &unit,
        "#include <stddef.h>\n#include <stdint.h>\n#include \"vanderpol.h\"\n\
         int run(void *storage) {\n\
         \x20   float x[VANDERPOL_TARGETS];\n    vanderpol_saturation s[VANDERPOL_TARGETS];\n\
         \x20   if (vanderpol_init(storage, VANDERPOL_STORAGE_SIZE) != VANDERPOL_OK) return 1;\n\
         \x20   return (int)vanderpol_estimate(storage, x, s) + (int)vanderpol_storage_size();\n}\n",
    )
    .unwrap();
    std::fs::write(dir.join("vanderpol.h"), &header).unwrap();
    let object = dir.join("firmware.o");
    let Ok(built) = Command::new("c++")
        .args(["-std=c++11", "-Wall", "-Wextra", "-Werror", "-c", "-o"])
        .arg(&object)
        .arg(&unit)
        .output()
    else {
        assert!(std::env::var_os("CI").is_none(), "no C++ compiler (c++)");
        return;
    };
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
    let symbols = Command::new("nm")
        .arg("--undefined-only")
        .arg(&object)
        .output()
        .unwrap();
    let symbols = String::from_utf8_lossy(&symbols.stdout).into_owned();
    for call in ["vanderpol_init", "vanderpol_estimate", "vanderpol_storage_size"] {
        assert!(
            symbols.lines().any(|l| l.split_whitespace().last() == Some(call)),
            "{call} is not referred to by its C name: {symbols}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
