//! Cone angles θ_v: the sum of corner angles at each vertex.

use super::triangle::corner_angle;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// Cone angle `θ_v = Σ α_v` over all corners at `v` (MATH.md §2), from per-edge lengths
/// `lengths[e]`. Corners are counted with multiplicity (a face may have a vertex twice).
pub fn cone_angles<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    let zero = lengths[0].zero_like();
    let mut theta = vec![zero; mesh.n_vertices()];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            // Corner opposite hs[i] is at the tail of hs[(i+2)%3].
            let a = &lengths[hs[i].edge().idx()];
            let b = &lengths[hs[(i + 1) % 3].edge().idx()];
            let c = &lengths[hs[(i + 2) % 3].edge().idx()];
            let v = mesh.tail(hs[(i + 2) % 3]).idx();
            theta[v] += &corner_angle(a, b, c);
        }
    }
    theta
}
