//! The Jacobian `∂θ_i/∂u_j` of the cone angles of a circle pattern in `u = log r`, from the
//! power centres of the faces (docs/catalogue.md §8; Glickenstein, *Discrete conformal variations and
//! scalar curvature on piecewise flat two- and three-dimensional manifolds*, 2011).
//!
//! In a face `ijk` the power centre `c` has equal power `|c − p_v|² − r_v²` for the three
//! vertex circles. Its signed distance to the edge `ij` (positive towards the face) is
//! `h_ij = (d_ik − d_ij cos α_i) / sin α_i` with the power distances
//! `d_ij = (r_i² + r_i r_j cos Φ_ij)/ℓ_ij = ∂ℓ_ij/∂u_i`, and
//! `∂α_i/∂u_j = ∂α_j/∂u_i = h_ij/ℓ_ij` for `i ≠ j`. Angles are invariant under a global
//! scale, so `∂α_i/∂u_i = −∂α_i/∂u_j − ∂α_i/∂u_k`. Summed over faces: a symmetric matrix
//! with zero row sums, nonnegative off the diagonal for `Φ ∈ [0, π/2]` (Chow–Luo 2003,
//! Lemma 2.3), so `−∂θ/∂u` is positive semidefinite.

use crate::geometry::triangle::kahan_area;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// The weight `h_ij/ℓ_ij` of edge `ij` in one face with vertex radii `r = [r_i, r_j, r_k]`,
/// `cos Φ` of the sides `c = [c_ij, c_jk, c_ki]` and lengths `l = [ℓ_ij, ℓ_jk, ℓ_ki]`:
/// `∂α_i/∂u_j` of that face. With `2A` twice the area,
/// `h_ij/ℓ_ij = (2 d_ik ℓ_ij ℓ_ki − d_ij (ℓ_ij² + ℓ_ki² − ℓ_jk²)) / (4 A ℓ_ij)`.
pub fn face_weight<T: Real>(r: [&T; 3], c: [&T; 3], l: [&T; 3]) -> T {
    let [ri, rj, rk] = r;
    let [cij, _, cki] = c;
    let [lij, ljk, lki] = l;
    let dij = (ri.clone() * ri + &(ri.clone() * rj * cij)) / lij;
    let dik = (ri.clone() * ri + &(ri.clone() * rk * cki)) / lki;
    let two = ri.lit(2.0);
    let num = two * &dik * lij * lki
        - &(dij * &(lij.clone() * lij + &(lki.clone() * lki) - &(ljk.clone() * ljk)));
    let area = kahan_area(lij, ljk, lki);
    num / &(area * &ri.lit(4.0) * lij)
}

/// `∂θ/∂u` as a dense `n × n` matrix (row `i`, column `j`) for radii `r`, per-edge
/// `cos Φ` and the pattern's lengths `l` ([`super::metric::lengths_from_radii`]). Every
/// face adds its three edge weights `w` at `(i, j)` and `(j, i)` and `−w` at `(i, i)` and
/// `(j, j)`; a face meeting one vertex twice (a Δ-complex) adds nothing for that pair.
pub fn angle_jacobian<T: Real>(mesh: &Mesh, r: &[T], cos_phi: &[T], l: &[T]) -> Vec<Vec<T>> {
    let n = mesh.n_vertices();
    let Some(r0) = r.first() else {
        return Vec::new();
    };
    let mut j = vec![vec![r0.zero_like(); n]; n];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for s in 0..3 {
            // h = a→b; the corner at a between sides ab and ca.
            let (hab, hbc, hca) = (hs[s], hs[(s + 1) % 3], hs[(s + 2) % 3]);
            let (a, b, cvx) = (
                mesh.tail(hab).idx(),
                mesh.tip(hab).idx(),
                mesh.tail(hca).idx(),
            );
            let w = face_weight(
                [&r[a], &r[b], &r[cvx]],
                [
                    &cos_phi[hab.edge().idx()],
                    &cos_phi[hbc.edge().idx()],
                    &cos_phi[hca.edge().idx()],
                ],
                [
                    &l[hab.edge().idx()],
                    &l[hbc.edge().idx()],
                    &l[hca.edge().idx()],
                ],
            );
            if a != b {
                j[a][b] += &w;
                j[b][a] += &w;
                j[a][a] -= &w;
                j[b][b] -= &w;
            }
        }
    }
    j
}
