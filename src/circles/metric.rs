//! Lengths, corner angles and cone angles of a circle pattern, generic over [`Real`].
//!
//! Euclidean (notes Eq. 9, docs/catalogue.md §8): circles of radii `r_i, r_j` meeting at angle `Φ`
//! (0 tangent, π/2 orthogonal) have centres at distance
//! `ℓ_ij² = r_i² + r_j² + 2 r_i r_j cos Φ_ij`. The inversive distance
//! `I_ij = (ℓ² − r_i² − r_j²)/(2 r_i r_j)` replaces `cos Φ` for disjoint circles (`I > 1`).
//! Hyperbolic: `cosh ℓ = cosh r_i cosh r_j + sinh r_i sinh r_j cos Φ`.
//!
//! On [`Interval`](crate::scalar::Interval)s every function here returns a certified
//! enclosure of the exact value (inclusion property, proofs/B20).

use crate::geometry::corners::halfedge_angles;
use crate::mesh::Mesh;
use crate::scalar::Real;
use rug::Rational;

/// Euclidean length `√(r_i² + r_j² + 2 r_i r_j cos Φ)` between the centres of two circles
/// of radii `r_i, r_j` meeting at angle `Φ` (notes Eq. 9).
///
/// ```
/// use penner::circles::metric::euclidean_length;
/// assert_eq!(euclidean_length(&1.0_f64, &2.0, &1.0), 3.0); // tangent: r_i + r_j
/// assert_eq!(euclidean_length(&3.0_f64, &4.0, &0.0), 5.0); // orthogonal: Pythagoras
/// ```
pub fn euclidean_length<T: Real>(ri: &T, rj: &T, cos_phi: &T) -> T {
    let two = ri.lit(2.0);
    (ri.clone() * ri + &(rj.clone() * rj) + &(two * ri * rj * cos_phi)).sqrt()
}

/// Length from radii and an inversive distance `I` (any real `I > −1`): the formula of
/// [`euclidean_length`] with `cos Φ` replaced by `I` (docs/catalogue.md §8).
pub fn inversive_length<T: Real>(ri: &T, rj: &T, inversive: &T) -> T {
    euclidean_length(ri, rj, inversive)
}

/// Inversive distance `I = (ℓ² − r_i² − r_j²)/(2 r_i r_j)` of two circles of radii
/// `r_i, r_j` whose centres are `ℓ` apart: 1 tangent, `|I| < 1` crossing at angle
/// `arccos I`, `I > 1` disjoint.
///
/// ```
/// use penner::circles::metric::inversive_distance;
/// assert_eq!(inversive_distance(&3.0_f64, &1.0, &2.0), 1.0);
/// ```
pub fn inversive_distance<T: Real>(l: &T, ri: &T, rj: &T) -> T {
    (l.clone() * l - &(ri.clone() * ri) - &(rj.clone() * rj)) / (ri.lit(2.0) * ri * rj)
}

/// Hyperbolic distance between the centres of two hyperbolic circles of radii `r_i, r_j`
/// meeting at angle `Φ`: `ℓ = arcosh(cosh r_i cosh r_j + sinh r_i sinh r_j cos Φ)`, with
/// `arcosh x = ln(x + √(x² − 1))` (docs/catalogue.md §8).
///
/// ```
/// use penner::circles::metric::hyperbolic_length;
/// let l = hyperbolic_length(&0.5_f64, &0.7, &1.0);
/// assert!((l - 1.2).abs() < 1e-14); // tangent circles: r_i + r_j
/// ```
pub fn hyperbolic_length<T: Real>(ri: &T, rj: &T, cos_phi: &T) -> T {
    let half = ri.lit(0.5);
    let cosh = |x: &T| (x.exp() + &(-x.clone()).exp()) * &half;
    let sinh = |x: &T| (x.exp() - &(-x.clone()).exp()) * &half;
    let x = cosh(ri) * &cosh(rj) + &(sinh(ri) * &sinh(rj) * cos_phi);
    let one = ri.one_like();
    (x.clone() + &((x.clone() * &x) - &one).sqrt()).ln()
}

/// `cos(qπ)` exactly where it is rational on `[0, 1]` (Niven):
/// `q ∈ {0, 1/3, 1/2, 2/3, 1}` give `1, 1/2, 0, −1/2, −1`.
pub fn cos_pi_exact(q: &Rational) -> Option<Rational> {
    [
        (0, 1, 1, 1),
        (1, 3, 1, 2),
        (1, 2, 0, 1),
        (2, 3, -1, 2),
        (1, 1, -1, 1),
    ]
    .iter()
    .find(|&&(a, b, _, _)| *q == Rational::from((a, b)))
    .map(|&(_, _, c, d)| Rational::from((c, d)))
}

/// `cos(qπ)` in the backend of `ctx`: exact where [`cos_pi_exact`] knows it, else
/// `cos(q·π)` rounded by the backend.
pub fn cos_pi<T: Real>(q: &Rational, ctx: T::Ctx) -> T {
    match cos_pi_exact(q) {
        Some(c) => T::from_rational(&c, ctx),
        None => (T::from_rational(q, ctx) * &T::pi(ctx)).cos(),
    }
}

/// Euclidean lengths of every edge of `mesh` for radii `r_v = e^{u_v}` and the per-edge
/// values `cos Φ_e` (notes Eq. 9).
pub fn pattern_lengths<T: Real>(mesh: &Mesh, u: &[T], cos_phi: &[T]) -> Vec<T> {
    let r: Vec<T> = u.iter().map(Real::exp).collect();
    lengths_from_radii(mesh, &r, cos_phi)
}

/// Euclidean lengths of every edge for radii `r` and per-edge `cos Φ_e` (notes Eq. 9).
pub fn lengths_from_radii<T: Real>(mesh: &Mesh, r: &[T], cos_phi: &[T]) -> Vec<T> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            euclidean_length(&r[i], &r[j], &cos_phi[e.idx()])
        })
        .collect()
}

/// Exact squared lengths `r_i² + r_j² + 2 r_i r_j cos Φ_e` from rational radii and rational
/// cosines (notes Eq. 9).
pub fn squared_lengths_exact(mesh: &Mesh, r: &[Rational], cos_phi: &[Rational]) -> Vec<Rational> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            let (ri, rj) = (&r[mesh.tail(h).idx()], &r[mesh.tip(h).idx()]);
            let c = &cos_phi[e.idx()];
            Rational::from(ri * ri) + Rational::from(rj * rj) + Rational::from(ri * rj) * c * 2u32
        })
        .collect()
}

/// Cone angle `θ_v`: the sum of the corner angles at `v` over all its corners (docs/catalogue.md §2).
pub fn cone_angles<T: Real>(mesh: &Mesh, lengths: &[T]) -> Vec<T> {
    let Some(l0) = lengths.first() else {
        return Vec::new();
    };
    let mut theta = vec![l0.zero_like(); mesh.n_vertices()];
    for (h, a) in mesh.halfedges().zip(halfedge_angles(mesh, lengths)) {
        if !mesh.is_boundary_halfedge(h) {
            theta[mesh.opposite_vertex(h).idx()] += &a;
        }
    }
    theta
}
