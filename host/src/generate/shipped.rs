//! Where `gen` finds its checkout and the shipped specs: the defaults when no path is given.

use std::path::{Path, PathBuf};

use super::error::GenerateError;
use crate::spec::{self, Design};

/// The checkout `gen` works in: the nearest folder, from the current one upward, that holds
/// `host/specs/` and `generated/Cargo.toml`. Found at run time, so that a copied or moved checkout
/// writes into itself, never into the one the binary was built in.
pub fn workspace_root() -> Result<PathBuf, GenerateError> {
    let here = std::env::current_dir().map_err(|source| GenerateError::Io {
        path: PathBuf::from("."),
        source,
    })?;
    here.ancestors()
        .find(|dir| dir.join("host/specs").is_dir() && dir.join("generated/Cargo.toml").is_file())
        .map(Path::to_owned)
        .ok_or(GenerateError::NoWorkspace { from: here })
}

/// Every spec shipped in `host/specs/` of the [`workspace_root`], sorted: what `gen` runs by default.
pub fn shipped_specs() -> Result<Vec<PathBuf>, GenerateError> {
    let folder = workspace_root()?.join("host/specs");
    let entries = std::fs::read_dir(&folder).map_err(|source| GenerateError::Io {
        path: folder.clone(),
        source,
    })?;
    let mut specs: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    specs.sort();
    Ok(specs)
}

/// The shipped design named `name`. A broken spec of another design does not stand in the way; a
/// broken spec whose file is `<name>.toml` gives its own error; otherwise the error lists the designs
/// found and the specs that did not load.
pub fn shipped_design(name: &str) -> Result<Design, GenerateError> {
    let (mut known, mut broken) = (Vec::new(), Vec::new());
    for path in shipped_specs()? {
        match spec::load(&path) {
            Ok(design) if design.name == name => return Ok(design),
            Ok(design) => known.push(design.name),
            Err(e) if path.file_stem().is_some_and(|stem| stem == name) => return Err(e.into()),
            Err(_) => broken.push(path.display().to_string()),
        }
    }
    Err(GenerateError::UnknownDesign {
        name: name.to_owned(),
        known: known.join(", "),
        broken: if broken.is_empty() {
            String::new()
        } else {
            format!(" ({} did not load)", broken.join(", "))
        },
    })
}
