//! Discrete curvature: angle defects `K_i = 2π − θ_i` at interior vertices and geodesic
//! curvature `k_i = π − θ_i` at boundary vertices (notes §1.2, Eq. 1; docs/catalogue.md §2).

use super::cone_angles::cone_angles;
use crate::mesh::Mesh;
use crate::scalar::Real;

/// Per-vertex curvature from per-edge lengths: `K_i = 2π − θ_i` at interior vertices and
/// `k_i = π − θ_i` at boundary vertices (docs/catalogue.md §2, notes §1.2), with `θ_i` from
/// [`cone_angles`]. Which formula applies is decided by the topology only.
///
/// ```
/// use penner::geometry::curvature::curvature;
/// use penner::mesh::Mesh;
/// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
/// let k = curvature(&tri, &[1.0_f64, 1.0, 1.0]);
/// // Every corner of an equilateral triangle turns by π − π/3.
/// assert!(k.iter().all(|x| (x - 2.0 * std::f64::consts::FRAC_PI_3).abs() < 1e-15));
/// ```
pub fn curvature<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    let theta = cone_angles(mesh, lengths);
    let boundary = mesh.boundary_vertices();
    let Some(l0) = lengths.first() else {
        return Vec::new();
    };
    let pi = T::pi(l0.ctx());
    let two_pi = pi.clone() * &l0.lit(2.0);
    theta
        .into_iter()
        .zip(boundary)
        .map(|(t, on_boundary)| {
            if on_boundary {
                pi.clone() - &t
            } else {
                two_pi.clone() - &t
            }
        })
        .collect()
}

/// The Gauss–Bonnet total `Σ_int K_i + Σ_∂ k_i` (docs/catalogue.md §2), summed in vertex order.
/// Forward error: proofs/B42.
pub fn gauss_bonnet_total<T: Real>(mesh: &Mesh, lengths: &[T]) -> Option<T> {
    let l0 = lengths.first()?;
    let mut total = l0.zero_like();
    for k in curvature(mesh, lengths) {
        total += &k;
    }
    Some(total)
}

/// `2πχ` in the context `ctx`, with `χ = V − E + F` counted on the Δ-complex
/// (docs/catalogue.md §2). `2χ` is an exact `f64` for every mesh that fits in memory.
pub fn gauss_bonnet_target<T: Real>(mesh: &Mesh, ctx: T::Ctx) -> T {
    let chi = mesh.euler_characteristic();
    T::pi(ctx) * &T::from_f64(2.0 * chi as f64, ctx)
}
