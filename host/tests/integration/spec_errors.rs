//! Every error the spec validator can return, reached from TOML text by one table.
//!
//! Each case edits a shipped spec (every find-string must occur exactly once, so a changed spec cannot
//! turn a case into a no-op), parses it and checks the error's field (written by hand from reading
//! `host/src/spec/`, not computed), that the message names the file, the field and a fix, and what the
//! fix mentions. All failing cases are reported together.
//!
//! **Error sites.** `host/src/spec/` builds a [`SpecError`] at 42 places: 2 in `mod.rs` (`load` cannot
//! read the file; `parse` gets a TOML/serde error), 21 `self.err(` in `validate.rs` and 19 in
//! `validate_model.rs` (not counted: the body of `Validator::err` itself, and `Design::error`, which
//! `data` and `fit` use after validation; `bad_input.rs` beside this file covers those). Some sites are shared, so
//! the table counts branches, one per (site, caller or cause), 72 in all:
//! - `identifier` (invalid, reserved) × its 6 callers (states, inputs, parameters, definitions,
//!   outputs, targets): 12; `declare`'s "declared twice" × its 5 kinds of name: 5;
//! - `keys_among` × `model.derivatives`, `learning.grid`, `learning.inputs`, `scenario.x0`: 4;
//!   `positive` × `sampling.tau`, `map.beta`, `map.epsilon`: 3;
//! - expression errors of `expr.rs` (`Syntax`, `AmbiguousMinus`, `UnknownVariable`) × the fields that
//!   hold an expression (`model.definitions[i].expr`, `model.derivatives.*`, `model.outputs[i].expr`,
//!   through `model.rs` and `validate_model.rs`; `targets[i].expr` through `validate.rs`): 12;
//! - `parse` (line, document): 2; every other site once: 34.
//!
//! Since then `limits.rs` added 3 sites (`at_most`, with 9 callers, and the two budget errors, all in
//! the table) and `identifier` a third error, a name of the expression language (6 callers, tested on
//! parameters by `names_the_expression_language_reserves_are_refused_where_declared`).
//!
//! **Reached: all 45 sites, 83 of the 89 branches:** not reached are the one below, and the
//! expression-language name check through 5 of its 6 callers (the same function as the one tested). The one unreachable branch is the `"(document)"`
//! fallback of `parse` for a TOML error without a span: with toml 1.2, every syntax error carries the
//! span of the unexpected text, and the root deserializer gives the whole document's span to any
//! serde error that has none (a missing top-level field is reported at `(line 1)`, see
//! `toml_missing_top_level_field`).
//!
//! Parameters with a range (`{ value, min, max }`) then added 6 sites, all reached by the table: 5 in
//! `validate_model.rs` `parameter_range` (bounds not finite, inverted, empty; value not finite,
//! outside) and `at_most_uncertain` in `limits.rs`; the table also reaches the type check of `raw.rs`
//! `RawParameter` (through `parse`) and the mismatch runs' share of the budget.
//!
//! Physical bounds (`[model.bounds]`) added 5 sites in `validate.rs` `bounds` (not a state, neither
//! side, a side not finite, `min` not below `max`, the learning box outside), all in the table, and
//! the unknown key of `raw.rs` `RawBounds` (through `parse`).
//!
//! Target weights (`[[targets]] weight`) added 2 sites in `validate_design.rs` `targets` (a weight
//! negative or not finite; every weight 0), both in the table.

use std::collections::HashSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use host::spec::{self, SpecError};

const VANDERPOL: &str = include_str!("../../specs/vanderpol.toml");
const ECOLI_X0_0P5: &str = include_str!("../../specs/ecoli_x0_0p5.toml");
const ECOLI_X0_2: &str = include_str!("../../specs/ecoli_x0_2.toml");

/// The shipped spec a case edits.
#[derive(Clone, Copy, Debug)]
enum Base {
    Vdp,
    E05,
    E2,
    /// No text: `spec::load` of a path that does not exist.
    NoFile,
}

impl Base {
    fn text(self) -> &'static str {
        match self {
            Base::Vdp => VANDERPOL,
            Base::E05 => ECOLI_X0_0P5,
            Base::E2 => ECOLI_X0_2,
            Base::NoFile => "",
        }
    }
}

/// One edit of the base text.
enum Edit {
    /// Replace the only occurrence of the first string by the second.
    Swap(&'static str, &'static str),
    /// Append text at the end of the file.
    Append(&'static str),
}

/// The field the error must name.
enum Field {
    Exact(&'static str),
    Prefix(&'static str),
}

struct Case {
    /// Unique; also the file name the spec is parsed as (`<name>.toml`).
    name: &'static str,
    base: Base,
    edits: &'static [Edit],
    field: Field,
    /// A substring the fix must contain.
    fix: &'static str,
}

use Base::*;
use Edit::*;
use Field::*;

const fn case(name: &'static str, base: Base, edits: &'static [Edit], field: Field, fix: &'static str) -> Case {
    Case {
        name,
        base,
        edits,
        field,
        fix,
    }
}

#[rustfmt::skip]
const CASES: &[Case] = &[
    // ---- mod.rs `load`: the file cannot be read.
    case("unreadable_file", NoFile, &[], Exact("(file)"), "existing, readable"),

    // ---- mod.rs `parse`: TOML or serde refuses the text (the line is counted by hand in vanderpol.toml).
    case("toml_syntax", Vdp, &[Swap("tau = 0.1", "tau = = 0.1")], Exact("(line 20)"), "TOML"),
    case("toml_unterminated_string", Vdp, &[Swap("tau = 0.1", "tau = \"0.1")], Prefix("(line "), "TOML"),
    case("toml_duplicate_key", Vdp, &[Swap("tau = 0.1", "tau = 0.1\ntau = 0.2")], Exact("(line 21)"), "TOML"),
    case("toml_unknown_field", Vdp, &[Swap("tau = 0.1", "taux = 0.1")], Exact("sampling.taux"), "TOML"),
    case("toml_unknown_table", Vdp, &[Swap("[map]", "[maps]")], Exact("maps"), "TOML"),
    case("toml_missing_field", Vdp, &[Swap("trajectories = 64\n", "")], Exact("validation"), "TOML"),
    // A missing top-level field is reported with the span of the whole document: line 1. The fallback
    // field "(document)", for an error without a span, is unreachable with toml 1.2 (see the file's doc).
    case("toml_missing_top_level_field", Vdp, &[Swap("name = \"vanderpol\"\n", "")], Exact("(line 1)"), "TOML"),
    case("toml_wrong_type", Vdp, &[Swap("substeps = 10 ", "substeps = -1 ")], Exact("sampling.substeps"), "TOML"),
    case("toml_unknown_normalisation", Vdp, &[Swap("normalisation = \"intercept\"", "normalisation = \"none\"")], Exact("map.normalisation"), "TOML"),

    // ---- validate.rs `design`: the design name.
    case("name_upper_case", Vdp, &[Swap("name = \"vanderpol\"", "name = \"VanDerPol\"")], Exact("name"), "lower-case"),
    case("name_rust_keyword", Vdp, &[Swap("name = \"vanderpol\"", "name = \"match\"")], Exact("name"), "not a Rust keyword"),
    case("name_digit_first", Vdp, &[Swap("name = \"vanderpol\"", "name = \"1vdp\"")], Exact("name"), "starting with a letter"),
    // `lib` is the crate root of generated/: a design `lib` overwrote it and reported success.
    case("name_lib", Vdp, &[Swap("name = \"vanderpol\"", "name = \"lib\"")], Exact("name"), "nor `lib`"),

    // ---- validate_model.rs `model`: no state, no output.
    case("states_empty", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = []")], Exact("model.states"), "states = ["),
    case("outputs_empty", Vdp, &[
        Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\noutputs = []"),
        Swap("[[model.outputs]]\nname = \"y\"\nexpr = \"x1 + x2\"\n", ""),
        Swap("noise_variance = 0.2\n", ""),
    ], Exact("model.outputs"), "[[model.outputs]]"),

    // ---- validate.rs `identifier` (invalid, reserved) and validate_model.rs `declare` (declared twice), for
    // each kind of name declared in the model.
    case("state_invalid_name", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x 2\"]")], Exact("model.states[1]"), "letters, digits and `_`"),
    case("state_reserved_name", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"time\"]")], Exact("model.states[1]"), "reserved: time, t, run, status, saturated"),
    case("units_of_an_output", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nunits = { y = \"V\" }")], Exact("model.units.y"), "`unit` field"),
    case("units_of_an_unknown_name", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nunits = { x3 = \"V\" }")], Exact("model.units.x3"), "name a state or an input (x1, x2)"),
    case("units_on_two_lines", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nunits = { x1 = \"c\\nm\" }")], Exact("model.units.x1"), "without line breaks"),
    case("output_unit_on_two_lines", Vdp, &[Swap("noise_variance = 0.2", "noise_variance = 0.2\nunit = \"V\\n*/\"")], Exact("model.outputs[0].unit"), "without line breaks"),
    case("target_unit_too_long", Vdp, &[Swap("name = \"x2\"\nexpr = \"x2\"", "name = \"x2\"\nexpr = \"x2\"\nunit = \"a unit that is really a whole sentence\"")], Exact("targets[1].unit"), "at most 32 characters"),
    case("time_unit_with_a_control_character", Vdp, &[Swap("time_unit = \"s\"", "time_unit = \"s\\u001b[31m\"")], Exact("sampling.time_unit"), "control characters"),
    case("description_with_a_control_character", Vdp, &[Swap("(paper Example 1)\"", "(paper Example 1)\\u0007\"")], Exact("description"), "plain text"),
    // `[model.bounds]` (validate.rs `bounds`): a state's physical bounds.
    case("bounds_of_an_unknown_state", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nbounds = { x3 = { min = 0.0 } }")], Exact("model.bounds.x3"), "name a state (x1, x2)"),
    case("bounds_with_neither_side", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nbounds = { x1 = {} }")], Exact("model.bounds.x1"), "one side or both"),
    case("bounds_min_above_max", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nbounds = { x1 = { min = 3.0, max = -3.0 } }")], Exact("model.bounds.x1"), "`min` < `max`"),
    case("bounds_not_finite", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nbounds = { x1 = { max = inf } }")], Exact("model.bounds.x1.max"), "leave `max` out"),
    case("bounds_exclude_the_learning_box", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nbounds = { x2 = { min = 0.0 } }")], Exact("model.bounds.x2"), "widen the bounds"),
    case("bounds_with_an_unknown_key", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\nbounds = { x1 = { minimum = 0.0 } }")], Exact("model.bounds.x1.minimum"), "correct the TOML"),
    case("target_reserved_prefix", Vdp, &[Swap("name = \"x1\"", "name = \"truth_x1\"")], Exact("targets[0].name"), "names starting with saturated_ or truth_"),
    case("state_declared_twice", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x1\"]")], Exact("model.states[1]"), "its own name"),
    case("input_invalid_name", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\ninputs = [\"u.1\"]")], Exact("model.inputs[0]"), "letters, digits and `_`"),
    case("input_reserved_name", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\ninputs = [\"saturated\"]")], Exact("model.inputs[0]"), "reserved"),
    case("input_named_like_a_state", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\ninputs = [\"x2\"]")], Exact("model.inputs[0]"), "its own name"),
    // Parameters are a TOML table: checked in key order (upper case first), after states and inputs.
    case("parameter_invalid_name", E05, &[Swap("I = 1.0 ", "\"I 2\" = 1.0\nI = 1.0 ")], Exact("model.parameters.I 2"), "letters, digits and `_`"),
    case("parameter_reserved_name", E05, &[Swap("I = 1.0 ", "run = 1.0\nI = 1.0 ")], Exact("model.parameters.run"), "reserved"),
    case("parameter_named_like_a_state", E05, &[Swap("I = 1.0 ", "X = 1.0\nI = 1.0 ")], Exact("model.parameters.X"), "its own name"),
    case("definition_invalid_name", E05, &[Swap("name = \"mu\"", "name = \"mu'\"")], Exact("model.definitions[0].name"), "letters, digits and `_`"),
    case("definition_reserved_name", E05, &[Swap("name = \"death\"", "name = \"time\"")], Exact("model.definitions[1].name"), "reserved"),
    case("definition_named_like_a_parameter", E05, &[Swap("name = \"mu\"", "name = \"k_s\"")], Exact("model.definitions[0].name"), "its own name"),
    case("output_invalid_name", Vdp, &[Swap("name = \"y\"", "name = \"y-meas\"")], Exact("model.outputs[0].name"), "letters, digits and `_`"),
    case("output_reserved_name", Vdp, &[Swap("name = \"y\"", "name = \"time\"")], Exact("model.outputs[0].name"), "reserved"),
    case("output_named_like_a_definition", E05, &[Swap("name = \"L\"", "name = \"mu\"")], Exact("model.outputs[1].name"), "its own name"),

    // ---- validate_model.rs `model`: values of parameters and noise variances.
    case("parameter_nan", E05, &[Swap("mu_m = 0.2 ", "mu_m = nan ")], Exact("model.parameters.mu_m"), "finite number"),
    case("parameter_infinite", Vdp, &[Swap("[model.derivatives]", "[model.parameters]\nk = -inf\n\n[model.derivatives]")], Exact("model.parameters.k"), "finite number"),
    // A parameter with a range, `{ value, min, max }` (validate_model.rs `parameter_range`): each error
    // names the key to change, as for the bounds of an axis.
    case("parameter_range_inverted", E05, &[Swap("mu_m = 0.2 ", "mu_m = { value = 0.2, min = 0.3, max = 0.1 } ")], Exact("model.parameters.mu_m.max"), "swap `min` and `max`"),
    case("parameter_range_empty", E05, &[Swap("mu_m = 0.2 ", "mu_m = { value = 0.2, min = 0.2, max = 0.2 } ")], Exact("model.parameters.mu_m.max"), "plain number: `mu_m = 0.2`"),
    case("parameter_range_min_infinite", E05, &[Swap("mu_m = 0.2 ", "mu_m = { value = 0.2, min = -inf, max = 0.3 } ")], Exact("model.parameters.mu_m.min"), "finite bounds"),
    case("parameter_range_max_nan", E05, &[Swap("mu_m = 0.2 ", "mu_m = { value = 0.2, min = 0.1, max = nan } ")], Exact("model.parameters.mu_m.max"), "finite bounds"),
    case("parameter_range_span_overflows", Vdp, &[Swap("[model.derivatives]", "[model.parameters]\na = { value = 0.0, min = -1e308, max = 1e308 }\n\n[model.derivatives]")], Exact("model.parameters.a.max"), "finite bounds"),
    case("parameter_range_value_nan", E05, &[Swap("mu_m = 0.2 ", "mu_m = { value = nan, min = 0.1, max = 0.3 } ")], Exact("model.parameters.mu_m.value"), "finite value"),
    case("parameter_range_value_above", E05, &[Swap("mu_m = 0.2 ", "mu_m = { value = 0.4, min = 0.1, max = 0.3 } ")], Exact("model.parameters.mu_m.value"), "between `min` and `max`"),
    case("parameter_range_value_below", E2, &[Swap("k_s = 0.1 ", "k_s = { value = 0.01, min = 0.05, max = 0.2 } ")], Exact("model.parameters.k_s.value"), "widen the range"),
    // The TOML of a parameter: a number or a table of exactly `value`, `min`, `max` (raw.rs `RawParameter`).
    case("parameter_range_without_max", E05, &[Swap("mu_m = 0.2 ", "mu_m = { value = 0.2, min = 0.1 } ")], Exact("model.parameters.mu_m"), "TOML"),
    case("parameter_range_unknown_key", E05, &[Swap("mu_m = 0.2 ", "mu_m = { value = 0.2, min = 0.1, max = 0.3, mid = 0.2 } ")], Exact("model.parameters.mu_m.mid"), "TOML"),
    case("parameter_not_a_number", E05, &[Swap("mu_m = 0.2 ", "mu_m = \"0.2\" ")], Exact("model.parameters.mu_m"), "TOML"),
    // limits.rs: at most 8 parameters with a range (the mismatch set runs all 2^p corners).
    case("parameter_ranges_too_many", Vdp, &[Swap("[model.derivatives]", "[model.parameters]\na1 = { value = 0.0, min = -1.0, max = 1.0 }\na2 = { value = 0.0, min = -1.0, max = 1.0 }\na3 = { value = 0.0, min = -1.0, max = 1.0 }\na4 = { value = 0.0, min = -1.0, max = 1.0 }\na5 = { value = 0.0, min = -1.0, max = 1.0 }\na6 = { value = 0.0, min = -1.0, max = 1.0 }\na7 = { value = 0.0, min = -1.0, max = 1.0 }\na8 = { value = 0.0, min = -1.0, max = 1.0 }\na9 = { value = 0.0, min = -1.0, max = 1.0 }\n\n[model.derivatives]")], Exact("model.parameters.a9"), "at most 8 parameters a range"),
    case("noise_variance_negative", Vdp, &[Swap("noise_variance = 0.2", "noise_variance = -0.2")], Exact("model.outputs[0].noise_variance"), "variance"),
    case("noise_variance_nan", E05, &[Swap("noise_variance = 20.0", "noise_variance = nan")], Exact("model.outputs[1].noise_variance"), "0 for none"),

    // ---- validate.rs `keys_among` for `model.derivatives`, and validate_model.rs: a derivative missing.
    case("derivative_of_no_state", Vdp, &[Swap("x1 = \"-x2\"", "x1 = \"-x2\"\nx3 = \"0\"")], Exact("model.derivatives.x3"), "one derivative per state of `model.states` (x1, x2)"),
    case("derivative_missing", Vdp, &[Swap("x1 = \"-x2\"\n", "")], Exact("model.derivatives.x1"), "x1 = \"…\""),

    // ---- model.rs `compile` (through validate_model.rs `model`): each expression field × each ExprError of expr.rs
    // (Syntax, AmbiguousMinus, UnknownVariable).
    case("definition_expr_syntax", E05, &[Swap("expr = \"mu_m*S/(k_s + S)\"", "expr = \"mu_m*S/(k_s + S\"")], Exact("model.definitions[0].expr"), "exmex syntax"),
    case("definition_expr_minus_before_power", E05, &[Swap("expr = \"k_d*exp(-k_p/max(P, 0.001))\"", "expr = \"k_d*exp(-k_p^2/max(P, 0.001))\"")], Exact("model.definitions[1].expr"), "-(k_p^…)"),
    // A definition may only use the definitions before it.
    case("definition_expr_uses_a_later_definition", E05, &[Swap("expr = \"mu_m*S/(k_s + S)\"", "expr = \"mu_m*S/(k_s + S) + death\"")], Exact("model.definitions[0].expr"), "declare `death`"),
    case("derivative_expr_syntax", Vdp, &[Swap("x1 = \"-x2\"", "x1 = \"-x2 * (\"")], Exact("model.derivatives.x1"), "exmex syntax"),
    case("derivative_expr_minus_before_power", Vdp, &[Swap("x1 = \"-x2\"", "x1 = \"-x2^3\"")], Exact("model.derivatives.x1"), "-(x2^…)"),
    case("derivative_expr_unknown_variable", E05, &[Swap("- death*P\"", "- decay*P\"")], Exact("model.derivatives.P"), "declare `decay`"),
    case("output_expr_syntax", Vdp, &[Swap("expr = \"x1 + x2\"", "expr = \"x1 +\"")], Exact("model.outputs[0].expr"), "exmex syntax"),
    case("output_expr_minus_before_power", Vdp, &[Swap("expr = \"x1 + x2\"", "expr = \"x1 + -x2^2\"")], Exact("model.outputs[0].expr"), "-(x2^…)"),
    case("output_expr_unknown_variable", E05, &[Swap("*X*P\"", "*X*Q\"")], Exact("model.outputs[1].expr"), "declare `Q`"),

    // ---- validate.rs `positive` (τ) and `design` (substeps).
    case("tau_zero", Vdp, &[Swap("tau = 0.1", "tau = 0.0")], Exact("sampling.tau"), "positive"),
    case("tau_negative", E05, &[Swap("tau = 0.2", "tau = -0.2")], Exact("sampling.tau"), "positive"),
    case("tau_nan", Vdp, &[Swap("tau = 0.1", "tau = nan")], Exact("sampling.tau"), "positive"),
    case("substeps_zero", Vdp, &[Swap("substeps = 10 ", "substeps = 0 ")], Exact("sampling.substeps"), "1 or more"),

    // ---- validate.rs `map` (and `positive` for β and ε).
    case("horizon_zero", Vdp, &[Swap("horizon = 10 ", "horizon = 0 ")], Exact("map.horizon"), "set `map.horizon`"),
    case("nm_zero", Vdp, &[Swap("nm = 5 ", "nm = 0 ")], Exact("map.nm"), "set `map.nm`"),
    case("beta_zero", Vdp, &[Swap("beta = 0.5 ", "beta = 0.0 ")], Exact("map.beta"), "positive"),
    case("beta_negative", E05, &[Swap("beta = 1.0", "beta = -1.0")], Exact("map.beta"), "positive"),
    case("beta_degenerate_basis", Vdp, &[Swap("beta = 0.5 ", "beta = 8.0 ")], Exact("map.beta"), "β·(n_m - 1) ≤ 30"),
    case("epsilon_zero", Vdp, &[Swap("epsilon = 0.01 ", "epsilon = 0.0 ")], Exact("map.epsilon"), "positive"),
    case("epsilon_infinite", E05, &[Swap("epsilon = 0.01", "epsilon = inf")], Exact("map.epsilon"), "positive"),
    case("monotonicity_grid_too_small", Vdp, &[Swap("monotonicity_grid = 201", "monotonicity_grid = 2")], Exact("map.monotonicity_grid"), "201 or more"),

    // ---- validate.rs `map` candidates (`choices`) and `budget`; raw.rs `RawChoice`.
    case("horizon_word_not_auto", Vdp, &[Swap("horizon = 10 ", "horizon = \"best\" ")], Exact("map.horizon"), "TOML"),
    case("horizon_fraction", Vdp, &[Swap("horizon = 10 ", "horizon = 10.5 ")], Exact("map.horizon"), "TOML"),
    case("horizon_list_of_words", Vdp, &[Swap("horizon = 10 ", "horizon = [5, \"auto\"] ")], Exact("map.horizon"), "TOML"),
    case("horizon_empty_list", Vdp, &[Swap("horizon = 10 ", "horizon = [] ")], Exact("map.horizon"), "a list of candidates"),
    case("horizon_candidate_zero", Vdp, &[Swap("horizon = 10 ", "horizon = [0, 10] ")], Exact("map.horizon"), "set `map.horizon`"),
    case("taps_zero", Vdp, &[Swap("beta = 0.5 ", "beta = 0.5\ntaps = 0 ")], Exact("map.taps"), "(≥ 1)"),
    case("taps_candidate_zero", Vdp, &[Swap("beta = 0.5 ", "beta = 0.5\ntaps = [0, 4] ")], Exact("map.taps"), "set `map.taps`"),
    case("taps_word_not_auto", Vdp, &[Swap("beta = 0.5 ", "beta = 0.5\ntaps = \"few\" ")], Exact("map.taps"), "TOML"),
    case("beta_candidate_degenerate", Vdp, &[Swap("beta = 0.5 ", "beta = [0.5, 8.0] ")], Exact("map.beta"), "for every candidate"),
    case("budget_zero_instructions", Vdp, &[Append("\n[budget]\ninstructions = 0\n")], Exact("budget.instructions"), "most the chip can spend"),
    case("budget_negative_delay", Vdp, &[Append("\n[budget]\nfirst_estimate = -1.0\n")], Exact("budget.first_estimate"), "positive"),
    case("budget_unknown_field", Vdp, &[Append("\n[budget]\ncycles = 100\n")], Exact("budget.cycles"), "TOML"),

    // ---- validate_model.rs `learning`: the horizon against the run length (blamed on `map.horizon`).
    case("learning_runs_not_longer_than_horizon", Vdp, &[Swap("samples = 100\nseed = 1\n", "samples = 10\nseed = 1\n")], Exact("map.horizon"), "raise `learning.samples`"),

    // ---- validate.rs `keys_among` for `learning.grid`, and validate_model.rs `learning`: an axis missing.
    case("grid_axis_of_no_state", Vdp, &[Swap("grid.x2 = { min = -5.0, max = 5.0, points = 4 }", "grid.x2 = { min = -5.0, max = 5.0, points = 4 }\ngrid.x3 = { value = 0.0 }")], Exact("learning.grid.x3"), "one axis per state (x1, x2)"),
    case("grid_axis_missing", Vdp, &[Swap("grid.x2 = { min = -5.0, max = 5.0, points = 4 }\n", "")], Exact("learning.grid.x2"), "grid.x2 = { min"),

    // ---- validate.rs `keys_among` for `learning.inputs`, and validate_model.rs `learning`: input profiles.
    case("input_profile_of_no_input", Vdp, &[Swap("grid.x2 = { min = -5.0, max = 5.0, points = 4 }", "grid.x2 = { min = -5.0, max = 5.0, points = 4 }\ninputs.u = { min = 0.0, max = 1.0, hold = 5 }")], Exact("learning.inputs.u"), "one profile per input"),
    case("input_profile_missing", Vdp, &[Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\ninputs = [\"u\"]")], Exact("learning.inputs.u"), "inputs.u = { min"),
    case("input_profile_inverted", Vdp, &[
        Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\ninputs = [\"u\"]"),
        Swap("grid.x2 = { min = -5.0, max = 5.0, points = 4 }", "grid.x2 = { min = -5.0, max = 5.0, points = 4 }\ninputs.u = { min = 1.0, max = 0.0, hold = 5 }"),
    ], Exact("learning.inputs.u.max"), "min ≤ max"),
    // The bad bound is `max`, and the error names it (it named `min` until this test found it).
    case("input_profile_infinite_max", Vdp, &[
        Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\ninputs = [\"u\"]"),
        Swap("grid.x2 = { min = -5.0, max = 5.0, points = 4 }", "grid.x2 = { min = -5.0, max = 5.0, points = 4 }\ninputs.u = { min = 0.0, max = inf, hold = 5 }"),
    ], Exact("learning.inputs.u.max"), "finite bounds"),
    case("input_profile_infinite_min", Vdp, &[
        Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\ninputs = [\"u\"]"),
        Swap("grid.x2 = { min = -5.0, max = 5.0, points = 4 }", "grid.x2 = { min = -5.0, max = 5.0, points = 4 }\ninputs.u = { min = -inf, max = 1.0, hold = 5 }"),
    ], Exact("learning.inputs.u.min"), "finite bounds"),
    case("input_profile_hold_zero", Vdp, &[
        Swap("states = [\"x1\", \"x2\"]", "states = [\"x1\", \"x2\"]\ninputs = [\"u\"]"),
        Swap("grid.x2 = { min = -5.0, max = 5.0, points = 4 }", "grid.x2 = { min = -5.0, max = 5.0, points = 4 }\ninputs.u = { min = 0.0, max = 1.0, hold = 0 }"),
    ], Exact("learning.inputs.u.hold"), "1 or more"),

    // ---- validate_model.rs `axis`.
    case("axis_value_nan", E05, &[Swap("grid.X = { value = 0.5 }", "grid.X = { value = nan }")], Exact("learning.grid.X.value"), "finite value"),
    case("axis_value_infinite", E2, &[Swap("grid.X = { value = 2.0 }", "grid.X = { value = inf }")], Exact("learning.grid.X.value"), "finite value"),
    case("axis_span_overflows", Vdp, &[Swap("min = -5.0, max = 5.0", "min = -1e308, max = 1e308")], Exact("learning.grid.x2.max"), "finite bounds"),
    // The bad bound is `max`, and the error names it (it named `min` until this test found it).
    case("axis_max_nan", Vdp, &[Swap("min = -5.0, max = 5.0", "min = -5.0, max = nan")], Exact("learning.grid.x2.max"), "finite bounds"),
    case("axis_min_infinite", Vdp, &[Swap("min = -5.0, max = 5.0", "min = -inf, max = 5.0")], Exact("learning.grid.x2.min"), "finite bounds"),
    case("axis_inverted", Vdp, &[Swap("min = -5.0, max = 5.0", "min = 5.0, max = -5.0")], Exact("learning.grid.x2.max"), "swap"),
    case("axis_empty", Vdp, &[Swap("min = -2.0, max = 2.0", "min = 2.0, max = 2.0")], Exact("learning.grid.x1.max"), "{ value = … }"),
    case("axis_zero_points", Vdp, &[Swap("max = 2.0, points = 4", "max = 2.0, points = 0")], Exact("learning.grid.x1.points"), "2 or more"),
    case("axis_one_point", E05, &[Swap("max = 5.0, points = 5", "max = 5.0, points = 1")], Exact("learning.grid.S.points"), "hold the state fixed"),
    case("axis_range_and_value", Vdp, &[Swap("max = 2.0, points = 4 }", "max = 2.0, points = 4, value = 1.0 }")], Exact("learning.grid.x1"), "{ value = … }"),
    case("axis_without_points", Vdp, &[Swap("min = -5.0, max = 5.0, points = 4 }", "min = -5.0, max = 5.0 }")], Exact("learning.grid.x2"), "points = …"),
    case("axis_empty_table", E05, &[Swap("grid.X = { value = 0.5 }", "grid.X = {}")], Exact("learning.grid.X"), "min = …, max = …, points = …"),

    // ---- validate.rs `validation`.
    case("validation_no_trajectory", Vdp, &[Swap("trajectories = 64", "trajectories = 0")], Exact("validation.trajectories"), "1 or more"),
    case("validation_runs_shorter_than_horizon", Vdp, &[Swap("trajectories = 64\nsamples = 100", "trajectories = 64\nsamples = 9")], Exact("validation.samples"), "≥ `map.horizon`"),

    // ---- limits.rs: an upper bound on every size, and the budget of the whole run (each used to end
    // in an allocation abort, a hang or the OOM killer).
    case("epsilon_huge", Vdp, &[Swap("epsilon = 0.01 ", "epsilon = 1e300 ")], Exact("map.epsilon"), "0.01 is usual"),
    case("epsilon_tiny", Vdp, &[Swap("epsilon = 0.01 ", "epsilon = 1e-300 ")], Exact("map.epsilon"), "0.01 is usual"),
    case("limit_horizon", Vdp, &[Swap("horizon = 10 ", "horizon = 100000 ")], Exact("map.horizon"), "at most 1000"),
    case("limit_nm", Vdp, &[Swap("nm = 5 ", "nm = 1000000 ")], Exact("map.nm"), "at most 50"),
    case("limit_monotonicity_grid", Vdp, &[Swap("monotonicity_grid = 201 ", "monotonicity_grid = 10000000 ")], Exact("map.monotonicity_grid"), "at most 100001"),
    case("limit_axis_points", Vdp, &[Swap("max = 2.0, points = 4", "max = 2.0, points = 1000000")], Exact("learning.grid.x1.points"), "at most 10000"),
    case("limit_substeps", Vdp, &[Swap("substeps = 10 ", "substeps = 10000000000 ")], Exact("sampling.substeps"), "at most 10000"),
    case("limit_learning_samples", Vdp, &[Swap("samples = 100\nseed = 1", "samples = 1000000000\nseed = 1")], Exact("learning.samples"), "at most 10000000"),
    case("limit_validation_samples", Vdp, &[Swap("trajectories = 64\nsamples = 100", "trajectories = 64\nsamples = 1000000000")], Exact("validation.samples"), "at most 10000000"),
    case("limit_validation_trajectories", Vdp, &[Swap("trajectories = 64", "trajectories = 1000000000")], Exact("validation.trajectories"), "at most 1000000"),
    case("limit_scenario_samples", Vdp, &[Swap("samples = 101", "samples = 1000000000")], Exact("scenario.samples"), "at most 10000000"),
    // Every size within its bound, the total beyond the budget: 8·10⁷ stored samples, then 2·10¹¹ RK4 steps.
    case("budget_stored_values", Vdp, &[Swap("samples = 100\nseed = 1", "samples = 5000000\nseed = 1")], Exact("learning"), "shorter runs"),
    case("budget_simulation_steps", Vdp, &[Swap("substeps = 10 ", "substeps = 10000 "), Swap("trajectories = 64", "trajectories = 200000")], Exact("validation"), "fewer `sampling.substeps`"),
    // The mismatch runs count too: 2⁸ corners × 4·10⁵ validation samples take 1.03·10⁹ steps (8·10⁶ without them).
    case("budget_mismatch_runs", Vdp, &[
        Swap("[model.derivatives]", "[model.parameters]\na1 = { value = 0.0, min = -1.0, max = 1.0 }\na2 = { value = 0.0, min = -1.0, max = 1.0 }\na3 = { value = 0.0, min = -1.0, max = 1.0 }\na4 = { value = 0.0, min = -1.0, max = 1.0 }\na5 = { value = 0.0, min = -1.0, max = 1.0 }\na6 = { value = 0.0, min = -1.0, max = 1.0 }\na7 = { value = 0.0, min = -1.0, max = 1.0 }\na8 = { value = 0.0, min = -1.0, max = 1.0 }\n\n[model.derivatives]"),
        Swap("trajectories = 64", "trajectories = 4000"),
    ], Exact("model.parameters"), "fewer parameters with a range"),
    // The tuning runs count too: 10⁹ samples of them alone, everything else as shipped.
    // The score's start-up: at least one sample (0.01 / 0.1 rounds to 0), at most a tuning run's 91 estimates.
    case("tuning_start_up_short", Vdp, &[Swap("[tuning]", "[tuning]\nstart_up = 0.01")], Exact("tuning.start_up"), "between 0.1 and 9.1"),
    case("tuning_start_up_long", Vdp, &[Swap("[tuning]", "[tuning]\nstart_up = 9.2")], Exact("tuning.start_up"), "or leave it out (the box filters' settling time"),
    case("budget_tuning_runs", Vdp, &[Swap("[tuning]", "[tuning]\ntrajectories = 1000000\nsamples = 1000")], Exact("tuning"), "fewer validation or tuning runs"),
    // A long scenario is named as such (it used to be blamed on `learning`): 10⁷ samples, its 16
    // tuning runs and its noise draws hold 7·10⁸ samples.
    case("budget_scenario_samples", Vdp, &[Swap("samples = 101", "samples = 10000000")], Exact("scenario.samples"), "shorter scenarios"),

    // ---- validate.rs `targets` (and `identifier` for their names).
    case("targets_empty", Vdp, &[
        Swap("name = \"vanderpol\"", "name = \"vanderpol\"\ntargets = []"),
        Swap("[[targets]]\nname = \"x1\"\nexpr = \"x1\"\n\n[[targets]]\nname = \"x2\"\nexpr = \"x2\"\n", ""),
    ], Exact("targets"), "[[targets]]"),
    case("target_invalid_name", Vdp, &[Swap("name = \"x1\"\nexpr", "name = \"x 1\"\nexpr")], Exact("targets[0].name"), "letters, digits and `_`"),
    case("target_reserved_name", Vdp, &[Swap("name = \"x2\"\nexpr", "name = \"run\"\nexpr")], Exact("targets[1].name"), "reserved"),
    case("target_weight_negative", Vdp, &[Swap("name = \"x2\"\nexpr = \"x2\"", "name = \"x2\"\nexpr = \"x2\"\nweight = -0.5")], Exact("targets[1].weight"), "default 1"),
    case("target_weights_all_zero", Vdp, &[Swap("name = \"x1\"\nexpr = \"x1\"", "name = \"x1\"\nexpr = \"x1\"\nweight = 0"), Swap("name = \"x2\"\nexpr = \"x2\"", "name = \"x2\"\nexpr = \"x2\"\nweight = 0.0")], Exact("targets[0].weight"), "above 0"),
    case("target_declared_twice", Vdp, &[Swap("name = \"x2\"\nexpr", "name = \"x1\"\nexpr")], Exact("targets[1].name"), "its own name"),
    case("target_expr_syntax", Vdp, &[Swap("expr = \"x2\"", "expr = \"x2)\"")], Exact("targets[1].expr"), "exmex syntax"),
    case("target_expr_minus_before_power", Vdp, &[Swap("name = \"x1\"\nexpr = \"x1\"", "name = \"x1\"\nexpr = \"-x1^2\"")], Exact("targets[0].expr"), "-(x1^…)"),
    case("target_expr_unknown_variable", E05, &[Swap("expr = \"mu*X\"", "expr = \"mu*Y\"")], Exact("targets[1].expr"), "declare `Y`"),

    // ---- validate.rs `family`.
    case("family_name_upper_case", E05, &[Swap("name = \"ecoli\"", "name = \"E_coli\"")], Exact("family.name"), "lower-case identifier"),
    case("family_name_rust_keyword", E2, &[Swap("name = \"ecoli\"", "name = \"mod\"")], Exact("family.name"), "not a Rust keyword"),
    case("family_name_is_the_design_name", E2, &[Swap("name = \"ecoli\"", "name = \"ecoli_x0_2\"")], Exact("family.name"), "differs from every design name"),
    case("family_name_is_the_design_name_appended", Vdp, &[Append("\n[family]\nname = \"vanderpol\"\noutput = \"y\"\nvalue = 1.0\n")], Exact("family.name"), "differs from every design name"),
    case("family_output_is_a_state", E05, &[Swap("output = \"X_meas\"", "output = \"X\"")], Exact("family.output"), "X_meas, L"),
    case("family_output_unknown", Vdp, &[Append("\n[family]\nname = \"vdp\"\noutput = \"z\"\nvalue = 1.0\n")], Exact("family.output"), "outputs: y"),
    case("family_value_nan", E05, &[Swap("output = \"X_meas\"\nvalue = 0.5", "output = \"X_meas\"\nvalue = nan")], Exact("family.value"), "value of the output"),
    case("family_value_infinite", E2, &[Swap("output = \"X_meas\"\nvalue = 2.0", "output = \"X_meas\"\nvalue = -inf")], Exact("family.value"), "value of the output"),

    // ---- validate.rs `keys_among` for `scenario.x0`, and `scenario`.
    case("scenario_x0_of_no_state", Vdp, &[Swap("x0 = { x1 = 2.0, x2 = 0.5 }", "x0 = { x1 = 2.0, x2 = 0.5, x3 = 0.0 }")], Exact("scenario.x0.x3"), "one initial value per state (x1, x2)"),
    case("scenario_x0_nan", Vdp, &[Swap("x0 = { x1 = 2.0, x2 = 0.5 }", "x0 = { x1 = nan, x2 = 0.5 }")], Exact("scenario.x0.x1"), "finite initial value"),
    case("scenario_x0_missing", Vdp, &[Swap("x0 = { x1 = 2.0, x2 = 0.5 }", "x0 = { x1 = 2.0 }")], Exact("scenario.x0.x2"), "`x2 = …` to `scenario.x0`"),
    case("scenario_shorter_than_horizon", Vdp, &[Swap("samples = 101", "samples = 9")], Exact("scenario.samples"), "≥ `map.horizon`"),
    case("scenarios_one_unnamed", Vdp, &[Swap("[scenario]", "[[scenario]]\nname = \"paper\""), Append("\n[[scenario]]\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n")], Exact("scenario[1].name"), "give each `[[scenario]]` a `name`"),
    case("scenarios_same_name", Vdp, &[Swap("[scenario]", "[[scenario]]\nname = \"paper\""), Append("\n[[scenario]]\nname = \"paper\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n")], Exact("scenario[1].name"), "a name of its own"),
    case("scenarios_name_not_an_identifier", Vdp, &[Swap("[scenario]", "[[scenario]]\nname = \"start up\"")], Exact("scenario[0].name"), "letters, digits and `_`"),
    case("scenarios_second_x0_missing", Vdp, &[Swap("[scenario]", "[[scenario]]\nname = \"a\""), Append("\n[[scenario]]\nname = \"b\"\nx0 = { x1 = 0.0 }\nsamples = 50\nseed = 8\n")], Exact("scenario[1].x0.x2"), "`x2 = …` to `scenario[1].x0`"),
    case("scenarios_second_too_short", Vdp, &[Swap("[scenario]", "[[scenario]]\nname = \"a\""), Append("\n[[scenario]]\nname = \"b\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 5\nseed = 8\n")], Exact("scenario[1].samples"), "`scenario[1].samples` ≥ `map.horizon`"),
    case("scenarios_seed_is_the_tuning_seed", Vdp, &[Swap("[scenario]", "[[scenario]]\nname = \"a\""), Append("\n[[scenario]]\nname = \"b\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 3\n")], Exact("tuning.seed"), "choose another seed"),
    case("scenarios_too_many", Vdp, &[Swap("[scenario]", "[[scenario]]\nname = \"a\""), Append("\n[[scenario]]\nname = \"b\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n\n[[scenario]]\nname = \"c\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n\n[[scenario]]\nname = \"d\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n\n[[scenario]]\nname = \"e\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n\n[[scenario]]\nname = \"f\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n\n[[scenario]]\nname = \"g\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n\n[[scenario]]\nname = \"h\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n\n[[scenario]]\nname = \"i\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nsamples = 50\nseed = 8\n")], Exact("scenario"), "1 to 8"),
    case("scenario_unknown_field_keeps_its_message", Vdp, &[Swap("samples = 101", "samples = 101\nsteps = 3")], Exact("scenario.steps"), "correct the TOML"),
    case("scenario_shorter_than_horizon_ecoli", E05, &[Swap("samples = 40\nseed = 13", "samples = 2\nseed = 13")], Exact("scenario.samples"), "≥ `map.horizon`"),

    // ---- validate_states.rs: every start inside `[model.bounds]` (a negative concentration).
    case("start_scenario_x0_outside_bounds", E05, &[Swap("x0 = { X = 0.5, S = 3.0, P = 0.1 }", "x0 = { X = 0.5, S = -3.0, P = 0.1 }")], Exact("scenario.x0"), "start `S` within its bounds"),
    case("start_observer_x0_outside_bounds", E05, &[Swap("x0 = { X = 0.5, S = 3.0, P = 0.1 }", "x0 = { X = 0.5, S = 3.0, P = 0.1 }\nobserver_x0 = { X = 0.5, S = 3.0, P = -0.1 }")], Exact("scenario.observer_x0"), "start `P` within its bounds"),
    case("start_filter_x0_outside_bounds", E05, &[Append("\n[observer.ukf]\nx0 = { X = -0.5, S = 3.0, P = 0.1 }\n")], Exact("observer.ukf.x0"), "widen `model.bounds.X`"),
    // ---- filters.rs: `[observer.ekf]`, `[observer.ukf]` (the constants a spec fixes).
    case("filter_x0_of_no_state", Vdp, &[Append("\n[observer.ekf]\nx0 = { x1 = 1.0, x2 = 0.7, x3 = 0.0 }\n")], Exact("observer.ekf.x0.x3"), "one initial value per state (x1, x2)"),
    case("filter_x0_missing", Vdp, &[Append("\n[observer.ukf]\nx0 = { x1 = 1.0 }\n")], Exact("observer.ukf.x0.x2"), "`x2 = …` to `observer.ukf.x0`"),
    case("filter_q_diagonal_missing", Vdp, &[Append("\n[observer.ekf]\nq = { x1 = 1e-3 }\n")], Exact("observer.ekf.q.x2"), "`x2 = …` to `observer.ekf.q`"),
    case("filter_q_diagonal_of_no_state", Vdp, &[Append("\n[observer.ekf]\nq = { x1 = 1e-3, x2 = 1e-3, y = 1.0 }\n")], Exact("observer.ekf.q.y"), "one variance per state"),
    case("filter_q_diagonal_zero", Vdp, &[Append("\n[observer.ekf]\nq = { x1 = 1e-3, x2 = 0.0 }\n")], Exact("observer.ekf.q"), "symmetric positive definite"),
    case("filter_p0_not_square", Vdp, &[Append("\n[observer.ekf]\np0 = [[1.0, 0.0], [0.0]]\n")], Exact("observer.ekf.p0"), "rows in the states' order (x1, x2)"),
    case("filter_p0_not_symmetric", Vdp, &[Append("\n[observer.ukf]\np0 = [[1.0, 0.5], [0.4, 1.0]]\n")], Exact("observer.ukf.p0"), "symmetric positive definite"),
    case("filter_p0_indefinite", Vdp, &[Append("\n[observer.ekf]\np0 = [[1.0, 2.0], [2.0, 1.0]]\n")], Exact("observer.ekf.p0"), "symmetric positive definite"),
    case("filter_q_not_finite", Vdp, &[Append("\n[observer.ekf]\nq = [[1.0, nan], [nan, 1.0]]\n")], Exact("observer.ekf.q"), "symmetric positive definite"),
    case("filter_q_neither_table_nor_rows", Vdp, &[Append("\n[observer.ekf]\nq = 0.1\n")], Exact("observer.ekf.q"), "correct the TOML"),
    case("filter_unknown_constant", Vdp, &[Append("\n[observer.ekf]\nr = { y = 0.2 }\n")], Exact("observer.ekf.r"), "correct the TOML"),

    // ---- validate_chip.rs: `[chip]` and its raw scalings.
    case("chip_raw_of_no_signal", Vdp, &[Swap("raw.y = {", "raw.z = {")], Exact("chip.raw.z"), "outputs or inputs (y)"),
    case("chip_raw_with_float_arithmetic", Vdp, &[Swap("arithmetic = \"fixed\"", "arithmetic = \"float\"")], Exact("chip.raw.y"), "arithmetic = \"fixed\""),
    case("chip_raw_scale_zero", Vdp, &[Swap("scale = 0.005", "scale = 0.0")], Exact("chip.raw.y.scale"), "positive"),
    case("chip_raw_offset_nan", Vdp, &[Swap("offset = -10.24", "offset = nan")], Exact("chip.raw.y.offset"), "value at a raw reading of 0"),
    case("chip_raw_beyond_24_bits", Vdp, &[Swap("max = 4095", "max = 16777217")], Exact("chip.raw.y.max"), "at most 24 bits"),
    // `i64::MIN` used to wrap through `abs` and pass, read as 0.
    case("chip_raw_min_of_i64", Vdp, &[Swap("min = 0, max = 4095", "min = -9223372036854775808, max = 4095")], Exact("chip.raw.y.min"), "at most 24 bits"),
    case("chip_raw_empty_range", Vdp, &[Swap("min = 0, max = 4095", "min = 4095, max = 4095")], Exact("chip.raw.y.max"), "`min` below `max`"),
];

/// Applies the case's edits; each find-string must occur exactly once in the text it edits.
fn edited(case: &Case) -> Result<String, String> {
    let mut text = case.base.text().to_owned();
    for edit in case.edits {
        match *edit {
            Swap(find, with) => {
                let count = text.matches(find).count();
                if count != 1 {
                    return Err(format!(
                        "the edit's find-string {find:?} occurs {count} times (must be once)"
                    ));
                }
                if find == with {
                    return Err(format!("the edit of {find:?} changes nothing"));
                }
                text = text.replacen(find, with, 1);
            }
            Append(more) => text.push_str(more),
        }
    }
    Ok(text)
}

/// `Ok` when the case's spec is refused with the expected field and fix, else what went wrong.
fn check(case: &Case) -> Result<(), String> {
    let (path, result) = match case.base {
        NoFile => {
            let path = std::env::temp_dir()
                .join(format!("host-spec-errors-{}", std::process::id()))
                .join(format!("{}.toml", case.name));
            let result = catch_unwind(AssertUnwindSafe(|| spec::load(&path)));
            (path, result)
        }
        _ => {
            let text = edited(case)?;
            let path = PathBuf::from(format!("{}.toml", case.name));
            let result = catch_unwind(AssertUnwindSafe(|| spec::parse(&path, &text)));
            (path, result)
        }
    };
    let error: SpecError = match result {
        Err(_) => return Err("the validator panicked".into()),
        Ok(Ok(_)) => return Err("the spec was accepted".into()),
        Ok(Err(e)) => e,
    };
    let message = error.to_string();
    let file = path.display().to_string();
    let (field_ok, wanted) = match case.field {
        Exact(f) => (error.field == f, format!("field {f:?}")),
        Prefix(f) => (error.field.starts_with(f), format!("a field starting with {f:?}")),
    };
    let mut problems = Vec::new();
    if !field_ok {
        problems.push(format!("names field {:?}, expected {wanted}", error.field));
    }
    if error.file != file || !message.contains(&file) {
        problems.push(format!("does not name the file {file:?}"));
    }
    if !message.contains(&format!("`{}`", error.field)) {
        problems.push("the message does not name the field".into());
    }
    if !message.contains("fix:") || error.fix.trim().is_empty() || error.problem.trim().is_empty() {
        problems.push("the message has an empty problem or no fix".into());
    }
    if !error.fix.contains(case.fix) {
        problems.push(format!("the fix does not mention {:?}", case.fix));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "{}\n      message: {}",
            problems.join("; "),
            message.replace('\n', "\n      ")
        ))
    }
}

#[test]
fn every_validator_error_names_its_field_and_a_fix() {
    let mut names = HashSet::new();
    let mut failures = Vec::new();
    for case in CASES {
        assert!(names.insert(case.name), "two cases are named {:?}", case.name);
        if let Err(why) = check(case) {
            failures.push(format!("  {} ({:?}): {why}", case.name, case.base));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        CASES.len(),
        failures.join("\n")
    );
}

#[test]
fn the_shipped_specs_are_valid() {
    for (name, text) in [
        ("vanderpol.toml", VANDERPOL),
        ("ecoli_x0_0p5.toml", ECOLI_X0_0P5),
        ("ecoli_x0_2.toml", ECOLI_X0_2),
    ] {
        if let Err(e) = spec::parse(Path::new(name), text) {
            panic!("the base of the table must be valid: {e}");
        }
    }
    // Every spec shipped in host/specs, so a new one joins the check.
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("specs");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            count += 1;
            if let Err(e) = spec::load(&path) {
                panic!("{e}");
            }
        }
    }
    assert!(count >= 3, "{count} specs in {}", dir.display());
}

/// exmex reads `E`, `e`, `PI`, `TAU` as constants and `sin`, `exp`, … as functions, so a parameter
/// with one of these names used to be accepted and then silently ignored by every expression using it
/// (`E*x1` was 2.718·x1, whatever `E` was set to). Such names are refused where they are declared.
#[test]
fn names_the_expression_language_reserves_are_refused_where_declared() {
    for name in ["E", "e", "PI", "TAU", "sin", "exp", "ln"] {
        let text = VANDERPOL.replacen(
            "[model.derivatives]",
            &format!("[model.parameters]\n{name} = 5.0\n\n[model.derivatives]"),
            1,
        );
        assert_ne!(text, VANDERPOL, "the edit must apply");
        match spec::parse(Path::new("constant.toml"), &text) {
            Ok(_) => panic!("a parameter named `{name}` was accepted"),
            Err(e) => {
                assert_eq!(e.field, format!("model.parameters.{name}"), "{e}");
                assert!(
                    e.problem.contains("expression language") && e.fix.contains("rename"),
                    "{e}"
                );
            }
        }
    }
    // The check is not over-eager: names that merely contain an operator's name are fine.
    let text = VANDERPOL.replacen(
        "[model.derivatives]",
        "[model.parameters]\nE0 = 5.0\nexponent = 2.0\n\n[model.derivatives]",
        1,
    );
    spec::parse(Path::new("constant.toml"), &text).unwrap();
}

/// An expression longer than `MAX_EXPRESSION_CHARS` is refused with a way out: exmex evaluates a long
/// expression in more than linear time (a 10 000-term derivative took minutes to simulate).
#[test]
fn an_overlong_expression_is_refused_naming_its_field() {
    let long = (0..1200)
        .map(|i| format!("x{}", 1 + i % 2))
        .collect::<Vec<_>>()
        .join(" + ");
    let text = VANDERPOL.replacen("x1 = \"-x2\"", &format!("x1 = \"-x2 + 0*({long})\""), 1);
    assert_ne!(text, VANDERPOL);
    let error = spec::parse(Path::new("long.toml"), &text).unwrap_err();
    assert_eq!(error.field, "model.derivatives.x1", "{error}");
    assert!(
        error.problem.contains("longer than the limit") && error.fix.contains("model.definitions"),
        "{error}"
    );
    // The same sum in four definitions of 300 terms each is accepted.
    let part = (0..300)
        .map(|i| format!("x{}", 1 + i % 2))
        .collect::<Vec<_>>()
        .join(" + ");
    let definitions: String = (0..4)
        .map(|k| format!("\n[[model.definitions]]\nname = \"part{k}\"\nexpr = \"{part}\"\n"))
        .collect();
    let text = VANDERPOL.replacen("x1 = \"-x2\"", "x1 = \"-x2 + 0*(part0 + part1 + part2 + part3)\"", 1);
    let text = text.replacen("[model.derivatives]", &format!("{definitions}\n[model.derivatives]"), 1);
    spec::parse(Path::new("split.toml"), &text).unwrap();
}

/// Numbers in messages read as numbers: `1e308`, not a 309-digit decimal.
#[test]
fn huge_numbers_in_messages_are_in_scientific_notation() {
    let text = VANDERPOL.replacen("min = -5.0, max = 5.0", "min = -1e308, max = 1e308", 1);
    let error = spec::parse(Path::new("huge.toml"), &text).unwrap_err().to_string();
    assert!(error.contains("[-1e308, 1e308]") && error.len() < 400, "{error}");
    assert_eq!(spec::readable(1e308), "1e308");
    assert_eq!(spec::readable(2.5e-7), "2.5e-7");
    assert_eq!(spec::readable(0.25), "0.25");
    assert_eq!(spec::readable(-1234.5), "-1234.5");
}

/// `"auto"` and lists in `[map]` become the search's candidates (sorted, without repeats), the fitted
/// settings holding the largest `N`; one value each is no search.
#[test]
fn map_choices_become_the_search_candidates() {
    let path = Path::new("vanderpol.toml");
    let fixed = spec::parse(path, VANDERPOL).unwrap();
    assert_eq!(fixed.search, None);
    let text = VANDERPOL.replacen("horizon = 10 ", "horizon = \"auto\" ", 1).replacen(
        "beta = 0.5 ",
        "beta = [2, 0.5, 0.5, 1.0] ",
        1,
    );
    let searched = spec::parse(path, &text).unwrap();
    let search = searched.search.expect("a search");
    assert_eq!(search.horizons, (5..=40).collect::<Vec<_>>());
    assert_eq!(search.nms, [5]);
    assert_eq!(search.betas, [0.5, 1.0, 2.0]);
    assert_eq!(search.candidates().len(), 36 * 3);
    assert_eq!(search.candidates()[0], (5, 5, 0.5));
    assert_eq!(searched.map.horizon, 40);
    let budget = spec::parse(
        path,
        &format!("{VANDERPOL}\n[budget]\ninstructions = 150\nfirst_estimate = 1.5\n"),
    )
    .unwrap()
    .budget;
    assert_eq!(
        (budget.instructions, budget.first_estimate, budget.flash),
        (Some(150), Some(1.5), None)
    );
    // One tap count is a setting, not a search; a list or "auto" is searched.
    let taps = |value: &str| {
        spec::parse(
            path,
            &VANDERPOL.replacen("beta = 0.5 ", &format!("beta = 0.5\ntaps = {value} "), 1),
        )
        .unwrap()
    };
    let one = taps("6");
    assert_eq!((one.map.taps, one.search), (Some(6), None));
    let listed = taps("[8, 4, 8]").search.expect("a search over taps");
    assert_eq!(listed.taps, spec::Taps::Counts(vec![4, 8]));
    assert_eq!(listed.taps.for_regressor(10), [8, 4]);
    assert_eq!(listed.taps.for_regressor(6), [6, 4]);
    assert_eq!(
        taps("\"auto\"").search.expect("a search").taps.for_regressor(10),
        [10, 8, 6, 5, 4, 3]
    );
    assert_eq!(fixed.map.taps, None);
}

#[test]
fn a_filters_fixed_constants_are_read_in_state_order_and_a_start_outside_the_box_is_warned() {
    use host::plant::Covariance;
    let text = format!(
        "{VANDERPOL}\n[observer.ekf]\nx0 = {{ x2 = 0.7, x1 = 3.0 }}\nq = {{ x2 = 2e-3, x1 = 1e-3 }}\np0 = [[1.0, 0.3], [0.3, 4.0]]\n"
    );
    let design = spec::parse(Path::new("fixed.toml"), &text).unwrap();
    let ekf = design.filters.of("observer.ekf");
    assert_eq!(ekf.x0, Some(vec![3.0, 0.7]));
    assert_eq!(ekf.q, Some(Covariance::Diagonal(vec![1e-3, 2e-3])));
    assert_eq!(ekf.p0, Some(Covariance::Full(vec![vec![1.0, 0.3], vec![0.3, 4.0]])));
    assert_eq!(ekf.fixed(), ["x0", "q", "p0"]);
    assert!(
        !design.filters.of("observer.ukf").any(),
        "the UKF's constants stay tuned"
    );
    // x1 = 3 is outside the learning box [−2, 2]; x2 = 0.7 inside [−5, 5]; the scenario's
    // `observer_x0` (1, 0.7) inside: one warning.
    let gates = host::report::gates::starts_outside_box(&design);
    assert_eq!(gates.len(), 1, "{gates:?}");
    let message = gates[0].to_string();
    assert!(
        message.contains("`observer.ekf.x0.x1` = 3") && message.contains("[-2, 2]"),
        "{message}"
    );
    // The same start inside the box: no warning.
    let inside = text.replace("x1 = 3.0 }", "x1 = 2.0 }");
    let design = spec::parse(Path::new("fixed.toml"), &inside).unwrap();
    assert!(host::report::gates::starts_outside_box(&design).is_empty());
    // The scenario's `observer_x0` is checked too.
    let scenario = VANDERPOL.replacen(
        "observer_x0 = { x1 = 1.0, x2 = 0.7 }",
        "observer_x0 = { x1 = 1.0, x2 = -7.0 }",
        1,
    );
    let design = spec::parse(Path::new("scenario.toml"), &scenario).unwrap();
    let gates = host::report::gates::starts_outside_box(&design);
    assert_eq!(gates.len(), 1, "{gates:?}");
    assert!(
        gates[0].to_string().contains("`scenario.observer_x0.x2` = -7"),
        "{}",
        gates[0]
    );
    // And every named scenario's, not only the first's.
    let named = VANDERPOL.replacen("[scenario]", "[[scenario]]\nname = \"paper\"", 1)
        + "\n[[scenario]]\nname = \"b\"\nx0 = { x1 = 0.0, x2 = 0.0 }\nobserver_x0 = { x1 = 0.0, x2 = 9.0 }\nsamples = 50\nseed = 8\n";
    let design = spec::parse(Path::new("named.toml"), &named).unwrap();
    let gates = host::report::gates::starts_outside_box(&design);
    assert_eq!(gates.len(), 1, "{gates:?}");
    assert!(
        gates[0].to_string().contains("`scenario[1].observer_x0.x2` = 9"),
        "{}",
        gates[0]
    );
}

#[test]
fn the_literature_example_fixes_the_published_filter_and_is_warned_of_its_start() {
    // examples/specs/gas_phase_reactor.toml: Haseltine & Rawlings' EKF, x̂(0) = (0.1, 4.5),
    // Q = diag(0.001², 0.001²), P(0) = diag(6², 6²), written by hand here from the paper.
    use host::plant::Covariance;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/specs/gas_phase_reactor.toml");
    let design = spec::load(&path).unwrap();
    let ekf = design.filters.of("observer.ekf");
    assert_eq!(ekf.x0, Some(vec![0.1, 4.5]));
    assert_eq!(ekf.q, Some(Covariance::Diagonal(vec![1e-6, 1e-6])));
    assert_eq!(ekf.p0, Some(Covariance::Diagonal(vec![36.0, 36.0])));
    // pB = 4.5 lies above the learning box [0, 4], for the filter and for the scenario's guess.
    let gates: Vec<String> = host::report::gates::starts_outside_box(&design)
        .iter()
        .map(ToString::to_string)
        .collect();
    assert_eq!(gates.len(), 2, "{gates:?}");
    assert!(gates[0].contains("`observer.ekf.x0.pB` = 4.5"), "{}", gates[0]);
    assert!(gates[1].contains("`scenario.observer_x0.pB` = 4.5"), "{}", gates[1]);
}

#[test]
fn the_four_tank_example_loads_with_its_bounds_and_its_tuning_starts_on_the_box() {
    // examples/specs/quadruple_tank.toml: Johansson's quadruple tank, the levels bounded below by 0,
    // the box [4, 20]² × [0.2, 6]² (written by hand here from the file).
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/specs/quadruple_tank.toml");
    let design = spec::load(&path).unwrap();
    assert_eq!(design.state_bounds.len(), 4);
    assert!(design
        .state_bounds
        .iter()
        .all(|b| b.min == Some(0.0) && b.max.is_none()));
    // 2 n + min(2ⁿ, 16) edge starts for n = 4 states with a range: 8 + 16, the upper tanks' lower
    // edge 0.2 cm above their bound.
    use rand::SeedableRng;
    let starts = host::data::edge_starts(&design, &mut rand_chacha::ChaCha8Rng::seed_from_u64(1));
    assert_eq!(starts.len(), 24);
    assert!(
        starts.iter().any(|x0| x0[2] == 0.2 && x0[3] == 0.2),
        "a corner with both upper tanks at 0.2 cm"
    );
}
