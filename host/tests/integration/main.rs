//! The `host` crate's tests of its command line and library from outside, one binary: one module
//! per subject, each in its own file here. `cargo test -p host --test integration NAME` runs the
//! tests whose path contains `NAME` (a module's name runs that module: `--test integration fuzz`).

mod bad_input;
mod c_header_text;
mod cli;
mod crate_ownership;
mod estimate_cli;
mod fuzz;
mod generate;
mod plot_long;
mod search_bound;
mod spec_errors;
