//! `[observer.<filter>]` (the sections the spec may give: `raw::RawObserver`): the constants of a
//! filter that the spec fixes instead of leaving them to the tuning. A published filter is reproduced this way: its start `x̂(0)`, its
//! `Q` and its `P(0)`, each a diagonal or a full symmetric matrix, in the states' units.
//!
//! The constants the spec leaves out are tuned as before, by the same search over the rest
//! (`crate::observers::ekf::tuning`).

use super::model::Model;
use super::raw::{RawCovariance, RawFilter};
use super::validate::Validator;
use super::SpecError;
use crate::plant::Covariance;

/// One filter's fixed constants; `None` is tuned (the start: the state box's centre).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FixedFilter {
    /// `x̂(0)`, in state order.
    pub x0: Option<Vec<f64>>,
    /// `Q`, per sampling period, in each state's unit squared.
    pub q: Option<Covariance>,
    /// `P(0)`, in each state's unit squared.
    pub p0: Option<Covariance>,
}

impl FixedFilter {
    /// Whether the spec fixes any of its constants.
    pub fn any(&self) -> bool {
        self.x0.is_some() || self.q.is_some() || self.p0.is_some()
    }

    /// The names of the constants it fixes, in the spec's order (`["q", "p0"]`).
    pub fn fixed(&self) -> Vec<&'static str> {
        [
            (self.x0.is_some(), "x0"),
            (self.q.is_some(), "q"),
            (self.p0.is_some(), "p0"),
        ]
        .into_iter()
        .filter_map(|(fixed, name)| fixed.then_some(name))
        .collect()
    }
}

/// The fixed constants of each `[observer.<filter>]` section the spec gives, by the section's full
/// name (`observer.ekf`), in the spec's order; the kind that reads a section names it
/// (`crate::observers::kind::FixedSection`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FixedFilters {
    sections: Vec<(&'static str, FixedFilter)>,
}

/// What a section the spec leaves out fixes: nothing.
static NOTHING_FIXED: FixedFilter = FixedFilter {
    x0: None,
    q: None,
    p0: None,
};

impl FixedFilters {
    /// The constants section `section` (`observer.ekf`) fixes: none when the spec leaves it out.
    pub fn of(&self, section: &str) -> &FixedFilter {
        self.sections
            .iter()
            .find(|(name, _)| *name == section)
            .map_or(&NOTHING_FIXED, |(_, fixed)| fixed)
    }

    /// The constants section `section` fixes, for a test or a tool that changes a design.
    pub fn of_mut(&mut self, section: &'static str) -> &mut FixedFilter {
        let at = self
            .sections
            .iter()
            .position(|(name, _)| *name == section)
            .unwrap_or_else(|| {
                self.sections.push((section, FixedFilter::default()));
                self.sections.len() - 1
            });
        &mut self.sections[at].1
    }

    /// Every section with what it fixes, in the spec's order.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, &FixedFilter)> {
        self.sections.iter().map(|(name, fixed)| (*name, fixed))
    }

    /// Sets what section `section` fixes.
    pub(super) fn insert(&mut self, section: &'static str, fixed: FixedFilter) {
        *self.of_mut(section) = fixed;
    }
}

impl Validator {
    /// `[observer.<section>]`: every state named once, every value finite, each covariance symmetric
    /// and positive definite.
    pub(super) fn fixed_filter(
        &self,
        section: &str,
        raw: Option<&RawFilter>,
        model: &Model,
    ) -> Result<FixedFilter, SpecError> {
        let Some(raw) = raw else {
            return Ok(FixedFilter::default());
        };
        let x0 = raw
            .x0
            .as_ref()
            .map(|values| self.state_values(&format!("{section}.x0"), values, model))
            .transpose()?;
        let covariance = |name: &str, raw: &Option<RawCovariance>| -> Result<Option<Covariance>, SpecError> {
            let field = format!("{section}.{name}");
            let Some(raw) = raw else { return Ok(None) };
            let covariance = match raw {
                RawCovariance::Diagonal(values) => {
                    self.keys_among(
                        &field,
                        values.keys(),
                        &model.states,
                        "a state",
                        "give one variance per state",
                    )?;
                    let missing = model.states.iter().find(|s| !values.contains_key(*s));
                    if let Some(state) = missing {
                        return Err(self.err(
                            format!("{field}.{state}"),
                            format!("no variance for `{state}`"),
                            format!("add `{state} = …` to `{field}`, in `{state}`'s unit squared"),
                        ));
                    }
                    Covariance::Diagonal(model.states.iter().map(|s| values[s]).collect())
                }
                RawCovariance::Full(rows) => Covariance::Full(rows.clone()),
            };
            let order = model.states.join(", ");
            covariance.check(model.states.len()).map_err(|e| {
                self.err(
                    &field,
                    format!("`{name}` cannot be a covariance: {e}"),
                    format!(
                        "give each state's variance (> 0) by name, or the full symmetric positive definite matrix as rows in the states' order ({order})"
                    ),
                )
            })?;
            Ok(Some(covariance))
        };
        Ok(FixedFilter {
            x0,
            q: covariance("q", &raw.q)?,
            p0: covariance("p0", &raw.p0)?,
        })
    }
}
