//! Texture coordinates on the user's own mesh for the closed flat and cone targets: the
//! common refinement of the input triangulation `T_in` and the final triangulation `T_F`
//! of [`uniformize_closed`](super::uniformize_closed), laid out with the solved metric
//! (issue 29; proofs: B105, B108, B109).
//!
//! The Euclidean flips to `T₀` are recomputed (the solve's deterministic run) and
//! followed by the solve's Ptolemy flips; the input edges are tracked through the first in
//! the input metric (B108) and through the second in the Klein picture of the base metric
//! (B111), then moved to the final metric ([`track_euclidean_then_ptolemy`]). The crossing
//! counts are compared with the normal coordinates replayed independently (B105). `T_F` is
//! laid out with the final lengths `e^{(u_i+u_j)/2} ℓ_ij` (binary64); the map is affine on
//! each face of `T_F`. Along an input edge, the position of a crossing made by a Ptolemy
//! flip is a parametrization choice (B111), not the flat arc length; the properties claimed
//! (no fold, each input face tiled, seams) are checked on the written output (B109, B110).

use super::{BoundaryOutcome, ClosedOutcome, PipelineError};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::io::Surface;
use crate::mesh::double::Sheet;
use crate::mesh::Mesh;
use crate::overlay::check::check_parametrization_text;
use crate::overlay::check::ParametrizationError;
use crate::overlay::tracking::track_euclidean_then_ptolemy;
use crate::overlay::tracking::TrackError;
use crate::overlay::uv::UvError;
use crate::overlay::{check_seams, ParametrizationReport, SeamReport};
use crate::overlay::{common_refinement, replay_normal_coordinates, uv_mesh, Refinement, UvMesh};
use crate::uniformization::newton::Uniformization;
use crate::uniformization::svg::scaled_lengths_f64;
use rug::Rational;

/// The UV mesh of a converged closed-surface outcome of `input` (the surface as given,
/// whose 3-D positions are written): module documentation. Bad input (no positions, an
/// input face with a repeated corner) is [`PipelineError::Unsupported`]; a flip sequence
/// that cannot be followed (a Euclidean flip refused by rounding, a Klein crossing outside
/// its diagonal) or a disagreement of the checks is [`PipelineError::NotComputed`].
pub fn uv_closed(input: &Surface, outcome: &ClosedOutcome) -> Result<UvMesh, PipelineError> {
    let positions = positions_f64(input)?;
    let surface = &outcome.surface;
    let lengths = surface.lengths::<f64>(());
    let (refinement, final_lengths) =
        refinement_of_solve(&surface.mesh, &lengths, &outcome.solution)?;
    let sol = &outcome.solution;
    uv_mesh(
        &surface.mesh,
        &positions,
        &sol.mesh,
        &final_lengths,
        refinement,
        &cones_of(sol),
    )
    .map_err(uv_error)
}

/// The UV mesh of a converged outcome of `input`, a surface with boundary, on copy 1 of
/// the double (issue 29: "the UVs are those of copy 1"). The common refinement is built on
/// the double `D` exactly as for a closed surface (its input triangulation is `D` before
/// any flip), then restricted to the faces `0..F` of copy 1, which keep the ids of the
/// input's faces, edges and vertices (B78); the part of `T_F` they meet is laid out alone.
/// When no seam edge was flipped that part is copy 1 of `T_F`, and on a disk with flat
/// interior it is one chart; otherwise its cut edges are reported by the seam check. The
/// written ids (faces, edges, vertices) are the input's; the final faces and edges in the
/// sidecar are those of the double's final triangulation.
pub fn uv_boundary(input: &Surface, outcome: &BoundaryOutcome) -> Result<UvMesh, PipelineError> {
    let not = |m: &str| PipelineError::NotComputed(format!("UV not computed: {m}"));
    let positions = positions_f64(input)?;
    let b = &outcome.boundary;
    let d = &b.double;
    let m = &outcome.surface.mesh;
    let double_positions: Vec<[f64; 3]> = d
        .vertex_origin
        .iter()
        .map(|v| positions.get(v.idx()).copied())
        .collect::<Option<_>>()
        .ok_or_else(|| not("the double's vertices do not match the input's"))?;
    let lengths = d
        .pull_back_edges(&outcome.surface.lengths::<f64>(()))
        .ok_or_else(|| not("the lengths could not be pulled back to the double"))?;
    let (refinement, final_lengths) = refinement_of_solve(&d.mesh, &lengths, &b.solution)?;
    let copy_1 = refinement
        .restricted_to_input_faces(m.n_faces(), m.n_vertices())
        .ok_or_else(|| not("a triangle of copy 1 lies on a mirror vertex"))?;
    let mut uv = uv_mesh(
        &d.mesh,
        &double_positions,
        &b.solution.mesh,
        &final_lengths,
        copy_1,
        &cones_of(&b.solution),
    )
    .map_err(uv_error)?;
    uv.input_faces = m.n_faces();
    Ok(uv)
}

/// The cones of a solve: the vertices whose target angle is not 2π.
fn cones_of(sol: &Uniformization) -> Vec<bool> {
    sol.targets.over_pi().iter().map(|t| *t != 2).collect()
}

/// The input's vertex positions in binary64 (for the written `v` lines).
fn positions_f64(input: &Surface) -> Result<Vec<[f64; 3]>, PipelineError> {
    Ok(input
        .positions
        .as_ref()
        .ok_or_else(|| PipelineError::Unsupported(UvError::NoPositions.to_string()))?
        .iter()
        .map(|p| [p[0].to_f64(), p[1].to_f64(), p[2].to_f64()])
        .collect())
}

/// A layout error: bad input or not computed.
fn uv_error(e: UvError) -> PipelineError {
    match e {
        UvError::NoPositions | UvError::RepeatedCorner(_) => {
            PipelineError::Unsupported(e.to_string())
        }
        other => PipelineError::NotComputed(format!("UV not computed: {other}")),
    }
}

/// The common refinement of `mesh` (lengths `lengths`, binary64, as the solve read them)
/// and the final triangulation of the converged solve `sol`, and the final lengths
/// `e^{(u_i+u_j)/2} ℓ_ij` of `T_F`: the Euclidean flips to `T₀` recomputed, then the
/// solve's Ptolemy flips, tracked and compared with the normal coordinates (B105).
fn refinement_of_solve(
    mesh: &Mesh,
    lengths: &[f64],
    sol: &Uniformization,
) -> Result<(Refinement, Vec<f64>), PipelineError> {
    let not = |m: String| PipelineError::NotComputed(format!("UV not computed: {m}"));
    if !sol.converged() {
        return Err(not("the solve did not converge".into()));
    }
    let mut t0 = mesh.clone();
    let mut l = lengths.to_vec();
    let opts = FlipOptions {
        record: true,
        ..FlipOptions::default()
    };
    let rep = flip_to_delaunay(&mut t0, &mut l, FlipKind::Euclidean, &opts)
        .map_err(|e| not(e.to_string()))?;
    if t0 != sol.initial_mesh {
        return Err(not(
            "the Euclidean flips do not reproduce the solve's T₀".into()
        ));
    }
    let n_euclidean = rep.sequence.len();
    let tracked = track_euclidean_then_ptolemy(
        mesh,
        lengths,
        &rep.sequence,
        &sol.flip_sequence,
        Some(&sol.u),
    )
    .map_err(|e| match e {
        TrackError::Inconsistent { flip, edge, reason } if flip >= n_euclidean => not(format!(
            "Ptolemy flip {} (edge {edge}): {reason}",
            flip - n_euclidean
        )),
        other => not(other.to_string()),
    })?;
    let mut flips = rep.sequence;
    flips.extend_from_slice(&sol.flip_sequence);
    if tracked.mesh != sol.mesh {
        return Err(not(
            "the flips do not reproduce the solve's final triangulation".into(),
        ));
    }
    let (_, normal) = replay_normal_coordinates(mesh, &flips).map_err(|e| not(e.to_string()))?;
    if normal.values() != tracked.crossing_counts().as_slice() {
        return Err(not(
            "the tracked crossings disagree with the normal coordinates (B105)".into(),
        ));
    }
    let refinement = common_refinement(mesh, &tracked).map_err(|e| not(e.to_string()))?;
    Ok((
        refinement,
        scaled_lengths_f64(&sol.mesh, &sol.base_lengths, &sol.u),
    ))
}

/// Which input vertices are cones of a UV mesh, and whether its seams are checked (B110):
/// the transitions across cut edges are rotations by multiples of π/2 when every cone
/// angle the layout can be cut around is such a multiple.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UvCones {
    /// Per input vertex: its target angle is not 2π (drawn as a cone).
    pub cones: Vec<bool>,
    /// Every relevant cone angle is a multiple of π/2 (the seam check applies).
    pub quarter_turns: bool,
}

/// Whether `Θ/π` is a multiple of `1/2`.
fn quarter_turn(t: &Rational) -> bool {
    Rational::from(t * 2u32).is_integer()
}

impl UvCones {
    /// The cones of [`uv_closed`]'s mesh: every vertex whose target is not 2π; the seams
    /// are checked when every target is a multiple of π/2.
    pub fn of_closed(outcome: &ClosedOutcome) -> Self {
        let t = outcome.solution.targets.over_pi();
        Self {
            cones: t.iter().map(|t| *t != 2).collect(),
            quarter_turns: t.iter().all(quarter_turn),
        }
    }

    /// The cones of [`uv_boundary`]'s mesh: the input's vertices whose angle on the double
    /// is not 2π (interior cones and boundary corners). Copy 1 is cut only around interior
    /// vertices when the seam is intact, so the seams are checked when every interior
    /// target (and, if a seam edge was flipped, every boundary one) is a multiple of π/2.
    pub fn of_boundary(outcome: &BoundaryOutcome) -> Self {
        let b = &outcome.boundary;
        let t = b.solution.targets.over_pi();
        let n = outcome.surface.mesh.n_vertices();
        let flipped = !b.seam_flips.is_empty();
        Self {
            cones: t.iter().take(n).map(|t| *t != 2).collect(),
            quarter_turns: t
                .iter()
                .zip(&b.double.vertex_sheet)
                .filter(|(_, s)| **s == Sheet::Original || flipped)
                .all(|(t, _)| quarter_turn(t)),
        }
    }
}

/// The exact checks of a written UV mesh: folds and tiling (B109) and, when the cones
/// allow it, the seams within the relative tolerance `seam_epsilon` (B110).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WrittenUvChecks {
    /// No fold, every input face tiled.
    pub parametrization: ParametrizationReport,
    /// The seams (`None`: not every cone angle is a multiple of π/2).
    pub seams: Option<SeamReport>,
}

/// Check the OBJ text `obj` and its sidecar's text `sidecar` as written (module
/// documentation).
pub fn check_written_uv(
    obj: &str,
    sidecar: &str,
    cones: &UvCones,
    seam_epsilon: &Rational,
) -> Result<WrittenUvChecks, ParametrizationError> {
    let parametrization = check_parametrization_text(obj, sidecar)?;
    let seams = if cones.quarter_turns {
        Some(check_seams(obj, seam_epsilon)?)
    } else {
        None
    };
    Ok(WrittenUvChecks {
        parametrization,
        seams,
    })
}
