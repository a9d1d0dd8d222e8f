//! The cross-crate tests, one binary: one module per subject, each in its own file here. In one
//! process the designs the modules share are fitted once (`integration_tests::build`,
//! `integration_tests::settled` keep them per process). `cargo test -p integration-tests --test
//! integration NAME` runs the tests whose path contains `NAME`: a module's name runs that module
//! (`--test integration layout`).

/// The fixture whose tables have searched knots (see `integration_tests::SEARCHED_FIXTURE_SPEC`),
/// compiled once for the modules that check it.
#[rustfmt::skip]
#[path = "../../fixtures/vanderpol_beta7.rs"]
#[allow(dead_code)]
mod vanderpol_beta7;

mod board_example;
mod c_source;
mod design_search;
mod example1;
mod example2;
mod fixed_point;
mod generated_followers;
mod generated_is_current;
mod generated_mhe;
mod generated_model;
mod generated_units;
mod generated_vs_library;
mod inverse_table;
mod layout;
mod lost_samples;
mod observer_contract;
mod observer_tuning;
mod on_target;
mod on_target_m0;
mod plot_cli;
mod quality_gates;
mod readme;
mod refusals;
mod report_html;
mod saved_tables;
mod standalone;
mod watch;
