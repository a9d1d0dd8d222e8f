//! `[map]` and `[search]`: one value of each of the map's settings, or the candidates of the design
//! search, each within [`super::limits`].

use super::limits;
use super::raw::*;
use super::validate::Validator;
use super::*;

impl Validator {
    /// `[map]`: one value of each field, or the search's candidates.
    pub(super) fn map(&self, raw: &RawMap) -> Result<(MapSettings, Option<Search>), SpecError> {
        let horizons = self.choices("map.horizon", &raw.horizon, || Search::AUTO_HORIZONS.collect())?;
        let nms = self.choices("map.nm", &raw.nm, || Search::AUTO_NMS.to_vec())?;
        let betas = self.choices("map.beta", &raw.beta, || Search::AUTO_BETAS.to_vec())?;
        for &horizon in &horizons {
            if horizon == 0 {
                return Err(self.err(
                    "map.horizon",
                    "the horizon N must be at least 1",
                    "set `map.horizon` to the number of past measurements to use (the paper uses 10 and 3), or \"auto\"",
                ));
            }
            self.at_most("map.horizon", horizon, limits::MAX_HORIZON)?;
        }
        for &nm in &nms {
            self.at_most("map.nm", nm, limits::MAX_NM)?;
            if nm == 0 {
                return Err(self.err(
                    "map.nm",
                    "n_m must be at least 1",
                    "set `map.nm` (the paper uses 5), or \"auto\"",
                ));
            }
        }
        for &beta in &betas {
            self.positive("map.beta", beta, "β")?;
        }
        self.at_most(
            "map.monotonicity_grid",
            raw.monotonicity_grid,
            limits::MAX_MONOTONICITY_GRID,
        )?;
        let largest = |values: &[f64]| values.iter().copied().fold(f64::MIN, f64::max);
        let (nm_max, beta_max) = (*nms.iter().max().expect("checked non-empty"), largest(&betas));
        if beta_max * (nm_max as f64 - 1.0) > 30.0 {
            return Err(self.err(
                "map.beta",
                format!(
                    "β·(n_m - 1) = {} (β = {beta_max}, n_m = {nm_max}) makes basis odds ratios reach e^{:.0}: the basis degenerates to steps",
                    beta_max * (nm_max as f64 - 1.0),
                    beta_max * (nm_max as f64 - 1.0)
                ),
                "keep β·(n_m - 1) ≤ 30 for every candidate (β of 0.5 to 3 is usual)",
            ));
        }
        let taps = match &raw.taps {
            None => Taps::All,
            Some(RawChoice::Auto) => Taps::Auto,
            Some(choice) => {
                let counts = self.choices("map.taps", choice, Vec::new)?;
                if counts.contains(&0) {
                    return Err(self.err(
                        "map.taps",
                        "a map needs at least one tap",
                        "set `map.taps` to the number of non-zero gains to keep per target (≥ 1), a list of them, or \"auto\"; leave it out to keep every gain",
                    ));
                }
                Taps::Counts(counts)
            }
        };
        let (horizon, nm, beta) = (*horizons.iter().max().expect("checked non-empty"), nms[0], betas[0]);
        let fixed_taps = match &taps {
            Taps::All => Some(None),
            Taps::Counts(counts) if counts.len() == 1 => Some(Some(counts[0])),
            _ => None,
        };
        let search =
            (horizons.len() > 1 || nms.len() > 1 || betas.len() > 1 || fixed_taps.is_none()).then_some(Search {
                horizons,
                nms,
                betas,
                taps,
            });
        let epsilon = self.positive("map.epsilon", raw.epsilon, "ε")?;
        if !(1e-12..=1e12).contains(&epsilon) {
            return Err(self.err(
                "map.epsilon",
                format!("ε = {} is outside [1e-12, 1e12]: the QP loses its scale", readable(epsilon)),
                "set `map.epsilon` near the spread of the target times 1e-2 (0.01 is usual; with `intercept` the map does not depend on it)",
            ));
        }
        if raw.monotonicity_grid < 3 {
            return Err(self.err(
                "map.monotonicity_grid",
                format!(
                    "{} points cannot constrain the slope of Γ on [0, 1]",
                    raw.monotonicity_grid
                ),
                "use 201 or more points",
            ));
        }
        let settings = MapSettings {
            horizon,
            nm,
            beta,
            epsilon,
            normalisation: raw.normalisation,
            monotonicity_grid: raw.monotonicity_grid,
            taps: fixed_taps.flatten(),
        };
        Ok((settings, search))
    }

    /// `[search] max_candidates`: a whole number ≥ 1, or the default.
    pub(super) fn max_candidates(&self, raw: Option<&RawSearch>) -> Result<usize, SpecError> {
        let default = crate::search::DEFAULT_MAX_CANDIDATES;
        let fix =
            format!("set `search.max_candidates` to a whole number ≥ 1 (the default is {default}), or leave it out");
        match raw.and_then(|r| r.max_candidates.as_ref()) {
            None => Ok(default),
            Some(toml::Value::Integer(n)) => match usize::try_from(*n) {
                Ok(n) if n >= 1 => Ok(n),
                _ => Err(self.err(
                    "search.max_candidates",
                    format!("{n} allows no candidate: a search fits at least one"),
                    fix,
                )),
            },
            Some(other) => Err(self.err(
                "search.max_candidates",
                format!("`{other}` is not a whole number of candidates"),
                fix,
            )),
        }
    }

    /// The candidates of one `[map]` field: its value, its list (sorted, without repeats) or `auto`'s.
    fn choices<T: Copy + PartialOrd>(
        &self,
        field: &str,
        raw: &RawChoice<T>,
        auto: impl FnOnce() -> Vec<T>,
    ) -> Result<Vec<T>, SpecError> {
        let mut values = match raw {
            RawChoice::One(v) => vec![*v],
            RawChoice::List(values) => values.clone(),
            RawChoice::Auto => auto(),
        };
        if values.is_empty() {
            return Err(self.err(
                field,
                "an empty list of candidates",
                format!("give `{field}` one value, a list of candidates, or \"auto\""),
            ));
        }
        values.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
        values.dedup_by(|a, b| a == b);
        Ok(values)
    }
}
