//! Planar layout of a flat (or flattened) metric by unfolding: faces are placed breadth
//! first along a spanning tree of the dual graph, each new face from the shared edge and
//! its two other lengths. On a surface that is not a simply connected flat disk (a torus,
//! cones) the layout is a fundamental domain: the surface is cut along the edges not in
//! the tree and a vertex gets one position per face corner.
//!
//! The layout is computed in `f64`; whether it folds is *decided* afterwards by the
//! certified orientation of every laid-out triangle ([`face_orientations`], exact
//! `orient2d` on the binary64 coordinates, B25), so a fold is never hidden by rounding.

use crate::geometry::unfold::{unfold_faces, Unfolded};
use crate::mesh::{Face, HalfEdge, Mesh};
use crate::predicates::ladder::Ladder;
use crate::predicates::planar::{orient2d, point_from_f64};
use crate::scalar::{Certified, Sign};

pub use crate::geometry::unfold::third_corner;

/// A layout: the position of the tail of every face half-edge (`None` for boundary
/// half-edges and for faces not reached), and the dual spanning tree used.
#[derive(Clone, Debug)]
pub struct Layout {
    /// Position of `tail(h)` in the face of `h`, per half-edge.
    pub corner: Vec<Option<[f64; 2]>>,
    /// Per face, the half-edge of the face through which it was reached (`None` for the
    /// root face and faces not reached).
    pub parent: Vec<Option<HalfEdge>>,
}

impl Layout {
    /// The three corner positions of face `f`, if laid out.
    pub fn face_corners(&self, mesh: &Mesh, f: Face) -> Option<[[f64; 2]; 3]> {
        let [a, b, c] = mesh.face_halfedges(f);
        Some([
            self.corner[a.idx()]?,
            self.corner[b.idx()]?,
            self.corner[c.idx()]?,
        ])
    }

    /// Whether edge `h.edge()` is cut (its two sides laid out in different places):
    /// not a tree edge and not on the boundary.
    pub fn is_cut(&self, mesh: &Mesh, h: HalfEdge) -> bool {
        let t = h.twin();
        let (Some(f), Some(g)) = (mesh.face(h), mesh.face(t)) else {
            return false;
        };
        self.parent[f.idx()] != Some(h) && self.parent[g.idx()] != Some(t)
    }

    /// One position per vertex: the first corner laid out at it (a disk layout, where all
    /// corners of a vertex agree up to rounding); `None` for vertices not reached.
    pub fn vertex_positions(&self, mesh: &Mesh) -> Vec<Option<[f64; 2]>> {
        let mut out = vec![None; mesh.n_vertices()];
        for f in mesh.faces() {
            for h in mesh.face_halfedges(f) {
                let v = mesh.tail(h).idx();
                if out[v].is_none() {
                    out[v] = self.corner[h.idx()];
                }
            }
        }
        out
    }
}

/// Unfold `mesh` with edge `lengths` from face `root` (its first half-edge on the positive
/// x-axis from the origin), breadth first over the dual graph.
pub fn unfold(mesh: &Mesh, lengths: &[f64], root: Face) -> Layout {
    unfold_within(mesh, lengths, root, None)
}

/// [`unfold`] over the faces with `keep[f]` only (all faces for `None`): the layout of a
/// region, never crossing into a face outside it (e.g. copy 1 of a double, B79).
pub fn unfold_within(mesh: &Mesh, lengths: &[f64], root: Face, keep: Option<&[bool]>) -> Layout {
    let kept = |f: Face| keep.is_none_or(|k| k.get(f.idx()).copied().unwrap_or(false));
    let Unfolded { corner, parent } = unfold_faces(mesh, lengths, root, kept);
    Layout { corner, parent }
}

/// The certified orientation of every laid-out face (counterclockwise is
/// [`Sign::Positive`]): exact `orient2d` of the binary64 corner positions through the
/// ladder (B25). `None` for faces not laid out or with a non-finite corner.
pub fn face_orientations(mesh: &Mesh, layout: &Layout) -> Vec<Option<Certified<Sign>>> {
    let ladder = Ladder::default();
    mesh.faces()
        .map(|f| {
            let c = layout.face_corners(mesh, f)?;
            let [a, b, c] = [
                point_from_f64(c[0][0], c[0][1])?,
                point_from_f64(c[1][0], c[1][1])?,
                point_from_f64(c[2][0], c[2][1])?,
            ];
            Some(orient2d(&a, &b, &c, &ladder))
        })
        .collect()
}

/// The faces whose laid-out triangle is not certified counterclockwise (folded,
/// degenerate, undecided or not laid out): empty when the layout provably has no fold.
pub fn unproved_faces(mesh: &Mesh, layout: &Layout) -> Vec<Face> {
    face_orientations(mesh, layout)
        .into_iter()
        .zip(mesh.faces())
        .filter(|(o, _)| o.as_ref().and_then(Certified::value) != Some(Sign::Positive))
        .map(|(_, f)| f)
        .collect()
}

/// The largest mismatch of the layout's cut edges from a translation, relative to the
/// layout's diameter: for a cut edge laid out as `p → q` in one face and `q' → p'` in the
/// other, `|(p' − p) − (q' − q)|/diam`. A flat torus's fundamental domain tiles the plane
/// by translations, so this vanishes up to the layout's rounding and the solve's residual
/// (B75); a cone (rotational holonomy) makes it of the order of the cone's defect.
/// `None` when a face is not laid out.
pub fn cut_translation_mismatch(mesh: &Mesh, layout: &Layout) -> Option<f64> {
    let (mut x0, mut y0, mut x1, mut y1) = (f64::MAX, f64::MAX, f64::MIN, f64::MIN);
    for p in layout.corner.iter().flatten() {
        x0 = x0.min(p[0]);
        y0 = y0.min(p[1]);
        x1 = x1.max(p[0]);
        y1 = y1.max(p[1]);
    }
    let diam = (x1 - x0).hypot(y1 - y0);
    let mut worst: f64 = 0.0;
    for h in mesh.halfedges() {
        if mesh.face(h).is_none() || !layout.is_cut(mesh, h) {
            continue;
        }
        let t = h.twin();
        let p = layout.corner[h.idx()]?;
        let q = layout.corner[mesh.next(h).idx()]?;
        let q2 = layout.corner[t.idx()]?;
        let p2 = layout.corner[mesh.next(t).idx()]?;
        let d = ((p2[0] - p[0]) - (q2[0] - q[0])).hypot((p2[1] - p[1]) - (q2[1] - q[1]));
        worst = worst.max(d / diam);
    }
    Some(worst)
}
