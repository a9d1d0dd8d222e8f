//! The `firmware` runtime as the tool carries it: its library source embedded at build time
//! (`host/build.rs`), written into a standalone crate (`<crate>/firmware/`) when no other runtime
//! is given, so that a crate written outside the checkout builds with nothing but the Rust
//! toolchain. The sources are the checkout's byte for byte (tests beside the code left out); the
//! manifest is the checkout's with the workspace's values written in, since the crate is a workspace
//! of its own.

use std::path::PathBuf;

include!(concat!(env!("OUT_DIR"), "/runtime_files.rs"));

/// The runtime's folder in a crate.
pub const FOLDER: &str = "firmware";

/// The runtime's `Cargo.toml`.
pub fn manifest() -> String {
    format!(
        "# The observer's `firmware` runtime, as mho {version} carries it. Do not edit: regenerate.\n\
         [package]\n\
         name = \"firmware\"\n\
         description = \"no_std runtime of the off-line moving-horizon observer: basis functions, Γ, Γ⁻¹ and the per-target map\"\n\
         version = \"{version}\"\n\
         edition = \"2021\"\n\
         license = \"MIT OR Apache-2.0\"\n\
         rust-version = \"1.95\"\n\
         publish = false\n\
         \n\
         [dependencies]\n\
         nalgebra = {{ version = \"0.35\", default-features = false, features = [\"libm\"] }}\n\
         libm = \"0.2\"\n\
         defmt = {{ version = \"1\", optional = true }}\n\
         \n\
         [features]\n\
         reference = []\n\
         defmt = [\"dep:defmt\"]\n",
        version = env!("CARGO_PKG_VERSION"),
    )
}

/// Every file of the runtime, by path relative to the crate.
pub fn files() -> Vec<(PathBuf, String)> {
    let folder = PathBuf::from(FOLDER);
    std::iter::once((folder.join("Cargo.toml"), manifest()))
        .chain(FILES.iter().map(|(path, text)| (folder.join(path), (*text).to_owned())))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// The checkout's `firmware/Cargo.toml` with `x.workspace = true` replaced by the workspace's
    /// value, without the dev-dependencies (a crate builds the runtime, it does not test it).
    fn resolved_checkout_manifest() -> toml::Table {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        let read = |path: PathBuf| -> toml::Table { std::fs::read_to_string(path).unwrap().parse().unwrap() };
        let workspace = read(root.join("Cargo.toml"));
        let mut firmware = read(root.join("firmware/Cargo.toml"));
        let inherit = |table: &mut toml::Table, from: &toml::Table| {
            for (key, value) in table.iter_mut() {
                if value.get("workspace").and_then(toml::Value::as_bool) == Some(true) {
                    *value = from[key].clone();
                }
            }
        };
        inherit(
            firmware["package"].as_table_mut().unwrap(),
            workspace["workspace"]["package"].as_table().unwrap(),
        );
        inherit(
            firmware["dependencies"].as_table_mut().unwrap(),
            workspace["workspace"]["dependencies"].as_table().unwrap(),
        );
        firmware.remove("dev-dependencies");
        firmware
    }

    #[test]
    fn the_manifest_is_the_checkouts_with_the_workspace_written_in() {
        let mut ours: toml::Table = manifest().parse().unwrap();
        ours["package"].as_table_mut().unwrap().remove("publish");
        // Dependencies given as a bare version are the same requirement as `{ version = … }`.
        let normal = |table: &mut toml::Table| {
            for (_, value) in table["dependencies"].as_table_mut().unwrap().iter_mut() {
                if let Some(version) = value.as_str() {
                    *value = toml::Value::Table(toml::Table::from_iter([("version".to_owned(), version.into())]));
                }
            }
        };
        let mut checkout = resolved_checkout_manifest();
        normal(&mut ours);
        normal(&mut checkout);
        assert_eq!(ours, checkout);
    }

    #[test]
    fn the_sources_are_the_checkouts_byte_for_byte_without_tests() {
        let firmware = Path::new(env!("CARGO_MANIFEST_DIR")).join("../firmware");
        let mut on_disk = Vec::new();
        let mut pending = vec![firmware.join("src")];
        while let Some(dir) = pending.pop() {
            for entry in std::fs::read_dir(dir).unwrap().flatten() {
                let path = entry.path();
                if path.is_dir() {
                    pending.push(path);
                } else if path.file_name().unwrap() != "tests.rs" {
                    let relative = path.strip_prefix(&firmware).unwrap().to_string_lossy().into_owned();
                    on_disk.push((relative, std::fs::read_to_string(&path).unwrap()));
                }
            }
        }
        on_disk.sort();
        let embedded: Vec<(String, String)> = FILES.iter().map(|(p, t)| ((*p).to_owned(), (*t).to_owned())).collect();
        assert_eq!(embedded, on_disk);
        assert!(embedded.iter().any(|(p, _)| p == "src/lib.rs"));
    }
}
