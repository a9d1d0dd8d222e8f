//! How big a search may be: the candidates counted before anything is simulated, and the refusal of
//! a search above the spec's `[search] max_candidates` with a rough time and the fix.

use super::pace;
use crate::spec::{Design, Search, SpecError, Taps};

/// The most candidates a search fits unless the spec's `[search] max_candidates` says otherwise: at
/// most about ten minutes on this project's 2-core machine whatever the horizon. `vanderpol_searched`
/// (432 candidates, N ≤ 40, two targets) searches in 4.5 s there in a release build
/// ([`SECONDS_PER_CANDIDATE`]: 5,000 candidates in about 1 minute); longer horizons and more runs cost
/// up to ten times more per candidate (0.12 s at N = 160 to 320 over 400 samples: 5,000 in about 10
/// minutes). A search of 28,500 candidates, which ran for hours without a word, is refused; the
/// estimate printed after the first few candidates tells how long a larger allowed one takes.
pub const DEFAULT_MAX_CANDIDATES: usize = 5_000;

/// Wall-clock seconds per candidate of `vanderpol_searched` on this project's 2-core machine
/// (release: 432 in 4.5 s): the rough estimate a refusal gives before anything is fitted.
pub const SECONDS_PER_CANDIDATE: f64 = 0.0104;

/// Candidates of `search` for `design`, as the summary and `report.json` count them: every
/// `(N, n_m, β)`, once per count of taps its regressor of `N·(outputs + inputs)` entries keeps.
pub fn count(design: &Design, search: &Search) -> usize {
    let per_sample = design.model.outputs.len() + design.model.inputs.len();
    let taps: usize = search
        .horizons
        .iter()
        .map(|&n| search.taps.for_regressor(n * per_sample).len())
        .sum();
    taps * search.nms.len() * search.betas.len()
}

/// The number of candidates, or, above the design's `max_candidates`, an error naming the `[map]`
/// field with the most values, the count, the limit, a rough time and how to raise the limit:
/// checked when the spec is loaded and again before a search runs (`search --auto` replaces the
/// spec's candidates).
pub fn check_size(design: &Design, search: &Search) -> Result<usize, SpecError> {
    let total = count(design, search);
    if total <= design.max_candidates {
        return Ok(total);
    }
    let per_sample = design.model.outputs.len() + design.model.inputs.len();
    let most_taps = search
        .horizons
        .iter()
        .map(|&n| search.taps.for_regressor(n * per_sample).len())
        .max()
        .unwrap_or(1);
    let mut factors = vec![
        ("map.horizon", search.horizons.len()),
        ("map.nm", search.nms.len()),
        ("map.beta", search.betas.len()),
    ];
    if !matches!(search.taps, Taps::All) {
        factors.push(("map.taps", most_taps));
    }
    // The first of the fields with the most values (`rev`: `max_by_key` keeps the last maximum).
    let largest = factors
        .iter()
        .rev()
        .max_by_key(|(_, n)| *n)
        .map_or("map.horizon", |(field, _)| field);
    let product = factors
        .iter()
        .map(|(field, n)| format!("{n} of `{field}`"))
        .collect::<Vec<_>>()
        .join(" × ");
    let taps_note = if matches!(search.taps, Taps::All) {
        ""
    } else {
        " (tap counts: at most; fewer where N is short)"
    };
    Err(design.error(
        largest,
        format!(
            "the search has {total} candidates ({product}{taps_note}), above the limit of {}: at the {:.0} ms per candidate `vanderpol_searched` takes on a 2-core machine that is about {}, and longer horizons take longer",
            design.max_candidates,
            SECONDS_PER_CANDIDATE * 1e3,
            pace::duration(std::time::Duration::from_secs_f64(total as f64 * SECONDS_PER_CANDIDATE)),
        ),
        format!(
            "offer fewer values in `{largest}` (or the other fields above), or raise the limit: `[search]` `max_candidates = {total}`"
        ),
    ))
}
