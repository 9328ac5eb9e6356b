//! `penner uniformize` on a surface with boundary: interior cone angles and boundary angle
//! sums (`--targets FILE`: `Θ_v/π` inside, `φ_v/π` on the boundary; `--flat`: `2π` inside
//! and the boundary curvature spread evenly), solved and certified on the double (B79).
//! The certificate is the double's `uniformization` claim.

use super::error::{code, CliError};
use super::files::create_new;
use penner::mesh::Face;
use penner::scalar::{Certified, Sign};
use penner::uniformization::boundary::{
    flat_with_even_boundary, uniformize_with_boundary, BoundaryUniformization,
};
use penner::uniformization::layout::{face_orientations, unfold, unfold_within};
use penner::uniformization::pipeline::{
    certify_solution, double_surface, CertifiedMetric, PipelineError, Precision,
};
use penner::uniformization::svg::{render_layout_svg, scaled_lengths_f64};
use penner::uniformization::UniformizeOptions;
use std::fmt::Write as _;
use std::io::Write;
use std::path::Path;

/// The surface with boundary, its lengths, the CLI options and the precision.
pub struct Input<'a> {
    /// The file name shown.
    pub shown: &'a str,
    /// The surface (with boundary), after the rescaling by `2^shift`.
    pub surface: &'a penner::io::Surface,
    /// The triangulation (with boundary).
    pub mesh: &'a penner::mesh::Mesh,
    /// Its lengths.
    pub lengths: &'a [f64],
    /// The exact power of two the lengths were divided by.
    pub shift: i64,
    /// MPFR bits and refinement tolerance.
    pub bits: u32,
}

/// Run `penner uniformize` on a surface with boundary.
#[allow(clippy::too_many_lines)] // solve, report, draw, certify and write, in order
pub fn run(i: &Input<'_>, o: &super::uniformize::Options<'_>) -> Result<u8, CliError> {
    let shown = i.shown;
    let targets = match (o.targets, o.flat) {
        (Some(_), true) => {
            return Err(CliError::Input(
                "give either --targets FILE or --flat, not both".into(),
            ))
        }
        (Some(p), false) => super::uniformize::read_targets(p, i.mesh.n_vertices())?,
        (None, true) => flat_with_even_boundary(i.mesh),
        (None, false) => {
            return Err(CliError::Input(
                "the target angles are required: --targets FILE (a JSON array: Θ_v/π at interior vertices, φ_v/π at boundary vertices) or --flat"
                    .into(),
            ))
        }
    };
    let b = uniformize_with_boundary(
        i.mesh,
        i.lengths,
        &targets,
        &UniformizeOptions::default(),
        &mut |_| {},
    )
    .map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
    let sol = &b.solution;
    let d = &b.double.mesh;
    let mut out = String::new();
    if i.shift != 0 {
        let _ = writeln!(
            out,
            "{shown}: lengths divided by 2^{} (exactly) before solving: the angles and u do not change with the scale",
            i.shift
        );
    }
    let _ = writeln!(
        out,
        "{shown}: surface with boundary ({} boundary edges), solved on its double (V, E, F = {}, {}, {}; χ = {}) with Θ = 2φ at boundary vertices",
        i.mesh.n_boundary_edges(),
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
    report_seam(&b, &mut out);
    if let Some(path) = o.extra.svg.as_deref() {
        out.push_str(&write_svg(path, &b)?);
    }
    let precision = o.precision.parse::<Precision>().map_err(CliError::Input)?;
    let (Some(double), Some(lengths)) = (
        double_surface(i.surface, &b.double),
        b.double.pull_back_edges(i.lengths),
    ) else {
        return Err(CliError::NotConverged(format!(
            "{shown}: not certified: the exact metric could not be pulled back to the double"
        )));
    };
    let c = certify_solution(&double, &lengths, sol, precision).map_err(|e| match e {
        PipelineError::Input(e) => CliError::Input(format!("{shown}: {e}")),
        PipelineError::Certificate(e) => super::uniformize::certificate_error(shown, e),
    })?;
    let proof = &c.proof;
    let _ = writeln!(
        out,
        "converged: max |Θ − θ| = {:e} (f64), {:e} after refinement",
        sol.residual_max, proof.residual_max
    );
    let written = format!(
        "certificate of the double (copy 1 = vertices 0..{} and faces 0..{} of its input)",
        i.mesh.n_vertices(),
        i.mesh.n_faces()
    );
    let claim = c.claim(&double, sol, i.bits);
    let holds = match &c.metric {
        CertifiedMetric::Input => "certified on the double for the input's exact metric (by symmetry and uniqueness it solves the boundary problem on copy 1, B79)".to_string(),
        CertifiedMetric::Rounded { reason } => format!(
            "certified on the double for the binary64-rounded lengths of the input, not its exact metric ({reason}; by symmetry and uniqueness it solves the boundary problem on copy 1, B79)"
        ),
    };
    let status = super::uniformize::report_certificate(
        &mut out,
        &proof.outcome,
        claim,
        o.output,
        &super::uniformize::Certified {
            holds: &holds,
            written: &written,
        },
    )?;
    super::files::emit(&out)?;
    Ok(status)
}

/// The seam lines of the report: intact or flipped, symmetric triangulation, and the
/// numerical angle sums on copy 1.
fn report_seam(b: &BoundaryUniformization, out: &mut String) {
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
    if let Some(sums) = b.angle_sums_on_original() {
        let worst = sums
            .iter()
            .zip(b.solution.targets.over_pi())
            .zip(&b.double.vertex_sheet)
            .map(|((s, q), sheet)| {
                let full = q.to_f64() * std::f64::consts::PI;
                let want = if *sheet == penner::mesh::double::Sheet::Seam {
                    full / 2.0
                } else {
                    full
                };
                (s - want).abs()
            })
            .fold(0.0, f64::max);
        let _ = writeln!(
            out,
            "angle sums on copy 1 (f64, numerical): max |θ_v − target| = {worst:e}"
        );
    }
}

/// Draw copy 1 of the final triangulation (the flattened surface) when the seam is
/// intact, else the whole double; the line to report.
fn write_svg(path: &Path, b: &BoundaryUniformization) -> Result<String, CliError> {
    let sol = &b.solution;
    let lengths = scaled_lengths_f64(&sol.mesh, &sol.base_lengths, &sol.u);
    let region = b.original_faces();
    let (layout, what) = match (&region, b.original_root()) {
        (Some(keep), Some(root)) => (
            unfold_within(&sol.mesh, &lengths, root, Some(keep)),
            "the surface (copy 1 of the double)",
        ),
        _ => (
            unfold(&sol.mesh, &lengths, Face(0)),
            "the whole double (a seam edge was flipped)",
        ),
    };
    let orientations = face_orientations(&sol.mesh, &layout);
    let folds = orientations
        .iter()
        .enumerate()
        .filter(|(f, _)| region.as_ref().is_none_or(|k| k[*f]))
        .filter(|(_, o)| o.as_ref().and_then(Certified::value) != Some(Sign::Positive))
        .count();
    let picture = render_layout_svg(&sol.mesh, &layout);
    let mut f = create_new(path)?;
    f.write_all(picture.as_bytes())
        .map_err(|e| CliError::Write {
            path: path.to_path_buf(),
            reason: e.to_string(),
        })?;
    Ok(format!(
        "layout of {what} drawn to {} ({folds} faces not certified counterclockwise)\n",
        path.display()
    ))
}
