//! `penner certify CLAIM`: answer a JSON claim (protocol v1) with a JSON verdict.

use super::error::{code, CliError};
use super::files::{emit, read_text};
use penner::oracle::certify::{certify, ClaimVerdict};
use penner::oracle::claim;
use serde_json::json;
use std::path::Path;

/// Print a machine-readable refusal on stdout (the human message goes to stderr through
/// the returned error); when that answer cannot be written, the write error is returned.
fn refuse(e: CliError) -> CliError {
    let written = emit(&format!(
        "{:#}\n",
        json!({
            "penner_answer": claim::PROTOCOL_VERSION,
            "verdict": "bad_input",
            "error": e.to_string(),
        })
    ));
    match written {
        Ok(()) => e,
        Err(w) => w,
    }
}

/// Run `penner certify`.
pub fn run(path: &Path) -> Result<u8, CliError> {
    let text = read_text(path).map_err(refuse)?;
    let name = path.display().to_string();
    let c = claim::parse(&text, &name).map_err(|e| refuse(CliError::Input(e.to_string())))?;
    let answer = certify(&c).map_err(|e| refuse(CliError::Input(format!("{name}: {e}"))))?;
    emit(&format!("{:#}\n", answer.to_json()))?;
    Ok(match answer.verdict {
        ClaimVerdict::Holds => code::HOLDS,
        ClaimVerdict::Refuted => code::FAILS,
        ClaimVerdict::Undecided => code::UNDECIDED,
    })
}
