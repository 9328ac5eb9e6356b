//! T17 — equal length cross ratios ⇒ discretely conformally equivalent (notes Theorem 8, ⇐):
//! the scale factors are reconstructed by Lemma 1 in every face, must agree at every vertex,
//! and must reproduce `ℓ̃`. A metric that is not equivalent (e.g. one perturbed edge) is
//! refused, naming every inconsistent corner.
//!
//! API:
//! - `pub fn check_conformal_equivalence<T: Real>(mesh: &Mesh, l: &[T], lt: &[T], settings: &Settings) -> Verdict`
//! - `pub fn check_conformal_equivalence_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict`

use super::bounds::SAFETY;
use super::inputs::{two_metrics, two_rational_metrics};
use super::report::Tally;
use super::t15_lemma1::{verify_lemma1, verify_lemma1_exact};
use super::verdict::{Settings, Verdict};
use crate::geometry::scaling::{reconstruct_scale_factors, Reconstruction};
use crate::mesh::{HalfEdge, Mesh};
use crate::scalar::{nearest_f64, Real};
use rug::Rational;

/// Per face half-edge, the value of the representative corner of its tail vertex.
fn vertex_values<T: Clone>(mesh: &Mesh, r: &Reconstruction<T>) -> Vec<Option<T>> {
    let per_vertex = r.exp_u();
    mesh.halfedges()
        .map(|h| {
            if mesh.is_boundary_halfedge(h) {
                None
            } else {
                per_vertex[mesh.tail(h).idx()].clone()
            }
        })
        .collect()
}

/// Every corner `h` with a Lemma 1 factor `x` whose vertex has a representative corner
/// `rep ≠ h` with a factor `x_rep`, as `(h, rep, x, x_rep)`: the pairs T17 compares (the
/// representative itself is equal to itself and skipped).
fn corners_and_representatives<'a, T>(
    mesh: &'a Mesh,
    r: &'a Reconstruction<T>,
) -> impl Iterator<Item = (HalfEdge, HalfEdge, &'a T, &'a T)> + 'a {
    mesh.halfedges().filter_map(move |h| {
        let x = r.corner_exp_u[h.idx()].as_ref()?;
        let rep = r.representative[mesh.tail(h).idx()]?;
        let xr = r.corner_exp_u[rep.idx()].as_ref()?;
        (rep != h).then_some((h, rep, x, xr))
    })
}

/// Element name of the corner of `h`: `v3@f2`.
fn corner_name(mesh: &Mesh, h: HalfEdge) -> String {
    match mesh.face(h) {
        Some(f) => format!("{}@{f}", mesh.tail(h)),
        None => format!("{}", mesh.tail(h)),
    }
}

/// T17, numerical: Lemma 1 corner factors ([`reconstruct_scale_factors`]); every corner of a
/// vertex must match its representative within `2ε(5|x| + 5|x_rep| + |x − x_rep|)`
/// (proofs/B45); the per-vertex factors must then reproduce `ℓ̃`
/// ([`verify_lemma1`]). `Holds` means `ℓ̃ = e^{(u_i+u_j)/2} ℓ` with the reconstructed `u`;
/// `Fails` lists every inconsistent corner (`v…@f…`) and every edge not reproduced.
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t17_cross_ratio_equivalence::check_conformal_equivalence, Settings};
/// let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
/// let l = [1.0_f64; 6];
/// let mut lt = [2.0_f64; 6];
/// assert!(check_conformal_equivalence(&tet, &l, &lt, &Settings::default()).holds());
/// lt[0] = 2.5; // no longer a conformal scaling
/// assert!(check_conformal_equivalence(&tet, &l, &lt, &Settings::default()).fails());
/// ```
pub fn check_conformal_equivalence<T: Real>(
    mesh: &Mesh,
    l: &[T],
    lt: &[T],
    settings: &Settings,
) -> Verdict {
    let p = match two_metrics(mesh, l, lt) {
        Ok(p) => p,
        Err(v) => return v,
    };
    let e = p.eps;
    let r = reconstruct_scale_factors(mesh, l, lt);
    let mut tally = p.tally();
    for (h, rep, x, xr) in corners_and_representatives(mesh, &r) {
        let d = x.clone() - xr;
        let tol = settings.slack
            * SAFETY
            * e
            * (5.0 * x.approx_f64().abs() + 5.0 * xr.approx_f64().abs() + d.approx_f64().abs());
        tally.within(
            corner_name(mesh, h),
            &format!(
                "Lemma 1 factor differs from the corner {}",
                corner_name(mesh, rep)
            ),
            &d,
            tol,
        );
    }
    let scaled = verify_lemma1(mesh, l, lt, &vertex_values(mesh, &r), settings);
    merge(tally, scaled)
}

/// T17, exact in ℚ for rational lengths (certified).
pub fn check_conformal_equivalence_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict {
    if let Some(v) = two_rational_metrics(mesh, l, lt) {
        return v;
    }
    let r = reconstruct_scale_factors(mesh, l, lt);
    let mut tally = Tally::new(true, 0);
    for (h, rep, x, xr) in corners_and_representatives(mesh, &r) {
        if x != xr {
            let d = nearest_f64(&Rational::from(x - xr));
            tally.fail(
                corner_name(mesh, h),
                format!(
                    "Lemma 1 factor differs from the corner {}",
                    corner_name(mesh, rep)
                ),
                d,
            );
        }
    }
    let scaled = verify_lemma1_exact(mesh, l, lt, &vertex_values(mesh, &r));
    merge(tally, scaled)
}

/// Add the witnesses of a second verdict to a tally.
fn merge(mut tally: Tally, other: Verdict) -> Verdict {
    match other {
        Verdict::Fails { witnesses, .. } => {
            for w in witnesses {
                tally.fail(w.element, w.detail, w.value);
            }
        }
        Verdict::Undecided { witnesses, .. } => {
            for w in witnesses {
                tally.undecided(w.element, w.detail, w.value);
            }
        }
        Verdict::NotApplicable { reason } => return Verdict::NotApplicable { reason },
        Verdict::Holds { .. } => {}
    }
    tally.verdict()
}
