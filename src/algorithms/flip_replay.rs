//! Our side of a `delaunay_flip` claim (`oracle::flip_claim` routes the claim here): the
//! proposed flip sequence replayed with certified arithmetic to a certified Delaunay
//! triangulation (B80, on the lengths of [`super::replay`]), and the comparison of the
//! claimed result's lengths with it under one relabeling. Shared by the claim and the
//! tie-flip search [`super::tie_search`] (B82).

use super::replay::{from_q, new_length, positive, sign, tie_length, Enclosure, Len};
use super::verdict::{tally, ClaimVerdict, Witness};
use crate::io::json::edge_order;
use crate::io::{Metric, Surface};
use crate::mesh::relabel::Relabeling;
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::QuadEdges;
use crate::predicates::directed::valid;
use crate::scalar::{nearest_f64, Real, Sign};
use rug::Rational;
use std::cmp::Ordering;

/// At most this many relabelings are compared (symmetries fixing every vertex).
pub(crate) const MAX_RELABELINGS: usize = 64;

/// Our certified Delaunay triangulation.
pub(crate) struct Ours {
    pub(crate) mesh: Mesh,
    pub(crate) lens: Vec<Len>,
    /// Interior edges with `D = 0` certified.
    pub(crate) ties: Vec<Edge>,
}

/// Why a precision did not suffice.
pub(crate) struct Open {
    pub(crate) reason: String,
    pub(crate) witnesses: Vec<Witness>,
}

pub(crate) fn edge_name(mesh: &Mesh, e: Edge) -> String {
    let h = e.halfedge();
    format!("v{}–v{}", mesh.tail(h).0, mesh.tip(h).0)
}

/// An open step at edge `e` of `mesh`.
fn open(reason: String, mesh: &Mesh, e: Edge) -> Open {
    Open {
        witnesses: vec![Witness {
            element: format!("edge {}", edge_name(mesh, e)),
            detail: reason.clone(),
            value: f64::NAN,
        }],
        reason,
    }
}

/// Replay `sequence` on `surface` with certified arithmetic at `bits` ([`super::flip_claim`],
/// "How it is decided").
pub(crate) fn replay(
    surface: &Surface,
    sequence: &[Edge],
    ptolemy: bool,
    bits: u32,
) -> Result<Ours, Open> {
    let mut mesh = surface.mesh.clone();
    let mut lens: Vec<Len> = match &surface.metric {
        Metric::Lengths(l) => l.iter().cloned().map(Len::Exact).collect(),
        Metric::SquaredLengths(s) => s.iter().cloned().map(Len::Root).collect(),
    };
    for (n, &e) in sequence.iter().enumerate() {
        let Some(q) = QuadEdges::of(&mesh, e) else {
            return Err(open(
                format!("flip {n} of the proposed sequence is not flippable"),
                &mesh,
                e,
            ));
        };
        let tie = match sign(&lens, q.edges, bits) {
            Some(Sign::Zero) => true,
            Some(Sign::Negative) => false,
            Some(Sign::Positive) => {
                return Err(open(
                    format!("flip {n} of the proposed sequence is of an edge certified strictly Delaunay (rounding in the proposing run at {bits} bits)"),
                    &mesh,
                    e,
                ))
            }
            None => {
                return Err(open(
                    format!("the Delaunay sign before flip {n} is not decided at {bits} bits"),
                    &mesh,
                    e,
                ))
            }
        };
        // A tie flip's length by Ptolemy's theorem, exact where possible (proof: B82).
        let new = if tie {
            tie_length(q.lengths(&lens), ptolemy, bits)
        } else {
            new_length(q.lengths(&lens), ptolemy, bits)
        };
        let Some(new) = new else {
            return Err(open(
                format!("the new length of flip {n} is not enclosed at {bits} bits"),
                &mesh,
                e,
            ));
        };
        if mesh.flip(e).is_err() {
            return Err(open(
                format!("flip {n} of the proposed sequence is refused by the mesh"),
                &mesh,
                e,
            ));
        }
        lens[e.idx()] = new;
    }
    finish(mesh, lens, bits)
}

/// Certify the end of a replay: every interior edge Delaunay, ties collected.
pub(crate) fn finish(mesh: Mesh, lens: Vec<Len>, bits: u32) -> Result<Ours, Open> {
    let mut ties = Vec::new();
    let mut undecided = Vec::new();
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(&mesh, e) else {
            continue;
        };
        match sign(&lens, q.edges, bits) {
            Some(Sign::Positive) => {}
            Some(Sign::Zero) => ties.push(e),
            Some(Sign::Negative) => {
                return Err(open(
                    format!(
                    "the proposed sequence ends at an edge certified not Delaunay ({bits} bits)"
                ),
                    &mesh,
                    e,
                ))
            }
            None => undecided.push(e),
        }
    }
    if !undecided.is_empty() {
        return Err(Open {
            reason: format!(
                "{} edge(s) of the flipped triangulation have a Delaunay sign not decided at {bits} bits (a cocircular tie D = 0 is certified only on exact lengths)",
                undecided.len()
            ),
            witnesses: undecided
                .iter()
                .map(|&e| Witness {
                    element: format!("edge {}", edge_name(&mesh, e)),
                    detail: "Delaunay sign not decided".to_string(),
                    value: f64::NAN,
                })
                .collect(),
        });
    }
    Ok(Ours { mesh, lens, ties })
}

/// One edge's comparison of claimed and computed length.
enum Cmp {
    Inside,
    Outside,
    Open,
}

/// |x − c| ≤ ε decided exactly.
fn within_exact(x: &Rational, c: &Rational, eps: &Rational) -> Cmp {
    let d = Rational::from(x - c).abs();
    if d <= *eps {
        Cmp::Inside
    } else {
        Cmp::Outside
    }
}

/// |√s − c| ≤ ε decided exactly for s > 0, c > 0: c − ε ≤ √s ≤ c + ε.
fn within_root(s: &Rational, c: &Rational, eps: &Rational) -> Cmp {
    let lo = Rational::from(c - eps);
    let hi = Rational::from(c + eps);
    let lo_ok = lo.cmp0() != Ordering::Greater || Rational::from(&lo * &lo) <= *s;
    let hi_ok = Rational::from(&hi * &hi) >= *s;
    if lo_ok && hi_ok {
        Cmp::Inside
    } else {
        Cmp::Outside
    }
}

/// |x − c| < ε (Inside) or > ε (Outside) proved by the enclosure `x`, else Open.
fn within_enclosure(x: &Enclosure, c: &Rational, eps: &Rational, bits: u32) -> Cmp {
    let (Some(c), Some(e)) = (from_q(c, bits), from_q(eps, bits)) else {
        return Cmp::Open;
    };
    let d = x.clone() - &c;
    if positive(&(e.clone() - &d)) && positive(&(e.clone() + &d)) {
        Cmp::Inside
    } else if positive(&(d.clone() - &e)) || (e.clone() + &d).sign() == Some(Sign::Negative) {
        Cmp::Outside
    } else {
        Cmp::Open
    }
}

fn midpoint_abs(x: &Enclosure, c: &Rational, bits: u32) -> f64 {
    let Some(c) = from_q(c, bits) else {
        return f64::NAN;
    };
    let d = x.clone() - &c;
    f64::midpoint(d.lo().approx_f64(), d.hi().approx_f64()).abs()
}

/// The verdict of one relabeling: per claimed edge, in the result's edge order.
pub(crate) struct Compared {
    pub(crate) verdict: ClaimVerdict,
    pub(crate) witnesses: Vec<Witness>,
    pub(crate) max_discrepancy: Option<f64>,
}

pub(crate) fn compare(
    result: &Surface,
    ours: &Ours,
    rel: &Relabeling,
    eps: &Rational,
    bits: u32,
) -> Compared {
    let squared = matches!(result.metric, Metric::SquaredLengths(_));
    let values = result.metric.values();
    let mut outside = Vec::new();
    let mut open = Vec::new();
    let mut max_d: Option<f64> = None;
    for (k, &er) in edge_order(&result.mesh).iter().enumerate() {
        let Some(c) = values.get(er) else {
            continue;
        };
        let e = rel.edge(Edge(er as u32));
        let Some(ours_l) = ours.lens.get(e.idx()) else {
            continue;
        };
        let (cmp, shown) = match (squared, ours_l) {
            (false, Len::Exact(x)) => (
                within_exact(x, c, eps),
                nearest_f64(&Rational::from(x - c).abs()),
            ),
            (false, Len::Root(s)) => {
                let x = from_q(s, bits).and_then(|x| valid(x.sqrt()));
                let shown = x.as_ref().map_or(f64::NAN, |x| midpoint_abs(x, c, bits));
                (within_root(s, c, eps), shown)
            }
            (true, l) if l.exact_square().is_some() => {
                let s = l.exact_square().unwrap_or_default();
                (
                    within_exact(&s, c, eps),
                    nearest_f64(&Rational::from(&s - c).abs()),
                )
            }
            (_, l) => match l.enclose(bits) {
                Some(x) => {
                    let x = if squared { x.clone() * &x } else { x };
                    (
                        within_enclosure(&x, c, eps, bits),
                        midpoint_abs(&x, c, bits),
                    )
                }
                None => (Cmp::Open, f64::NAN),
            },
        };
        if !shown.is_nan() {
            max_d = Some(max_d.map_or(shown, |m| m.max(shown)));
        }
        let what = if squared { "squared length" } else { "length" };
        let h = Edge(er as u32).halfedge();
        let element = format!(
            "result edge {k} (v{}–v{})",
            result.mesh.tail(h).0,
            result.mesh.tip(h).0
        );
        match cmp {
            Cmp::Inside => {}
            Cmp::Outside => outside.push(Witness {
                element,
                detail: format!(
                    "the claimed {what} differs from the {what} of the Delaunay edge by more than epsilon"
                ),
                value: shown,
            }),
            Cmp::Open => open.push(Witness {
                element,
                detail: format!("cannot separate |{what} difference| from epsilon at {bits} bits"),
                value: shown,
            }),
        }
    }
    let (verdict, witnesses) = tally(outside, open);
    Compared {
        verdict,
        witnesses,
        max_discrepancy: max_d,
    }
}
