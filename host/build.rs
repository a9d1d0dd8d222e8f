//! Embeds the `firmware` runtime's library source in the tool, so that a crate `mho gen --spec`
//! writes outside the checkout builds with nothing but the Rust toolchain (`standalone::runtime`).
//! Tests beside the code (`tests.rs` files) are left out: the runtime is built, not tested, there.

use std::path::{Path, PathBuf};

fn sources(dir: &Path, into: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("a readable folder").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            sources(&path, into);
        } else if path.extension().is_some_and(|e| e == "rs") && path.file_name().is_some_and(|n| n != "tests.rs") {
            into.push(path);
        }
    }
}

fn main() {
    let firmware = Path::new(env!("CARGO_MANIFEST_DIR")).join("../firmware");
    let src = firmware.join("src");
    println!("cargo:rerun-if-changed={}", src.display());
    let mut files = Vec::new();
    sources(&src, &mut files);
    // In the order of their paths as text (`src/mhe.rs` before `src/mhe/observer.rs`).
    files.sort_by_key(|path| path.to_string_lossy().into_owned());
    let mut text = String::from("/// The runtime's library sources: (path relative to its folder, content).\npub const FILES: &[(&str, &str)] = &[\n");
    for path in &files {
        println!("cargo:rerun-if-changed={}", path.display());
        let relative = path.strip_prefix(&firmware).expect("under firmware/");
        let absolute = path.canonicalize().expect("an existing file");
        text += &format!(
            "    ({:?}, include_str!({:?})),\n",
            relative.to_string_lossy(),
            absolute.to_string_lossy()
        );
    }
    text += "];\n";
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR")).join("runtime_files.rs");
    std::fs::write(out, text).expect("OUT_DIR is writable");
}
