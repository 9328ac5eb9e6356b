//! `penner uniformize SURFACE [--targets FILE | --flat] [--precision P] [-o cert.json]`:
//! discrete uniformization with Ptolemy flips (T24), refined and certified (B71); the
//! certificate is written as a `uniformization` claim that `penner certify` re-checks.

use super::error::{code, CliError};
use super::files::{create_new, read_text};
use super::input::{load_flip_case, FlipCase};
use penner::io::json::exact_number;
use penner::uniformization::certificate::CertificateOutcome;
use penner::uniformization::pipeline::{
    rescaled, uniformize_closed, CertifiedMetric, ClosedOutcome, Options as ClosedOptions,
    PipelineError, Precision,
};
use penner::uniformization::Targets;
use std::fmt::Write as _;
use std::io::{IsTerminal, Write};
use std::path::Path;

/// Options of `penner uniformize`.
pub struct Options<'a> {
    /// The surface file.
    pub path: &'a Path,
    /// Targets file (JSON array of Θ_i/π).
    pub targets: Option<&'a Path>,
    /// Flat targets.
    pub flat: bool,
    /// `f64`, `dd` or MPFR bits.
    pub precision: &'a str,
    /// Certificate output.
    pub output: Option<&'a Path>,
    /// `--sphere`, `--pole`, `--obj`, `--svg`.
    pub extra: &'a super::args::UniformizeExtra,
}

/// Interval bits and refinement tolerance of a precision word ([`Precision`]).
fn bits_and_tolerance(p: &str) -> Result<(u32, f64), CliError> {
    p.parse::<Precision>()
        .map(Precision::bits_and_tolerance)
        .map_err(|e| CliError::Input(format!("--precision: {e}")))
}

pub(super) fn read_targets(path: &Path, n: usize) -> Result<Targets, CliError> {
    let shown = path.display().to_string();
    let text = read_text(path)?;
    let v: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| CliError::Input(format!("{shown}:{}:{}: {e}", e.line(), e.column())))?;
    let arr = v.as_array().ok_or_else(|| {
        CliError::Input(format!(
            "{shown}: expected a JSON array of Θ_i/π, one per vertex"
        ))
    })?;
    if arr.len() != n {
        return Err(CliError::Input(format!(
            "{shown}: {} targets for {n} vertices (one Θ_i/π per vertex)",
            arr.len()
        )));
    }
    let q = arr
        .iter()
        .enumerate()
        .map(|(i, x)| {
            exact_number(x, &format!("[{i}]")).map_err(|e| CliError::Input(format!("{shown}: {e}")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Targets::from_multiples_of_pi(q))
}

/// Run `penner uniformize`.
#[allow(clippy::too_many_lines)] // solve, refine, certify and write, in order
pub fn run(o: &Options<'_>) -> Result<u8, CliError> {
    let (bits, tolerance) = bits_and_tolerance(o.precision)?;
    let shown = o.path.display().to_string();
    let case = load_flip_case(o.path)?;
    if o.extra.hyperbolic {
        return super::uniformize_hyperbolic::run(&shown, &case, o, bits, tolerance);
    }
    if o.extra.sphere {
        let (surface, shift) = rescaled(&into_surface(case));
        let lengths = surface.lengths::<f64>(());
        let precision = match o.precision {
            "f64" => super::uniformize_sphere::SpherePrecision {
                bits,
                refine: false,
                tolerance,
            },
            "dd" => return Err(CliError::Input(
                "--precision dd is not implemented for --sphere; use f64 or MPFR bits (128..=4096)"
                    .into(),
            )),
            _ => super::uniformize_sphere::SpherePrecision {
                bits,
                refine: true,
                tolerance,
            },
        };
        return super::uniformize_sphere::run(
            &shown, &surface, &lengths, shift, &precision, o.output, o.extra,
        );
    }
    if !case.mesh().is_closed() {
        let (surface, shift) = rescaled(&into_surface(case));
        let lengths = surface.lengths::<f64>(());
        let input = super::uniformize_boundary::Input {
            shown: &shown,
            surface: &surface,
            mesh: &surface.mesh,
            lengths: &lengths,
            shift,
            bits,
        };
        return super::uniformize_boundary::run(&input, o);
    }
    let surface = into_surface(case);
    let targets =
        match (o.targets, o.flat) {
            (Some(_), true) => {
                return Err(CliError::Input(
                    "give either --targets FILE or --flat, not both".into(),
                ))
            }
            (Some(p), false) => read_targets(p, surface.mesh.n_vertices())?,
            (None, true) => Targets::flat(surface.mesh.n_vertices()),
            (None, false) => return Err(CliError::Input(
                "the target angles are required: --targets FILE (a JSON array of Θ_i/π) or --flat"
                    .into(),
            )),
        };
    let bar = std::io::stderr().is_terminal().then(|| {
        let b = indicatif::ProgressBar::new_spinner();
        b.set_message(format!(
            "uniformizing {shown} ({} faces)",
            surface.mesh.n_faces()
        ));
        b.enable_steady_tick(std::time::Duration::from_millis(120));
        b
    });
    let mut progress = |s: &penner::uniformization::StepReport| {
        if let Some(b) = &bar {
            b.set_message(format!(
                "Newton step {}: max |Θ − θ| = {:.3e}, {} flips",
                s.iteration, s.residual_max, s.flips
            ));
        }
    };
    let options = ClosedOptions {
        precision: o.precision.parse::<Precision>().map_err(CliError::Input)?,
        certify: true,
    };
    let outcome =
        uniformize_closed(&surface, &targets, &options, &mut progress).map_err(|e| match e {
            PipelineError::Input(e) => CliError::Input(format!("{shown}: {e}")),
            PipelineError::Certificate(e) => certificate_error(&shown, e),
        })?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    report_closed(&shown, &outcome, o)
}

/// The report of [`uniformize_closed`]'s outcome, the SVG and the claim written.
fn report_closed(shown: &str, outcome: &ClosedOutcome, o: &Options<'_>) -> Result<u8, CliError> {
    let sol = &outcome.solution;
    let bits = outcome.bits;
    let mut out = String::new();
    if outcome.shift != 0 {
        let _ = writeln!(
            out,
            "{shown}: lengths divided by 2^{} (exactly) before solving: the cone angles and u do not change with the scale, and the certificate is about the rescaled surface",
            outcome.shift
        );
    }
    let _ = writeln!(
        out,
        "{shown}: {} Euclidean flips to intrinsic Delaunay; {} Newton steps, {} Ptolemy flips (per step: {:?})",
        sol.euclidean_flips,
        sol.steps.len(),
        sol.flip_sequence.len(),
        sol.steps.iter().map(|s| s.flips).collect::<Vec<_>>()
    );
    let Some(proof) = &outcome.proof else {
        let _ = writeln!(
            out,
            "not converged ({:?}); max |Θ − θ| = {:e}; no certificate",
            sol.stop, sol.residual_max
        );
        super::files::emit(&out)?;
        return Ok(code::UNDECIDED);
    };
    if let Some(path) = o.extra.svg.as_deref() {
        out.push_str(&super::uniformize_svg::write(path, sol)?);
    }
    if o.precision == "dd" {
        let _ = writeln!(
            out,
            "converged: max |Θ − θ| = {:e} (f64), {:e} after refinement in double-double; the certificate runs in {bits}-bit MPFR interval arithmetic (double-double has no directed rounding)",
            sol.residual_max, proof.residual_max
        );
    } else {
        let _ = writeln!(
            out,
            "converged: max |Θ − θ| = {:e} (f64), {:e} after refinement at {bits} bits",
            sol.residual_max, proof.residual_max
        );
    }
    let holds = match &outcome.metric {
        Some(CertifiedMetric::Rounded { reason }) => format!(
            "certified for the binary64-rounded lengths of the input, not its exact metric ({reason})"
        ),
        _ => "certified for the input's exact metric".to_string(),
    };
    let status = report_certificate(
        &mut out,
        &proof.outcome,
        outcome.claim(),
        o.output,
        &Certified {
            holds: &holds,
            written: "certificate",
        },
    )?;
    super::files::emit(&out)?;
    Ok(status)
}

/// The exact surface of a loaded case.
fn into_surface(case: FlipCase) -> penner::io::Surface {
    match case {
        FlipCase::Exact(s) => s,
        FlipCase::Decimal(d) => d.into_surface(),
    }
}

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
pub(super) fn report_certificate(
    out: &mut String,
    outcome: &CertificateOutcome,
    claim: Option<serde_json::Value>,
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
        if let (code::HOLDS, Some(claim)) = (status, claim) {
            let text = serde_json::to_string_pretty(&claim).unwrap_or_default();
            let mut f = create_new(path)?;
            f.write_all(text.as_bytes())
                .and_then(|()| f.write_all(b"\n"))
                .map_err(|e| CliError::Write {
                    path: path.to_path_buf(),
                    reason: e.to_string(),
                })?;
            let _ = writeln!(
                out,
                "{} written to {} (re-check: penner certify {})",
                words.written,
                path.display(),
                path.display()
            );
        } else {
            out.push_str("no certificate written\n");
        }
    }
    Ok(status)
}

/// A certificate error as the CLI reports it: the input's fault (bad input, exit 3) or a
/// refinement of penner's own solution that did not go through (undecided, exit 2).
pub fn certificate_error(
    shown: &str,
    e: penner::uniformization::certificate::CertificateError,
) -> CliError {
    use penner::uniformization::certificate::CertificateError;
    match e {
        CertificateError::Replay(r) => CliError::NotConverged(format!(
            "{shown}: not certified: the refinement did not go through: {r}"
        )),
        other => CliError::Input(format!("{shown}: {other}")),
    }
}

/// The exact values of a solver's `u`, or — when an entry is not finite — undecided (exit
/// 2) naming its index: a non-finite `u` is a failure of the computation, never input.
pub fn finite_u(
    shown: &str,
    values: impl IntoIterator<Item = Option<rug::Rational>>,
) -> Result<Vec<rug::Rational>, CliError> {
    values
        .into_iter()
        .enumerate()
        .map(|(i, q)| {
            q.ok_or_else(|| {
                CliError::NotConverged(format!(
                    "{shown}: not certified: u[{i}] of the computed solution is not finite"
                ))
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use penner::uniformization::certificate::CertificateError;
    use penner::uniformization::refine::RefineError;

    /// A refinement of penner's own solution that does not go through is undecided (exit
    /// 2); a refused certificate parameter stays bad input (exit 3).
    #[test]
    fn refinement_failures_are_undecided_and_bad_parameters_are_bad_input() {
        let stalled = certificate_error("s.off", CertificateError::Replay(RefineError::Hessian));
        assert_eq!(stalled.exit_code(), code::UNDECIDED, "{stalled}");
        let bad = certificate_error("s.off", CertificateError::Radius("-1".into()));
        assert_eq!(bad.exit_code(), code::BAD_INPUT, "{bad}");
    }

    /// A non-finite entry of a computed `u` is named and undecided, never dropped.
    #[test]
    fn a_non_finite_u_is_named_by_index() {
        let u = [
            Some(rug::Rational::from(1)),
            None,
            Some(rug::Rational::from(2)),
        ];
        let e = finite_u("s.off", u).expect_err("u[1] is not finite");
        assert_eq!(e.exit_code(), code::UNDECIDED);
        assert!(e.to_string().contains("u[1]"), "{e}");
        assert_eq!(
            finite_u("s.off", [Some(rug::Rational::from(3))])
                .map(|v| v.len())
                .ok(),
            Some(1)
        );
    }
}
