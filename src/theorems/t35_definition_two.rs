//! T35 (notes §1.5.3 Definition 2; docs/catalogue.md §5–6), exactly over ℚ: (I) metrics related by
//! conformal scalings and Ptolemy flips ⇔ (II) metrics with the same ideal polyhedron,
//! i.e. equal shear data `s_ij = ln c_ij` (compared as equal cross ratios `c_ij`) on a
//! common triangulation. Proof: T35.

use super::{Verdict, Witness};
use crate::algorithms::flips::flip_ptolemy_exact;
use crate::geometry::cross_ratio::length_cross_ratios;
use crate::geometry::scaling::{conformal_scaling_exact, reconstruct_scale_factors};
use crate::mesh::{Edge, FlipError, Mesh};
use crate::scalar::nearest_f64;
use rug::Rational;

/// Apply the Ptolemy flips `flips` in order to a copy of `(mesh, l)` (exact, notes Eq. 18).
///
/// # Errors
/// The first flip the mesh refuses (out of range, boundary, or an edge inside one face).
pub fn ptolemy_flips_exact(
    mesh: &Mesh,
    l: &[Rational],
    flips: &[Edge],
) -> Result<(Mesh, Vec<Rational>), FlipError> {
    let (mut m, mut x) = (mesh.clone(), l.to_vec());
    for &e in flips {
        flip_ptolemy_exact(&mut m, &mut x, e)?;
    }
    Ok((m, x))
}

/// Metric (I) of Definition 2: `l` scaled by `ℓ_ij ↦ s_i s_j ℓ_ij` (rational `s_i = e^{u_i/2}`),
/// then transported by the Ptolemy flips `flips`.
///
/// # Errors
/// As [`ptolemy_flips_exact`].
pub fn scaled_then_flipped_exact(
    mesh: &Mesh,
    l: &[Rational],
    s: &[Rational],
    flips: &[Edge],
) -> Result<(Mesh, Vec<Rational>), FlipError> {
    ptolemy_flips_exact(mesh, &conformal_scaling_exact(mesh, l, s), flips)
}

/// Check Definition 2 for metric `l` on `mesh` and metric `lb` given on the triangulation
/// reached from `mesh` by the Ptolemy flips `flips`. Flipping `l` by the same sequence gives
/// `la` on that triangulation; then
/// - (I ⇒ II) every interior edge has `c_ij(la) = c_ij(lb)` (same shear data);
/// - (II ⇒ I) Lemma 1 per corner gives one factor `e^{u_v}` per vertex (all corners at `v`
///   agree) and `lb_ij² = e^{u_i} e^{u_j} la_ij²` on every edge, so `lb` is a scaling of `la`.
///
/// Every failing edge or vertex is a witness. Exact, hence `certified: true`.
///
/// ```
/// use penner::mesh::{builders, Edge};
/// use penner::theorems::t35_definition_two::{check_definition_two_exact, scaled_then_flipped_exact};
/// use rug::Rational;
/// let m = builders::tetrahedron().mesh;
/// let l: Vec<Rational> = (0..6).map(|i| Rational::from(i + 2)).collect();
/// let s: Vec<Rational> = (0..4).map(|i| Rational::from((i + 1, 2))).collect();
/// let (_, lb) = scaled_then_flipped_exact(&m, &l, &s, &[Edge(0)]).unwrap();
/// assert!(check_definition_two_exact(&m, &l, &[Edge(0)], &lb).holds());
/// ```
pub fn check_definition_two_exact(
    mesh: &Mesh,
    l: &[Rational],
    flips: &[Edge],
    lb: &[Rational],
) -> Verdict {
    if l.len() != mesh.n_edges() || lb.len() != mesh.n_edges() {
        return Verdict::NotApplicable {
            reason: "one length per edge is required for both metrics".into(),
        };
    }
    if l.iter().chain(lb).any(|x| *x <= 0) {
        return Verdict::NotApplicable {
            reason: "lengths must be positive".into(),
        };
    }
    let (m, la) = match ptolemy_flips_exact(mesh, l, flips) {
        Ok(x) => x,
        Err(err) => {
            return Verdict::NotApplicable {
                reason: format!("flip sequence refused: {err}"),
            }
        }
    };
    let mut witnesses = Vec::new();
    // (I ⇒ II): equal cross ratios on the common triangulation.
    let (ca, cb) = (length_cross_ratios(&m, &la), length_cross_ratios(&m, lb));
    for e in m.edges() {
        if ca[e.idx()] != cb[e.idx()] {
            witnesses.push(Witness {
                element: e.to_string(),
                detail: "cross ratios (shear data) of the two metrics differ".into(),
                value: cb[e.idx()].as_ref().map_or(f64::NAN, nearest_f64),
            });
        }
    }
    // (II ⇒ I): Lemma 1 per corner, one factor per vertex, then lb = scaled la.
    let rec = reconstruct_scale_factors(&m, &la, lb);
    let exp_u = rec.exp_u();
    for h in m.halfedges() {
        let v = m.tail(h).idx();
        if let (Some(c), Some(r)) = (&rec.corner_exp_u[h.idx()], &exp_u[v]) {
            if c != r {
                witnesses.push(Witness {
                    element: format!("v{v}"),
                    detail: format!("Lemma 1 factor at corner {h} differs from {r}"),
                    value: nearest_f64(c),
                });
            }
        }
    }
    for e in m.edges() {
        let h = e.halfedge();
        let (Some(ui), Some(uj)) = (&exp_u[m.tail(h).idx()], &exp_u[m.tip(h).idx()]) else {
            continue;
        };
        let want = Rational::from(ui * uj) * Rational::from(la[e.idx()].square_ref());
        let got = Rational::from(lb[e.idx()].square_ref());
        if want != got {
            witnesses.push(Witness {
                element: e.to_string(),
                detail: "length is not the reconstructed scaling e^{(u_i+u_j)/2} of the other"
                    .into(),
                value: nearest_f64(&got),
            });
        }
    }
    Verdict::certified(witnesses, Vec::new(), 0)
}
