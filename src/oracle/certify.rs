//! Answering claims (protocol v1, [`super::claim`]) with certified verdicts.

use super::answer::{interval_lengths, summarize, START_BITS};
pub use super::answer::{Answer, ClaimVerdict};
use super::claim::{Assertion, Claim};
use crate::geometry::cone_angles::cone_angles;
use crate::geometry::cotan::cotan_weights;
use crate::io::json::edge_order;
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::{delaunay_sign_squared, QuadEdges};
use crate::predicates::within::within_all;
use crate::scalar::{Interval, Mpfr, Precision, Real, Sign};
use crate::theorems::Witness;
use rug::Rational;

/// A claim kind this build cannot evaluate.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("claim kind `{0}` cannot be evaluated by this build of penner")]
pub struct Unsupported(pub &'static str);

/// The user-facing index of each edge (first-appearance order of the surface format).
fn user_edge_index(mesh: &Mesh) -> Vec<usize> {
    let order = edge_order(mesh);
    let mut idx = vec![0; mesh.n_edges()];
    for (k, &e) in order.iter().enumerate() {
        idx[e] = k;
    }
    idx
}

/// `intrinsic_delaunay`: the sign of every interior edge's Delaunay polynomial, decided
/// exactly from the rational squared lengths (`delaunay_sign_squared`, proof: B63).
/// Boundary edges and edges with one face on both sides are Delaunay by definition.
fn intrinsic_delaunay(claim: &Claim) -> Answer {
    let mesh = &claim.surface.mesh;
    let sq = claim.surface.metric.squared();
    let order = edge_order(mesh);
    let mut witnesses = Vec::new();
    for (k, &e) in order.iter().enumerate() {
        let e = Edge(e as u32);
        if mesh.is_boundary_edge(e) {
            continue;
        }
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        if delaunay_sign_squared(q.lengths(&sq)) == Sign::Negative {
            let h = e.halfedge();
            witnesses.push(Witness {
                element: format!("edge {k} (v{}–v{})", mesh.tail(h).0, mesh.tip(h).0),
                detail: "not Delaunay: the opposite angles sum to more than π".to_string(),
                value: -1.0,
            });
        }
    }
    let verdict = if witnesses.is_empty() {
        ClaimVerdict::Holds
    } else {
        ClaimVerdict::Refuted
    };
    Answer {
        id: claim.id.clone(),
        kind: claim.assertion.kind(),
        verdict,
        certified: true,
        precision_bits: 0,
        max_discrepancy: None,
        counterexample: witnesses.first().cloned(),
        witnesses,
    }
}

/// Answer `claim`.
pub fn certify(claim: &Claim) -> Result<Answer, Unsupported> {
    let mesh = &claim.surface.mesh;
    match &claim.assertion {
        Assertion::ConeAngles { angles, epsilon } => {
            let mut enclose = |p| cone_angles(mesh, &interval_lengths(&claim.surface, p));
            let b = within_all(&mut enclose, angles, epsilon, START_BITS, claim.max_bits);
            Ok(summarize(claim, &b, &|i| format!("v{i}"), "cone angle"))
        }
        Assertion::ConformalEquivalence { target, u, epsilon } => {
            let user = user_edge_index(mesh);
            let mut enclose = |p: Precision| {
                let l = interval_lengths(&claim.surface, p);
                let lt = interval_lengths(target, p);
                let uu: Vec<Interval<Mpfr>> =
                    u.iter().map(|x| Interval::from_rational(x, p)).collect();
                let half = Interval::from_rational(&Rational::from((1, 2)), p);
                // Residual per edge, in user order: log ℓ̃ − log ℓ − (u_i + u_j)/2.
                let mut r = vec![Interval::from_rational(&Rational::new(), p); mesh.n_edges()];
                for e in mesh.edges() {
                    let h = e.halfedge();
                    let (i, j) = (mesh.tail(h).idx(), mesh.tip(h).idx());
                    let s = (uu[i].clone() + &uu[j]) * &half;
                    r[user[e.idx()]] = lt[e.idx()].ln() - &l[e.idx()].ln() - &s;
                }
                r
            };
            let zeros = vec![Rational::new(); mesh.n_edges()];
            let b = within_all(&mut enclose, &zeros, epsilon, START_BITS, claim.max_bits);
            let order = edge_order(mesh);
            let name = |k: usize| {
                let e = Edge(order[k] as u32);
                let h = e.halfedge();
                format!("edge {k} (v{}–v{})", mesh.tail(h).0, mesh.tip(h).0)
            };
            Ok(summarize(claim, &b, &name, "log-length residual"))
        }
        Assertion::CotanLaplacian { weights, epsilon } => {
            let order = edge_order(mesh);
            let mut enclose = |p| {
                let w = cotan_weights(mesh, &interval_lengths(&claim.surface, p));
                order.iter().map(|&e| w[e].clone()).collect()
            };
            let b = within_all(&mut enclose, weights, epsilon, START_BITS, claim.max_bits);
            let name = |k: usize| {
                let e = Edge(order[k] as u32);
                let h = e.halfedge();
                format!("edge {k} (v{}–v{})", mesh.tail(h).0, mesh.tip(h).0)
            };
            Ok(summarize(claim, &b, &name, "cotan weight"))
        }
        Assertion::DelaunayFlip {
            ptolemy,
            result,
            epsilon,
        } => Ok(super::flip_claim::delaunay_flip(
            claim, *ptolemy, result, epsilon,
        )),
        Assertion::IntrinsicDelaunay => Ok(intrinsic_delaunay(claim)),
        Assertion::Energy {
            u,
            targets,
            energy,
            gradient,
            epsilon,
        } => Ok(super::certify_energy::energy_claim(
            claim,
            u,
            targets.as_deref(),
            energy,
            gradient,
            epsilon,
        )),
        Assertion::Lobachevsky { x, y, epsilon } => {
            // Enclosure of Л over the outward-rounded argument (proofs/B52).
            let mut enclose = |p| {
                vec![crate::special::lobachevsky_enclosure(
                    &Interval::from_rational(x, p),
                )]
            };
            let b = within_all(
                &mut enclose,
                std::slice::from_ref(y),
                epsilon,
                START_BITS,
                claim.max_bits,
            );
            Ok(summarize(claim, &b, &|_| "x".to_string(), "value of Л(x)"))
        }
        Assertion::Uniformization(u) => Ok(uniformization(claim, u)),
        Assertion::SphereUniformization(c) => Ok(certificate_answer(
            claim,
            crate::uniformization::sphere_claim::recheck(&claim.surface, c, claim.max_bits)
                .map_err(|e| e.to_string()),
        )),
        Assertion::HyperbolicUniformization(h) => Ok(super::certify_hyperbolic::answer(claim, h)),
        Assertion::Parametrization(p) => Ok(parametrization(claim, p)),
        Assertion::CirclePacking { .. } | Assertion::CirclePattern { .. } => {
            super::certify_circles::answer(claim).ok_or(Unsupported(claim.assertion.kind()))
        }
    }
}

/// `parametrization`: the exact re-check of [`crate::overlay::claim::recheck`] (B109,
/// B110). `holds` or `refuted` (every failure a witness), both certified; files that
/// cannot be read are refused before ([`crate::oracle::claim::parse`] reads them).
fn parametrization(claim: &Claim, p: &crate::overlay::claim::ParametrizationClaim) -> Answer {
    use crate::overlay::claim::{recheck, ParametrizationVerdict};
    let (verdict, witnesses) = match recheck(&claim.surface, p) {
        Ok(ParametrizationVerdict::Holds { .. }) => (ClaimVerdict::Holds, Vec::new()),
        Ok(ParametrizationVerdict::Refuted(failures)) => (
            ClaimVerdict::Refuted,
            failures
                .into_iter()
                .map(|f| Witness {
                    element: f.element,
                    detail: f.detail,
                    value: f64::NAN,
                })
                .collect(),
        ),
        Err(e) => (
            ClaimVerdict::Undecided,
            vec![Witness {
                element: "files".into(),
                detail: e.to_string(),
                value: f64::NAN,
            }],
        ),
    };
    super::answer::decided_answer(claim, verdict, 0, None, witnesses)
}

/// `uniformization`: the re-check of `uniformization::claim_form::recheck` (B71) at the
/// claim's `max_bits`. Never refuted (no proof of non-existence is attempted); a malformed
/// certificate is one witness of an undecided answer.
fn uniformization(
    claim: &Claim,
    u: &crate::uniformization::claim_form::UniformizationClaim,
) -> Answer {
    let outcome = crate::uniformization::claim_form::recheck(&claim.surface, u, claim.max_bits);
    certificate_answer(claim, outcome.map_err(|e| e.to_string()))
}

/// The answer to a certificate claim (`uniformization`, `sphere_uniformization`) from its
/// re-check: `holds` with the proved distance, otherwise `undecided` with the reason (a
/// malformed certificate, `Err`, as the witness `certificate`). Never `fails`.
fn certificate_answer(
    claim: &Claim,
    outcome: Result<crate::uniformization::certificate::CertificateOutcome, String>,
) -> Answer {
    use crate::uniformization::certificate::CertificateOutcome;
    let (verdict, max_discrepancy, witnesses) = match outcome {
        Ok(CertificateOutcome::Holds { distance, .. }) => {
            (ClaimVerdict::Holds, Some(distance), Vec::new())
        }
        Ok(CertificateOutcome::Undecided { reason }) => (
            ClaimVerdict::Undecided,
            None,
            vec![Witness {
                element: "surface".into(),
                detail: reason,
                value: f64::NAN,
            }],
        ),
        Err(detail) => (
            ClaimVerdict::Undecided,
            None,
            vec![Witness {
                element: "certificate".into(),
                detail,
                value: f64::NAN,
            }],
        ),
    };
    Answer {
        id: claim.id.clone(),
        kind: claim.assertion.kind(),
        verdict,
        certified: verdict == ClaimVerdict::Holds,
        precision_bits: claim.max_bits,
        max_discrepancy,
        counterexample: None,
        witnesses,
    }
}
