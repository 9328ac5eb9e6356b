//! Answering `circle_packing` and `circle_pattern` claims (protocol v1) from the enclosures
//! and exact signs of [`crate::circles::realize`] (proofs/B98): tangency defects and cone
//! angles are decided by [`within_all`] at rising MPFR precision (an entry holds when its
//! enclosure lies within ε of the claimed value, is refuted only when it lies farther
//! than ε, and stays undecided otherwise); orientations and winding numbers are exact, and
//! a proved violation of one refutes the packing whatever the enclosures say.

use super::answer::{summarize, Answer, ClaimVerdict, START_BITS};
use super::claim::{Assertion, Claim};
use super::claim_circles::Packing;
use crate::circles::realize::{
    cap_orientation_violations, cap_tangency_defects, pattern_cone_angles,
    plane_orientation_violations, plane_tangency_defects, Violation,
};
use crate::io::json::edge_order;
use crate::mesh::Edge;
use crate::predicates::within::within_all;
use crate::scalar::{Interval, Mpfr, Precision};
use crate::theorems::Witness;
use rug::Rational;

/// Answer a `circle_packing` or `circle_pattern` claim (module docs); `None` for other
/// kinds.
pub fn answer(claim: &Claim) -> Option<Answer> {
    Some(match &claim.assertion {
        Assertion::CirclePacking { packing, epsilon } => packing_claim(claim, packing, epsilon),
        Assertion::CirclePattern {
            radii,
            phi_over_pi,
            angles,
            epsilon,
        } => pattern_claim(claim, radii, phi_over_pi, angles, epsilon),
        _ => return None,
    })
}

/// Answer a `circle_packing` claim (module docs).
pub fn packing_claim(claim: &Claim, packing: &Packing, epsilon: &Rational) -> Answer {
    let mesh = &claim.surface.mesh;
    let order = edge_order(mesh);
    let in_user_order = |d: Vec<Interval<Mpfr>>| -> Vec<Interval<Mpfr>> {
        order.iter().map(|&e| d[e].clone()).collect()
    };
    let (exact, what) = match packing {
        Packing::Plane(c) => (
            plane_orientation_violations(mesh, c),
            "tangency defect ‖c_i − c_j‖ − (ρ_i + ρ_j)",
        ),
        Packing::Sphere(c) => (
            cap_orientation_violations(mesh, c),
            "tangency defect I_ij − 1 (inversive distance)",
        ),
    };
    let mut enclose = |p: Precision| match packing {
        Packing::Plane(c) => in_user_order(plane_tangency_defects(mesh, c, p)),
        Packing::Sphere(c) => in_user_order(cap_tangency_defects(mesh, c, p)),
    };
    let zeros = vec![Rational::new(); mesh.n_edges()];
    let b = within_all(&mut enclose, &zeros, epsilon, START_BITS, claim.max_bits);
    let name = |k: usize| {
        let h = Edge(order[k] as u32).halfedge();
        format!("edge {k} (v{}–v{})", mesh.tail(h).0, mesh.tip(h).0)
    };
    let answer = summarize(claim, &b, &name, what);
    with_exact_violations(answer, exact)
}

/// A proved exact violation refutes the claim: it leads the witnesses, before any tangency
/// proved off by more than ε.
fn with_exact_violations(mut a: Answer, exact: Vec<Violation>) -> Answer {
    if exact.is_empty() {
        return a;
    }
    let mut witnesses: Vec<Witness> = exact
        .into_iter()
        .map(|v| Witness {
            element: v.element,
            detail: v.detail,
            value: f64::NAN,
        })
        .collect();
    if a.verdict == ClaimVerdict::Refuted {
        witnesses.append(&mut a.witnesses);
    }
    a.verdict = ClaimVerdict::Refuted;
    a.certified = true;
    a.counterexample = witnesses.first().cloned();
    a.witnesses = witnesses;
    a
}

/// Answer a `circle_pattern` claim (module docs): `phi_over_pi` is in the surface's edge
/// order.
pub fn pattern_claim(
    claim: &Claim,
    radii: &[Rational],
    phi_over_pi: &[Rational],
    angles: &[Rational],
    epsilon: &Rational,
) -> Answer {
    let mesh = &claim.surface.mesh;
    let mut phi = vec![Rational::new(); mesh.n_edges()];
    for (k, &e) in edge_order(mesh).iter().enumerate() {
        phi[e].clone_from(&phi_over_pi[k]);
    }
    let mut enclose = |p: Precision| pattern_cone_angles(mesh, radii, &phi, p);
    let b = within_all(&mut enclose, angles, epsilon, START_BITS, claim.max_bits);
    summarize(claim, &b, &|i| format!("v{i}"), "cone angle")
}
