//! Reading a spec file: TOML to the raw spec (serde, unknown fields rejected), validated into a
//! [`Design`], with any error tied to its line or field.

use std::path::Path;

use super::raw::RawSpec;
use super::validate::Validator;
use super::{Design, SpecError};

/// Reads, parses and validates a spec file.
pub fn load(path: &Path) -> Result<Design, SpecError> {
    let text = std::fs::read_to_string(path).map_err(|e| SpecError {
        file: path.display().to_string(),
        field: "(file)".into(),
        problem: format!("cannot read the file: {e}"),
        fix: "give the path of an existing, readable design spec (TOML)".into(),
    })?;
    parse(path, &text)
}

/// Parses and validates spec text; `path` is only used in messages and kept in the design.
pub fn parse(path: &Path, text: &str) -> Result<Design, SpecError> {
    let file = path.display().to_string();
    let toml_error = |e: toml::de::Error, path: String| {
        let line = e
            .span()
            .map(|s| format!("(line {})", 1 + text[..s.start].matches('\n').count()))
            .unwrap_or_else(|| "(document)".into());
        // A value of the wrong type is named by its field path (serde's path); syntax errors by line.
        let (field, problem) = if path.is_empty() || path == "." {
            (line, e.message().trim().to_owned())
        } else {
            (path, format!("{} {line}", e.message().trim()))
        };
        SpecError {
            file: file.clone(),
            field,
            problem,
            fix: "correct the TOML there; see host/specs/vanderpol.toml for a complete example".into(),
        }
    };
    let deserializer = toml::Deserializer::parse(text).map_err(|e| toml_error(e, String::new()))?;
    let raw: RawSpec = serde_path_to_error::deserialize(deserializer).map_err(|e| {
        let path = e.path().to_string();
        toml_error(e.into_inner(), path)
    })?;
    let mut design = Validator {
        file,
        path: path.to_owned(),
    }
    .design(raw)?;
    design.spec_sha256 = crate::output::sha256_hex(text.as_bytes());
    Ok(design)
}
