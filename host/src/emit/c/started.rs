//! What the observers the map starts or checks share in C: the choice of each state's map estimate,
//! the targets of a follower's states, and `push` as `firmware::Started::push` runs it.

use askama::Template;

/// `static void <prefix>_map_states(const float *all, float *map)`: each state's estimate from the
/// map's rows (`Follower::STATE_TARGETS`: a target's, or a helper map's).
pub(crate) fn map_states(prefix: &str, state_targets: &[usize]) -> String {
    let lines: String = state_targets
        .iter()
        .enumerate()
        .map(|(i, &t)| format!("    map[{i}] = all[{t}];\n"))
        .collect();
    super::text::render(&MapStates { prefix, lines: &lines })
}

/// `static void <prefix>_targets_of(…)`: the targets of a follower's states, each flagged with its
/// state's saturation where a state is a target (`firmware::started::targets_of`).
pub(crate) fn targets_of(name: &str, prefix: &str, state_targets: &[usize], targets: usize) -> String {
    let upper = name.to_uppercase();
    let inside: String = (0..targets)
        .map(|t| format!("    flags[{t}] = {upper}_INSIDE;\n"))
        .collect();
    let flagged: String = state_targets
        .iter()
        .enumerate()
        .filter(|(_, &t)| t < targets)
        .map(|(i, &t)| format!("    flags[{t}] = state_flags[{i}];\n"))
        .collect();
    super::text::render(&TargetsOf {
        name,
        prefix,
        unused: flagged.is_empty(),
        inside: &inside,
        flagged: &flagged,
    })
}

/// How one follower of the map runs: its C names and `firmware::Follower`'s constants.
pub(crate) struct Follower<'a> {
    /// The design.
    pub name: &'a str,
    /// The kind (`corrected`, `ekf_map`).
    pub kind: &'a str,
    /// The prefix of its `_map_states`, `_targets_of`, `_start` and `_follow`.
    pub prefix: &'a str,
    /// Its `Follower::predict` (a lost output).
    pub predict: &'a str,
    /// `Follower::START_UP`.
    pub start_up: usize,
    /// `Follower::STEADY_READS_MAP`.
    pub steady_reads_map: bool,
    /// The carried state's fields, as passed to `_start` and `_follow` (`o->x`, …).
    pub carried: &'a str,
    /// Those of them `predict` reads and writes (a watched mean is not predicted).
    pub predicted: &'a str,
}

/// `<name>_<kind>_init`, `_push` and `_estimate` of a follower as `firmware::Started` runs it: the
/// map's window until its first estimate starts the follower, then the follower's `follow` every
/// sample (the map read during the start-up, and after it if the follower reads it); a refused sample
/// is the follower's `predict` once it has started. `init` is given the carried state's own reset.
pub(crate) fn observer(f: &Follower<'_>, init_carried: &str) -> String {
    let Follower {
        name,
        kind,
        prefix,
        predict,
        start_up,
        steady_reads_map,
        carried,
        predicted,
    } = *f;
    super::text::render(&StartedC {
        name,
        upper: &name.to_uppercase(),
        kind,
        prefix,
        predict,
        start_up,
        steady_reads_map,
        carried,
        predicted,
        init_carried,
    })
}

/// `<name>_<kind>_estimate`: the latest accepted sample's targets, kept in `values` and `flags`.
pub(crate) fn estimate(name: &str, kind: &str) -> String {
    super::text::render(&EstimateC {
        name,
        upper: &name.to_uppercase(),
        kind,
    })
}

/// The header's part for a kind: its struct (the window when the map starts it, the carried
/// `fields`, the latest estimate) and its three functions, documented by `what`.
pub(crate) fn header(name: &str, kind: &str, what: &str, window: bool, fields: &str) -> String {
    super::text::render(&KindH {
        name,
        upper: &name.to_uppercase(),
        kind,
        what,
        window,
        fields,
    })
}

/// `<prefix>_map_states` (`lines`: one assignment per state).
#[derive(Template)]
#[template(path = "c/map_states.c", escape = "none")]
struct MapStates<'a> {
    prefix: &'a str,
    lines: &'a str,
}

/// `<prefix>_targets_of`.
#[derive(Template)]
#[template(path = "c/targets_of.c", escape = "none")]
struct TargetsOf<'a> {
    name: &'a str,
    prefix: &'a str,
    unused: bool,
    inside: &'a str,
    flagged: &'a str,
}

/// A follower's observer ([`Follower`]'s fields, `init_carried`: the carried state's reset).
#[derive(Template)]
#[template(path = "c/started.c", escape = "none")]
struct StartedC<'a> {
    name: &'a str,
    upper: &'a str,
    kind: &'a str,
    prefix: &'a str,
    predict: &'a str,
    start_up: usize,
    steady_reads_map: bool,
    carried: &'a str,
    predicted: &'a str,
    init_carried: &'a str,
}

/// `<name>_<kind>_estimate`.
#[derive(Template)]
#[template(path = "c/estimate.c", escape = "none")]
struct EstimateC<'a> {
    name: &'a str,
    upper: &'a str,
    kind: &'a str,
}

/// A kind's part of the header.
#[derive(Template)]
#[template(path = "c/kind.h", escape = "none")]
struct KindH<'a> {
    name: &'a str,
    upper: &'a str,
    kind: &'a str,
    what: &'a str,
    window: bool,
    fields: &'a str,
}
