//! T16 — conformal scaling preserves length cross ratios (notes Theorem 8, ⇒; Eqs. 10, 12).
//!
//! API:
//! - `pub fn check_scaling_preserves_cross_ratios<T: Real>(mesh: &Mesh, l: &[T], u: &[T], settings: &Settings) -> Verdict`
//! - `pub fn verify_equal_cross_ratios<T: Real>(mesh: &Mesh, l: &[T], lt: &[T], l_rel_err: &[f64], lt_rel_err: &[f64], settings: &Settings) -> Verdict`
//! - `pub fn check_scaling_preserves_cross_ratios_exact(mesh: &Mesh, l: &[Rational], s: &[Rational]) -> Verdict`
//! - `pub fn verify_equal_cross_ratios_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict`

use super::bounds::{eps, scale_factor_rel_error, SAFETY};
use super::inputs::{count_mismatch, two_metrics, two_rational_metrics};
use super::report::{check_lengths, check_rational_lengths, Tally};
use super::verdict::{Settings, Verdict};
use crate::geometry::cross_ratio::{cross_ratio_halfedges, length_cross_ratios};
use crate::geometry::scaling::{conformal_scaling, conformal_scaling_exact};
use crate::mesh::Mesh;
use crate::scalar::{nearest_f64, Real};
use rug::Rational;

/// T16, numerical: scales `l` by `u` ([`conformal_scaling`]) and compares cross ratios with
/// [`verify_equal_cross_ratios`], the scaled lengths carrying the error of B45.
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t16_scaling_cross_ratios::check_scaling_preserves_cross_ratios, Settings};
/// let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
/// let v = check_scaling_preserves_cross_ratios(&tet, &[1.0_f64; 6], &[0.1, -0.3, 0.7, 0.2], &Settings::default());
/// assert!(v.holds());
/// ```
pub fn check_scaling_preserves_cross_ratios<T: Real>(
    mesh: &Mesh,
    l: &[T],
    u: &[T],
    settings: &Settings,
) -> Verdict {
    if let Some(v) = check_lengths(mesh, l) {
        return v;
    }
    if let Some(v) = count_mismatch(u.len(), "scale factors", mesh.n_vertices(), "vertices") {
        return v;
    }
    let e = eps::<T>(l[0].ctx());
    let lt = conformal_scaling(mesh, l, u);
    let lt_err: Vec<f64> = mesh
        .edges()
        .map(|edge| {
            let h = edge.halfedge();
            let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
            scale_factor_rel_error(u[i].approx_f64(), u[j].approx_f64(), e) + SAFETY * e
        })
        .collect();
    verify_equal_cross_ratios(mesh, l, &lt, &vec![0.0; l.len()], &lt_err, settings)
}

/// The comparison behind T16/T17: `c̃_e = c_e` on every interior edge, where `l_rel_err`,
/// `lt_rel_err` bound the relative errors of the given lengths (0 for exact data). Tolerance
/// (proofs/B45): `2(|c| (3ε + Σ_4 δℓ) + |c̃| (3ε + Σ_4 δℓ̃) + ε|c̃ − c|)`. Witnesses `e…`.
pub fn verify_equal_cross_ratios<T: Real>(
    mesh: &Mesh,
    l: &[T],
    lt: &[T],
    l_rel_err: &[f64],
    lt_rel_err: &[f64],
    settings: &Settings,
) -> Verdict {
    let p = match two_metrics(mesh, l, lt) {
        Ok(p) => p,
        Err(v) => return v,
    };
    if l_rel_err.len() != l.len() || lt_rel_err.len() != lt.len() {
        return Verdict::NotApplicable {
            reason: "one relative error per edge expected".to_string(),
        };
    }
    let e = p.eps;
    let c = length_cross_ratios(mesh, l);
    let ct = length_cross_ratios(mesh, lt);
    let mut tally = p.tally();
    for edge in mesh.edges() {
        let (Some(a), Some(b), Some(hs)) = (
            &c[edge.idx()],
            &ct[edge.idx()],
            cross_ratio_halfedges(mesh, edge),
        ) else {
            continue;
        };
        let sum = |r: &[f64]| hs.iter().map(|h| r[h.edge().idx()]).sum::<f64>();
        let d = b.clone() - a;
        let tol = settings.slack
            * SAFETY
            * (a.approx_f64().abs() * (3.0 * e + sum(l_rel_err))
                + b.approx_f64().abs() * (3.0 * e + sum(lt_rel_err))
                + e * d.approx_f64().abs());
        tally.within(format!("{edge}"), "c̃ − c", &d, tol);
    }
    tally.verdict()
}

/// T16, exact in ℚ: `ℓ̃ = s_i s_j ℓ` with rational `s` ([`conformal_scaling_exact`]), then
/// [`verify_equal_cross_ratios_exact`] (certified).
pub fn check_scaling_preserves_cross_ratios_exact(
    mesh: &Mesh,
    l: &[Rational],
    s: &[Rational],
) -> Verdict {
    if let Some(v) = check_rational_lengths(mesh, l) {
        return v;
    }
    if let Some(v) = count_mismatch(s.len(), "scale factors", mesh.n_vertices(), "vertices") {
        return v;
    }
    let lt = conformal_scaling_exact(mesh, l, s);
    verify_equal_cross_ratios_exact(mesh, l, &lt)
}

/// Exact comparison `c̃_e = c_e` in ℚ on every interior edge (witnesses `e…`). Also valid on
/// squared lengths, where it compares squared cross ratios.
pub fn verify_equal_cross_ratios_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict {
    if let Some(v) = two_rational_metrics(mesh, l, lt) {
        return v;
    }
    let mut tally = Tally::new(true, 0);
    for (k, (a, b)) in length_cross_ratios(mesh, l)
        .into_iter()
        .zip(length_cross_ratios(mesh, lt))
        .enumerate()
    {
        if let (Some(a), Some(b)) = (a, b) {
            if a != b {
                let d = nearest_f64(&(b - a));
                tally.fail(format!("e{k}"), "c̃ ≠ c", d);
            }
        }
    }
    tally.verdict()
}
