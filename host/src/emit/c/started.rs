//! What the observers the map starts or checks share in C: the choice of each state's map estimate,
//! the targets of a follower's states, and `push` as `firmware::Started::push` runs it.

/// `static void <prefix>_map_states(const float *all, float *map)`: each state's estimate from the
/// map's targets (`Follower::STATE_TARGETS`; 0 for a state that is no target).
pub(super) fn map_states(prefix: &str, state_targets: &[usize], targets: usize) -> String {
    let lines: String = state_targets
        .iter()
        .enumerate()
        .map(|(i, &t)| {
            if t < targets {
                format!("    map[{i}] = all[{t}];\n")
            } else {
                format!("    map[{i}] = 0.0f;\n")
            }
        })
        .collect();
    format!(
        "/* Each state's map estimate, from the map's targets. */\n\
         static void {prefix}_map_states(const float *all, float *map) {{\n{lines}}}\n\n"
    )
}

/// `static void <prefix>_targets_of(…)`: the targets of a follower's states, each flagged with its
/// state's saturation where a state is a target (`firmware::started::targets_of`).
pub(super) fn targets_of(name: &str, prefix: &str, state_targets: &[usize], targets: usize) -> String {
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
    let unused = if flagged.is_empty() {
        "    (void)state_flags;\n"
    } else {
        ""
    };
    format!(
        "/* The targets of a follower's states, flagged with their states' saturation. */\n\
         static void {prefix}_targets_of(const float *states, const {name}_saturation *state_flags, const float *u,\n\
         \x20                               float *values, {name}_saturation *flags) {{\n\
         {unused}\
         \x20   targets(states, u, values);\n\
         {inside}{flagged}}}\n\n"
    )
}

/// How one follower of the map runs: its C names and `firmware::Follower`'s constants.
pub(super) struct Follower<'a> {
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
    /// The carried state's fields, as passed to `_start`, `_follow` and `_predict` (`o->x`, …).
    pub carried: &'a str,
}

/// `<name>_<kind>_init`, `_push` and `_estimate` of a follower as `firmware::Started` runs it: the
/// map's window until its first estimate starts the follower, then the follower's `follow` every
/// sample (the map read during the start-up, and after it if the follower reads it); a refused sample
/// is the follower's `predict` once it has started. `init` is given the carried state's own reset.
pub(super) fn observer(f: &Follower<'_>, init_carried: &str) -> String {
    let Follower {
        name,
        kind,
        prefix,
        predict,
        start_up,
        steady_reads_map,
        carried,
    } = *f;
    let upper = name.to_uppercase();
    let reads = if steady_reads_map { "start_up || 1" } else { "start_up" };
    format!(
        "void {name}_{kind}_init({name}_{kind} *o) {{\n\
         \x20   {name}_map_init(&o->window);\n\
         {init_carried}\
         \x20   o->count = 0u;\n\
         \x20   o->started = 0;\n\
         \x20   o->ready = 0;\n\
         }}\n\
         \n\
         {name}_status {name}_{kind}_push({name}_{kind} *o, const float *y, const float *u) {{\n\
         \x20   const int start_up = o->count <= {start_up}u;\n\
         \x20   float all[{upper}_TARGETS], map[{upper}_STATES], states[{upper}_STATES];\n\
         \x20   {name}_saturation all_flags[{upper}_TARGETS], state_flags[{upper}_STATES];\n\
         \x20   int estimated = 0;\n\
         \x20   if (!accepts(y, u)) {{\n\
         \x20       if (o->started && inputs_finite(u)) {{\n\
         \x20           {predict}({carried}, u);\n\
         \x20       }}\n\
         \x20       return {upper}_REFUSED;\n\
         \x20   }}\n\
         \x20   memset(map, 0, sizeof map);\n\
         \x20   if ({reads}) {{\n\
         \x20       (void){name}_map_push(&o->window, y, u);\n\
         \x20       if (o->window.filled < {upper}_HORIZON) {{\n\
         \x20           return {upper}_OK;\n\
         \x20       }}\n\
         \x20       (void){name}_map_estimate(&o->window, all, all_flags);\n\
         \x20       {prefix}_map_states(all, map);\n\
         \x20       estimated = 1;\n\
         \x20   }}\n\
         \x20   if (!o->started && estimated) {{\n\
         \x20       if (!{prefix}_start(map, u, {carried})) {{\n\
         \x20           return {upper}_REFUSED;\n\
         \x20       }}\n\
         \x20       o->started = 1;\n\
         \x20       memcpy(o->values, all, sizeof all);\n\
         \x20       memcpy(o->flags, all_flags, sizeof all_flags);\n\
         \x20   }} else if (o->started) {{\n\
         \x20       if (!{prefix}_follow({carried}, o->count, start_up, map, y, u, states, state_flags)) {{\n\
         \x20           return {upper}_REFUSED;\n\
         \x20       }}\n\
         \x20       {prefix}_targets_of(states, state_flags, u, o->values, o->flags);\n\
         \x20   }} else {{\n\
         \x20       return {upper}_OK;\n\
         \x20   }}\n\
         \x20   o->ready = 1;\n\
         \x20   o->count = start_up ? o->count + 1u : o->count;\n\
         \x20   return {upper}_OK;\n\
         }}\n\
         \n\
         {estimate}",
        estimate = estimate(name, kind),
    )
}

/// `<name>_<kind>_estimate`: the latest accepted sample's targets, kept in `values` and `flags`.
pub(super) fn estimate(name: &str, kind: &str) -> String {
    let upper = name.to_uppercase();
    format!(
        "{name}_status {name}_{kind}_estimate(const {name}_{kind} *o, float *values, {name}_saturation *saturation) {{\n\
         \x20   if (!o->ready) {{\n\
         \x20       return {upper}_NO_ESTIMATE_YET;\n\
         \x20   }}\n\
         \x20   memcpy(values, o->values, sizeof o->values);\n\
         \x20   memcpy(saturation, o->flags, sizeof o->flags);\n\
         \x20   return {upper}_OK;\n\
         }}\n\n"
    )
}

/// The header's part for a kind: its struct (the window when the map starts it, the carried
/// `fields`, the latest estimate) and its three functions, documented by `what`.
pub(super) fn header(name: &str, kind: &str, what: &str, window: bool, fields: &str) -> String {
    let upper = name.to_uppercase();
    let window = if window {
        format!("    {name}_map window;\n")
    } else {
        String::new()
    };
    format!(
        "/* {what} */\n\
         typedef struct {{\n\
         {window}{fields}\
         \x20   float values[{upper}_TARGETS];\n\
         \x20   {name}_saturation flags[{upper}_TARGETS];\n\
         \x20   int ready;\n\
         }} {name}_{kind};\n\
         \n\
         void {name}_{kind}_init({name}_{kind} *observer);\n\
         {name}_status {name}_{kind}_push({name}_{kind} *observer, const float *y, const float *u);\n\
         {name}_status {name}_{kind}_estimate(const {name}_{kind} *observer, float *values, {name}_saturation *saturation);\n\
         \n"
    )
}
