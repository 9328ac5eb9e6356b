//! Answering `hyperbolic_uniformization` claims (protocol v1) by the from-scratch re-check
//! of [`crate::uniformization::hyperbolic_claim::recheck`] (B39) at the claim's `max_bits`.

use super::answer::{decided_answer, Answer, ClaimVerdict};
use super::claim::Claim;
use crate::theorems::Witness;
use crate::uniformization::hyperbolic_claim::{recheck, HyperbolicClaim, HyperbolicVerdict};

/// Answer a `hyperbolic_uniformization` claim: `holds` when B39 certifies it, `refuted`
/// only with a proof (Gauss–Bonnet, the residual enclosed away from 0 on the whole box, or
/// above `residual_bound` at `u`), `undecided` with the reason otherwise. Every `holds`
/// and `refuted` is certified.
pub fn answer(claim: &Claim, h: &HyperbolicClaim) -> Answer {
    let witness = |element: String, detail: String, value: f64| Witness {
        element,
        detail,
        value,
    };
    let (verdict, max_discrepancy, witnesses) = match recheck(&claim.surface, h, claim.max_bits) {
        Ok(HyperbolicVerdict::Holds { distance, .. }) => {
            (ClaimVerdict::Holds, Some(distance), Vec::new())
        }
        Ok(HyperbolicVerdict::Refuted {
            element,
            detail,
            value,
        }) => (
            ClaimVerdict::Refuted,
            Some(value),
            vec![witness(element, detail, value)],
        ),
        Ok(HyperbolicVerdict::Undecided { reason }) => (
            ClaimVerdict::Undecided,
            None,
            vec![witness("surface".into(), reason, f64::NAN)],
        ),
        Err(e) => (
            ClaimVerdict::Undecided,
            None,
            vec![witness("certificate".into(), e.to_string(), f64::NAN)],
        ),
    };
    decided_answer(claim, verdict, claim.max_bits, max_discrepancy, witnesses)
}
