//! Hyperbolic discrete metrics (notes Thm 11; BPS15 §6; docs/catalogue.md §7): the sinh scaling,
//! hyperbolic triangle angles by two independent formulas, and the hyperbolic energy with
//! gradient `Θ − θ_hyp(u)`.
//!
//! **Convention.** The logarithmic length of a hyperbolic edge is `λ = 2 log sinh(ℓ/2)`;
//! the discrete conformal scaling `sinh(ℓ̃_ij/2) = e^{(u_i+u_j)/2} sinh(ℓ_ij/2)` is then
//! `λ̃_ij = λ_ij + u_i + u_j`, and `ℓ = 2 arsinh(e^{λ/2})`.
//!
//! **Energy (BPS15 §6).** Per triangle with angles `α_m` (opposite side `m`),
//! `α′ = ½(π − α_1 − α_2 − α_3)` (half the area) and
//! `β_m = ½(π + α_m − α_{m+1} − α_{m+2})`:
//! `F_h(λ) = Σ_m [β_m λ_m + Л(α_m) + Л(β_m)] + Л(α′)`, `∂F_h/∂λ_m = β_m` (the volume
//! of the ideal prism over the triangle enters through the Л terms). Then
//! `E_hyp(u) = Σ_t [F_h(λ̃_t) − (π/2) Σ_{e∈t} λ̃_e] + Σ_i Θ_i u_i`, and since `u_i` enters
//! the two sides at `i`, `∂/∂u_i` of a face term is `β_k + β_j − π = −α_i`: the gradient is
//! `Θ_i − θ_i`, `θ_i` the hyperbolic cone angle.
//!
//! Degenerate triangles (`ℓ_m ≥ ℓ_{m+1} + ℓ_{m+2}`) get the angles `(π, 0, 0)` as in the
//! Euclidean case; then `α′ = 0`, `β = (π, 0, 0)` and `F_h = π λ_m`, so `F_h` stays C¹.
//!
//! ```
//! use penner::variational::hyperbolic::{angles_half_angle, angles_law_of_cosines};
//! let l = [1.0_f64, 1.2, 0.9];
//! let (a, b) = (angles_half_angle(&l), angles_law_of_cosines(&l));
//! for m in 0..3 { assert!((a[m] - b[m]).abs() < 1e-13); }
//! // Hyperbolic triangles have angle sum below π.
//! assert!(a.iter().sum::<f64>() < std::f64::consts::PI);
//! ```

use super::triangle::{shape, Shape};
use crate::mesh::Mesh;
use crate::scalar::Real;
use crate::special::lobachevsky;

/// `sinh x = (eˣ − e⁻ˣ)/2`.
pub fn sinh<T: Real>(x: &T) -> T {
    (x.exp() - &(-x.clone()).exp()) * &x.lit(0.5)
}

/// `cosh x = (eˣ + e⁻ˣ)/2`.
fn cosh<T: Real>(x: &T) -> T {
    (x.exp() + &(-x.clone()).exp()) * &x.lit(0.5)
}

/// `arsinh y = ln(y + √(y² + 1))` for `y > 0`.
fn arsinh<T: Real>(y: &T) -> T {
    (y.clone() + &(y.clone() * y + &y.one_like()).sqrt()).ln()
}

/// `λ = 2 log sinh(ℓ/2)` of a hyperbolic length `ℓ > 0`.
pub fn hyperbolic_log_length<T: Real>(l: &T) -> T {
    sinh(&(l.clone() * &l.lit(0.5))).ln() * &l.lit(2.0)
}

/// The hyperbolic length `ℓ = 2 arsinh(e^{λ/2})` of a logarithmic length `λ`.
pub fn length_from_log<T: Real>(lambda: &T) -> T {
    arsinh(&(lambda.clone() * &lambda.lit(0.5)).exp()) * &lambda.lit(2.0)
}

/// The lengths of the sinh-scaled metric: `sinh(ℓ̃_ij/2) = e^{(u_i+u_j)/2} sinh(ℓ_ij/2)`
/// (notes Thm 11; BPS15 §6), through `λ̃ = λ + u_i + u_j`.
pub fn scaled_lengths<T: Real>(mesh: &Mesh, lengths: &[T], u: &[T]) -> Vec<T> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let lt = hyperbolic_log_length(&lengths[e.idx()])
                + &u[mesh.tail(h).idx()]
                + &u[mesh.tip(h).idx()];
            length_from_log(&lt)
        })
        .collect()
}

/// The degenerate angles `(π, 0, 0)` with `π` at side `m`.
fn degenerate<T: Real>(z: &T, m: usize) -> [T; 3] {
    let mut a = [z.zero_like(), z.zero_like(), z.zero_like()];
    a[m] = T::pi(z.ctx());
    a
}

/// The angles of the hyperbolic triangle with sides `l` (angle `m` opposite side `m`) by
/// the half-angle form (docs/catalogue.md §7; BPS15 §6):
/// `tan(α_i/2) = √( sinh(s−ℓ_j) sinh(s−ℓ_k) / (sinh s · sinh(s−ℓ_i)) )`,
/// `s − ℓ_j = (ℓ_i − ℓ_j + ℓ_k)/2` formed directly; `(π, 0, 0)` when degenerate.
pub fn angles_half_angle<T: Real>(l: &[T; 3]) -> [T; 3] {
    if let Shape::Degenerate(m) = shape(l) {
        return degenerate(&l[0], m);
    }
    let half = l[0].lit(0.5);
    let s = (l[0].clone() + &l[1] + &l[2]) * &half;
    // d[m] = s − ℓ_m.
    let d = [0, 1, 2].map(|m| (l[(m + 1) % 3].clone() + &l[(m + 2) % 3] - &l[m]) * &half);
    let sh = d.clone().map(|x| sinh(&x));
    let shs = sinh(&s);
    [0, 1, 2].map(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let t = (sh[j].clone() * &sh[k] / &(shs.clone() * &sh[i])).sqrt();
        t.atan() * &l[0].lit(2.0)
    })
}

/// The angles of the hyperbolic triangle with sides `l` by the hyperbolic law of cosines,
/// `cos α_i = (cosh ℓ_j cosh ℓ_k − cosh ℓ_i) / (sinh ℓ_j sinh ℓ_k)` (BPS15 §6): an
/// independent second formula for [`angles_half_angle`] (less accurate near 0 and π).
pub fn angles_law_of_cosines<T: Real>(l: &[T; 3]) -> [T; 3] {
    if let Shape::Degenerate(m) = shape(l) {
        return degenerate(&l[0], m);
    }
    let ch = [0, 1, 2].map(|m| cosh(&l[m]));
    let sh = [0, 1, 2].map(|m| sinh(&l[m]));
    [0, 1, 2].map(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        ((ch[j].clone() * &ch[k] - &ch[i]) / &(sh[j].clone() * &sh[k])).acos()
    })
}

/// `F_h(λ)` of one hyperbolic triangle with logarithmic lengths `λ_m = 2 log sinh(ℓ_m/2)`
/// (module doc), angles by [`angles_half_angle`].
pub fn triangle_energy<T: Real>(lambda: &[T; 3]) -> T {
    let l = lambda.clone().map(|x| length_from_log(&x));
    let half = lambda[0].lit(0.5);
    let pi = T::pi(lambda[0].ctx());
    if let Shape::Degenerate(m) = shape(&l) {
        return pi * &lambda[m];
    }
    let a = angles_half_angle(&l);
    let area_half = (pi.clone() - &a[0] - &a[1] - &a[2]) * &half;
    let mut f = lobachevsky(&area_half);
    for m in 0..3 {
        let beta = (pi.clone() + &a[m] - &a[(m + 1) % 3] - &a[(m + 2) % 3]) * &half;
        f += &(beta.clone() * &lambda[m]);
        f += &lobachevsky(&a[m]);
        f += &lobachevsky(&beta);
    }
    f
}

/// `E_hyp(u)` (module doc) from the hyperbolic lengths `ℓ` of the edges, log scale factors
/// `u` and targets `Θ`; `None` without edges and vertices.
pub fn energy<T: Real>(mesh: &Mesh, lengths: &[T], u: &[T], targets: &[T]) -> Option<T> {
    let z = lengths.first().or(u.first())?;
    let lt = scaled_log_lengths(mesh, lengths, u);
    let half_pi = T::pi(z.ctx()) * &z.lit(0.5);
    let mut e = z.zero_like();
    for f in mesh.faces() {
        let x = mesh.face_halfedges(f).map(|h| lt[h.edge().idx()].clone());
        let sum = x[0].clone() + &x[1] + &x[2];
        e += &(triangle_energy(&x) - &(half_pi.clone() * &sum));
    }
    for (t, ui) in targets.iter().zip(u) {
        e += &(t.clone() * ui);
    }
    Some(e)
}

/// `λ̃_ij = 2 log sinh(ℓ_ij/2) + u_i + u_j`.
fn scaled_log_lengths<T: Real>(mesh: &Mesh, lengths: &[T], u: &[T]) -> Vec<T> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            hyperbolic_log_length(&lengths[e.idx()])
                + &u[mesh.tail(h).idx()]
                + &u[mesh.tip(h).idx()]
        })
        .collect()
}

/// The hyperbolic cone angles `θ_i` of the metric `lengths` (corner angles by
/// [`angles_half_angle`], or by [`angles_law_of_cosines`] with `cosines`).
pub fn cone_angles<T: Real>(mesh: &Mesh, lengths: &[T], cosines: bool) -> Vec<T> {
    let Some(z) = lengths.first() else {
        return Vec::new();
    };
    let mut theta = vec![z.zero_like(); mesh.n_vertices()];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let l = hs.map(|h| lengths[h.edge().idx()].clone());
        let a = if cosines {
            angles_law_of_cosines(&l)
        } else {
            angles_half_angle(&l)
        };
        for m in 0..3 {
            theta[mesh.tail(hs[(m + 2) % 3]).idx()] += &a[m];
        }
    }
    theta
}

/// `∇E_hyp(u) = Θ − θ_hyp(u)`, `θ_hyp` the cone angles of the sinh-scaled metric
/// ([`scaled_lengths`], [`cone_angles`] by the half-angle form).
pub fn gradient<T: Real>(mesh: &Mesh, lengths: &[T], u: &[T], targets: &[T]) -> Vec<T> {
    let lt = scaled_lengths(mesh, lengths, u);
    let theta = cone_angles(mesh, &lt, false);
    if theta.is_empty() {
        return targets.to_vec();
    }
    theta
        .into_iter()
        .zip(targets)
        .map(|(th, t)| t.clone() - &th)
        .collect()
}
