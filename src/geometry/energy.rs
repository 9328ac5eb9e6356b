//! Energies of piecewise-linear maps `f: V → ℂ` (notes §1.3.3; docs/catalogue.md §3). A complex
//! value is a pair `[re, im]`.

use super::triangle::corner_angle;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// The Dirichlet energy `E_D(f) = ½ Σ_{edges ij} w_ij |f_j − f_i|²` (docs/catalogue.md §3, notes
/// Eq. 5), each edge once, from per-edge cotan weights `w` (see
/// [`super::cotan::cotan_weights`]). Equals `½ ∫ |∇f|²` of the piecewise-linear
/// interpolant, hence `≥ 0` whatever the signs of the weights. `None` if `f` is empty.
pub fn dirichlet_energy<T: Real>(mesh: &Mesh, weights: &[T], f: &[[T; 2]]) -> Option<T> {
    let mut e = f.first()?[0].zero_like();
    for edge in mesh.edges() {
        let h = edge.halfedge();
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        let dx = f[j][0].clone() - &f[i][0];
        let dy = f[j][1].clone() - &f[i][1];
        e += &(weights[edge.idx()].clone() * &(dx.clone() * &dx + &(dy.clone() * &dy)));
    }
    Some(e * &f[0][0].lit(0.5))
}

/// Signed area of the image polygon, `A(f) = ½ Σ_{ij∈∂M} Im(conj(f_i) f_j)` over the
/// boundary edges oriented with the surface on their left (docs/catalogue.md §3, notes §1.3.3).
/// Zero on a closed surface. `None` if `f` is empty.
pub fn signed_area<T: Real>(mesh: &Mesh, f: &[[T; 2]]) -> Option<T> {
    let mut a = f.first()?[0].zero_like();
    for h in mesh.halfedges() {
        // The face side of a boundary edge runs with the surface on its left.
        if mesh.is_boundary_halfedge(h) || !mesh.is_boundary_halfedge(h.twin()) {
            continue;
        }
        let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
        a += &(f[i][0].clone() * &f[j][1] - &(f[i][1].clone() * &f[j][0]));
    }
    Some(a * &f[0][0].lit(0.5))
}

/// The conformal energy `E_C(f) = E_D(f) − A(f)` (docs/catalogue.md §3, notes §1.3.3).
pub fn conformal_energy<T: Real>(mesh: &Mesh, weights: &[T], f: &[[T; 2]]) -> Option<T> {
    Some(dirichlet_energy(mesh, weights, f)? - &signed_area(mesh, f)?)
}

/// The Cauchy–Riemann form of the conformal energy, computed triangle by triangle and
/// independent of cotan weights and of the boundary:
/// `E_CR(f) = Σ_t ½ Area_t |∂_x f + i ∂_y f|²`, where each triangle `ijk` is laid out
/// counter-clockwise from its lengths (`p_i = 0`, `p_j = (ℓ_ij, 0)`,
/// `p_k = ℓ_ki (cos α_i, sin α_i)`) and `∇f = (1/2A) Σ_m f_m J e_m` with `e_m` the edge
/// opposite `m` and `J` the rotation by +90°. Smoothly `½|∇f|² − det df = 2|∂_z̄ f|²`, so
/// `E_CR = E_D − A` is the identity of notes §1.3.3 (theorem T07). `None` if `f` or
/// `lengths` is empty.
pub fn cauchy_riemann_energy<T: Real>(mesh: &Mesh, lengths: &[T], f: &[[T; 2]]) -> Option<T> {
    let l0 = lengths.first()?;
    let mut total = l0.zero_like();
    for face in mesh.faces() {
        let [hij, hjk, hki] = mesh.face_halfedges(face);
        let (i, j, k) = (
            mesh.tail(hij).idx(),
            mesh.tail(hjk).idx(),
            mesh.tail(hki).idx(),
        );
        let (lij, ljk, lki) = (
            &lengths[hij.edge().idx()],
            &lengths[hjk.edge().idx()],
            &lengths[hki.edge().idx()],
        );
        let alpha_i = corner_angle(ljk, lki, lij);
        let p = [
            [l0.zero_like(), l0.zero_like()],
            [lij.clone(), l0.zero_like()],
            [lki.clone() * &alpha_i.cos(), lki.clone() * &alpha_i.sin()],
        ];
        // Twice the signed area of the layout.
        let area2 = p[1][0].clone() * &p[2][1] - &(p[1][1].clone() * &p[2][0]);
        let fv = [&f[i], &f[j], &f[k]];
        // ∇(re f), ∇(im f): Σ_m f_m J(p_{m+2} − p_{m+1}) / (2A), J(x, y) = (−y, x).
        let mut g = [
            [l0.zero_like(), l0.zero_like()],
            [l0.zero_like(), l0.zero_like()],
        ];
        for m in 0..3 {
            let (a, b) = (&p[(m + 1) % 3], &p[(m + 2) % 3]);
            let ex = b[0].clone() - &a[0];
            let ey = b[1].clone() - &a[1];
            for (c, gc) in g.iter_mut().enumerate() {
                gc[0] -= &(fv[m][c].clone() * &ey);
                gc[1] += &(fv[m][c].clone() * &ex);
            }
        }
        // 2A·(∂_x f + i ∂_y f) = (g_re,x − g_im,y) + i (g_im,x + g_re,y).
        let re = g[0][0].clone() - &g[1][1];
        let im = g[1][0].clone() + &g[0][1];
        // ½ A |(re + i im)/(2A)|² = (re² + im²) / (8 A) = (re² + im²) / (4 · area2).
        total += &((re.clone() * &re + &(im.clone() * &im)) / &(area2 * &l0.lit(4.0)));
    }
    Some(total)
}
