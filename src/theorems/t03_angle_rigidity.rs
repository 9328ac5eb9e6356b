//! T03 — equal corner angles ⇒ the metrics differ by one global scale (notes §1.3.1:
//! "angles are too rigid").
//!
//! API:
//! - `pub fn check_equal_angles_imply_scale<T: Real>(mesh: &Mesh, l: &[T], lt: &[T], settings: &Settings) -> Verdict`
//!
//! Hypotheses: `mesh` connected (a disconnected surface may carry one scale per component,
//! which this check reports as a failure: that is the negative control).

use super::bounds::{corner_angle_error, SAFETY};
use super::inputs::two_metrics;
use super::verdict::{Settings, Verdict};
use crate::geometry::corners::halfedge_angles;
use crate::mesh::Mesh;
use crate::predicates::tolerance::abs_at_most;
use crate::scalar::Real;

/// T03, numerical. First compares every corner angle of `l` and `lt` (tolerance: B40 for
/// both plus the subtraction). If some corner differs beyond its tolerance the hypothesis
/// fails and the verdict is `NotApplicable` (naming how many corners differ). Otherwise every
/// edge ratio `ℓ̃_e/ℓ_e` must equal that of edge 0 within
/// `2(ε|r_e| + ε|r_0| + ε|r_e − r_0|)` (proofs/B45); each edge that does not is a witness.
pub fn check_equal_angles_imply_scale<T: Real>(
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
    let a = halfedge_angles(mesh, l);
    let at = halfedge_angles(mesh, lt);
    let la = |x: &[T], h: crate::mesh::HalfEdge| x[h.edge().idx()].approx_f64();
    let mut angles = p.tally();
    for h in mesh.halfedges() {
        if mesh.is_boundary_halfedge(h) {
            continue;
        }
        let (n, p) = (mesh.next(h), mesh.prev(h));
        let tol = settings.slack
            * (corner_angle_error(la(l, h), la(l, n), la(l, p), e)
                + corner_angle_error(la(lt, h), la(lt, n), la(lt, p), e)
                + SAFETY * e * (a[h.idx()].approx_f64() - at[h.idx()].approx_f64()).abs());
        let d = at[h.idx()].clone() - &a[h.idx()];
        angles.within(format!("{h}"), "corner angle difference", &d, tol);
    }
    match angles.verdict() {
        Verdict::Fails { witnesses, .. } => {
            return Verdict::NotApplicable {
                reason: format!(
                    "hypothesis fails: corner angles differ at {} corners",
                    witnesses.len()
                ),
            }
        }
        u @ Verdict::Undecided { .. } => return u,
        _ => {}
    }
    let ratio: Vec<T> = l.iter().zip(lt).map(|(x, y)| y.clone() / x).collect();
    let r0 = ratio[0].approx_f64().abs();
    let mut tally = p.tally();
    for edge in mesh.edges() {
        let d = ratio[edge.idx()].clone() - &ratio[0];
        let re = ratio[edge.idx()].approx_f64().abs();
        let tol = settings.slack * SAFETY * e * (re + r0 + d.approx_f64().abs());
        tally.within(
            format!("{edge}"),
            "scale ℓ̃/ℓ differs from that of e0",
            &d,
            tol,
        );
    }
    if abs_at_most(&ratio[0], 0.0) == Some(true) {
        tally.fail("e0", "scale ℓ̃/ℓ is zero", 0.0);
    }
    tally.verdict()
}
