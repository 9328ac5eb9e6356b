//! A cut graph through the cones (proof: B113): the edges along which a connected set of
//! faces is cut open into a topological disk whose interior holds no cone, so that a flat
//! cone metric on it develops into the plane consistently across every edge not cut.
//!
//! The faces are spanned breadth first through the edges they share (a dual spanning
//! tree); the shared edges outside the tree are the cut graph of that tree, which meets
//! every vertex. Then every non-terminal vertex (terminals: the cones and the vertices on
//! the region's boundary) that is the end of exactly one cut edge is freed, repeatedly:
//! the edge is no longer cut. What remains is a forest joining the cones to each other and
//! to the boundary, plus the loops the topology needs (`2g` on a closed surface of genus
//! `g`).
//!
//! ```
//! use penner::mesh::builders;
//! use penner::mesh::cut::cut_through_cones;
//! use penner::mesh::Face;
//! // The octahedron with cones at vertices 0 and 1 (antipodal): one path of cut edges
//! // joins them, two edges long.
//! let m = builders::octahedron().mesh;
//! let cones: Vec<bool> = (0..6).map(|v| v < 2).collect();
//! let cut = cut_through_cones(&m, &vec![true; m.n_faces()], Face(0), &cones);
//! assert_eq!(cut.iter().filter(|&&c| c).count(), 2);
//! ```

use super::{Edge, Face, Mesh};
use std::collections::VecDeque;

/// The cut edges (per edge) of the faces with `region[f]` reached from `root` through
/// shared edges, with `cone[v]` marking the vertices around which the metric does not
/// close up (module documentation). Edges not shared by two reached faces are never cut.
pub fn cut_through_cones(mesh: &Mesh, region: &[bool], root: Face, cone: &[bool]) -> Vec<bool> {
    let in_region = |f: Option<Face>| f.is_some_and(|f| region.get(f.idx()).copied() == Some(true));
    let mut cut = vec![false; mesh.n_edges()];
    if !in_region(Some(root)) {
        return cut;
    }
    let mut reached = vec![false; mesh.n_faces()];
    let mut tree = vec![false; mesh.n_edges()];
    reached[root.idx()] = true;
    let mut queue = VecDeque::from([root]);
    while let Some(f) = queue.pop_front() {
        for h in mesh.face_halfedges(f) {
            let t = h.twin();
            match mesh.face(t) {
                Some(g) if in_region(Some(g)) && !reached[g.idx()] => {
                    reached[g.idx()] = true;
                    tree[t.edge().idx()] = true;
                    queue.push_back(g);
                }
                _ => {}
            }
        }
    }
    let shared = |e: Edge| {
        let [a, b] = [e.side(0), e.side(1)].map(|h| mesh.face(h));
        matches!((a, b), (Some(a), Some(b)) if reached[a.idx()] && reached[b.idx()])
    };
    let mut terminal: Vec<bool> = mesh
        .vertices()
        .map(|v| cone.get(v.idx()).copied() == Some(true))
        .collect();
    let mut degree = vec![0u32; mesh.n_vertices()];
    let mut incident: Vec<Vec<Edge>> = vec![Vec::new(); mesh.n_vertices()];
    for e in mesh.edges() {
        let h = e.side(0);
        let ends = [mesh.tail(h), mesh.tip(h)];
        let touches = [h, h.twin()]
            .iter()
            .any(|&g| mesh.face(g).is_some_and(|f| reached[f.idx()]));
        if !touches {
            continue;
        }
        if !shared(e) {
            // The region's boundary: its vertices are terminals.
            for v in ends {
                terminal[v.idx()] = true;
            }
        } else if !tree[e.idx()] {
            cut[e.idx()] = true;
            for v in ends {
                degree[v.idx()] += 1;
                incident[v.idx()].push(e);
            }
        }
    }
    let mut leaves: Vec<usize> = (0..mesh.n_vertices())
        .filter(|&v| degree[v] == 1 && !terminal[v])
        .collect();
    while let Some(v) = leaves.pop() {
        if degree[v] != 1 {
            continue;
        }
        let Some(&e) = incident[v].iter().find(|e| cut[e.idx()]) else {
            continue;
        };
        cut[e.idx()] = false;
        let h = e.side(0);
        for w in [mesh.tail(h), mesh.tip(h)] {
            degree[w.idx()] -= 1;
            if degree[w.idx()] == 1 && !terminal[w.idx()] {
                leaves.push(w.idx());
            }
        }
    }
    cut
}
