//! Errors of the binary and the exit codes they map to.

use penner::uniformization::pipeline::PipelineError;
use std::path::PathBuf;

/// Exit codes (README.md, docs/oracle.md).
pub mod code {
    /// Every check holds (or does not apply); the claim holds.
    pub const HOLDS: u8 = 0;
    /// A check fails; the claim is refuted.
    pub const FAILS: u8 = 1;
    /// A check or the claim is undecided (and nothing fails).
    pub const UNDECIDED: u8 = 2;
    /// Bad input: unreadable or malformed file, bad argument.
    pub const BAD_INPUT: u8 = 3;
    /// An output file could not be written (e.g. it already exists).
    pub const OUTPUT: u8 = 4;
    /// A defect inside penner (a check broke); please report it.
    pub const INTERNAL: u8 = 5;
}

/// An error that ends the command.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Bad input: the message names the file, line or element.
    #[error("{0}")]
    Input(String),
    /// A computation on valid input did not converge or could not be refined: undecided
    /// (exit 2), with what stalled.
    #[error("{0}")]
    NotConverged(String),
    /// A file could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// An output file could not be created or written.
    #[error("cannot write {}: {reason}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// Why.
        reason: String,
    },
}

impl CliError {
    /// The exit code of this error.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Input(_) | CliError::Read { .. } => code::BAD_INPUT,
            CliError::Write { .. } => code::OUTPUT,
            CliError::NotConverged(_) => code::UNDECIDED,
        }
    }
}

/// A pipeline error as the CLI reports it: the input's fault (bad input, exit 3) or a
/// computation of penner's own that did not go through (undecided, exit 2).
pub(crate) fn pipeline_error(shown: &str, e: &PipelineError) -> CliError {
    if e.is_bad_input() {
        CliError::Input(format!("{shown}: {e}"))
    } else {
        CliError::NotConverged(format!("{shown}: {e}"))
    }
}
