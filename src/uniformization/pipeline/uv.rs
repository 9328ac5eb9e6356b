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

use super::{ClosedOutcome, PipelineError};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::io::Surface;
use crate::overlay::tracking::track_euclidean_then_ptolemy;
use crate::overlay::tracking::TrackError;
use crate::overlay::uv::UvError;
use crate::overlay::{common_refinement, replay_normal_coordinates, uv_mesh, UvMesh};
use crate::uniformization::svg::scaled_lengths_f64;

/// The UV mesh of a converged closed-surface outcome of `input` (the surface as given,
/// whose 3-D positions are written): module documentation. Bad input (no positions, an
/// input face with a repeated corner) is [`PipelineError::Unsupported`]; a flip sequence
/// that cannot be followed (a Euclidean flip refused by rounding, a Klein crossing outside
/// its diagonal) or a disagreement of the checks is [`PipelineError::NotComputed`].
pub fn uv_closed(input: &Surface, outcome: &ClosedOutcome) -> Result<UvMesh, PipelineError> {
    let not = |m: String| PipelineError::NotComputed(format!("UV not computed: {m}"));
    let sol = &outcome.solution;
    if !sol.converged() {
        return Err(not("the solve did not converge".into()));
    }
    let positions: Vec<[f64; 3]> = input
        .positions
        .as_ref()
        .ok_or_else(|| PipelineError::Unsupported(UvError::NoPositions.to_string()))?
        .iter()
        .map(|p| [p[0].to_f64(), p[1].to_f64(), p[2].to_f64()])
        .collect();
    let surface = &outcome.surface;
    let lengths = surface.lengths::<f64>(());
    let mut t0 = surface.mesh.clone();
    let mut l = lengths.clone();
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
        &surface.mesh,
        &lengths,
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
    let (_, normal) =
        replay_normal_coordinates(&surface.mesh, &flips).map_err(|e| not(e.to_string()))?;
    if normal.values() != tracked.crossing_counts().as_slice() {
        return Err(not(
            "the tracked crossings disagree with the normal coordinates (B105)".into(),
        ));
    }
    let refinement = common_refinement(&surface.mesh, &tracked).map_err(|e| not(e.to_string()))?;
    let final_lengths = scaled_lengths_f64(&sol.mesh, &sol.base_lengths, &sol.u);
    uv_mesh(
        &surface.mesh,
        &positions,
        &sol.mesh,
        &final_lengths,
        refinement,
    )
    .map_err(|e| match e {
        UvError::NoPositions | UvError::RepeatedCorner(_) => {
            PipelineError::Unsupported(e.to_string())
        }
        other => not(other.to_string()),
    })
}
