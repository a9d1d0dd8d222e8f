//! Field-by-field validation of a parsed spec: every problem becomes a [`SpecError`] naming the field
//! and the fix. Here: the [`Validator`] and its checks of one value (a unit, a name, a table's keys, a
//! positive number, a size against [`super::limits`]). The sections are checked in the `validate_*`
//! modules beside it: the whole design in `validate_design`, `[map]` in `validate_map`, the runs in
//! `validate_runs`, units and bounds in `validate_states`, the model and the learning grid in
//! `validate_model`.

use super::limits::MAX_UNCERTAIN;
use super::model::Uncertain;
use super::*;

/// Characters a unit may not hold: markup of Markdown tables, HTML, SVG and code spans.
const LABEL_MARKUP: &str = "<>&|`\\\"";

pub(super) struct Validator {
    pub(super) file: String,
    pub(super) path: PathBuf,
}

impl Validator {
    pub(super) fn err(
        &self,
        field: impl Into<String>,
        problem: impl Into<String>,
        fix: impl Into<String>,
    ) -> SpecError {
        SpecError {
            file: self.file.clone(),
            field: field.into(),
            problem: problem.into(),
            fix: fix.into(),
        }
    }

    /// A unit: a short label on one line. Units reach doc comments, the C header, the report's
    /// Markdown tables and the figures' SVG; each of those escapes what it must, and nothing of more
    /// than one line or [`MAX_LABEL`] characters is a unit.
    pub(super) fn label(&self, field: impl Into<String>, text: &str) -> Result<(), SpecError> {
        if text.chars().any(char::is_control) || text.chars().count() > MAX_LABEL {
            return Err(self.err(
                field,
                "a unit is a short label on one line",
                format!("write it in at most {MAX_LABEL} characters, without line breaks or control characters (e.g. \"cm\", \"m/s^2\")"),
            ));
        }
        // A unit is shown as it is written in Markdown tables, HTML, SVG (XML) and code comments: none
        // of their markup characters may appear in it.
        if let Some(c) = text.chars().find(|c| LABEL_MARKUP.contains(*c)) {
            return Err(self.err(
                field,
                format!("a unit may not hold `{c}`: the reports' tables, HTML and figures would read it as markup"),
                "write it without < > & | ` \\ \" (e.g. \"g/(L h)\", \"m·s\", \"deg C\")",
            ));
        }
        Ok(())
    }

    pub(super) fn identifier(&self, field: &str, name: &str) -> Result<(), SpecError> {
        let mut chars = name.chars();
        let valid = matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
            && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
        if RESERVED_NAMES.contains(&name) || RESERVED_PREFIXES.iter().any(|p| name.starts_with(p)) {
            return Err(self.err(
                field,
                format!(
                    "`{name}` is reserved: it names a column of the CSV files `simulate`, `estimate` and `plot` use"
                ),
                format!(
                    "rename it (reserved: {}, and names starting with {})",
                    RESERVED_NAMES.join(", "),
                    RESERVED_PREFIXES.join(" or ")
                ),
            ));
        }
        if crate::spec::expr::is_operator_name(name) {
            return Err(self.err(
                field,
                format!("`{name}` is a function or constant of the expression language: expressions would read it as that, not as this name"),
                "rename it (e.g. `E` → `E0`, `PI` → `p`, `exp` → `expo`)",
            ));
        }
        if valid {
            Ok(())
        } else {
            Err(self.err(
                field,
                format!("`{name}` is not a valid name"),
                "use letters, digits and `_`, starting with a letter",
            ))
        }
    }

    /// Every key of the table `section` must be one of `names` (`kind`: "a state", "an input"); `fix`
    /// says what the table holds, and the names are listed after it.
    pub(super) fn keys_among<'k>(
        &self,
        section: &str,
        keys: impl IntoIterator<Item = &'k String>,
        names: &[String],
        kind: &str,
        fix: &str,
    ) -> Result<(), SpecError> {
        match keys.into_iter().find(|key| !names.contains(key)) {
            Some(key) => Err(self.err(
                format!("{section}.{key}"),
                format!("`{key}` is not {kind}"),
                format!("{fix} ({})", names.join(", ")),
            )),
            None => Ok(()),
        }
    }

    pub(super) fn positive(&self, field: &str, value: f64, what: &str) -> Result<f64, SpecError> {
        if value.is_finite() && value > 0.0 {
            Ok(value)
        } else {
            Err(self.err(
                field,
                format!("{what} must be a finite number > 0, got {}", readable(value)),
                format!("set `{field}` to a positive value"),
            ))
        }
    }

    /// `value ≤ limit`, or an error naming `field`.
    pub(super) fn at_most(&self, field: &str, value: usize, limit: usize) -> Result<(), SpecError> {
        if value <= limit {
            Ok(())
        } else {
            Err(self.err(
                field,
                format!("{value} is above the limit of {limit}"),
                format!("set `{field}` to at most {limit} (see host/src/spec/limits.rs)"),
            ))
        }
    }

    /// At most [`MAX_UNCERTAIN`] parameters with a range, or an error naming the first one beyond.
    pub(super) fn at_most_uncertain(&self, uncertain: &[Uncertain]) -> Result<(), SpecError> {
        match uncertain.get(MAX_UNCERTAIN) {
            None => Ok(()),
            Some(first) => Err(self.err(
                format!("model.parameters.{}", first.name),
                format!(
                    "{} parameters have a range: the mismatch runs would simulate the validation runs at each of the 2^{} corners of their box",
                    uncertain.len(),
                    uncertain.len()
                ),
                format!(
                    "give at most {MAX_UNCERTAIN} parameters a range `{{ value, min, max }}`, the others a plain number (see host/src/spec/limits.rs)"
                ),
            )),
        }
    }
}
