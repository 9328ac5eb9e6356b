//! Length cross ratios of interior edges (notes Eq. 12; docs/catalogue.md §4).

use crate::mesh::{Edge, HalfEdge, Mesh};
use crate::scalar::{Field, Real};

/// The four half-edges around interior edge `e`, in the order `(il, jk, ki, lj)` of
/// `c_ij = (ℓ_il ℓ_jk)/(ℓ_ki ℓ_lj)`, where `h = side(0) = i→j` lies in face `ijk` and its
/// twin in face `jil`. `None` for a boundary edge.
pub fn cross_ratio_halfedges(mesh: &Mesh, e: Edge) -> Option<[HalfEdge; 4]> {
    if mesh.is_boundary_edge(e) {
        return None;
    }
    let h = e.side(0);
    let t = h.twin();
    Some([mesh.next(t), mesh.next(h), mesh.prev(h), mesh.prev(t)])
}

/// Length cross ratio `c_ij = (ℓ_il ℓ_jk)/(ℓ_ki ℓ_lj)` of each interior edge (notes
/// Eq. 12, docs/catalogue.md §4), `None` on boundary edges. Symmetric in the choice of `i→j` or
/// `j→i`; invariant under conformal scaling (theorem T16). Forward error: proofs/B45.
///
/// ```
/// use penner::geometry::cross_ratio::length_cross_ratios;
/// use penner::mesh::Mesh;
/// // Regular tetrahedron: every cross ratio is 1.
/// let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
/// let c = length_cross_ratios(&tet, &[1.0_f64; 6]);
/// assert!(c.iter().all(|x| *x == Some(1.0)));
/// ```
pub fn length_cross_ratios<T: Field>(mesh: &Mesh, lengths: &[T]) -> Vec<Option<T>> {
    let l = |h: HalfEdge| &lengths[h.edge().idx()];
    mesh.edges()
        .map(|e| {
            let [il, jk, ki, lj] = cross_ratio_halfedges(mesh, e)?;
            Some(l(il).clone() * l(jk) / &(l(ki).clone() * l(lj)))
        })
        .collect()
}

/// Product of the cross ratios of the interior edges at each vertex, each edge counted once
/// per end (a loop twice): `Π_j c_ij`, which is 1 at every interior vertex for any lengths
/// (docs/catalogue.md §4). Boundary edges contribute nothing.
pub fn vertex_cross_ratio_products<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    let c = length_cross_ratios(mesh, lengths);
    let one = lengths.first().map(Real::one_like);
    let mut p: Vec<Option<T>> = vec![one; mesh.n_vertices()];
    for e in mesh.edges() {
        if let Some(ce) = &c[e.idx()] {
            let h = e.side(0);
            for v in [mesh.tail(h), mesh.tip(h)] {
                if let Some(pv) = p[v.idx()].as_mut() {
                    *pv *= ce;
                }
            }
        }
    }
    p.into_iter().flatten().collect()
}
