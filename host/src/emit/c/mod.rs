//! A design's observers as portable C99 source (`<name>.h`, `<name>.c`), emitted from the same f32
//! tables and the same straight-line programs as the Rust design file, operation for operation, so
//! that without fused multiply-add the C observer gives the Rust observer's bits. One module per
//! piece: `map` (the map), `program` (a program as a C function, the model's functions: `exp` as
//! libm computes it, the correctly rounded ones from `<math.h>`; others would come from the C
//! library, within an ulp of Rust's), `kinds` (the model-based kinds: the helpers, then each kind's part
//! from its folder), `box_filter` (what the filters from the box centre share), `started` (what the
//! observers the map starts share), and `storage` (the Rust static library's interface over the
//! chosen kind).
//!
//! C99 with `float` only: no `malloc`, no recursion, no VLA, no global mutable state; `<math.h>` only
//! where the model calls a function; a value is finite when its exponent bits are not all ones. Each
//! kind is a struct the caller allocates (`<name>_<kind>`) with `_init`, `_push` and `_estimate`, the
//! Rust observer's `new`, `push` and `estimate`; `<name>_observer` names the design's chosen kind.

pub(crate) mod box_filter;
mod fixed;
mod kinds;
mod map;
pub(crate) mod program;
pub(crate) mod started;
mod storage;
pub(crate) mod text;

pub use storage::{mark, sample_period, storage_bound, MARK_BYTES};
pub use text::CPart;
pub(crate) use text::{float, floats, render};

use askama::Template;

use super::model::Observers;
use super::EmitError;
use crate::fit::DesignResult;
use crate::plant::ModelCode;
use crate::spec::Design;

/// The first word (up to its first `_`, lower case) of every name the C interface appends to a
/// design's `<name>_` or `<NAME>_`, besides the observer kinds' names ([`c_name_clash`] adds those
/// from the registry): types, calls, enum values and macros of the C source's header, of the Rust
/// static library's header and its symbols. `tests/tests/integration/c_source.rs` checks that every name in
/// every emitted header starts with one of them, so that a new suffix cannot slip past the check.
pub const C_SUFFIX_WORDS: &[&str] = &[
    "bad",
    "covariance",
    "estimate",
    "fixed",
    "h",
    "high",
    "horizon",
    "init",
    "inputs",
    "inside",
    "kind",
    "low",
    "no",
    "not",
    "observer",
    "ok",
    "outputs",
    "push",
    "refused",
    "restarted",
    "sample",
    "saturation",
    "states",
    "status",
    "storage",
    "stored",
    "targets",
];

/// Whether designs `a` and `b`, written by one `gen` run, could declare the same C name; then the
/// word of the longer name that one of the shorter's names also begins with (the `map` of `vdp` and
/// `vdp_map`: `vdp_map_init` is both `vdp`'s map observer's `init` and `vdp_map`'s `init`).
///
/// Why refuse rather than rename: every C name is the design's name followed by `_` and a suffix
/// (`vdp_map`, `vdp_map_init`, `VDP_OK`), so a name users type and read in their firmware and in every
/// document stays the design's own; giving it a prefix or a separator (`vdp__map`) only for some
/// designs would make the names depend on which other specs were in the run. Two names can only
/// clash when one is the other followed by `_` and a word the interface appends (a name `b_Y` equal
/// to `a_X` needs `X` to begin with the rest of `b` after `a_`), so refusing exactly those pairs,
/// where the specs are read and before anything is fitted, leaves every other name free
/// (`vanderpol` beside `vanderpol_uncertain`). Designs written by separate runs are not compared:
/// linking two of them into one program is the user's choice of names.
pub fn c_name_clash(a: &str, b: &str) -> Option<String> {
    let (short, long) = if a.len() <= b.len() { (a, b) } else { (b, a) };
    let rest = long.strip_prefix(short)?.strip_prefix('_')?;
    let word = rest.split('_').next().unwrap_or(rest).to_ascii_lowercase();
    let a_kind = crate::observers::kind::REGISTRY
        .iter()
        .any(|k| k.kind.name().split('_').next() == Some(word.as_str()));
    let clashes = a_kind || C_SUFFIX_WORDS.contains(&word.as_str());
    clashes.then_some(word)
}

/// The header and the source of a design.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CSource {
    /// `<name>.h`.
    pub header: String,
    /// `<name>.c`.
    pub source: String,
}

/// The C source of `design`: its map (tables in `result`) and, given its model's programs and the
/// observers the Rust file has, every model-based kind.
pub fn c_source(
    design: &Design,
    result: &DesignResult,
    model: Option<(&ModelCode, &Observers<'_>)>,
) -> Result<CSource, EmitError> {
    let name = &design.name;
    let upper = name.to_uppercase();
    let (n, ny, nu, nt) = (
        design.map.horizon,
        design.model.outputs.len(),
        design.model.inputs.len(),
        design.targets.len(),
    );
    let map = map::map(design, result)?;
    let integer = match model.and_then(|(_, observers)| observers.fixed) {
        Some(point) => fixed::fixed(design, point),
        None => fixed::FixedC {
            header: String::new(),
            source: String::new(),
        },
    };
    let kinds = match model {
        Some((code, observers)) => kinds::kinds(design, code, observers)?,
        None => kinds::Kinds::default(),
    };
    let chosen = model.map(|(_, o)| o.kind.name());
    let (interface_header, interface_source) = match chosen {
        Some(kind) if kind == "map" || kinds.names.contains(&kind) => storage::storage_interface(design),
        _ => (String::new(), String::new()),
    };
    let alias = match chosen {
        Some(kind) => render(&AliasH {
            name,
            upper: &upper,
            kind,
            c_form: kind == "map" || kinds.names.contains(&kind),
        }),
        None => String::new(),
    };
    let header = render(&DesignH {
        name,
        upper: &upper,
        licence: &super::licence_comment(" * "),
        ny,
        nu,
        nt,
        n,
        tau: &storage::sample_period(design),
        sizes: model.map(|(code, _)| {
            let nx = code.dimensions.states;
            (nx, crate::plant::kalman::triangle(nx))
        }),
        map_header: &map.header,
        fixed_header: &integer.header,
        kinds_header: &kinds.header,
        alias: &alias,
        interface_header: &interface_header,
    });
    let body = format!("{}{}{}{interface_source}", map.source, integer.source, kinds.source);
    // Only the helpers the body calls: an unused static function is a warning.
    let calls = |f: &str| body.contains(&format!("{f}("));
    let source = render(&DesignC {
        name,
        upper: &upper,
        licence: &super::licence_comment(" * "),
        math: kinds.needs_math,
        // Only where a follower checks a sample.
        accepts: calls("accepts"),
        inputs: nu > 0,
        // `choose_float`, one `?:` per statement, which compilers make a conditional move;
        // `select_bits` and `select_float`, by masks, where a chain of selects on one condition would
        // become a branch.
        choose_float: calls("choose_float"),
        select_bits: calls("select_bits") || calls("select_float"),
        select_float: calls("select_float"),
        body: &body,
    });
    Ok(CSource { header, source })
}

/// `<name>.h`.
#[derive(Template)]
#[template(path = "c/design.h", escape = "none")]
struct DesignH<'a> {
    name: &'a str,
    upper: &'a str,
    licence: &'a str,
    ny: usize,
    nu: usize,
    nt: usize,
    n: usize,
    tau: &'a str,
    /// With a model: its states and the covariance's kept entries.
    sizes: Option<(usize, usize)>,
    map_header: &'a str,
    fixed_header: &'a str,
    kinds_header: &'a str,
    alias: &'a str,
    interface_header: &'a str,
}

/// The header's `<name>_observer` for the chosen kind (`c_form`: the kind has a C form).
#[derive(Template)]
#[template(path = "c/alias.h", escape = "none")]
struct AliasH<'a> {
    name: &'a str,
    upper: &'a str,
    kind: &'a str,
    c_form: bool,
}

/// `<name>.c`: the helpers that `body` calls, then `body`.
#[derive(Template)]
#[template(path = "c/design.c", escape = "none")]
struct DesignC<'a> {
    name: &'a str,
    upper: &'a str,
    licence: &'a str,
    math: bool,
    accepts: bool,
    inputs: bool,
    choose_float: bool,
    select_bits: bool,
    select_float: bool,
    body: &'a str,
}
