//! `penner uniformize SURFACE --hyperbolic [--targets FILE] [--precision P] [-o RESULT.json]`:
//! the report of [`penner::uniformization::pipeline::uniformize_hyperbolic`] (notes Thm 11;
//! B38, B39, B87, B89, B104). With `-o`, a certified result is written as a
//! `hyperbolic_uniformization` claim that `penner certify` re-checks from scratch.

use super::certificate_report::write_claim;
use super::error::{code, CliError};
use super::files::emit;
use penner::uniformization::hyperbolic::HyperbolicStop;
use penner::uniformization::hyperbolic_certificate::Existence;
use penner::uniformization::pipeline::{CertifiedMetric, HyperbolicOutcome, Precision};
use std::fmt::Write as _;
use std::path::Path;

/// Print the outcome of `penner uniformize --hyperbolic` and write its claim to `output`.
pub fn report(
    shown: &str,
    outcome: &HyperbolicOutcome,
    precision: Precision,
    output: Option<&Path>,
) -> Result<u8, CliError> {
    let sol = &outcome.solution;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{shown}: hyperbolic target (lengths read as hyperbolic lengths): {} geometric flips to hyperbolic Delaunay, {} Newton steps, {} Ptolemy flips, max |Θ − θ| = {:e} (f64)",
        sol.input_flips.len(),
        sol.steps.len(),
        sol.flips.len(),
        sol.residual_max
    );
    if !sol.converged() {
        let why = match &sol.stop {
            HyperbolicStop::Degenerate(reason) => {
                format!("degenerate along the Newton path even after flips: {reason}")
            }
            other => format!("{other:?}"),
        };
        let _ = writeln!(out, "not converged: {why}; no certificate");
        emit(&out)?;
        return Ok(code::UNDECIDED);
    }
    let bits = outcome.bits;
    if let (Some((_, refined)), Some(cert)) = (&outcome.refined, &outcome.certificate) {
        let _ = writeln!(out, "refined ({precision}): max |Θ − θ| = {refined:e}");
        let _ = writeln!(
            out,
            "certified ({bits}-bit intervals): max |Θ − θ(u)| ≤ {:e}, ‖Θ − θ(u)‖₂ ≤ {:e}",
            cert.residual_max, cert.residual_norm2
        );
    }
    let about = match &outcome.metric {
        CertifiedMetric::Input => " for the input's exact metric".to_string(),
        CertifiedMetric::Rounded { reason } => {
            format!(" for the binary64-rounded lengths of the input ({reason})")
        }
    };
    let status = match outcome.certificate.as_ref().map(|c| &c.existence) {
        Some(Existence::Holds {
            distance,
            mu,
            radius,
        }) => {
            let _ = writeln!(
                out,
                "certified{about}: an exact solution lies within {distance:e} (2-norm) of u (Hessian ≥ {mu:e} on the box of radius {radius:e}, B39)"
            );
            code::HOLDS
        }
        Some(Existence::Undecided { reason }) => {
            let _ = writeln!(out, "existence not certified: {reason}");
            code::UNDECIDED
        }
        None => {
            out.push_str(&super::uniformize_options::numerical_line(sol.residual_max));
            code::UNDECIDED
        }
    };
    let _ = writeln!(
        out,
        "numerical: total area by L'Huilier = {}, Gauss–Bonnet Σ(2π − Θ) − 2πχ = {}",
        outcome
            .area
            .map_or("undefined".to_string(), |a| a.to_string()),
        outcome.gauss_bonnet
    );
    if let Some(path) = output {
        let what = match (&outcome.metric, outcome.claim_metric()) {
            (CertifiedMetric::Input, CertifiedMetric::Rounded { .. }) => {
                "certificate of the binary64-rounded lengths (the claim form's)"
            }
            _ => "certificate",
        };
        write_claim(&mut out, path, outcome.claim(), what)?;
    }
    emit(&out)?;
    Ok(status)
}
