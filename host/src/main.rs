//! `mho`: the command line of the design-time tool (off-line moving-horizon observers). It parses
//! the arguments and runs them ([`host::cli`]); errors end it with a message and a non-zero status.

use std::process::ExitCode;

use clap::Parser;

use host::cli::{self, args::Cli};

fn main() -> ExitCode {
    match cli::run(Cli::parse().command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {}", cli::message(&error));
            ExitCode::FAILURE
        }
    }
}
