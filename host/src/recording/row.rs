//! The observer's output at one sample, as both the estimating ([`super::estimate`]) and the writing
//! ([`super::write`]) of a recording see it: a module of its own so that neither imports the other
//! for it.

use firmware::Saturation;

/// What the observer did with one sample: the statuses of the C interface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// An estimate of every target.
    Ok,
    /// The sample held a NaN or an infinity: refused, nothing changed.
    Refused,
    /// Fewer than `N` accepted samples in this run (or, for an observer the map starts, no start yet).
    NoEstimateYet,
    /// The sample's values were finite but the observer's step was not: it restarted (from its
    /// start, or from the map), and gave no estimate at this sample.
    Restarted,
}

impl Status {
    /// The word written in the `status` column.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Refused => "refused",
            Status::NoEstimateYet => "no_estimate_yet",
            Status::Restarted => "restarted",
        }
    }
}

/// The observer's output at one sample.
#[derive(Clone, Debug, PartialEq)]
pub struct EstimateRow {
    /// What happened.
    pub status: Status,
    /// Per target, the estimate and whether it was held at an end of its range; empty unless `Ok`.
    pub targets: Vec<(f64, Saturation)>,
}

impl EstimateRow {
    /// A row without estimates.
    pub fn without(status: Status) -> Self {
        EstimateRow {
            status,
            targets: Vec::new(),
        }
    }
}
