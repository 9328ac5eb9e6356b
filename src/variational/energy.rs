//! The discrete-uniformization energy (SSP08; Springborn 2020 over Penner cells; notes
//! §1.6.4, Eq. 16; docs/catalogue.md §7):
//!
//! `E(u) = Σ_{ijk} [ 2 f(λ̃_ij, λ̃_jk, λ̃_ki) − (π/2)(λ̃_ij + λ̃_jk + λ̃_ki) ] + Σ_i Θ_i u_i`,
//! `λ̃_ij = λ_ij + u_i + u_j`, `λ = 2 log ℓ` (the convention of [`super::triangle`]).
//!
//! **Normalisation.** For a face `ijk`, `u_i` enters `λ̃_ij` and `λ̃_ki` with coefficient
//! 1; by `∂f/∂x_m = α_m/2` the face term contributes `(α_k + α_j) − π = −α_i`, so
//! `∂E/∂u_i = Θ_i − θ_i(u)` with `θ_i` the cone angle — the constants of docs/catalogue.md §7 are right as
//! printed (a factor `½` in front, as in some codes, would halve the gradient). The Hessian
//! is the cotan Laplacian with the sign making it positive semidefinite:
//! `∂²E/∂u_i∂u_j = −w_ij` (`i ≠ j`), `∂²E/∂u_i² = Σ_j w_ij`, `w_ij = ½(cot α_k + cot α_l)`,
//! i.e. `−L` for [`crate::geometry::laplacian::cotan_laplacian`]'s `L`.
//!
//! On a fixed triangulation degenerate faces use the extension of [`super::triangle`], so
//! `E` is C¹ and convex on all of ℝⱽ. On the variable triangulation ([`at_delaunay`]) `E`
//! is evaluated on the intrinsic Delaunay triangulation of the scaled metric reached by
//! Ptolemy flips; there every face is a triangle, and `E` is C² and convex (Springborn
//! 2020).
//!
//! ```
//! use penner::mesh::Mesh;
//! use penner::variational::energy::{energy, gradient};
//! // Two equilateral triangles glued into a sphere: every cone angle is 2π/3, so with
//! // these targets the gradient vanishes.
//! let m = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).unwrap();
//! let lambda = vec![0.0_f64; m.n_edges()];
//! let u = vec![0.0_f64; 3];
//! let t = vec![2.0 * std::f64::consts::FRAC_PI_3; 3];
//! let g = gradient(&m, &lambda, &u, &t);
//! assert!(g.iter().all(|x| x.abs() < 1e-15));
//! assert!(energy(&m, &lambda, &u, &t).unwrap().is_finite());
//! ```

use super::pattern::HessianPattern;
use super::triangle::{angles_from_log_lengths, face_terms, triangle_energy};
use crate::algorithms::flip_scaled::flip_to_delaunay_scaled;
use crate::algorithms::flip_to_delaunay::{FlipKind, FlipOptions, FlipReport, FlipToDelaunayError};
use crate::geometry::laplacian::SparseMatrix;
use crate::mesh::{Face, HalfEdge, Mesh};
use crate::scalar::exp_length::ExpLength;
use crate::scalar::Real;

/// Penner's logarithmic lengths `λ_e = 2 log ℓ_e`.
pub fn log_lengths<T: Real>(lengths: &[T]) -> Vec<T> {
    lengths.iter().map(|l| l.ln() * &l.lit(2.0)).collect()
}

/// The scaled logarithmic lengths `λ̃_ij = λ_ij + u_i + u_j` (docs/catalogue.md §4).
pub fn scaled_log_lengths<T: Real>(mesh: &Mesh, lambda: &[T], u: &[T]) -> Vec<T> {
    mesh.edges()
        .map(|e| {
            let h = e.halfedge();
            lambda[e.idx()].clone() + &u[mesh.tail(h).idx()] + &u[mesh.tip(h).idx()]
        })
        .collect()
}

/// The face's half-edges `[ij, jk, ki]` and their logarithmic lengths.
fn face_x<T: Real>(mesh: &Mesh, f: Face, lt: &[T]) -> ([HalfEdge; 3], [T; 3]) {
    let hs = mesh.face_halfedges(f);
    (hs, hs.map(|h| lt[h.edge().idx()].clone()))
}

/// `E` from the scaled logarithmic lengths `λ̃` (one per edge), the log scale factors `u`
/// and the target cone angles `Θ` (module doc). Faces are summed in face order. `None`
/// only for a mesh without edges and vertices (no number to take the precision from).
pub fn energy_at<T: Real>(mesh: &Mesh, lt: &[T], u: &[T], targets: &[T]) -> Option<T> {
    let z = lt.first().or(u.first())?;
    let mut e = face_energy_sum(mesh, mesh.faces(), lt, z);
    for (t, ui) in targets.iter().zip(u) {
        e += &(t.clone() * ui);
    }
    Some(e)
}

/// The face part `Σ_{f ∈ faces} [2f(λ̃_f) − (π/2)(λ̃_ij + λ̃_jk + λ̃_ki)]` of [`energy_at`]
/// over the given faces, in their order, in the context of `like`. Over all faces and
/// plus `Σ Θ_i u_i` it is `E`; over the faces touching the support of a direction `d` it is
/// all of `E(u + sd)` that depends on `s` (proofs/B32).
pub fn face_energy_sum<T: Real>(
    mesh: &Mesh,
    faces: impl IntoIterator<Item = Face>,
    lt: &[T],
    like: &T,
) -> T {
    let half_pi = T::pi(like.ctx()) * &like.lit(0.5);
    let two = like.lit(2.0);
    let mut e = like.zero_like();
    for f in faces {
        let (_, x) = face_x(mesh, f, lt);
        let sum = x[0].clone() + &x[1] + &x[2];
        e += &(triangle_energy(&x) * &two - &(half_pi.clone() * &sum));
    }
    e
}

/// `E(u)` from the unscaled logarithmic lengths `λ` (see [`energy_at`]).
pub fn energy<T: Real>(mesh: &Mesh, lambda: &[T], u: &[T], targets: &[T]) -> Option<T> {
    energy_at(mesh, &scaled_log_lengths(mesh, lambda, u), u, targets)
}

/// The cone angles `θ_i` (sums of the corner angles of [`angles_from_log_lengths`], with
/// the degenerate extension) of the metric with logarithmic lengths `λ̃`; empty when there
/// are no edges.
pub fn cone_angles_at<T: Real>(mesh: &Mesh, lt: &[T]) -> Vec<T> {
    let Some(zero) = lt.first().map(Real::zero_like) else {
        return Vec::new();
    };
    let mut theta = vec![zero; mesh.n_vertices()];
    for f in mesh.faces() {
        let (hs, x) = face_x(mesh, f, lt);
        let a = angles_from_log_lengths(&x);
        for m in 0..3 {
            // The corner opposite side m is at the tail of side m + 2.
            theta[mesh.tail(hs[(m + 2) % 3]).idx()] += &a[m];
        }
    }
    theta
}

/// `∇E = Θ − θ(λ̃)` from the scaled logarithmic lengths (module doc).
pub fn gradient_at<T: Real>(mesh: &Mesh, lt: &[T], targets: &[T]) -> Vec<T> {
    let theta = cone_angles_at(mesh, lt);
    if theta.is_empty() {
        return targets.to_vec();
    }
    theta
        .into_iter()
        .zip(targets)
        .map(|(th, t)| t.clone() - &th)
        .collect()
}

/// `∇E(u) = Θ − θ(u)` from the unscaled logarithmic lengths `λ`.
pub fn gradient<T: Real>(mesh: &Mesh, lambda: &[T], u: &[T], targets: &[T]) -> Vec<T> {
    gradient_at(mesh, &scaled_log_lengths(mesh, lambda, u), targets)
}

/// The Hessian of `E`, the cotan Laplacian `H = −L` (module doc), assembled sparse on the
/// [`HessianPattern`] of `mesh` face by face from the cotangents of
/// [`face_terms`] (scale-free per face, so no length over- or underflows): each side
/// `ij` with opposite angle `α` adds `½ cot α` to `H_ii`, `H_jj` and subtracts it from
/// `H_ij`, `H_ji` (loops cancel). Degenerate or undecided faces add nothing (their
/// second derivatives vanish inside the degenerate region); every pair joined by a side is
/// stored, with the value 0 when only such faces join it.
pub fn hessian_at<T: Real>(mesh: &Mesh, lt: &[T]) -> SparseMatrix<T> {
    let pattern = HessianPattern::new(mesh);
    let Some(zero) = lt.first().map(Real::zero_like) else {
        return SparseMatrix::from_triplets(mesh.n_vertices(), &[]);
    };
    let mut val = pattern.zeros(&zero);
    for f in mesh.faces() {
        let (hs, x) = face_x(mesh, f, lt);
        if let Some(c) = face_terms(&x, false, true).cot {
            add_face_hessian(&pattern, mesh, &mut val, hs, &c);
        }
    }
    pattern.matrix(val)
}

/// Adds one proper face's `½ cot α_m` for its three sides (see [`hessian_at`]).
#[inline]
fn add_face_hessian<T: Real>(
    pattern: &HessianPattern,
    mesh: &Mesh,
    val: &mut [T],
    hs: [HalfEdge; 3],
    cot: &[T; 3],
) {
    for m in 0..3 {
        let w = cot[m].clone() * &cot[m].lit(0.5);
        pattern.add_side(mesh, val, hs[m], &w);
    }
}

/// `E`, `∇E` and the Hessian at one point, from one pass over the faces.
#[derive(Clone, Debug)]
pub struct EnergyParts<T> {
    /// `E` as [`energy_at`] gives it.
    pub energy: Option<T>,
    /// `∇E = Θ − θ` as [`gradient_at`] gives it.
    pub gradient: Vec<T>,
    /// The cotan Laplacian as [`hessian_at`] gives it.
    pub hessian: SparseMatrix<T>,
}

/// [`energy_at`], [`gradient_at`] and [`hessian_at`] together: each face's shifted sides,
/// shape, angles, `Л` values and cotangents are computed once ([`face_terms`]) and the
/// Hessian is assembled in place on a [`HessianPattern`] built here. The same formulas,
/// in the same order of summation, as the three separate functions.
pub fn energy_gradient_hessian_at<T: Real>(
    mesh: &Mesh,
    lt: &[T],
    u: &[T],
    targets: &[T],
) -> EnergyParts<T> {
    let pattern = HessianPattern::new(mesh);
    energy_gradient_hessian_with(&pattern, mesh, lt, u, targets)
}

/// [`energy_gradient_hessian_at`] on a pattern built once for `mesh` (reused across
/// evaluations on the same triangulation, e.g. by a Newton solver).
///
/// A pattern of another mesh is a programming error: it panics when its size does not fit
/// ([`HessianPattern::fits`]).
pub fn energy_gradient_hessian_with<T: Real>(
    pattern: &HessianPattern,
    mesh: &Mesh,
    lt: &[T],
    u: &[T],
    targets: &[T],
) -> EnergyParts<T> {
    assert!(pattern.fits(mesh), "Hessian pattern of another mesh");
    let Some(z) = lt.first().or(u.first()) else {
        return EnergyParts {
            energy: None,
            gradient: targets.to_vec(),
            hessian: SparseMatrix::from_triplets(mesh.n_vertices(), &[]),
        };
    };
    let zero = z.zero_like();
    let half_pi = T::pi(z.ctx()) * &z.lit(0.5);
    let two = z.lit(2.0);
    let mut e = zero.clone();
    let mut theta = vec![zero.clone(); mesh.n_vertices()];
    let mut val = pattern.zeros(&zero);
    for f in mesh.faces() {
        let (hs, x) = face_x(mesh, f, lt);
        let ft = face_terms(&x, true, true);
        if let Some(fx) = &ft.f {
            let sum = x[0].clone() + &x[1] + &x[2];
            e += &(fx.clone() * &two - &(half_pi.clone() * &sum));
        }
        for m in 0..3 {
            theta[mesh.tail(hs[(m + 2) % 3]).idx()] += &ft.angles[m];
        }
        if let Some(c) = &ft.cot {
            add_face_hessian(pattern, mesh, &mut val, hs, c);
        }
    }
    close_parts(e, theta, !lt.is_empty(), u, targets, pattern.matrix(val))
}

/// The common end of the one-pass assemblies ([`energy_gradient_hessian_with`] and the
/// MPFR pass of [`super::fast_mpfr`]): `E = Σ_f F_f + Σ_i Θ_i u_i` from the face sum `e`,
/// `∇E = Θ − θ` from the cone angles `θ` (the targets alone when there are no edges) and
/// the assembled Hessian.
pub(super) fn close_parts<T: Real>(
    mut e: T,
    theta: Vec<T>,
    has_edges: bool,
    u: &[T],
    targets: &[T],
    hessian: SparseMatrix<T>,
) -> EnergyParts<T> {
    for (t, ui) in targets.iter().zip(u) {
        e += &(t.clone() * ui);
    }
    let gradient = if has_edges {
        theta
            .into_iter()
            .zip(targets)
            .map(|(th, t)| t.clone() - &th)
            .collect()
    } else {
        targets.to_vec()
    };
    EnergyParts {
        energy: Some(e),
        gradient,
        hessian,
    }
}

/// The Hessian of `E(u)` from the unscaled logarithmic lengths `λ` ([`hessian_at`]).
pub fn hessian<T: Real>(mesh: &Mesh, lambda: &[T], u: &[T]) -> SparseMatrix<T> {
    hessian_at(mesh, &scaled_log_lengths(mesh, lambda, u))
}

/// `λ = 2 log ℓ = 2(ln m + k ln 2)` for an exponent-apart length `ℓ = m·2ᵏ`, in the
/// context `ctx`: finite for every representable `ℓ` (docs/catalogue.md §4, proof: B67 for the
/// lengths themselves).
pub fn log_length_exp<T: Real>(l: &ExpLength, ctx: T::Ctx) -> T {
    let ln2 = T::from_f64(2.0, ctx).ln();
    let m = T::from_f64(l.mantissa(), ctx).ln();
    (m + &(ln2 * &T::from_f64(f64::from(l.exponent()), ctx))) * &T::from_f64(2.0, ctx)
}

/// The energy on the variable triangulation: the intrinsic Delaunay triangulation of the
/// scaled metric and the quantities of [`at_delaunay`] on it.
#[derive(Clone, Debug)]
pub struct DelaunayEnergy<T> {
    /// The intrinsic Delaunay triangulation `T(u)` (same vertices as the input).
    pub mesh: Mesh,
    /// The flip report (certified Delaunay edges, undecided or refused ones).
    pub report: FlipReport,
    /// `λ̃` on `T(u)`, from the flipped exponent-apart lengths.
    pub log_lengths: Vec<T>,
    /// `E(u)` (`None` only without edges and vertices).
    pub energy: Option<T>,
    /// `∇E(u) = Θ − θ(u)` on `T(u)`.
    pub gradient: Vec<T>,
    /// The cotan Laplacian of `T(u)`.
    pub hessian: SparseMatrix<T>,
}

/// `E`, `∇E` and the Hessian at `u` on the variable triangulation (S20, GSC21; docs/catalogue.md
/// §7): the scaled lengths `e^{(u_i+u_j)/2} ℓ_ij` are formed exponent apart and flipped to
/// intrinsic Delaunay by Ptolemy flips
/// ([`flip_to_delaunay_scaled`], certified signs of `D`), so any `|u| ≤ 2²⁰` neither
/// overflows nor underflows; then `λ̃ = 2(ln m + k ln 2)` ([`log_length_exp`]) in the
/// context `ctx`. The lengths after flipping carry the 53-bit rounding of
/// [`ExpLength`] (one per scaled length and per flip), whatever `ctx`.
pub fn at_delaunay<T: Real>(
    mesh: &Mesh,
    base: &[f64],
    u: &[f64],
    targets: &[T],
    ctx: T::Ctx,
) -> Result<DelaunayEnergy<T>, FlipToDelaunayError> {
    let mut m = mesh.clone();
    let (report, lengths) =
        flip_to_delaunay_scaled(&mut m, base, u, FlipKind::Ptolemy, &FlipOptions::default())?;
    let lt: Vec<T> = lengths.iter().map(|l| log_length_exp(l, ctx)).collect();
    let uu: Vec<T> = u.iter().map(|&x| T::from_f64(x, ctx)).collect();
    let EnergyParts {
        energy,
        gradient,
        hessian,
    } = energy_gradient_hessian_at(&m, &lt, &uu, targets);
    Ok(DelaunayEnergy {
        mesh: m,
        report,
        log_lengths: lt,
        energy,
        gradient,
        hessian,
    })
}
