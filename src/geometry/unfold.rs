//! Unfolding a triangulated surface with edge lengths into the plane (`f64`, for layouts and
//! pictures): faces are placed breadth first along a spanning tree of the dual graph, each
//! new face from the shared edge and its two other lengths ([`third_corner`]). On a surface
//! that is not a simply connected flat disk the result is a fundamental domain: a vertex
//! gets one position per face corner.

use crate::mesh::{Edge, Face, HalfEdge, Mesh};
use std::collections::VecDeque;

/// The third corner `k` of the counterclockwise triangle `p, q, k` with `|pk| = a`,
/// `|qk| = b`: `k = p + s·e + h·e⊥`, `e = (q − p)/d`, `d = |q − p|`,
/// `s = (a² − b² + d²)/(2d)`, `h = √max(a² − s², 0)` (0 if rounding makes it negative).
pub fn third_corner(p: [f64; 2], q: [f64; 2], a: f64, b: f64) -> [f64; 2] {
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    let d = dx.hypot(dy);
    let (ex, ey) = (dx / d, dy / d);
    let s = (a * a - b * b + d * d) / (2.0 * d);
    let h = (a * a - s * s).max(0.0).sqrt();
    [p[0] + s * ex - h * ey, p[1] + s * ey + h * ex]
}

/// An unfolding: the position of the tail of every face half-edge in its face, and per face
/// the half-edge through which it was reached.
#[derive(Clone, Debug)]
pub struct Unfolded {
    /// Position of `tail(h)` in the face of `h` (`None` for boundary half-edges and faces
    /// not reached).
    pub corner: Vec<Option<[f64; 2]>>,
    /// The half-edge of the face through which it was reached (`None` for the root face
    /// and faces not reached).
    pub parent: Vec<Option<HalfEdge>>,
}

/// Unfold `mesh` with `lengths` (per edge) from face `root`, its first half-edge on the
/// positive x-axis from the origin, breadth first over the dual graph through the faces
/// with `kept(f)` only. Nothing is laid out when `root` is not a kept face or `lengths` has
/// not one entry per edge.
pub fn unfold_faces(
    mesh: &Mesh,
    lengths: &[f64],
    root: Face,
    kept: impl Fn(Face) -> bool,
) -> Unfolded {
    unfold_across(mesh, lengths, root, kept, |_| true)
}

/// [`unfold_faces`] crossing only the edges with `cross(e)` (e.g. all but a cut graph).
pub fn unfold_across(
    mesh: &Mesh,
    lengths: &[f64],
    root: Face,
    kept: impl Fn(Face) -> bool,
    cross: impl Fn(Edge) -> bool,
) -> Unfolded {
    let mut corner: Vec<Option<[f64; 2]>> = vec![None; mesh.n_halfedges()];
    let mut parent = vec![None; mesh.n_faces()];
    if root.idx() >= mesh.n_faces() || lengths.len() != mesh.n_edges() || !kept(root) {
        return Unfolded { corner, parent };
    }
    let len = |h: HalfEdge| lengths[h.edge().idx()];
    let place = |corner: &mut Vec<Option<[f64; 2]>>, h: HalfEdge, p: [f64; 2], q: [f64; 2]| {
        let (n, pr) = (mesh.next(h), mesh.prev(h));
        corner[h.idx()] = Some(p);
        corner[n.idx()] = Some(q);
        corner[pr.idx()] = Some(third_corner(p, q, len(pr), len(n)));
    };
    let h0 = mesh.face_halfedge(root);
    place(&mut corner, h0, [0.0, 0.0], [len(h0), 0.0]);
    dual_breadth_first_across(mesh, root, kept, cross, |t| {
        // t runs from tip(h) to tail(h), h = twin(t) in a face laid out before.
        let h = t.twin();
        let (g, p, q) = (mesh.face(t), corner[mesh.next(h).idx()], corner[h.idx()]);
        if let (Some(g), Some(p), Some(q)) = (g, p, q) {
            place(&mut corner, t, p, q);
            parent[g.idx()] = Some(t);
        }
    });
    Unfolded { corner, parent }
}

/// Breadth first over the dual graph from face `root` through the faces with `kept(f)`:
/// `enter(t)` once for every other face reached, with `t` its half-edge whose twin lies in
/// the face it is reached from (entered before it).
pub fn dual_breadth_first(
    mesh: &Mesh,
    root: Face,
    kept: impl Fn(Face) -> bool,
    enter: impl FnMut(HalfEdge),
) {
    dual_breadth_first_across(mesh, root, kept, |_| true, enter);
}

/// [`dual_breadth_first`] crossing only the edges with `cross(e)`.
pub fn dual_breadth_first_across(
    mesh: &Mesh,
    root: Face,
    kept: impl Fn(Face) -> bool,
    cross: impl Fn(Edge) -> bool,
    mut enter: impl FnMut(HalfEdge),
) {
    let mut seen = vec![false; mesh.n_faces()];
    if root.idx() >= mesh.n_faces() {
        return;
    }
    seen[root.idx()] = true;
    let mut queue = VecDeque::from([root]);
    while let Some(f) = queue.pop_front() {
        for h in mesh.face_halfedges(f) {
            let t = h.twin();
            let Some(g) = mesh.face(t) else { continue };
            if seen[g.idx()] || !kept(g) || !cross(t.edge()) {
                continue;
            }
            enter(t);
            seen[g.idx()] = true;
            queue.push_back(g);
        }
    }
}
