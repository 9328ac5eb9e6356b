//! Planar layout of a triangulated surface with a metric, face by face along a spanning
//! tree of the dual graph (closed surfaces are cut open along the other edges): every face
//! keeps its shape, and a vertex gets one position per face corner. For pictures (`f64`).

use crate::mesh::{HalfEdge, Mesh};
use std::collections::VecDeque;

/// The third corner `k` of a triangle `p, q, k` (counterclockwise) with `|pk| = a`,
/// `|qk| = b`: `k = p + s·e + h·e⊥` with `e = (q − p)/|q − p|`,
/// `s = (a² − b² + d²)/(2d)`, `h = √(a² − s²)` (0 if rounding makes it negative).
pub fn third_corner(p: [f64; 2], q: [f64; 2], a: f64, b: f64) -> [f64; 2] {
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    let d = dx.hypot(dy);
    let (ex, ey) = (dx / d, dy / d);
    let s = (a * a - b * b + d * d) / (2.0 * d);
    let h = (a * a - s * s).max(0.0).sqrt();
    [p[0] + s * ex - h * ey, p[1] + s * ey + h * ex]
}

/// The position of the tail of every face half-edge (`None` for boundary half-edges and
/// faces of other components), laying out face 0 with its first half-edge on the positive
/// x-axis and its neighbours breadth first.
pub fn layout_faces(mesh: &Mesh, lengths: &[f64]) -> Vec<Option<[f64; 2]>> {
    let mut pos: Vec<Option<[f64; 2]>> = vec![None; mesh.n_halfedges()];
    let mut seen = vec![false; mesh.n_faces()];
    let Some(f0) = mesh.faces().next() else {
        return pos;
    };
    let len = |h: HalfEdge| lengths[h.edge().idx()];
    let place = |pos: &mut Vec<Option<[f64; 2]>>, h: HalfEdge, p: [f64; 2], q: [f64; 2]| {
        let (n, pr) = (mesh.next(h), mesh.prev(h));
        pos[h.idx()] = Some(p);
        pos[n.idx()] = Some(q);
        pos[pr.idx()] = Some(third_corner(p, q, len(pr), len(n)));
    };
    let h0 = mesh.face_halfedge(f0);
    place(&mut pos, h0, [0.0, 0.0], [len(h0), 0.0]);
    seen[f0.idx()] = true;
    let mut queue = VecDeque::from([f0]);
    while let Some(f) = queue.pop_front() {
        for h in mesh.face_halfedges(f) {
            let t = h.twin();
            let Some(g) = mesh.face(t) else { continue };
            if seen[g.idx()] {
                continue;
            }
            let (Some(p), Some(q)) = (pos[mesh.next(h).idx()], pos[h.idx()]) else {
                continue;
            };
            // t runs from tip(h) to tail(h).
            place(&mut pos, t, p, q);
            seen[g.idx()] = true;
            queue.push_back(g);
        }
    }
    pos
}
