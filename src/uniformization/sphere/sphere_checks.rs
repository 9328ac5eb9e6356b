//! Independent checks of a sphere uniformization ([`super::sphere`], B74, B75):
//!
//! - [`planar_delaunay`]: the laid-out disk (binary64 coordinates, taken exactly) is a
//!   planar Delaunay triangulation of a convex polygon: every triangle certified
//!   counterclockwise (`orient2d`), every interior edge certified locally Delaunay
//!   (`incircle ≤ 0`), every boundary corner certified convex (`orient2d ≥ 0`). By
//!   inverse stereographic projection (a Möbius map, which keeps circles), this is the
//!   convexity of the inscribed polyhedron with the pole's star (B74, "Convexity").
//!   Certified for the layout as computed.
//! - [`cross_ratio_deviation`]: `max_e |log c_e(chords) − log c_e(ℓ⁰ carried)|`, the
//!   length cross ratios of the output polyhedron's 3-D chords against those of the input
//!   lengths carried by the same Ptolemy flips (T16, T17, T20, T28). Numerical; its
//!   tolerance is B75.

use super::sphere::SphereUniformization;
use crate::algorithms::flips::flip_ptolemy;
use crate::geometry::cross_ratio::length_cross_ratios;
use crate::mesh::{Edge, Face, Mesh, Vertex};
use crate::predicates::ladder::Ladder;
use crate::predicates::planar::{incircle, orient2d, point_from_f64, Point};
use crate::scalar::Sign;

/// What [`planar_delaunay`] could not certify; all empty when the layout is proved a
/// Delaunay triangulation of a convex polygon.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PlanarDelaunay {
    /// Faces not certified counterclockwise (folded, flat or undecided).
    pub not_ccw: Vec<Face>,
    /// Interior edges not certified locally Delaunay.
    pub not_delaunay: Vec<Edge>,
    /// Boundary vertices where the boundary is not certified to turn left or go straight.
    pub not_convex: Vec<Vertex>,
}

impl PlanarDelaunay {
    /// Whether everything was certified.
    pub fn holds(&self) -> bool {
        self.not_ccw.is_empty() && self.not_delaunay.is_empty() && self.not_convex.is_empty()
    }
}

/// Certify that `points` (one per vertex of the disk `mesh`) lay `mesh` out as a Delaunay
/// triangulation of a convex polygon (see the module documentation). A non-finite point
/// fails every test it enters.
pub fn planar_delaunay(mesh: &Mesh, points: &[[f64; 2]]) -> PlanarDelaunay {
    let ladder = Ladder::default();
    let exact: Vec<Option<Point>> = points.iter().map(|p| point_from_f64(p[0], p[1])).collect();
    let at = |v: Vertex| exact.get(v.idx()).and_then(Option::as_ref);
    let positive = |a: Vertex, b: Vertex, c: Vertex| match (at(a), at(b), at(c)) {
        (Some(a), Some(b), Some(c)) => orient2d(a, b, c, &ladder).value(),
        _ => None,
    };
    let mut out = PlanarDelaunay::default();
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_vertices(f);
        if positive(a, b, c) != Some(Sign::Positive) {
            out.not_ccw.push(f);
        }
    }
    let mut boundary_from = vec![None; mesh.n_vertices()];
    for e in mesh.edges() {
        let h = e.halfedge();
        if mesh.is_boundary_edge(e) {
            // The side in a face runs with the disk on its left.
            let s = if mesh.is_boundary_halfedge(h) {
                h.twin()
            } else {
                h
            };
            boundary_from[mesh.tail(s).idx()] = Some(s);
            continue;
        }
        let (i, j) = (mesh.tail(h), mesh.tip(h));
        let k = mesh.opposite_vertex(h);
        let l = mesh.opposite_vertex(h.twin());
        let sign = match (at(i), at(j), at(k), at(l)) {
            (Some(i), Some(j), Some(k), Some(l)) => incircle(i, j, k, l, &ladder).value(),
            _ => None,
        };
        if !matches!(sign, Some(Sign::Negative | Sign::Zero)) {
            out.not_delaunay.push(e);
        }
    }
    for s in boundary_from.iter().flatten() {
        let (x, y) = (mesh.tail(*s), mesh.tip(*s));
        let z = boundary_from[y.idx()].map(|t| mesh.tip(t));
        let ok = z.is_some_and(|z| matches!(positive(x, y, z), Some(Sign::Positive | Sign::Zero)));
        if !ok {
            out.not_convex.push(y);
        }
    }
    out.not_convex.sort_unstable_by_key(|v| v.0);
    out
}

/// The chord lengths `|x_i − x_j|` of the output polyhedron on its final triangulation.
pub fn chord_lengths(sol: &SphereUniformization) -> Vec<f64> {
    sol.mesh
        .edges()
        .map(|e| {
            let h = e.halfedge();
            let (a, b) = (
                sol.positions[sol.mesh.tail(h).idx()],
                sol.positions[sol.mesh.tip(h).idx()],
            );
            ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
        })
        .collect()
}

/// `max_e |log c_e(chords) − log c_e(ℓ)|` over the edges of the final triangulation, with
/// `ℓ` the lengths `l0` of `T₀` carried by `sol.flip_sequence` (Ptolemy, T28): zero for an
/// exact solution (T16, T20); `None` when the flips do not replay or a ratio is not
/// positive. Numerical (`f64`); tolerance B75.
pub fn cross_ratio_deviation(sol: &SphereUniformization, l0: &[f64]) -> Option<f64> {
    let mut m = sol.initial_mesh.clone();
    let mut l = l0.to_vec();
    for &e in &sol.flip_sequence {
        flip_ptolemy(&mut m, &mut l, e).ok()?;
    }
    let chords = chord_lengths(sol);
    let a = length_cross_ratios(&m, &l);
    let b = length_cross_ratios(&m, &chords);
    let mut worst: f64 = 0.0;
    for (x, y) in a.iter().zip(&b) {
        let (Some(x), Some(y)) = (x, y) else { continue };
        if !(*x > 0.0 && *y > 0.0) {
            return None;
        }
        worst = worst.max((x.ln() - y.ln()).abs());
    }
    Some(worst)
}
