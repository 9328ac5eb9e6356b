//! `penner uniformize` on a surface with boundary: the report of
//! [`penner::uniformization::pipeline::uniformize_boundary`] (interior cone angles and
//! boundary angle sums, solved and certified on the double, B79). The certificate is the
//! double's `uniformization` claim.

use super::error::{code, CliError};
use super::files::write_new;
use penner::uniformization::pipeline::{BoundaryOutcome, CertifiedMetric};
use penner::uniformization::svg::render_layout_svg;
use std::fmt::Write as _;
use std::path::Path;

/// Print the outcome of `penner uniformize` on a surface with boundary; draw and write
/// where asked.
pub fn report(
    shown: &str,
    surface: &penner::io::Surface,
    outcome: &BoundaryOutcome,
    o: &super::uniformize_options::Options<'_>,
) -> Result<u8, CliError> {
    let b = &outcome.boundary;
    let mesh = &outcome.surface.mesh;
    let sol = &b.solution;
    let d = &b.double.mesh;
    let mut out = String::new();
    if outcome.shift != 0 {
        let _ = writeln!(
            out,
            "{shown}: lengths divided by 2^{} (exactly) before solving: the angles and u do not change with the scale",
            outcome.shift
        );
    }
    let _ = writeln!(
        out,
        "{shown}: surface with boundary ({} boundary edges), solved on its double (V, E, F = {}, {}, {}; χ = {}) with Θ = 2φ at boundary vertices",
        mesh.n_boundary_edges(),
        d.n_vertices(),
        d.n_edges(),
        d.n_faces(),
        d.euler_characteristic()
    );
    let _ = writeln!(
        out,
        "{} Euclidean flips to intrinsic Delaunay; {} Newton steps, {} Ptolemy flips",
        sol.euclidean_flips,
        sol.steps.len(),
        sol.flip_sequence.len()
    );
    if !sol.converged() {
        let _ = writeln!(
            out,
            "not converged ({:?}); max |Θ − θ| = {:e}; no certificate",
            sol.stop, sol.residual_max
        );
        super::files::emit(&out)?;
        return Ok(code::UNDECIDED);
    }
    let _ = writeln!(
        out,
        "mirror asymmetry max |u(v) − u(ι v)| = {:e} (numerical; the exact solution is symmetric, B79)",
        b.mirror_asymmetry
    );
    report_seam(outcome, &mut out);
    if let Some(path) = o.extra.svg.as_deref() {
        out.push_str(&write_svg(path, outcome)?);
    }
    let mut uv_missing = false;
    if let Some(path) = o.extra.uv.as_deref() {
        let source = super::uniformize_uv::boundary(surface, outcome);
        let svg = o.extra.uv_svg.as_deref();
        let (line, written) = super::uniformize_uv::write(path, svg, shown, source)?;
        out.push_str(&line);
        uv_missing = !written;
    }
    let Some(c) = &outcome.certification else {
        out.push_str(&super::uniformize_options::numerical_line(sol.residual_max));
        super::files::emit(&out)?;
        return Ok(code::UNDECIDED);
    };
    let proof = &c.proof;
    let _ = writeln!(
        out,
        "converged: max |Θ − θ| = {:e} (f64), {:e} after refinement",
        sol.residual_max, proof.residual_max
    );
    let written = format!(
        "certificate of the double (copy 1 = vertices 0..{} and faces 0..{} of its input)",
        mesh.n_vertices(),
        mesh.n_faces()
    );
    let holds = match &c.metric {
        CertifiedMetric::Input => "certified on the double for the input's exact metric (by symmetry and uniqueness it solves the boundary problem on copy 1, B79)".to_string(),
        CertifiedMetric::Rounded { reason } => format!(
            "certified on the double for the binary64-rounded lengths of the input, not its exact metric ({reason}; by symmetry and uniqueness it solves the boundary problem on copy 1, B79)"
        ),
    };
    let status = super::certificate_report::report_certificate(
        &mut out,
        &proof.outcome,
        outcome.claim_json(),
        o.output,
        &super::certificate_report::Certified {
            holds: &holds,
            written: &written,
        },
    )?;
    super::files::emit(&out)?;
    Ok(if uv_missing {
        status.max(code::UNDECIDED)
    } else {
        status
    })
}

/// The seam lines of the report: intact or flipped, symmetric triangulation, and the
/// numerical angle sums on copy 1.
fn report_seam(outcome: &BoundaryOutcome, out: &mut String) {
    let b = &outcome.boundary;
    if !b.seam_flips.is_empty() {
        let _ = writeln!(
            out,
            "{} seam edge(s) flipped: the final triangulation is of the double and crosses the boundary of the surface; the metric on the surface is the double's restricted to copy 1 (bounded by the fixed set of the mirror)",
            b.seam_flips.len()
        );
        return;
    }
    let symmetric = b.triangulation_symmetric().unwrap_or(false);
    let _ = writeln!(
        out,
        "seam intact (no boundary edge flipped); final triangulation {}mirror symmetric",
        if symmetric { "" } else { "not " }
    );
    if let Some(worst) = outcome.worst_angle_on_copy_1() {
        let _ = writeln!(
            out,
            "angle sums on copy 1 (f64, numerical): max |θ_v − target| = {worst:e}"
        );
    }
}

/// Draw [`BoundaryOutcome::layout`]; the line to report.
fn write_svg(path: &Path, outcome: &BoundaryOutcome) -> Result<String, CliError> {
    let sol = &outcome.boundary.solution;
    let drawn = outcome.layout();
    let picture = render_layout_svg(&sol.mesh, &drawn.layout);
    write_new(path, picture.as_bytes())?;
    Ok(format!(
        "layout of {} drawn to {} ({} faces not certified counterclockwise)\n",
        drawn.what,
        path.display(),
        drawn.folds
    ))
}
