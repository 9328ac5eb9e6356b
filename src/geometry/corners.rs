//! Corner angles of every face, indexed by the half-edge opposite the corner.

use super::triangle::corner_angle;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// Per half-edge `h`: the corner angle `α_k^{ij}` opposite `h = i→j` in its face `ijk`,
/// by the half-angle form (docs/catalogue.md §1, proofs/B40); zero on boundary half-edges.
///
/// ```
/// use penner::geometry::corners::halfedge_angles;
/// use penner::mesh::Mesh;
/// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
/// let a = halfedge_angles(&tri, &[1.0_f64; 3]);
/// let sum: f64 = a.iter().sum();
/// assert!((sum - std::f64::consts::PI).abs() < 1e-15);
/// ```
pub fn halfedge_angles<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    per_corner(mesh, lengths, corner_angle)
}

/// `f(ℓ_ij, ℓ_jk, ℓ_ki)` for every face half-edge `h = i→j` of face `ijk` (a function of
/// the corner at `k` opposite `h`), zero for boundary half-edges, which have no corner.
pub(crate) fn per_corner<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    f: impl Fn(&T, &T, &T) -> T,
) -> Vec<T> {
    let Some(l0) = lengths.first() else {
        return Vec::new();
    };
    let len = |h: crate::mesh::HalfEdge| &lengths[h.edge().idx()];
    mesh.halfedges()
        .map(|h| {
            if mesh.is_boundary_halfedge(h) {
                l0.zero_like()
            } else {
                f(len(h), len(mesh.next(h)), len(mesh.prev(h)))
            }
        })
        .collect()
}
