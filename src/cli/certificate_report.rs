//! The certificate lines of `penner uniformize`'s reports and the claim file written with
//! `-o` (never over an existing file).

use super::error::{code, CliError};
use super::files::create_new;
use penner::uniformization::certificate::CertificateOutcome;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::Path;

/// The words of [`report_certificate`]'s lines: what a certified result is called and what
/// the written claim is called (the closed surface's, or the double's with its copy 1).
pub(super) struct Certified<'a> {
    /// Prefix of the certified line.
    pub holds: &'a str,
    /// Name of the written claim, up to " written to".
    pub written: &'a str,
}

/// Report a B71 certificate outcome on `out` and, when it holds and `output` is given,
/// write the `uniformization` claim there (never over an existing file); the exit status:
/// `HOLDS` when certified, `UNDECIDED` otherwise.
pub(super) fn report_certificate<C: serde::Serialize>(
    out: &mut String,
    outcome: &CertificateOutcome,
    claim: Option<C>,
    output: Option<&Path>,
    words: &Certified<'_>,
) -> Result<u8, CliError> {
    let status = match outcome {
        CertificateOutcome::Holds {
            distance,
            mu,
            residual,
        } => {
            let _ = writeln!(
                out,
                "{}: an exact solution lies within {distance:e} (2-norm) of u; Hessian ≥ {mu:e} on the box; ‖Θ − θ(u)‖₂ ≤ {residual:e}",
                words.holds
            );
            code::HOLDS
        }
        CertificateOutcome::Undecided { reason } => {
            let _ = writeln!(out, "not certified: {reason}");
            code::UNDECIDED
        }
    };
    if let Some(path) = output {
        let claim = claim.filter(|_| status == code::HOLDS);
        write_claim(out, path, claim, words.written)?;
    }
    Ok(status)
}

/// Write `claim` to `path` (pretty JSON, never over an existing file) and say so on `out`
/// as "`what` written to …", or say that no certificate was written when there is none.
pub(super) fn write_claim<C: serde::Serialize>(
    out: &mut String,
    path: &Path,
    claim: Option<C>,
    what: &str,
) -> Result<(), CliError> {
    let Some(claim) = claim else {
        out.push_str("no certificate written\n");
        return Ok(());
    };
    // Streamed into the file: the text of a 10⁵-face claim (about 50 MB) is never held
    // in memory, nor (for a view such as `ClaimJson`) the claim's value tree. The bytes
    // are those of `to_string_pretty`.
    let mut w = std::io::BufWriter::new(create_new(path)?);
    serde_json::to_writer_pretty(&mut w, &claim)
        .map_err(std::io::Error::from)
        .and_then(|()| w.write_all(b"\n"))
        .and_then(|()| w.flush())
        .map_err(|e| CliError::Write {
            path: path.to_path_buf(),
            reason: e.to_string(),
        })?;
    let _ = writeln!(
        out,
        "{what} written to {} (re-check: penner certify {})",
        path.display(),
        path.display()
    );
    Ok(())
}
