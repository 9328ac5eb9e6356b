//! T15 — Lemma 1 (notes §1.5.1, Eq. 11): any two metrics `ℓ, ℓ̃` on one triangle are
//! discretely conformally equivalent, with `e^{u_i} = (ℓ̃_ij/ℓ_ij)(ℓ_jk/ℓ̃_jk)(ℓ̃_ki/ℓ_ki)`.
//! Checked face by face on any mesh: in every face the Lemma 1 factors satisfy
//! `ℓ̃_ab² = e^{u_a} e^{u_b} ℓ_ab²` for its three edges.
//!
//! API:
//! - `pub fn check_lemma1<T: Real>(mesh: &Mesh, l: &[T], lt: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_lemma1<T: Real>(mesh: &Mesh, l: &[T], lt: &[T], corner_exp_u: &[Option<T>], settings: &Settings) -> Verdict`
//! - `pub fn check_lemma1_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict`
//! - `pub fn verify_lemma1_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational], corner_exp_u: &[Option<Rational>]) -> Verdict`

use super::bounds::{eps, SAFETY};
use super::report::{check_lengths, check_rational_lengths, Tally};
use super::verdict::{Settings, Verdict};
use crate::geometry::scaling::{reconstruct_scale_factors, reconstruct_scale_factors_exact};
use crate::mesh::Mesh;
use crate::scalar::Real;
use rug::Rational;

/// T15, numerical: Lemma 1 factors of every corner by
/// [`reconstruct_scale_factors`]`.corner_exp_u`, then [`verify_lemma1`].
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t15_lemma1::check_lemma1, Settings};
/// let tri = Mesh::from_faces(3, &[[0, 1, 2]]).unwrap();
/// let v = check_lemma1(&tri, &[3.0_f64, 4.0, 5.0], &[1.0, 1.5, 2.0], &Settings::default());
/// assert!(v.holds());
/// ```
pub fn check_lemma1<T: Real>(mesh: &Mesh, l: &[T], lt: &[T], settings: &Settings) -> Verdict {
    if let Some(v) = check_lengths(mesh, l).or_else(|| check_lengths(mesh, lt)) {
        return v;
    }
    let r = reconstruct_scale_factors(mesh, l, lt);
    verify_lemma1(mesh, l, lt, &r.corner_exp_u, settings)
}

/// The comparison of T15 for claimed per-corner factors (`corner_exp_u[h]` = `e^u` at
/// `tail(h)` in the face of `h`): for every face half-edge `h = a→b`,
/// `|x_a x_b ℓ_ab² − ℓ̃_ab²| ≤ 2ε(13|x_a x_b ℓ_ab²| + |ℓ̃_ab²| + |difference|)` (proofs/B45:
/// each factor carries ≤ 5ε from its five roundings). Witnesses `h…`.
pub fn verify_lemma1<T: Real>(
    mesh: &Mesh,
    l: &[T],
    lt: &[T],
    corner_exp_u: &[Option<T>],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, l).or_else(|| check_lengths(mesh, lt)) {
        return v;
    }
    if corner_exp_u.len() != mesh.n_halfedges() {
        return Verdict::NotApplicable {
            reason: format!(
                "{} corner factors for {} half-edges",
                corner_exp_u.len(),
                mesh.n_halfedges()
            ),
        };
    }
    let ctx = l[0].ctx();
    let e = eps::<T>(ctx);
    let mut tally = Tally::new(false, T::precision_bits(ctx));
    for h in mesh.halfedges() {
        if mesh.is_boundary_halfedge(h) {
            continue;
        }
        let (Some(xa), Some(xb)) = (&corner_exp_u[h.idx()], &corner_exp_u[mesh.next(h).idx()])
        else {
            tally.fail(format!("{h}"), "missing corner factor", f64::NAN);
            continue;
        };
        let le = &l[h.edge().idx()];
        let lte = &lt[h.edge().idx()];
        let lhs = xa.clone() * xb * le * le;
        let rhs = lte.clone() * lte;
        let d = lhs.clone() - &rhs;
        let tol = settings.slack
            * SAFETY
            * e
            * (13.0 * lhs.approx_f64().abs() + rhs.approx_f64().abs() + d.approx_f64().abs());
        tally.within(format!("{h}"), "e^{u_a} e^{u_b} ℓ_ab² − ℓ̃_ab²", &d, tol);
    }
    tally.verdict()
}

/// T15, exact in ℚ for rational lengths (certified).
pub fn check_lemma1_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict {
    if let Some(v) = check_rational_lengths(mesh, l).or_else(|| check_rational_lengths(mesh, lt)) {
        return v;
    }
    let r = reconstruct_scale_factors_exact(mesh, l, lt);
    verify_lemma1_exact(mesh, l, lt, &r.corner_exp_u)
}

/// The exact comparison of T15: `x_a x_b ℓ_ab² = ℓ̃_ab²` in ℚ for every face half-edge.
pub fn verify_lemma1_exact(
    mesh: &Mesh,
    l: &[Rational],
    lt: &[Rational],
    corner_exp_u: &[Option<Rational>],
) -> Verdict {
    if let Some(v) = check_rational_lengths(mesh, l).or_else(|| check_rational_lengths(mesh, lt)) {
        return v;
    }
    if corner_exp_u.len() != mesh.n_halfedges() {
        return Verdict::NotApplicable {
            reason: "one corner factor per half-edge expected".to_string(),
        };
    }
    let mut tally = Tally::new(true, 0);
    for h in mesh.halfedges() {
        if mesh.is_boundary_halfedge(h) {
            continue;
        }
        let (Some(xa), Some(xb)) = (&corner_exp_u[h.idx()], &corner_exp_u[mesh.next(h).idx()])
        else {
            tally.fail(format!("{h}"), "missing corner factor", f64::NAN);
            continue;
        };
        let le = &l[h.edge().idx()];
        let lte = &lt[h.edge().idx()];
        let lhs = Rational::from(xa * xb) * le * le;
        let rhs = Rational::from(lte * lte);
        if lhs != rhs {
            let d = lhs - rhs;
            tally.fail(format!("{h}"), "e^{u_a} e^{u_b} ℓ_ab² ≠ ℓ̃_ab²", d.to_f64());
        }
    }
    tally.verdict()
}
