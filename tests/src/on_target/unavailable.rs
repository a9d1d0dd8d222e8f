//! Why a measurement could not be made, and the checks for the tools it needs: every step below
//! reports a missing tool as [`Unavailable::Missing`] so that a test can skip instead of fail.

use std::process::{Command, Stdio};

/// Why the on-target measurements could not be made.
#[derive(Debug)]
pub enum Unavailable {
    /// A tool is missing: its name and the Debian package that provides it.
    Missing {
        /// The command.
        tool: &'static str,
        /// The package to install.
        package: &'static str,
    },
    /// Something failed that should not have.
    Failed(String),
}

impl std::fmt::Display for Unavailable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Unavailable::Missing { tool, package } => {
                write!(
                    f,
                    "`{tool}` is not installed (Debian package `{package}`: apt-get install {package})"
                )
            }
            Unavailable::Failed(message) => f.write_str(message),
        }
    }
}

pub(super) fn failed(message: impl Into<String>) -> Unavailable {
    Unavailable::Failed(message.into())
}

pub(super) fn require(tool: &'static str, package: &'static str) -> Result<(), Unavailable> {
    match Command::new(tool)
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
    {
        Ok(status) if status.success() => Ok(()),
        _ => Err(Unavailable::Missing { tool, package }),
    }
}

/// QEMU and binutils, or which is missing.
pub(super) fn require_tools() -> Result<(), Unavailable> {
    require_emulator()?;
    require("arm-none-eabi-objdump", "binutils-arm-none-eabi")
}

/// QEMU (to run a program, [`run_on_emulator`](super::run_on_emulator)) and `arm-none-eabi-size` (to measure it,
/// [`sizes`](super::sizes)),
/// or which is missing.
pub fn require_emulator() -> Result<(), Unavailable> {
    require("qemu-system-arm", "qemu-system-arm")?;
    require("arm-none-eabi-size", "binutils-arm-none-eabi")
}
