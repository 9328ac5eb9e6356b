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

use super::bounds::SAFETY;
use super::inputs::{count_mismatch, two_metrics, two_rational_metrics};
use super::report::Tally;
use super::verdict::{Settings, Verdict};
use crate::geometry::scaling::reconstruct_scale_factors;
use crate::mesh::{HalfEdge, Mesh};
use crate::scalar::{nearest_f64, Real};
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
    if let Err(v) = two_metrics(mesh, l, lt) {
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
    let p = match two_metrics(mesh, l, lt) {
        Ok(p) => p,
        Err(v) => return v,
    };
    compare_corner_pairs(
        mesh,
        [l, lt],
        corner_exp_u,
        p.tally(),
        |tally, h, [xa, xb, le, lte]| {
            let lhs = xa.clone() * xb * le * le;
            let rhs = lte.clone() * lte;
            let d = lhs.clone() - &rhs;
            let tol = settings.slack
                * SAFETY
                * p.eps
                * (13.0 * lhs.approx_f64().abs() + rhs.approx_f64().abs() + d.approx_f64().abs());
            tally.within(format!("{h}"), "e^{u_a} e^{u_b} ℓ_ab² − ℓ̃_ab²", &d, tol);
        },
    )
}

/// T15, exact in ℚ for rational lengths (certified).
pub fn check_lemma1_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict {
    if let Some(v) = two_rational_metrics(mesh, l, lt) {
        return v;
    }
    let r = reconstruct_scale_factors(mesh, l, lt);
    verify_lemma1_exact(mesh, l, lt, &r.corner_exp_u)
}

/// The exact comparison of T15: `x_a x_b ℓ_ab² = ℓ̃_ab²` in ℚ for every face half-edge.
pub fn verify_lemma1_exact(
    mesh: &Mesh,
    l: &[Rational],
    lt: &[Rational],
    corner_exp_u: &[Option<Rational>],
) -> Verdict {
    if let Some(v) = two_rational_metrics(mesh, l, lt) {
        return v;
    }
    let tally = Tally::new(true, 0);
    compare_corner_pairs(
        mesh,
        [l, lt],
        corner_exp_u,
        tally,
        |tally, h, [xa, xb, le, lte]| {
            let lhs = Rational::from(xa * xb) * le * le;
            let rhs = Rational::from(lte * lte);
            if lhs != rhs {
                let d = lhs - rhs;
                tally.fail(
                    format!("{h}"),
                    "e^{u_a} e^{u_b} ℓ_ab² ≠ ℓ̃_ab²",
                    nearest_f64(&d),
                );
            }
        },
    )
}

/// The loop shared by [`verify_lemma1`] and [`verify_lemma1_exact`]: for every face
/// half-edge `h = a→b`, `compare` records the comparison of edge `h.edge()` given
/// `[x_a, x_b, ℓ_ab, ℓ̃_ab]`: the factors `x_a = corner_exp_u[h]` and
/// `x_b = corner_exp_u[next(h)]` (the corner of `b` in the same face) and the edge's two
/// lengths from `[l, lt]` (already validated, one per edge); a missing factor is a failure
/// at `h`. `NotApplicable` unless there is one entry per half-edge.
fn compare_corner_pairs<X>(
    mesh: &Mesh,
    [l, lt]: [&[X]; 2],
    corner_exp_u: &[Option<X>],
    mut tally: Tally,
    mut compare: impl FnMut(&mut Tally, HalfEdge, [&X; 4]),
) -> Verdict {
    if let Some(v) = count_mismatch(
        corner_exp_u.len(),
        "corner factors",
        mesh.n_halfedges(),
        "half-edges",
    ) {
        return v;
    }
    for h in mesh.halfedges() {
        if mesh.is_boundary_halfedge(h) {
            continue;
        }
        let (Some(xa), Some(xb)) = (&corner_exp_u[h.idx()], &corner_exp_u[mesh.next(h).idx()])
        else {
            tally.fail(format!("{h}"), "missing corner factor", f64::NAN);
            continue;
        };
        let e = h.edge().idx();
        compare(&mut tally, h, [xa, xb, &l[e], &lt[e]]);
    }
    tally.verdict()
}
