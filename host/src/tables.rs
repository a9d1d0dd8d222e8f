//! A fitted design saved as data (`design.json` beside its report): what `estimate` needs to run any
//! observer kind on recorded measurements without fitting, searching or tuning again. The maps are
//! the ones emitted (their certified tables included), the observers' constants the tuned ones.
//!
//! The file records the SHA-256 of the spec it came from and the settings the search chose: a
//! changed spec, or a file written by another version of the tool, is not used (`estimate` then fits
//! again and says so).

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::fit::maps::FittedMap;
use crate::fit::DesignResult;
use crate::observers::kind::{KindConstants, TunedConstants};
use crate::observers::Comparison;
use crate::spec::{Design, ObserverKind};

/// The file's name in a report folder.
pub const FILE: &str = "design.json";

/// The saved design.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Tables {
    /// The tool's version that wrote it.
    pub version: String,
    /// SHA-256 of the spec text it was fitted from.
    pub spec_sha256: String,
    /// SHA-256 of the observer file emitted with it: tables beside a report are used only while that
    /// file is unchanged (a rebuilt tool that fits differently rewrites it).
    pub source_sha256: String,
    /// SHA-256 of these tables themselves ([`Tables::content_sha256`]), which the observer file
    /// emitted with them carries as `TABLES_SHA256`: checked on every read, so that tables edited by
    /// hand, or from another run than the observer beside them, are never used.
    #[serde(default)]
    pub tables_sha256: String,
    /// `N` (as the search chose it, when the spec searches).
    pub horizon: usize,
    /// `n_m`, `β` and the taps kept, for the record.
    pub nm: usize,
    /// `β`.
    pub beta: f64,
    /// Non-zero gains per target, when `L` is pruned.
    pub taps: Option<usize>,
    /// The kind `observer()` is.
    pub chosen: ObserverKind,
    /// Every target's map, in the spec's order.
    pub maps: Vec<FittedMap>,
    /// The helper maps, one per state that no target is, in state order ([`crate::fit::helpers`]):
    /// read by the map-started kinds only. Empty where every state is a target.
    #[serde(default)]
    pub helpers: Vec<FittedMap>,
    /// The tuned constants of every kind the design has, keyed by the kind's name.
    pub constants: TunedConstants,
}

/// Why saved tables could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum TablesError {
    /// The file could not be read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The file is not a saved design.
    #[error("{}: not a saved design ({source}); delete it, or run `gen` again to rewrite it", path.display())]
    Format {
        /// The file.
        path: PathBuf,
        /// Why.
        source: serde_json::Error,
    },
    /// The tables do not hash to their `tables_sha256`: edited since `gen` wrote them.
    #[error("{}: changed since `gen` wrote it (its content does not match its `tables_sha256`); run `gen` again to rewrite it, or leave out --tables to fit for this call", path.display())]
    Edited {
        /// The file.
        path: PathBuf,
    },
    /// The observer file beside the tables was emitted with other tables.
    #[error("{}: these tables were not written with the observer {} (its TABLES_SHA256 differs: one of the two is from another `gen` run, or was interrupted); run `gen` again", path.display(), observer.display())]
    OtherObserver {
        /// The tables.
        path: PathBuf,
        /// The observer file.
        observer: PathBuf,
    },
    /// The tables do not fit the design (a field edited, or a bug): what is wrong.
    #[error("{}: `{field}` {problem}; run `gen` again to rewrite it", path.display())]
    Inconsistent {
        /// The file.
        path: PathBuf,
        /// The field.
        field: String,
        /// What is wrong with it.
        problem: String,
    },
}

impl Tables {
    /// The first kind whose constants `kind` runs on (its registry entry's
    /// [`Needs::reads`](crate::observers::kind::Needs::reads)) that these tables lack, if any.
    pub fn missing(&self, kind: ObserverKind) -> Option<ObserverKind> {
        let entry = crate::observers::kind::of(kind);
        entry.needs.reads.iter().copied().find(|&k| !self.constants.has(k))
    }

    /// A design as `gen` emitted it (fitted, compared, and its observer file's text `source`), as data.
    pub fn of(design: &Design, result: &DesignResult, comparison: &Comparison, source: &str) -> Self {
        let mut tables = Self::new(design, result, Some(comparison));
        tables.source_sha256 = sha256(source);
        tables
    }

    /// A fitted `design` (its map settled) as data: the maps of `result` and, when its observers were
    /// compared, their constants and the chosen kind (else the map alone). No observer file yet.
    pub fn new(design: &Design, result: &DesignResult, comparison: Option<&Comparison>) -> Self {
        let mut tables = Tables {
            version: env!("CARGO_PKG_VERSION").to_owned(),
            spec_sha256: design.spec_sha256.clone(),
            source_sha256: String::new(),
            horizon: design.map.horizon,
            nm: design.map.nm,
            beta: design.map.beta,
            taps: design.map.taps,
            chosen: comparison.map_or(ObserverKind::Map, |c| c.chosen.0),
            maps: result.targets.iter().map(|t| t.fit.map.clone()).collect(),
            helpers: result.helpers.iter().flatten().map(|t| t.fit.map.clone()).collect(),
            constants: comparison.map(|c| c.tuned.constants()).unwrap_or_default(),
            tables_sha256: String::new(),
        };
        tables.tables_sha256 = tables.content_sha256();
        tables
    }

    /// The maps the map-started kinds read, row by row: the targets', then the helpers'.
    pub fn start_maps(&self) -> Vec<FittedMap> {
        self.maps.iter().chain(&self.helpers).cloned().collect()
    }

    /// SHA-256 of the tables' JSON with both hashes left empty: what `tables_sha256` holds.
    pub fn content_sha256(&self) -> String {
        let mut content = self.clone();
        content.source_sha256.clear();
        content.tables_sha256.clear();
        sha256(&content.to_json())
    }

    /// The JSON text.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("plain data serialises") + "\n"
    }

    /// Reads `path`: `None` when there is no such file.
    pub fn read(path: &Path) -> Result<Option<Self>, TablesError> {
        let text = match std::fs::read_to_string(path) {
            Ok(text) => text,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(source) => {
                return Err(TablesError::Io {
                    path: path.to_owned(),
                    source,
                })
            }
        };
        let tables: Tables = serde_json::from_str(&text).map_err(|source| TablesError::Format {
            path: path.to_owned(),
            source,
        })?;
        if tables.tables_sha256 != tables.content_sha256() {
            return Err(TablesError::Edited { path: path.to_owned() });
        }
        Ok(Some(tables))
    }

    /// Whether `observer` (an emitted design file) was written with these tables: it carries their
    /// hash as `TABLES_SHA256`.
    pub fn written_with(&self, observer: &str) -> bool {
        observer.contains(&format!("pub const TABLES_SHA256: &str = \"{}\";", self.tables_sha256))
    }

    /// Checks that the tables fit `design` (read from `path`): every length the observers index by
    /// (maps per target, gains per regressor entry, constants per state and output), and that the
    /// chosen kind is one the tables hold. A `design.json` edited by hand whose hash was fixed up, or
    /// a bug, is refused here rather than indexing out of bounds later.
    pub fn check(&self, design: &Design, path: &Path) -> Result<(), TablesError> {
        let (nx, ny, nu) = (
            design.model.states.len(),
            design.model.outputs.len(),
            design.model.inputs.len(),
        );
        let bad = |field: String, problem: String| {
            Err(TablesError::Inconsistent {
                path: path.to_owned(),
                field,
                problem,
            })
        };
        let length = |field: &str, got: usize, want: usize| {
            if got == want {
                Ok(())
            } else {
                bad(field.to_owned(), format!("has {got} entries, the design needs {want}"))
            }
        };
        if self.horizon < 1 {
            return bad("horizon".to_owned(), "is 0".to_owned());
        }
        length("maps", self.maps.len(), design.targets.len())?;
        if !self.helpers.is_empty() {
            length(
                "helpers",
                self.helpers.len(),
                crate::fit::helpers::helper_states(design).len(),
            )?;
        }
        let regressor = self.horizon * (ny + nu);
        let helpers = self
            .helpers
            .iter()
            .enumerate()
            .map(|(h, map)| (format!("helpers[{h}]"), map));
        for (field, map) in self
            .maps
            .iter()
            .enumerate()
            .map(|(t, map)| (format!("maps[{t}]"), map))
            .chain(helpers)
        {
            length(&format!("{field}.gains"), map.gains.len(), regressor)?;
            if map.r_min.partial_cmp(&map.r_max) != Some(std::cmp::Ordering::Less) {
                return bad(format!("{field}.r_min"), "is not below r_max".to_owned());
            }
            if let Some(table) = &map.table {
                length(&format!("{field}.table.gains"), table.gains.len(), regressor)?;
                if table.segments.is_empty() {
                    return bad(format!("{field}.table.segments"), "is empty".to_owned());
                }
                if let Some(starts) = &table.starts {
                    length(&format!("{field}.table.starts"), starts.len(), table.segments.len())?;
                }
            }
        }
        for kind in self.constants.iter() {
            let name = |field: &str| format!("constants.{}.{field}", kind.kind().name());
            if let Some(e) = kind.filter() {
                length(&name("x0"), e.x0.len(), nx)?;
                for (field, covariance) in [("p0", &e.p0), ("q", &e.q)] {
                    if let Err(problem) = covariance.check(nx) {
                        return bad(name(field), problem.to_string());
                    }
                }
                length(&name("r"), e.r.len(), ny)?;
                if e.substeps == 0 {
                    return bad(name("substeps"), "is 0".to_owned());
                }
            }
            match kind {
                KindConstants::Corrected(c) => {
                    length(&name("g"), c.g.len(), nx)?;
                    length(&name("k"), c.k.len(), nx * ny)?;
                    length(&name("k_start"), c.k_start.len(), nx * ny)?;
                    length(&name("lower"), c.lower.len(), nx)?;
                    length(&name("upper"), c.upper.len(), nx)?;
                    if c.substeps == 0 {
                        return bad(name("substeps"), "is 0".to_owned());
                    }
                }
                KindConstants::EkfMap(s) => {
                    length(&name("p0"), s.p0.len(), nx)?;
                    length(&name("state_targets"), s.state_targets.len(), nx)?;
                    let rows = self.maps.len() + self.helpers.len();
                    if let Some(&t) = s.state_targets.iter().find(|&&t| t >= rows) {
                        return bad(
                            name("state_targets"),
                            format!("names map row {t}, beyond the maps and helpers"),
                        );
                    }
                }
                KindConstants::EkfRestart(r) => length(&name("variances"), r.variances.len(), nx)?,
                KindConstants::Mhe(m) => {
                    length(&name("weights"), m.weights.len(), ny)?;
                    for (field, values) in [
                        ("prior", &m.prior),
                        ("lower", &m.lower),
                        ("upper", &m.upper),
                        ("start", &m.start),
                    ] {
                        length(&name(field), values.len(), nx)?;
                    }
                    if m.substeps == 0 || m.iterations == 0 {
                        return bad(name("iterations"), format!("or `{}` is 0", name("substeps")));
                    }
                }
                // A filter's constants: checked above.
                _ => {}
            }
        }
        if self.missing(self.chosen).is_some() {
            return bad(
                "chosen".to_owned(),
                format!("is `{}`, whose constants are missing", self.chosen.name()),
            );
        }
        Ok(())
    }

    /// Whether these tables are `design`'s: the same spec text, read by this version of the tool.
    pub fn belongs_to(&self, design: &Design) -> bool {
        self.spec_sha256 == design.spec_sha256 && self.version == env!("CARGO_PKG_VERSION")
    }

    /// Whether `observer`, the emitted file these tables were written with, is unchanged.
    pub fn matches_observer(&self, observer: &Path) -> bool {
        std::fs::read_to_string(observer)
            .is_ok_and(|text| sha256(&text) == self.source_sha256 && self.written_with(&text))
    }
}

/// Lower-case hex SHA-256 of `text`.
fn sha256(text: &str) -> String {
    crate::output::sha256_hex(text.as_bytes())
}
