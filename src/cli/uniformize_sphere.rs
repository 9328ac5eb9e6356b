//! `penner uniformize SURFACE --sphere [--pole V] [-o CLAIM.json] [--obj OUT.obj]
//! [--svg OUT.svg]`: the conformally equivalent convex polyhedron inscribed in the unit
//! sphere (notes Thm 9; B74–B76; edges at the pole flipped when the disk is not convex,
//! B93). The disk problem is certified for the surface's exact
//! metric (B76 on the replayed Euclidean flips, B73, B90) and written with `-o` as a
//! `sphere_uniformization` claim that `penner certify` re-checks; the planar layout is
//! certified Delaunay and convex (exact predicates on its binary64 coordinates); the 3-D
//! positions (`--obj`) and the cross-ratio comparison are numerical and labelled so.

use super::error::{code, CliError};
use super::files::{create_new, emit};
use penner::uniformization::certificate::CertificateOutcome;
use penner::uniformization::dirichlet_certificate::certify_disk_near;
use penner::uniformization::layout::unproved_faces;
use penner::uniformization::sphere::{uniformize_sphere, SphereOptions};
use penner::uniformization::sphere_checks::{cross_ratio_deviation, planar_delaunay};
use penner::uniformization::sphere_claim::{claim_of, recheck, to_json};
use penner::uniformization::sphere_refine::{input_disk_metric, prove_disk};
use penner::uniformization::svg::render_layout_svg;
use std::fmt::Write as _;
use std::io::Write;
use std::path::Path;

/// The precision of `--sphere`: `f64` (the solve's `u`, certified with 128-bit
/// intervals) or MPFR bits (refined to `tolerance` at those bits, certified at them).
pub struct SpherePrecision {
    /// Interval (and refinement) bits.
    pub bits: u32,
    /// Refine in MPFR before certifying.
    pub refine: bool,
    /// Refinement tolerance on `max |2π − θ|`.
    pub tolerance: f64,
}

fn write_new(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    let mut f = create_new(path)?;
    f.write_all(bytes).map_err(|e| CliError::Write {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })
}

/// Run `penner uniformize --sphere` on `surface` (its exact metric; divided by `2^shift`
/// when `shift ≠ 0`), solved from its binary64 `lengths`.
#[allow(clippy::too_many_lines)] // solve, check, certify and write, in order
pub fn run(
    shown: &str,
    surface: &penner::io::Surface,
    lengths: &[f64],
    shift: i64,
    precision: &SpherePrecision,
    output: Option<&Path>,
    extra: &super::args::UniformizeExtra,
) -> Result<u8, CliError> {
    let mesh = &surface.mesh;
    let bits = precision.bits;
    let (obj, svg) = (extra.obj.as_deref(), extra.svg.as_deref());
    let opts = SphereOptions {
        pole: extra.pole,
        ..SphereOptions::default()
    };
    let sol = uniformize_sphere(mesh, lengths, &opts).map_err(|e| sphere_error(shown, e))?;
    let mut out = String::new();
    if shift != 0 {
        let _ = writeln!(
            out,
            "{shown}: lengths divided by 2^{shift} (exactly) before solving; the certificate is about the rescaled surface"
        );
    }
    let _ = writeln!(
        out,
        "{shown}: {} Euclidean flips to intrinsic Delaunay; pole v{} ({} link vertices); disk problem: {} Newton steps, {} Ptolemy flips ({} of edges at the pole, B93), max |Θ − θ| = {:e} (f64)",
        sol.euclidean_flips,
        sol.pole,
        sol.disk.pole_length.iter().flatten().count(),
        sol.solution.steps.len(),
        sol.flip_sequence.len(),
        sol.star_flips.len(),
        sol.solution.residual_max
    );
    if !sol.reflex.is_empty() {
        let names: Vec<String> = sol.reflex.iter().map(|v| format!("v{v}")).collect();
        let _ = writeln!(
            out,
            "{shown}: the disk is not convex at link vertex {} (angle > π after the flips at the pole): the inscribed polyhedron would not be convex",
            names.join(", ")
        );
    }
    // The disk certificate for the surface's exact metric (its Euclidean flips replayed on
    // enclosures, B73), near the f64 solution or its MPFR refinement; then its re-check as
    // the claim that `-o` writes (B90).
    let (outcome, claim) = match certify(surface, &sol, precision, &mut out) {
        Ok((data, CertificateOutcome::Holds { residual, .. })) => {
            let claim = claim_of(surface, &sol, &data, residual);
            let outcome =
                recheck(surface, &claim, bits).unwrap_or_else(|e| CertificateOutcome::Undecided {
                    reason: format!("the certificate does not re-check: {e}"),
                });
            (outcome, Some(claim))
        }
        Ok((_, undecided)) => (undecided, None),
        Err(reason) => (CertificateOutcome::Undecided { reason }, None),
    };
    let cert_ok = matches!(outcome, CertificateOutcome::Holds { .. });
    match &outcome {
        CertificateOutcome::Holds {
            distance,
            mu,
            residual,
        } => {
            let _ = writeln!(
                out,
                "disk problem certified for the surface's exact metric ({bits}-bit intervals): an exact solution lies within {distance:e} (2-norm) of u, its disk Delaunay with a convex boundary (Hessian ≥ {mu:e}, ‖Θ − θ(u)‖₂ ≤ {residual:e})"
            );
        }
        CertificateOutcome::Undecided { reason } => {
            let _ = writeln!(out, "disk problem not certified: {reason}");
        }
    }
    let planar = planar_delaunay(&sol.solution.mesh, &sol.planar);
    let _ = writeln!(
        out,
        "planar layout (certified, exact predicates on its coordinates): {} folded or flat faces, {} edges not Delaunay, {} reflex boundary corners",
        planar.not_ccw.len(),
        planar.not_delaunay.len(),
        planar.not_convex.len()
    );
    let deviation = cross_ratio_deviation(&sol, &sol.initial_lengths);
    let _ = writeln!(
        out,
        "numerical: output vertices on the unit sphere (|centroid| = {:e}); max |log c(chords) − log c(input)| = {}",
        sol.centroid_norm,
        deviation.map_or("undefined".to_string(), |d| format!("{d:e}"))
    );
    let status = if cert_ok && planar.holds() {
        code::HOLDS
    } else {
        code::UNDECIDED
    };
    if let Some(path) = obj {
        let mut text = Vec::new();
        penner::io::write::obj(&mut text, &sol.mesh, &sol.positions).map_err(|e| {
            CliError::Write {
                path: path.to_path_buf(),
                reason: e.to_string(),
            }
        })?;
        write_new(path, &text)?;
        let _ = writeln!(out, "inscribed polyhedron written to {}", path.display());
    }
    if let Some(path) = svg {
        let picture = render_layout_svg(&sol.solution.mesh, &sol.layout);
        write_new(path, picture.as_bytes())?;
        let folds = unproved_faces(&sol.solution.mesh, &sol.layout).len();
        let _ = writeln!(
            out,
            "planar disk drawn to {} ({folds} faces not certified counterclockwise)",
            path.display()
        );
    }
    if let Some(path) = output {
        match claim.filter(|_| cert_ok) {
            Some(claim) => {
                let doc = to_json(surface, &claim, bits);
                let text = serde_json::to_string_pretty(&doc).unwrap_or_default() + "\n";
                write_new(path, text.as_bytes())?;
                let _ = writeln!(
                    out,
                    "certificate written to {} (re-check: penner certify {})",
                    path.display(),
                    path.display()
                );
            }
            None => out.push_str("no certificate written\n"),
        }
    }
    emit(&out)?;
    Ok(status)
}

/// The disk certificate of `sol` for `surface`'s exact metric at `precision` (after an MPFR
/// refinement when asked, reported on `out`); `Err(reason)` when the exact metric cannot be
/// replayed to `T₀` or the refinement fails.
fn certify(
    surface: &penner::io::Surface,
    sol: &penner::uniformization::sphere::SphereUniformization,
    precision: &SpherePrecision,
    out: &mut String,
) -> Result<
    (
        penner::uniformization::dirichlet_certificate::DiskCertificateData,
        CertificateOutcome,
    ),
    String,
> {
    let bits = precision.bits;
    let prec = penner::scalar::Precision::new(u64::from(bits)).map_err(|e| e.to_string())?;
    let enclosures = surface.lengths::<penner::scalar::Interval<penner::scalar::Mpfr>>(prec);
    let metric = input_disk_metric(sol, &surface.mesh, enclosures)?;
    if !precision.refine {
        let Some(u) = sol
            .solution
            .u
            .iter()
            .map(|&x| rug::Rational::from_f64(x))
            .collect::<Option<Vec<rug::Rational>>>()
        else {
            return Err("a value of the computed u is not finite".into());
        };
        let residual = sol.solution.residual_max.max(4.0 * f64::EPSILON);
        return Ok(certify_disk_near(sol, Some(&metric), &u, residual, bits));
    }
    let proof =
        prove_disk(sol, Some(&metric), prec, precision.tolerance).map_err(|e| e.to_string())?;
    let _ = writeln!(
        out,
        "refined at {bits} bits (f64 factor, MPFR residuals): max |Θ − θ| = {:e} after {} steps",
        proof.history.last().copied().unwrap_or(f64::NAN),
        proof.history.len().saturating_sub(1)
    );
    Ok((proof.data, proof.outcome))
}

/// A sphere-target error as the CLI reports it: a surface that is not a sphere or a bad
/// `--pole` is bad input (exit 3); a disk problem that did not converge, a layout that
/// failed or no usable pole found is undecided (exit 2), with what stalled.
fn sphere_error(shown: &str, e: penner::uniformization::sphere::SphereError) -> CliError {
    use penner::uniformization::sphere::SphereError;
    match e {
        SphereError::NotConverged { .. } | SphereError::Layout(_) | SphereError::NoPole => {
            CliError::NotConverged(format!("{shown}: not certified: {e}"))
        }
        other => CliError::Input(format!("{shown}: {other}")),
    }
}
