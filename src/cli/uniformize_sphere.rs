//! `penner uniformize SURFACE --sphere [--pole V] [-o CLAIM.json] [--obj OUT.obj]
//! [--svg OUT.svg]`: the report of [`penner::uniformization::pipeline::uniformize_sphere`]
//! (notes Thm 9; B74–B76, B93): the disk problem certified for the surface's exact metric
//! and written with `-o` as a `sphere_uniformization` claim; the planar layout checked by
//! exact predicates; the 3-D positions (`--obj`) and the cross-ratio comparison numerical.

use super::certificate_report::write_claim;
use super::error::{code, CliError};
use super::files::{emit, write_new};
use penner::uniformization::certificate::CertificateOutcome;
use penner::uniformization::layout::unproved_faces;
use penner::uniformization::pipeline::SphereOutcome;
use penner::uniformization::svg::render_layout_svg;
use std::fmt::Write as _;
use std::path::Path;

/// Print the outcome of `penner uniformize --sphere`; write the claim, the inscribed
/// polyhedron and the planar disk where asked.
pub fn report(
    shown: &str,
    outcome: &SphereOutcome,
    output: Option<&Path>,
    extra: &super::args::UniformizeExtra,
) -> Result<u8, CliError> {
    let sol = &outcome.solution;
    let bits = outcome.bits;
    let mut out = String::new();
    if outcome.shift != 0 {
        let _ = writeln!(
            out,
            "{shown}: lengths divided by 2^{} (exactly) before solving; the certificate is about the rescaled surface",
            outcome.shift
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
    if let Some((residual, steps)) = outcome.refinement {
        let _ = writeln!(
            out,
            "refined at {bits} bits (f64 factor, MPFR residuals): max |Θ − θ| = {residual:e} after {steps} steps"
        );
    }
    match &outcome.certificate {
        Some(CertificateOutcome::Holds {
            distance,
            mu,
            residual,
        }) => {
            let _ = writeln!(
                out,
                "disk problem certified for the surface's exact metric ({bits}-bit intervals): an exact solution lies within {distance:e} (2-norm) of u, its disk Delaunay with a convex boundary (Hessian ≥ {mu:e}, ‖Θ − θ(u)‖₂ ≤ {residual:e})"
            );
        }
        Some(CertificateOutcome::Undecided { reason }) => {
            let _ = writeln!(out, "disk problem not certified: {reason}");
        }
        None => out.push_str("disk problem: numerical, not certified (--no-certify)\n"),
    }
    let planar = &outcome.planar;
    if let Some(reason) = &sol.layout_failure {
        let _ = writeln!(out, "planar layout incomplete: {reason}");
    }
    let _ = writeln!(
        out,
        "planar layout (certified, exact predicates on its coordinates): {} folded or flat faces, {} edges not Delaunay, {} reflex boundary corners",
        planar.not_ccw.len(),
        planar.not_delaunay.len(),
        planar.not_convex.len()
    );
    let _ = writeln!(
        out,
        "numerical: output vertices on the unit sphere (|centroid| = {:e}); max |log c(chords) − log c(input)| = {}",
        sol.centroid_norm,
        outcome
            .deviation
            .map_or("undefined".to_string(), |d| format!("{d:e}"))
    );
    if let Some(path) = extra.obj.as_deref() {
        write_polyhedron(&mut out, path, sol)?;
    }
    if let Some(path) = extra.svg.as_deref() {
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
        write_claim(&mut out, path, outcome.claim.clone(), "certificate")?;
    }
    emit(&out)?;
    Ok(if outcome.certified() {
        code::HOLDS
    } else {
        code::UNDECIDED
    })
}

/// Write the inscribed polyhedron of `sol` to the new file `path` as OBJ, or say why not
/// (a layout binary64 cannot hold has no positions for some vertices).
fn write_polyhedron(
    out: &mut String,
    path: &Path,
    sol: &penner::uniformization::sphere::SphereUniformization,
) -> Result<(), CliError> {
    if let Some(reason) = &sol.layout_failure {
        let _ = writeln!(out, "no polyhedron written to {}: {reason}", path.display());
        return Ok(());
    }
    let mut text = Vec::new();
    penner::io::write::obj(&mut text, &sol.mesh, &sol.positions).map_err(|e| CliError::Write {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })?;
    write_new(path, &text)?;
    let _ = writeln!(out, "inscribed polyhedron written to {}", path.display());
    Ok(())
}
