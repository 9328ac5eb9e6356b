//! The choice of the pole `v∞` of the sphere target (B74): which vertices qualify
//! ([`check_pole`]) and the order in which the default poles are tried
//! ([`pole_candidates`]: a graph centre first, then the vertices of largest degree).
//!
//! The pole only steers the computation: every pole gives the same inscribed polyhedron up
//! to a Möbius map, and the certificate (B76) decides. But the planar layout of the disk
//! `M − star(v∞)` crowds the parts of the surface far from the pole towards a point, by a
//! factor that grows exponentially with the distance along a thin part (a limb, a blade).
//! A pole at the graph centre halves the longest such distance, so the binary64 layout of a
//! long body keeps its far ends above the resolution of `f64`.

use crate::mesh::{Mesh, Vertex};
use std::collections::VecDeque;

/// How many default poles [`super::sphere::uniformize_sphere`] tries.
pub const POLE_ATTEMPTS: usize = 4;

/// Whether the star of `v` in `mesh` is a disk with a simple link: no loop at `v`, every
/// face at `v` has `v` once, the neighbours of `v` are distinct, and some face lies
/// outside the star. `Err(reason)` otherwise.
pub fn check_pole(mesh: &Mesh, v: Vertex) -> Result<(), String> {
    if v.idx() >= mesh.n_vertices() {
        return Err(format!(
            "out of range (the surface has {} vertices)",
            mesh.n_vertices()
        ));
    }
    // O(deg v): the faces at `v` are those of its outgoing half-edges (every corner at `v`
    // starts one), so no pass over the whole mesh per candidate pole.
    let mut seen = std::collections::HashSet::new();
    let mut star: Vec<usize> = Vec::new();
    for h in mesh.outgoing(v) {
        let w = mesh.tip(h);
        if w == v {
            return Err(format!("edge e{} is a loop at the pole", h.edge().0));
        }
        if !seen.insert(w) {
            return Err(format!("two edges join the pole to v{}", w.0));
        }
        star.extend(mesh.face(h).map(crate::mesh::Face::idx));
    }
    star.sort_unstable();
    star.dedup();
    let star = star.len();
    if star == mesh.n_faces() {
        return Err("every face contains the pole: nothing is left to lay out".into());
    }
    Ok(())
}

/// The number of edges on a shortest path from `from` to every vertex of `mesh` (the
/// 1-skeleton's graph distance, by breadth-first search); `u32::MAX` where unreachable.
pub fn hop_distances(mesh: &Mesh, from: Vertex) -> Vec<u32> {
    let mut d = vec![u32::MAX; mesh.n_vertices()];
    let mut queue = VecDeque::from([from]);
    d[from.idx()] = 0;
    while let Some(v) = queue.pop_front() {
        for h in mesh.outgoing(v) {
            let w = mesh.tip(h);
            if d[w.idx()] == u32::MAX {
                d[w.idx()] = d[v.idx()] + 1;
                queue.push_back(w);
            }
        }
    }
    d
}

/// The vertex farthest from `from` in hops (the smallest index among ties).
fn farthest(d: &[u32]) -> Vertex {
    let (i, _) = d
        .iter()
        .enumerate()
        .filter(|&(_, &x)| x != u32::MAX)
        .max_by_key(|&(i, &x)| (x, std::cmp::Reverse(i)))
        .expect("a breadth-first search reaches its start");
    Vertex(u32::try_from(i).expect("vertex index fits u32"))
}

/// An approximate graph centre of `mesh`: the two ends `a`, `b` of a double sweep
/// (`a` farthest from vertex 0, `b` farthest from `a`: a long shortest path, exactly a
/// diameter on a tree) and the vertex minimising `max(d(a, ·), d(b, ·))` among those that
/// pass [`check_pole`] (ties: the smaller `d(a, ·) + d(b, ·)`, then the larger degree, then
/// the smaller index). On a path-like surface (a tube, a limb) this is the middle of its
/// length. `None` when no vertex qualifies.
pub fn graph_centre(mesh: &Mesh) -> Option<Vertex> {
    let admissible: Vec<bool> = mesh
        .vertices()
        .map(|v| check_pole(mesh, v).is_ok())
        .collect();
    centre_among(mesh, &admissible)
}

/// [`graph_centre`] among the vertices with `admissible[v]` (those passing [`check_pole`],
/// computed once by the caller).
fn centre_among(mesh: &Mesh, admissible: &[bool]) -> Option<Vertex> {
    if mesh.n_vertices() == 0 {
        return None;
    }
    let a = farthest(&hop_distances(mesh, Vertex(0)));
    let da = hop_distances(mesh, a);
    let b = farthest(&da);
    let db = hop_distances(mesh, b);
    mesh.vertices()
        .filter(|&v| da[v.idx()] != u32::MAX && admissible[v.idx()])
        .min_by_key(|&v| {
            let (x, y) = (u64::from(da[v.idx()]), u64::from(db[v.idx()]));
            (x.max(y), x + y, std::cmp::Reverse(mesh.degree(v)), v.0)
        })
}

/// Default poles, tried in this order until the disk problem converges: the
/// [`graph_centre`], then the vertices that pass [`check_pole`] by decreasing degree and
/// increasing index; the first [`POLE_ATTEMPTS`] of these.
pub fn pole_candidates(mesh: &Mesh) -> Vec<Vertex> {
    let admissible: Vec<bool> = mesh
        .vertices()
        .map(|v| check_pole(mesh, v).is_ok())
        .collect();
    let centre = centre_among(mesh, &admissible);
    let mut v: Vec<Vertex> = mesh
        .vertices()
        .filter(|&v| Some(v) != centre && admissible[v.idx()])
        .collect();
    v.sort_by_key(|&w| (std::cmp::Reverse(mesh.degree(w)), w.0));
    v.truncate(POLE_ATTEMPTS.saturating_sub(usize::from(centre.is_some())));
    centre.into_iter().chain(v).collect()
}
