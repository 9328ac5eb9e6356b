//! The answer to a claim (protocol v1, docs/oracle.md, "Answers"): the verdict, the
//! answer record and its JSON, and the helpers that turn per-element decisions into an
//! answer. Shared by [`super::certify`] and the modules it dispatches claim kinds to.

use super::claim::Claim;
use crate::io::Surface;
use crate::predicates::within::{Batch, Within};
use crate::scalar::{Certified, Interval, Mpfr, Precision};
use crate::theorems::Witness;
use serde_json::{json, Value};

/// First MPFR precision of the ladder used for claims.
pub(crate) const START_BITS: u32 = 128;

pub(crate) use crate::algorithms::verdict::tally;
pub use crate::algorithms::verdict::ClaimVerdict;

/// The answer to a claim.
#[derive(Clone, Debug, PartialEq)]
pub struct Answer {
    /// The claim's `id`, echoed.
    pub id: Option<String>,
    /// The claim kind.
    pub kind: &'static str,
    /// The verdict.
    pub verdict: ClaimVerdict,
    /// Whether the verdict is rigorous (exact arithmetic or enclosures).
    pub certified: bool,
    /// Highest precision used, in bits (0 for purely exact answers).
    pub precision_bits: u32,
    /// Largest discrepancy between claimed and computed values (display only).
    pub max_discrepancy: Option<f64>,
    /// For a refutation: the first counterexample element.
    pub counterexample: Option<Witness>,
    /// Every element found wrong (refutation) or left open (undecided).
    pub witnesses: Vec<Witness>,
}

impl Answer {
    /// As JSON (docs/oracle.md, "Answers").
    pub fn to_json(&self) -> Value {
        json!({
            "penner_answer": super::claim::PROTOCOL_VERSION,
            "id": self.id,
            "kind": self.kind,
            "verdict": self.verdict.word(),
            "certified": self.certified,
            "precision_bits": self.precision_bits,
            "max_discrepancy": self.max_discrepancy,
            "counterexample": self.counterexample,
            "witnesses": self.witnesses,
        })
    }
}

/// Turn a batch of per-element decisions into an answer.
pub(crate) fn summarize(
    claim: &Claim,
    b: &Batch,
    name: &dyn Fn(usize) -> String,
    what: &str,
) -> Answer {
    let mut refuted = Vec::new();
    let mut open = Vec::new();
    for (i, a) in b.answers.iter().enumerate() {
        let w = || Witness {
            element: name(i),
            detail: String::new(),
            value: b.discrepancy[i],
        };
        match a {
            Certified::Known {
                value: Within::Outside,
                ..
            } => refuted.push(Witness {
                detail: format!("the {what} differs from the claimed value by more than epsilon"),
                ..w()
            }),
            Certified::Known {
                value: Within::Inside,
                ..
            } => {}
            Certified::Undecided { bits_tried } => open.push(Witness {
                detail: format!("cannot separate |difference| from epsilon at {bits_tried} bits"),
                ..w()
            }),
        }
    }
    let max_discrepancy = b
        .discrepancy
        .iter()
        .copied()
        .filter(|x| !x.is_nan())
        .reduce(f64::max);
    let (verdict, witnesses) = tally(refuted, open);
    decided_answer(claim, verdict, b.bits, max_discrepancy, witnesses)
}

/// The answer to `claim` with `verdict` at `bits`: certified unless undecided, and the
/// first witness as the counterexample of a refutation.
pub(crate) fn decided_answer(
    claim: &Claim,
    verdict: ClaimVerdict,
    bits: u32,
    max_discrepancy: Option<f64>,
    witnesses: Vec<Witness>,
) -> Answer {
    Answer {
        id: claim.id.clone(),
        kind: claim.assertion.kind(),
        verdict,
        certified: verdict != ClaimVerdict::Undecided,
        precision_bits: bits,
        max_discrepancy,
        counterexample: if verdict == ClaimVerdict::Refuted {
            witnesses.first().cloned()
        } else {
            None
        },
        witnesses,
    }
}

pub(crate) fn interval_lengths(case: &Surface, p: Precision) -> Vec<Interval<Mpfr>> {
    case.lengths::<Interval<Mpfr>>(p)
}
