//! Answering `delaunay_flip` claims: "flipping this surface to intrinsic Delaunay with
//! Euclidean (or Ptolemy) flips gives this triangulation with these lengths".
//!
//! **Meaning.** The claim holds when `result` is, up to renumbering of edges and faces
//! (vertices keep their ids under flips; [`super::relabel`]), an intrinsic Delaunay
//! triangulation reached from `surface` by flips of the given kind, and each claimed
//! length is within `epsilon` of the length of the corresponding edge.
//!
//! **How it is decided.** `flip_to_delaunay` proposes a flip sequence (exact Ptolemy
//! flipping over ℚ when the surface has rational lengths and Ptolemy flips are claimed,
//! otherwise MPFR at the working precision). The sequence is then *replayed* here with
//! certified arithmetic, independent of the rounding of the proposing run: every flipped
//! edge must be certified not strictly Delaunay at the time of its flip (so the flip is a
//! legal step: the quadrilateral is convex), the new lengths are exact rationals (Ptolemy
//! on rational lengths, T28) or outward-rounded MPFR enclosures (Euclidean, B62), and at the
//! end every interior edge must be certified Delaunay (`D ≥ 0`, docs/catalogue.md §5 Eq. 13). By T21
//! and T22 that triangulation is the intrinsic Delaunay triangulation, unique unless some
//! edge has `D = 0` exactly (a cocircular *tie*). For Ptolemy flips the lengths are
//! Penner coordinates and the same Delaunay condition selects the Epstein–Penner
//! decomposition, with the same uniqueness up to ties. The working precision doubles from
//! 128 bits to the claim's `max_bits` until every step is decided.
//!
//! **Ties.** A tie is certified only where all five lengths of a quadrilateral are exact
//! (rational lengths or rational squared lengths); on enclosed lengths `D = 0` cannot be
//! separated from a small `D ≠ 0` and the answer is `undecided`. A flip whose sign is
//! certified `Zero` takes its new length by Ptolemy's theorem (exact where possible). When
//! our triangulation has certified ties, the other Delaunay triangulations are reached by
//! tie flips: [`super::tie_search`] searches them (proof: B82) and answers `holds` on a
//! match, `refuted` only after a complete search, `undecided` past its bounds.
//!
//! **Lengths.** Compared per edge under every relabeling found: exactly where our length
//! is exact (rational, or a rational square compared by squaring), otherwise by enclosures
//! that must prove `|ours − claimed| < ε` (holds) or `> ε` (refutes). A `result` given by
//! `squared_lengths` is compared on squared lengths, with `epsilon` bounding the squared
//! difference.

use super::answer::{decided_answer, Answer, ClaimVerdict};
use super::claim::Claim;
use super::relabel::{first_extra_edge, isomorphisms};
use crate::algorithms::flip_replay::{compare, edge_name, replay, Compared, Ours, MAX_RELABELINGS};
use crate::algorithms::flip_to_delaunay::{
    flip_to_delaunay, flip_to_delaunay_exact, FlipKind, FlipOptions,
};
use crate::algorithms::replay::EXACT_GUARD_BITS;
use crate::algorithms::tie_search::{search, Search};
use crate::io::json::edge_order;
use crate::io::{Metric, Surface};
use crate::mesh::Edge;
use crate::scalar::{Mpfr, Precision};
use crate::theorems::Witness;
use rug::Rational;

/// The flip sequence proposed by `flip_to_delaunay` at `bits` (exact over ℚ for Ptolemy
/// flips of rational lengths, where `bits` is unused).
fn propose(surface: &Surface, ptolemy: bool, bits: u32) -> Vec<Edge> {
    let opts = FlipOptions {
        record: true,
        ..FlipOptions::default()
    };
    let mut mesh = surface.mesh.clone();
    if let (true, Metric::Lengths(l)) = (ptolemy, &surface.metric) {
        return flip_to_delaunay_exact(&mut mesh, l.clone(), EXACT_GUARD_BITS, &opts)
            .map(|(r, _)| r.sequence)
            .unwrap_or_default();
    }
    let Ok(p) = Precision::new(u64::from(bits)) else {
        return Vec::new();
    };
    let mut l: Vec<Mpfr> = surface.lengths(p);
    let kind = if ptolemy {
        FlipKind::Ptolemy
    } else {
        FlipKind::Euclidean
    };
    flip_to_delaunay(&mut mesh, &mut l, kind, &opts)
        .map(|r| r.sequence)
        .unwrap_or_default()
}

fn tie_witnesses(ours: &Ours, reason: &str) -> Vec<Witness> {
    ours.ties
        .iter()
        .map(|&e| Witness {
            element: format!("edge {}", edge_name(&ours.mesh, e)),
            detail: format!(
                "cocircular tie (D = 0) in the computed Delaunay triangulation; {reason}"
            ),
            value: 0.0,
        })
        .collect()
}

/// Why `result` is not our triangulation, as a refutation witness.
fn combinatorial_witness(result: &Surface, ours: &Ours) -> Witness {
    let (nv, nf) = (result.mesh.n_vertices(), result.mesh.n_faces());
    let (ov, of) = (ours.mesh.n_vertices(), ours.mesh.n_faces());
    if nv != ov || nf != of || result.mesh.n_edges() != ours.mesh.n_edges() {
        return Witness {
            element: "result".to_string(),
            detail: format!(
                "the result has {nv} vertices, {} edges and {nf} faces; the intrinsic Delaunay triangulation has {ov}, {} and {of}",
                result.mesh.n_edges(),
                ours.mesh.n_edges()
            ),
            value: f64::NAN,
        };
    }
    let order = edge_order(&result.mesh);
    match first_extra_edge(&result.mesh, &order, &ours.mesh) {
        Some((k, e, na, nb)) => Witness {
            element: format!("result edge {k} ({})", edge_name(&result.mesh, e)),
            detail: format!(
                "not an edge of the intrinsic Delaunay triangulation: the result has {na} edge(s) between these vertices, the Delaunay triangulation {nb}"
            ),
            value: f64::NAN,
        },
        None => Witness {
            element: "result".to_string(),
            detail: "the faces are glued differently from the intrinsic Delaunay triangulation (same vertex pairs, different gluing)".to_string(),
            value: f64::NAN,
        },
    }
}

/// The answer when our triangulation has ties, from the tie-flip search (proof: B82);
/// `Err` with the open comparison when more precision may decide it.
fn at_ties(
    claim: &Claim,
    result: &Surface,
    ours: &Ours,
    ptolemy: bool,
    eps: &Rational,
    bits: u32,
) -> Result<Answer, (ClaimVerdict, Option<f64>, Vec<Witness>)> {
    let (verdict, d, witnesses) = match search(result, ours, ptolemy, eps, bits) {
        Search::Holds { max_discrepancy } => (ClaimVerdict::Holds, max_discrepancy, Vec::new()),
        Search::Refuted {
            max_discrepancy,
            witnesses,
        } => (ClaimVerdict::Refuted, max_discrepancy, witnesses),
        Search::Undecided {
            max_discrepancy,
            mut witnesses,
            retry,
        } => {
            witnesses.extend(tie_witnesses(
                ours,
                "the claim may be a Delaunay triangulation that the tie-flip search did not settle",
            ));
            if retry {
                return Err((ClaimVerdict::Undecided, max_discrepancy, witnesses));
            }
            (ClaimVerdict::Undecided, max_discrepancy, witnesses)
        }
    };
    Ok(decided_answer(claim, verdict, bits, d, witnesses))
}

/// Answer a `delaunay_flip` claim (module documentation).
pub fn delaunay_flip(claim: &Claim, ptolemy: bool, result: &Surface, eps: &Rational) -> Answer {
    let mut bits = super::answer::START_BITS;
    let mut last: Option<(ClaimVerdict, Option<f64>, Vec<Witness>)> = None;
    let mut used = bits;
    while bits <= claim.max_bits {
        used = bits;
        let sequence = propose(&claim.surface, ptolemy, bits);
        let ours = match replay(&claim.surface, &sequence, ptolemy, bits) {
            Ok(o) => o,
            Err(o) => {
                let mut w = o.witnesses;
                if let Some(first) = w.first_mut() {
                    first.detail = o.reason;
                }
                last = Some((ClaimVerdict::Undecided, None, w));
                bits = bits.saturating_mul(2);
                continue;
            }
        };
        let (r, o) = (&result.mesh, &ours.mesh);
        if (r.n_vertices(), r.n_edges(), r.n_faces()) != (o.n_vertices(), o.n_edges(), o.n_faces())
        {
            // Flips keep the counts: no Delaunay triangulation has the result's (T02).
            let w = combinatorial_witness(result, &ours);
            return decided_answer(claim, ClaimVerdict::Refuted, bits, None, vec![w]);
        }
        if !ours.ties.is_empty() {
            match at_ties(claim, result, &ours, ptolemy, eps, bits) {
                Ok(a) => return a,
                Err(open) => {
                    last = Some(open);
                    bits = bits.saturating_mul(2);
                    continue;
                }
            }
        }
        let rels = isomorphisms(&result.mesh, &ours.mesh, MAX_RELABELINGS);
        if rels.is_empty() {
            let w = combinatorial_witness(result, &ours);
            return decided_answer(claim, ClaimVerdict::Refuted, bits, None, vec![w]);
        }
        let compared: Vec<Compared> = rels
            .iter()
            .map(|r| compare(result, &ours, r, eps, bits))
            .collect();
        if let Some(c) = compared.iter().find(|c| c.verdict == ClaimVerdict::Holds) {
            return decided_answer(
                claim,
                ClaimVerdict::Holds,
                bits,
                c.max_discrepancy,
                Vec::new(),
            );
        }
        let any_open = compared
            .iter()
            .any(|c| c.verdict == ClaimVerdict::Undecided);
        if !any_open {
            let first = compared.into_iter().next();
            let (d, w) = first.map_or((None, Vec::new()), |c| (c.max_discrepancy, c.witnesses));
            return decided_answer(claim, ClaimVerdict::Refuted, bits, d, w);
        }
        let open = compared
            .into_iter()
            .find(|c| c.verdict == ClaimVerdict::Undecided);
        last = open.map(|c| (ClaimVerdict::Undecided, c.max_discrepancy, c.witnesses));
        bits = bits.saturating_mul(2);
    }
    let (verdict, d, w) = last.unwrap_or((ClaimVerdict::Undecided, None, Vec::new()));
    decided_answer(claim, verdict, used, d, w)
}
