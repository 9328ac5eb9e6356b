//! Hyperbolic tangency packings of a disk with horocycles on the boundary (the maximal
//! packing, proofs/T11), in the variable `t_v = tanh(r_v/2)` (the Euclidean radius of the
//! circle when its hyperbolic centre is the origin of the Poincaré disk; `t = 1` a
//! horocycle) and `u_v = ln t_v`.
//!
//! The angle `α` at `v₀` of the triangle of centres of three mutually tangent circles with
//! hyperbolic radii `r₀, r₁, r₂` (sides `r₀ + r₁`, `r₀ + r₂` and `r₁ + r₂`) follows from the
//! hyperbolic half-angle formula `sin²(α/2) = sinh(s − b) sinh(s − c)/(sinh b sinh c)`:
//!
//! `Q = sin²(α/2) = (1 − t₀²)² t₁ t₂ / ((t₀ + t₁)(t₀ + t₂)(1 + t₀t₁)(1 + t₀t₂))`
//!
//! (rational in `t`, finite at horocycles `t = 1`; proofs/B95), and
//! `∂α/∂u_j = tan(α/2) · ∂ln Q/∂u_j` with
//! `∂ln Q/∂u₁ = t₀(1 − t₁²)/((t₀ + t₁)(1 + t₀t₁))` and
//! `∂ln Q/∂u₀ = −t₀(4t₀/(1 − t₀²) + 1/(t₀ + t₁) + 1/(t₀ + t₂) + t₁/(1 + t₀t₁) + t₂/(1 + t₀t₂))`.
//! In `u` the Jacobian `∂θ/∂u` is symmetric with negative diagonal (Colin de Verdière
//! 1991): `H = −∂θ/∂u` on the interior vertices is positive definite, the Hessian of a
//! strictly convex energy whose critical point is the packing.

use crate::mesh::{Mesh, Vertex};
use crate::scalar::Real;

/// `sin²(α/2)` of the angle at the circle `t0` of three mutually tangent hyperbolic circles
/// (module docs, proofs/B95).
pub fn half_angle_sin_sq<T: Real>(t0: &T, t1: &T, t2: &T) -> T {
    let one = t0.one_like();
    let a = one.clone() - &(t0.clone() * t0);
    let num = a.clone() * &a * t1 * t2;
    let den = (t0.clone() + t1)
        * &(t0.clone() + t2)
        * &(one.clone() + &(t0.clone() * t1))
        * &(one + &(t0.clone() * t2));
    num / &den
}

/// The angle `α = 2·atan2(√Q, √(1 − Q))` at the circle `t0` (module docs).
pub fn corner_angle<T: Real>(t0: &T, t1: &T, t2: &T) -> T {
    let q = half_angle_sin_sq(t0, t1, t2);
    let c = (q.one_like() - &q).abs().sqrt();
    q.sqrt().atan2(&c) * &q.lit(2.0)
}

/// `e^{iα}` as `(cos α, sin α) = (1 − 2Q, 2√(Q(1 − Q)))`, without trigonometric functions.
pub fn corner_rotation<T: Real>(t0: &T, t1: &T, t2: &T) -> (T, T) {
    let q = half_angle_sin_sq(t0, t1, t2);
    let one = q.one_like();
    let cos = one.clone() - &(q.clone() * &q.lit(2.0));
    let sin = (q.clone() * &(one - &q)).abs().sqrt() * &q.lit(2.0);
    (cos, sin)
}

/// The cone angles `θ_v = Σ α` over the corners of every vertex for `t` per vertex
/// (boundary vertices with `t = 1` get angle sums too; only interior ones are prescribed).
pub fn angle_sums<T: Real>(mesh: &Mesh, t: &[T]) -> Vec<T> {
    let zero = t.first().map(Real::zero_like);
    let Some(zero) = zero else {
        return Vec::new();
    };
    let mut theta = vec![zero; mesh.n_vertices()];
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_vertices(f).map(Vertex::idx);
        for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
            theta[x] += &corner_angle(&t[x], &t[y], &t[z]);
        }
    }
    theta
}

/// The residuals `2π − θ_v` on the interior vertices (interior order) from the product of
/// the corners' rotations around each vertex, `P_v = Π e^{iα}` ([`corner_rotation`], no
/// trigonometric function per corner), and one `atan2` per vertex (proofs/B112):
///
/// `2π − θ_v = 2π m_v − atan2(Im P_v, Re P_v)`, `m_v = round((g_v + atan2(Im P_v, Re P_v)) / 2π)`,
///
/// where `guide` holds an estimate `g_v` of `2π − θ_v` (one per interior vertex, in
/// interior order; the `f64` residual) within `π/2` of it; it fixes only the integer
/// `m_v`. Four multiplications and two additions per corner replace [`angle_sums`]'
/// `atan2` and second square root, the cost of a residual at MPFR precision. The vertices
/// are independent and run on rayon's thread pool (each vertex's corners in the order of
/// [`Mesh::outgoing`], so the result does not depend on the number of threads). The mesh
/// must be simplicial around the interior vertices (as the maximal packing requires).
pub fn residual_by_rotations<T: Real>(
    mesh: &Mesh,
    t: &[T],
    interior: &[bool],
    guide: &[f64],
) -> Vec<T> {
    use rayon::prelude::*;
    let Some(zero) = t.first().map(Real::zero_like) else {
        return Vec::new();
    };
    let two_pi = T::pi(zero.ctx()) * &zero.lit(2.0);
    let vertices: Vec<usize> = (0..interior.len()).filter(|&v| interior[v]).collect();
    vertices
        .par_iter()
        .zip(guide.par_iter())
        .map(|(&v, &g)| {
            let (mut re, mut im) = (zero.one_like(), zero.clone());
            for h in mesh.outgoing(Vertex(v as u32)) {
                let (y, z) = (mesh.tip(h).idx(), mesh.tip(mesh.next(h)).idx());
                let (cos, sin) = corner_rotation(&t[v], &t[y], &t[z]);
                let next_re = re.clone() * &cos - &(im.clone() * &sin);
                im = re * &sin + &(im * &cos);
                re = next_re;
            }
            let arg = im.atan2(&re);
            let m = ((g + arg.approx_f64()) / std::f64::consts::TAU).round();
            two_pi.clone() * &zero.lit(m) - &arg
        })
        .collect()
}

/// The entries of `∂θ/∂u` in `f64`: `(i, j, value)` triplets, repeated pairs to be summed
/// (module docs). Entries for horocycles (`t = 1`) are zero and left out.
pub fn angle_jacobian_triplets(
    mesh: &Mesh,
    t: &[f64],
    interior: &[bool],
) -> Vec<(usize, usize, f64)> {
    let mut out = Vec::with_capacity(9 * mesh.n_faces());
    for_each_angle_jacobian_entry(mesh, t, interior, |i, j, v| out.push((i, j, v)));
    out
}

/// The entries of [`angle_jacobian_triplets`], in the same order and with the same values,
/// passed to `visit(i, j, ∂θ_i/∂u_j)` one by one instead of collected (no allocation, for
/// filling a fixed sparsity pattern).
pub fn for_each_angle_jacobian_entry(
    mesh: &Mesh,
    t: &[f64],
    interior: &[bool],
    mut visit: impl FnMut(usize, usize, f64),
) {
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_vertices(f).map(Vertex::idx);
        for (x, y, z) in [(a, b, c), (b, c, a), (c, a, b)] {
            if !interior[x] {
                continue;
            }
            let (t0, t1, t2) = (t[x], t[y], t[z]);
            let q = half_angle_sin_sq(&t0, &t1, &t2);
            let tan_half = (q / (1.0 - q)).sqrt();
            let d_other = |ti: f64| t0 * (1.0 - ti * ti) / ((t0 + ti) * (1.0 + t0 * ti));
            let d_self = -t0
                * (4.0 * t0 / (1.0 - t0 * t0)
                    + 1.0 / (t0 + t1)
                    + 1.0 / (t0 + t2)
                    + t1 / (1.0 + t0 * t1)
                    + t2 / (1.0 + t0 * t2));
            visit(x, x, tan_half * d_self);
            if interior[y] {
                visit(x, y, tan_half * d_other(t1));
            }
            if interior[z] {
                visit(x, z, tan_half * d_other(t2));
            }
        }
    }
}

/// `t = e^u` per vertex, `1` (a horocycle) where `interior` is false.
pub fn radii_from_u<T: Real>(u: &[T], interior: &[bool]) -> Vec<T> {
    u.iter()
        .zip(interior)
        .map(|(x, &i)| if i { x.exp() } else { x.one_like() })
        .collect()
}
