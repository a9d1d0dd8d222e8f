//! The design search as the spec asks for it: the candidates of `[map]` `horizon`, `nm`, `beta` and
//! `taps`, and the tap counts `taps = "auto"` tries (the points of the pruning path of
//! [`crate::fit::identify::prune`], kept here so that the spec need not reach up into the fit).

/// The candidates of the design search (`"auto"` or a list in `[map]` `horizon`, `nm` or `beta`):
/// every combination is fitted and scored on the tuning runs ([`crate::search`]).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Search {
    /// Candidates for `N`.
    pub horizons: Vec<usize>,
    /// Candidates for `n_m`.
    pub nms: Vec<usize>,
    /// Candidates for `β`.
    pub betas: Vec<f64>,
    /// Candidates for the taps kept per target.
    pub taps: Taps,
}

/// The taps of `L` kept per target, as `[map] taps` asks.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub enum Taps {
    /// Every tap (no `taps`).
    All,
    /// These counts (sorted, without repeats); a count of at least `n_z` is every tap.
    Counts(Vec<usize>),
    /// `"auto"`: [`auto_counts`] of each candidate's regressor.
    Auto,
}

impl Taps {
    /// The counts to fit for a regressor of `regressor_len` entries: distinct, largest first.
    pub fn for_regressor(&self, regressor_len: usize) -> Vec<usize> {
        let mut counts = match self {
            Taps::All => vec![regressor_len],
            Taps::Counts(counts) => counts.iter().map(|&c| c.min(regressor_len)).collect(),
            Taps::Auto => auto_counts(regressor_len),
        };
        counts.sort_unstable_by(|a, b| b.cmp(a));
        counts.dedup();
        counts
    }
}

impl Search {
    /// `N` for `horizon = "auto"`: every horizon from 5 to 40 samples.
    pub const AUTO_HORIZONS: std::ops::RangeInclusive<usize> = 5..=40;
    /// `n_m` for `nm = "auto"`.
    pub const AUTO_NMS: [usize; 3] = [3, 5, 8];
    /// `β` for `beta = "auto"`.
    pub const AUTO_BETAS: [f64; 4] = [0.25, 0.5, 1.0, 2.0];

    /// Every field over its `"auto"` candidates.
    pub fn every_default() -> Self {
        Search {
            horizons: Self::AUTO_HORIZONS.collect(),
            nms: Self::AUTO_NMS.to_vec(),
            betas: Self::AUTO_BETAS.to_vec(),
            taps: Taps::All,
        }
    }

    /// Every candidate `(N, n_m, β)`, `N` varying slowest.
    pub fn candidates(&self) -> Vec<(usize, usize, f64)> {
        let mut all = Vec::new();
        for &n in &self.horizons {
            for &nm in &self.nms {
                for &beta in &self.betas {
                    all.push((n, nm, beta));
                }
            }
        }
        all
    }
}

/// The supports' sizes at which `μ` is re-fitted: `n_z`, then `⌈¾ c⌉` (at least one fewer) down to 1.
pub fn schedule(regressor_len: usize) -> Vec<usize> {
    let mut counts = vec![regressor_len];
    let mut count = regressor_len;
    while count > 1 {
        count = (count - 1).min((3 * count).div_ceil(4));
        counts.push(count);
    }
    counts
}

/// The counts `taps = "auto"` tries: the schedule's points down to a quarter of the taps.
pub fn auto_counts(regressor_len: usize) -> Vec<usize> {
    schedule(regressor_len)
        .into_iter()
        .filter(|&c| 4 * c >= regressor_len)
        .collect()
}
