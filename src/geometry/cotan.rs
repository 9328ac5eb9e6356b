//! Cotangents of corner angles and cotan edge weights (notes §1.3.3, Eq. 5; docs/catalogue.md §3).

use super::triangle::cot_opposite;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// Per half-edge: `cot α` of the corner opposite `h` in its face (`α_k^{ij}` for
/// `h = i→j` in face `ijk`), by [`cot_opposite`]; zero for boundary half-edges, which have
/// no corner.
pub fn halfedge_cotans<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    super::corners::per_corner(mesh, lengths, cot_opposite)
}

/// Cotan weights per edge: `w_ij = ½(cot α_k^{ij} + cot α_l^{ij})` on interior edges and
/// `w_ij = ½ cot α_k^{ij}` on boundary edges (docs/catalogue.md §3, notes Eq. 5). Forward error:
/// proofs/B44.
///
/// ```
/// use penner::geometry::cotan::cotan_weights;
/// use penner::mesh::Mesh;
/// // Unit square split along 0–2: the diagonal has two right angles opposite, w = 0.
/// let m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
/// let s = 2.0_f64.sqrt();
/// let mut l = vec![0.0; m.n_edges()];
/// for e in m.edges() {
///     let h = e.halfedge();
///     let (i, j) = (m.tail(h).0, m.tip(h).0);
///     l[e.idx()] = if (i + j) % 2 == 0 { s } else { 1.0 };
/// }
/// let w = cotan_weights(&m, &l);
/// for e in m.edges() {
///     let h = e.halfedge();
///     let diagonal = (m.tail(h).0 + m.tip(h).0) % 2 == 0;
///     let expect = if diagonal { 0.0 } else { 0.5 };
///     assert!((w[e.idx()] - expect).abs() < 1e-15);
/// }
/// ```
pub fn cotan_weights<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    let cots = halfedge_cotans(mesh, lengths);
    mesh.edges()
        .map(|e| {
            let half = lengths[e.idx()].lit(0.5);
            (cots[e.side(0).idx()].clone() + &cots[e.side(1).idx()]) * &half
        })
        .collect()
}
