//! `penner uniformize SURFACE --hyperbolic [--targets FILE] [--precision P] [-o RESULT.json]`:
//! the hyperbolic target (notes Thm 11; B38, B39, B87, B89, B104). The input lengths
//! (rounded to binary64) are read as hyperbolic lengths; geometric flips to hyperbolic
//! Delaunay, Newton over Penner cells with Ptolemy flips (counts printed), refinement, the residual enclosed in MPFR intervals and an existence
//! radius (certified); the Gauss–Bonnet area by L'Huilier is numerical and says so. With
//! `-o`, a certified result is written as a `hyperbolic_uniformization` claim that
//! `penner certify` re-checks from scratch.

use super::error::{code, CliError};
use super::files::{create_new, emit};
use super::input::FlipCase;
use super::uniformize::finite_u;
use penner::scalar::{Dd, Mpfr, Precision, Real};
use penner::uniformization::hyperbolic::{
    uniformize_hyperbolic, HyperbolicOptions, HyperbolicStop,
};
use penner::uniformization::hyperbolic_certificate::{
    certify_hyperbolic, refine_hyperbolic, total_area_lhuilier, Existence,
};
use penner::uniformization::hyperbolic_claim::{to_claim, ClaimData};
use penner::uniformization::Targets;
use rug::Rational;
use std::fmt::Write as _;
use std::io::Write;

/// Run `penner uniformize --hyperbolic` on the loaded surface; `bits` and `tolerance` are
/// those of `--precision` (f64: no refinement; dd: double-double; N: MPFR at N bits).
#[allow(clippy::too_many_lines)] // solve, refine, certify, check and write, in order
pub fn run(
    shown: &str,
    case: &FlipCase,
    o: &super::uniformize::Options<'_>,
    bits: u32,
    tolerance: f64,
) -> Result<u8, CliError> {
    let mesh = case.mesh().clone();
    let lengths: Vec<f64> = case.lengths::<f64>(());
    let targets = match o.targets {
        Some(p) => super::uniformize::read_targets(p, mesh.n_vertices())?,
        None => Targets::flat(mesh.n_vertices()),
    };
    let sol = uniformize_hyperbolic(&mesh, &lengths, &targets, &HyperbolicOptions::default())
        .map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
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
    let bad = |e: penner::uniformization::hyperbolic::HyperbolicError| {
        CliError::Input(format!("{shown}: {e}"))
    };
    let (u, refined): (Vec<Rational>, f64) = match o.precision {
        "f64" => (
            finite_u(shown, sol.u.iter().map(|&x| Rational::from_f64(x)))?,
            sol.residual_max,
        ),
        "dd" => {
            let r = refine_hyperbolic::<Dd>(&sol, (), tolerance, 30).map_err(bad)?;
            let u = finite_u(shown, r.u.iter().map(Real::to_rational))?;
            (u, r.residual_max())
        }
        _ => {
            let prec = Precision::new(u64::from(bits))
                .map_err(|_| CliError::Input(format!("--precision: {bits} bits out of range")))?;
            let r = refine_hyperbolic::<Mpfr>(&sol, prec, tolerance, 60).map_err(bad)?;
            let u = finite_u(shown, r.u.iter().map(Real::to_rational))?;
            (u, r.residual_max())
        }
    };
    let _ = writeln!(out, "refined ({}): max |Θ − θ| = {refined:e}", o.precision);
    let cert = certify_hyperbolic(&sol, &u, bits).map_err(bad)?;
    let _ = writeln!(
        out,
        "certified ({bits}-bit intervals): max |Θ − θ(u)| ≤ {:e}, ‖Θ − θ(u)‖₂ ≤ {:e}",
        cert.residual_max, cert.residual_norm2
    );
    let status = match &cert.existence {
        Existence::Holds {
            distance,
            mu,
            radius,
        } => {
            let _ = writeln!(
                out,
                "certified: an exact solution lies within {distance:e} (2-norm) of u (Hessian ≥ {mu:e} on the box of radius {radius:e}, B39)"
            );
            code::HOLDS
        }
        Existence::Undecided { reason } => {
            let _ = writeln!(out, "existence not certified: {reason}");
            code::UNDECIDED
        }
    };
    let scaled = sol.scaled_lengths();
    let area = total_area_lhuilier(&sol.mesh, &scaled);
    let gauss_bonnet = {
        let k: f64 = targets
            .over_pi()
            .iter()
            .map(|q| (2.0 - q.to_f64()) * std::f64::consts::PI)
            .sum();
        let chi = mesh.n_vertices() as f64 - mesh.n_edges() as f64 + mesh.n_faces() as f64;
        k - 2.0 * std::f64::consts::PI * chi
    };
    let _ = writeln!(
        out,
        "numerical: total area by L'Huilier = {}, Gauss–Bonnet Σ(2π − Θ) − 2πχ = {gauss_bonnet}",
        area.map_or("undefined".to_string(), |a| a.to_string())
    );
    if let Some(path) = o.output {
        write_claim(&mut out, path, &sol, &u, &cert, bits)?;
    }
    emit(&out)?;
    Ok(status)
}

/// Write the certificate as a `hyperbolic_uniformization` claim (`penner certify`
/// re-checks it from scratch, B39) when the existence radius is certified; never over an
/// existing file. Otherwise say that no certificate was written.
fn write_claim(
    out: &mut String,
    path: &std::path::Path,
    sol: &penner::uniformization::hyperbolic::HyperbolicUniformization,
    u: &[Rational],
    cert: &penner::uniformization::hyperbolic_certificate::HyperbolicCertificate,
    bits: u32,
) -> Result<(), CliError> {
    let Existence::Holds { radius, .. } = &cert.existence else {
        out.push_str("no certificate written\n");
        return Ok(());
    };
    let data = ClaimData {
        mesh: &sol.t0,
        lengths: &sol.lengths,
        flips: &sol.flips,
        targets: &sol.targets,
        u,
    };
    let claim = to_claim(&data, *radius, cert.residual_norm2, bits);
    let text = serde_json::to_string_pretty(&claim).unwrap_or_default() + "\n";
    let mut f = create_new(path)?;
    f.write_all(text.as_bytes()).map_err(|e| CliError::Write {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })?;
    let _ = writeln!(
        out,
        "certificate written to {} (re-check: penner certify {})",
        path.display(),
        path.display()
    );
    Ok(())
}
