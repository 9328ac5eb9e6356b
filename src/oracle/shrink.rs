//! Shrinking a failing case to a small reproducing surface: extract the neighbourhood of
//! the failing elements, then remove faces one at a time while the check still fails.

use super::case::MetricOps;
use crate::io::Surface;
use crate::mesh::{Face, Mesh};
use crate::theorems::Witness;
use std::collections::{BTreeSet, HashMap};
use std::time::{Duration, Instant};

/// The sub-surface made of the faces in `keep` (in the given order): vertices renumbered
/// densely, sides glued where both faces are kept, other sides on the boundary, lengths
/// carried over edge by edge. `None` when the faces do not form a valid surface (e.g. a
/// vertex would become non-manifold) or `keep` is empty.
pub fn sub_case(case: &Surface, keep: &[Face]) -> Option<Surface> {
    let mesh = &case.mesh;
    let faces = mesh.face_list();
    let gluing = mesh.gluing_list();
    let mut new_face: HashMap<u32, u32> = HashMap::new();
    let mut vmap: HashMap<u32, u32> = HashMap::new();
    let mut tris = Vec::with_capacity(keep.len());
    for f in keep {
        if f.idx() >= faces.len() || new_face.contains_key(&f.0) {
            return None;
        }
        new_face.insert(f.0, tris.len() as u32);
        let tri = faces[f.idx()].map(|v| {
            let n = vmap.len() as u32;
            *vmap.entry(v).or_insert(n)
        });
        tris.push(tri);
    }
    let glue: Vec<_> = gluing
        .iter()
        .filter_map(|&((fa, sa), (fb, sb))| {
            Some(((*new_face.get(&fa)?, sa), (*new_face.get(&fb)?, sb)))
        })
        .collect();
    let sub = Mesh::from_gluing(vmap.len() as u32, &tris, &glue).ok()?;
    let mut edge_map = vec![usize::MAX; sub.n_edges()];
    for (k, f) in keep.iter().enumerate() {
        let old = mesh.face_halfedges(*f);
        let new = sub.face_halfedges(Face(k as u32));
        for s in 0..3 {
            edge_map[new[s].edge().idx()] = old[s].edge().idx();
        }
    }
    if edge_map.contains(&usize::MAX) {
        return None;
    }
    let mut old_vertex = vec![0usize; vmap.len()];
    for (&old, &new) in &vmap {
        old_vertex[new as usize] = old as usize;
    }
    let positions = case
        .positions
        .as_ref()
        .map(|p| old_vertex.iter().map(|&v| p[v].clone()).collect());
    Some(Surface {
        name: case.name.clone(),
        metric: case.metric.reindex(&edge_map),
        mesh: sub,
        positions,
    })
}

/// The faces touching an element named like a witness: `v3` (faces at vertex 3), `e7`
/// (faces on edge 7), `f2`, `h5`. Unknown names give no face.
pub fn faces_at(mesh: &Mesh, element: &str) -> Vec<Face> {
    let (kind, num) = element.split_at(element.len().min(1));
    let Ok(i) = num.parse::<u32>() else {
        return Vec::new();
    };
    let mut out = BTreeSet::new();
    match kind {
        "f" if (i as usize) < mesh.n_faces() => {
            out.insert(Face(i));
        }
        "v" if (i as usize) < mesh.n_vertices() => {
            for h in mesh.halfedges() {
                if mesh.tail(h).0 == i {
                    out.extend(mesh.face(h));
                }
            }
        }
        "e" if (i as usize) < mesh.n_edges() => {
            let e = crate::mesh::Edge(i);
            out.extend(mesh.face(e.side(0)));
            out.extend(mesh.face(e.side(1)));
        }
        "h" if (i as usize) < mesh.n_halfedges() => {
            out.extend(mesh.face(crate::mesh::HalfEdge(i)));
        }
        _ => {}
    }
    out.into_iter().collect()
}

/// `faces` plus every face sharing a vertex with one of them.
fn grow(mesh: &Mesh, faces: &BTreeSet<Face>) -> BTreeSet<Face> {
    let verts: BTreeSet<u32> = faces
        .iter()
        .flat_map(|&f| mesh.face_vertices(f).map(|v| v.0))
        .collect();
    mesh.faces()
        .filter(|&f| {
            faces.contains(&f) || mesh.face_vertices(f).iter().any(|v| verts.contains(&v.0))
        })
        .collect()
}

/// Limits of one shrink.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    /// Wall-clock limit.
    pub time: Duration,
    /// Maximum number of candidate cases tried.
    pub attempts: usize,
}

impl Default for Budget {
    fn default() -> Budget {
        Budget {
            time: Duration::from_secs(10),
            attempts: 400,
        }
    }
}

/// Shrink `case` while `fails` stays true: first the smallest neighbourhood (k-ring of
/// the witnesses' faces, k = 0…3) that still fails, then greedy removal of single faces.
/// Returns the smallest failing case found (at worst `case` itself).
pub fn shrink(
    case: &Surface,
    witnesses: &[Witness],
    fails: &dyn Fn(&Surface) -> bool,
    budget: Budget,
) -> Surface {
    let start = Instant::now();
    let mut attempts = 0usize;
    let within = |attempts: &mut usize| {
        *attempts += 1;
        *attempts <= budget.attempts && start.elapsed() <= budget.time
    };
    let mut best = case.clone();
    let mut ring: BTreeSet<Face> = witnesses
        .iter()
        .flat_map(|w| faces_at(&case.mesh, &w.element))
        .collect();
    for _ in 0..4 {
        if ring.is_empty() || ring.len() >= case.mesh.n_faces() || !within(&mut attempts) {
            break;
        }
        let keep: Vec<Face> = ring.iter().copied().collect();
        if let Some(sub) = sub_case(case, &keep) {
            if fails(&sub) {
                best = sub;
                break;
            }
        }
        ring = grow(&case.mesh, &ring);
    }
    // Greedy passes: drop one face at a time (from the last face down, so indices of
    // faces not yet visited stay valid) while the check still fails; repeat until a pass
    // removes nothing.
    'passes: loop {
        let mut changed = false;
        let mut i = best.mesh.n_faces();
        while i > 0 && best.mesh.n_faces() > 1 {
            i -= 1;
            if !within(&mut attempts) {
                break 'passes;
            }
            let keep: Vec<Face> = best.mesh.faces().filter(|f| f.idx() != i).collect();
            if let Some(sub) = sub_case(&best, &keep) {
                if fails(&sub) {
                    best = sub;
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    best
}
