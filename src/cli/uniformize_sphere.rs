//! `penner uniformize SURFACE --sphere [--pole V] [-o RESULT.json] [--obj OUT.obj]
//! [--svg OUT.svg]`: the conformally equivalent convex polyhedron inscribed in the unit
//! sphere (notes Thm 9; B74–B76). The disk problem is certified (B76), the planar layout
//! certified Delaunay and convex (exact predicates on its binary64 coordinates); the 3-D
//! positions and the cross-ratio comparison are numerical and labelled so.

use super::error::{code, CliError};
use super::files::{create_new, emit};
use penner::uniformization::certificate::CertificateOutcome;
use penner::uniformization::dirichlet_certificate::certify_disk;
use penner::uniformization::layout::unproved_faces;
use penner::uniformization::sphere::{uniformize_sphere, SphereOptions};
use penner::uniformization::sphere_checks::{cross_ratio_deviation, planar_delaunay};
use penner::uniformization::svg::render_layout_svg;
use std::fmt::Write as _;
use std::io::Write;
use std::path::Path;

/// Interval bits of the disk certificate.
const BITS: u32 = 128;

fn write_new(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    let mut f = create_new(path)?;
    f.write_all(bytes).map_err(|e| CliError::Write {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })
}

/// Run `penner uniformize --sphere` on the triangulation `mesh` with binary64 `lengths`.
#[allow(clippy::too_many_lines)] // solve, check, certify and write, in order
pub fn run(
    shown: &str,
    mesh: &penner::mesh::Mesh,
    lengths: &[f64],
    output: Option<&Path>,
    extra: &super::args::UniformizeExtra,
) -> Result<u8, CliError> {
    let (obj, svg) = (extra.obj.as_deref(), extra.svg.as_deref());
    let opts = SphereOptions {
        pole: extra.pole,
        ..SphereOptions::default()
    };
    let sol = uniformize_sphere(mesh, lengths, &opts)
        .map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{shown}: {} Euclidean flips to intrinsic Delaunay; pole v{} ({} link vertices); disk problem: {} Newton steps, {} Ptolemy flips, max |Θ − θ| = {:e} (f64)",
        sol.euclidean_flips,
        sol.pole,
        sol.disk.pole_length.iter().flatten().count(),
        sol.solution.steps.len(),
        sol.flip_sequence.len(),
        sol.solution.residual_max
    );
    let (_, outcome) = certify_disk(&sol, BITS);
    let cert_ok = matches!(outcome, CertificateOutcome::Holds { .. });
    match &outcome {
        CertificateOutcome::Holds {
            distance,
            mu,
            residual,
        } => {
            let _ = writeln!(
                out,
                "disk problem certified ({BITS}-bit intervals): an exact solution lies within {distance:e} (2-norm) of u, its disk Delaunay with a convex boundary (Hessian ≥ {mu:e}, ‖Θ − θ(u)‖₂ ≤ {residual:e})"
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
        let (reason, distance) = match &outcome {
            CertificateOutcome::Holds { distance, .. } => (None, Some(*distance)),
            CertificateOutcome::Undecided { reason } => (Some(reason.clone()), None),
        };
        let doc = serde_json::json!({
            "kind": "sphere_uniformization",
            "surface": shown,
            "pole": sol.pole,
            "vertices": sol.positions,
            "faces": sol.mesh.face_list(),
            "flip_sequence": sol.flip_sequence.iter().map(|e| e.0).collect::<Vec<_>>(),
            "disk_certificate": {
                "certified": cert_ok,
                "bits": BITS,
                "distance": distance,
                "reason": reason,
            },
            "planar_delaunay": {
                "certified": planar.holds(),
                "not_ccw": planar.not_ccw.iter().map(|f| f.0).collect::<Vec<_>>(),
                "not_delaunay": planar.not_delaunay.iter().map(|e| e.0).collect::<Vec<_>>(),
                "not_convex": planar.not_convex.iter().map(|v| v.0).collect::<Vec<_>>(),
            },
            "numerical": {
                "residual_max": sol.solution.residual_max,
                "centroid_norm": sol.centroid_norm,
                "cross_ratio_deviation": deviation,
            },
        });
        let text = serde_json::to_string_pretty(&doc).unwrap_or_default() + "\n";
        write_new(path, text.as_bytes())?;
        let _ = writeln!(out, "result written to {}", path.display());
    }
    emit(&out)?;
    Ok(status)
}
