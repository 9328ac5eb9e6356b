//! Comparing two Δ-complexes on one vertex set up to renumbering of edges and faces.
//!
//! Flips keep vertex ids and change everything else, so two triangulations of one surface
//! are "the same" when a bijection of half-edges maps each half-edge to one with the same
//! tail and tip and preserves the gluing: `φ(twin h) = twin φ(h)`, `φ(next h) = next φ(h)`,
//! and face half-edges to face half-edges. Comparing face lists alone is not enough on a
//! Δ-complex: with loops and multi-edges (the one-vertex torus has three loops at one
//! vertex) the vertex triples do not determine the gluing.
//!
//! Several such bijections can exist (symmetries that fix every vertex, e.g. the
//! rotations of the one-vertex torus); [`isomorphisms`] lists them, up to a limit, so that
//! a caller can compare per-edge data under each.

use crate::mesh::{Edge, HalfEdge, Mesh};

/// A half-edge bijection from one mesh onto another that fixes vertex ids and preserves
/// the gluing (module documentation).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Relabeling {
    /// `halfedges[h]` is the image of half-edge `h`.
    pub halfedges: Vec<HalfEdge>,
}

impl Relabeling {
    /// The image of edge `e` (the edge of the image of its first half-edge).
    pub fn edge(&self, e: Edge) -> Edge {
        self.halfedges.get(e.side(0).idx()).map_or(e, |h| h.edge())
    }
}

/// The connected components of `m`'s half-edges under `twin` and `next`, each given by one
/// face half-edge (every component holds a face: a boundary half-edge's twin has one).
fn component_roots(m: &Mesh) -> Vec<HalfEdge> {
    let n = m.n_halfedges();
    let mut seen = vec![false; n];
    let mut roots = Vec::new();
    for start in m.halfedges() {
        if seen[start.idx()] || m.is_boundary_halfedge(start) {
            continue;
        }
        roots.push(start);
        let mut stack = vec![start];
        seen[start.idx()] = true;
        while let Some(h) = stack.pop() {
            for g in [h.twin(), m.next(h)] {
                if !std::mem::replace(&mut seen[g.idx()], true) {
                    stack.push(g);
                }
            }
        }
    }
    roots
}

/// Extend `h0 ↦ g0` over `h0`'s component; `None` if the gluing disagrees somewhere.
/// `map`/`inv` hold the images fixed so far (other components) and are left unchanged on
/// failure; on success the new pairs are returned (not yet written into `map`).
fn extend(
    a: &Mesh,
    b: &Mesh,
    h0: HalfEdge,
    g0: HalfEdge,
    map: &[Option<HalfEdge>],
    inv: &[Option<HalfEdge>],
) -> Option<Vec<(HalfEdge, HalfEdge)>> {
    let mut local: std::collections::HashMap<u32, HalfEdge> = std::collections::HashMap::new();
    let mut local_inv: std::collections::HashMap<u32, HalfEdge> = std::collections::HashMap::new();
    let mut pairs = Vec::new();
    let mut stack = vec![(h0, g0)];
    while let Some((h, g)) = stack.pop() {
        if let Some(&x) = local.get(&h.0) {
            if x != g {
                return None;
            }
            continue;
        }
        if map[h.idx()].is_some() || inv[g.idx()].is_some() || local_inv.contains_key(&g.0) {
            return None;
        }
        if a.tail(h) != b.tail(g)
            || a.tip(h) != b.tip(g)
            || a.is_boundary_halfedge(h) != b.is_boundary_halfedge(g)
        {
            return None;
        }
        local.insert(h.0, g);
        local_inv.insert(g.0, h);
        pairs.push((h, g));
        stack.push((h.twin(), g.twin()));
        stack.push((a.next(h), b.next(g)));
    }
    Some(pairs)
}

/// Every relabeling of `a` onto `b` (module documentation; proof: B81), at most `limit` of them, in a
/// deterministic order. Empty when the two are not the same triangulation.
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::mesh::relabel::isomorphisms;
/// let a = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
/// let b = Mesh::from_faces(4, &[[2, 3, 0], [1, 2, 0]]).unwrap();
/// assert_eq!(isomorphisms(&a, &b, 8).len(), 1);
/// // The other diagonal is a different triangulation.
/// let c = Mesh::from_faces(4, &[[0, 1, 3], [1, 2, 3]]).unwrap();
/// assert!(isomorphisms(&a, &c, 8).is_empty());
/// ```
pub fn isomorphisms(a: &Mesh, b: &Mesh, limit: usize) -> Vec<Relabeling> {
    if a.n_vertices() != b.n_vertices()
        || a.n_halfedges() != b.n_halfedges()
        || a.n_faces() != b.n_faces()
    {
        return Vec::new();
    }
    let roots = component_roots(a);
    let mut out = Vec::new();
    let mut map = vec![None; a.n_halfedges()];
    let mut inv = vec![None; b.n_halfedges()];
    search(a, b, &roots, &mut map, &mut inv, limit, &mut out);
    out
}

fn search(
    a: &Mesh,
    b: &Mesh,
    roots: &[HalfEdge],
    map: &mut Vec<Option<HalfEdge>>,
    inv: &mut Vec<Option<HalfEdge>>,
    limit: usize,
    out: &mut Vec<Relabeling>,
) {
    let Some((&h0, rest)) = roots.split_first() else {
        // Every component mapped; injective with equal counts, hence a bijection.
        if let Some(all) = map.iter().copied().collect::<Option<Vec<_>>>() {
            out.push(Relabeling { halfedges: all });
        }
        return;
    };
    for g0 in b.halfedges() {
        if out.len() >= limit {
            return;
        }
        if b.is_boundary_halfedge(g0) || b.tail(g0) != a.tail(h0) || b.tip(g0) != a.tip(h0) {
            continue;
        }
        let Some(pairs) = extend(a, b, h0, g0, map, inv) else {
            continue;
        };
        for &(h, g) in &pairs {
            map[h.idx()] = Some(g);
            inv[g.idx()] = Some(h);
        }
        search(a, b, rest, map, inv, limit, out);
        for &(h, g) in &pairs {
            map[h.idx()] = None;
            inv[g.idx()] = None;
        }
    }
}

/// Why two meshes on one vertex set are not the same triangulation, for a refutation:
/// the first edge of `a` (in the surface format's edge order `order_a`) whose unordered
/// vertex pair occurs more often in `a` than in `b`, with both counts; `None` when every
/// pair occurs equally often (then the gluing differs).
pub fn first_extra_edge(
    a: &Mesh,
    order_a: &[usize],
    b: &Mesh,
) -> Option<(usize, Edge, usize, usize)> {
    use std::collections::HashMap;
    let key = |m: &Mesh, e: Edge| {
        let h = e.halfedge();
        let (i, j) = (m.tail(h).0, m.tip(h).0);
        (i.min(j), i.max(j))
    };
    let mut count_b: HashMap<(u32, u32), usize> = HashMap::new();
    for e in b.edges() {
        *count_b.entry(key(b, e)).or_default() += 1;
    }
    let mut count_a: HashMap<(u32, u32), usize> = HashMap::new();
    for e in a.edges() {
        *count_a.entry(key(a, e)).or_default() += 1;
    }
    order_a.iter().enumerate().find_map(|(k, &e)| {
        let e = Edge(e as u32);
        let pair = key(a, e);
        let (na, nb) = (count_a[&pair], count_b.get(&pair).copied().unwrap_or(0));
        (na > nb).then_some((k, e, na, nb))
    })
}
