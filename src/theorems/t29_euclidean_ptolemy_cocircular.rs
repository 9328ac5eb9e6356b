//! T29 (notes §1.6.4; docs/catalogue.md §5): the Euclidean and Ptolemy flips of an edge give the same
//! new length iff the quadrilateral is cocircular (`D = 0`); otherwise the Ptolemy length
//! is the longer one (Ptolemy's inequality).
//!
//! Certified: the sign of `D` comes from the ladder; both new lengths are enclosed with
//! outward rounding at rising precision. At `D = 0` the enclosures must intersect; at
//! `D ≠ 0` the Ptolemy enclosure must lie strictly above the Euclidean one.

use super::{Settings, Verdict, Witness};
use crate::algorithms::flips::{euclidean_length_enclosure, ptolemy_length_enclosure};
use crate::mesh::Mesh;
use crate::predicates::delaunay::Quad;
use crate::predicates::delaunay::{QuadEdges, RealQuad};
use crate::predicates::directed::{overlaps, strictly_below};
use crate::predicates::ladder::decide;
use crate::scalar::{Interval, Mpfr, Precision, Real, Sign};

/// Check T29 on every interior edge whose two triangles satisfy the triangle inequality.
pub fn check_euclidean_equals_ptolemy_iff_cocircular<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
) -> Verdict {
    let mut count = settings.progress.counter("signs of D", mesh.n_edges());
    let signs: Vec<Option<Sign>> = mesh
        .edges()
        .map(|e| {
            count.add(1);
            let q = QuadEdges::of(mesh, e)?;
            decide(&RealQuad(q.lengths(lengths)), &settings.ladder).value()
        })
        .collect();
    count.finish();
    verify_cocircularity_signs(mesh, lengths, &signs, settings)
}

/// The comparison of T29 against given signs of `D`, one per edge (`None`: undecided;
/// ignored on edges without a quadrilateral): where the sign is zero the enclosures of the
/// Euclidean and Ptolemy lengths must intersect, elsewhere the Ptolemy one must lie strictly
/// above. The theorem is the case of the certified signs of the same lengths.
pub fn verify_cocircularity_signs<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    signs: &[Option<Sign>],
    settings: &Settings,
) -> Verdict {
    if signs.len() != mesh.n_edges() || lengths.len() != mesh.n_edges() {
        return Verdict::NotApplicable {
            reason: "one length and one sign per edge are required".into(),
        };
    }
    let mut witnesses = Vec::new();
    let mut undecided = Vec::new();
    let fast = f64_enclosures(lengths);
    let mut count = settings
        .progress
        .counter("new lengths compared", mesh.n_edges());
    for e in mesh.edges() {
        count.add(1);
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        if let Some(sign) = signs[e.idx()] {
            match compare_f64(&fast, q, sign) {
                Some(true) => continue,
                Some(false) => {
                    witnesses.push(disagreement(e, sign));
                    continue;
                }
                None => {}
            }
        }
        let quad = q.lengths(lengths);
        let Some(sign) = signs[e.idx()] else {
            undecided.push(Witness {
                element: e.to_string(),
                detail: "sign of D undecided".into(),
                value: 0.0,
            });
            continue;
        };
        let Some(rat) = quad
            .to_array()
            .map(Real::to_rational)
            .into_iter()
            .collect::<Option<Vec<_>>>()
        else {
            return Verdict::NotApplicable {
                reason: format!("a length at {e} is not finite"),
            };
        };
        let mut outcome = None;
        let mut bits = settings.ladder.start_bits.max(64);
        while bits <= settings.ladder.max_bits.max(64) {
            let Ok(prec) = Precision::new(u64::from(bits)) else {
                break;
            };
            let enc: Vec<Interval<Mpfr>> = rat
                .iter()
                .map(|x| Interval::from_rational(x, prec))
                .collect();
            let eq = crate::predicates::delaunay::Quad {
                ij: &enc[0],
                jk: &enc[1],
                ki: &enc[2],
                il: &enc[3],
                lj: &enc[4],
            };
            let (Some(eu), Some(pt)) =
                (euclidean_length_enclosure(eq), ptolemy_length_enclosure(eq))
            else {
                outcome = Some(None);
                break;
            };
            match sign {
                Sign::Zero => {
                    outcome = Some(Some(overlaps(&eu, &pt)));
                    break;
                }
                _ if strictly_below(&eu, &pt) => {
                    outcome = Some(Some(true));
                    break;
                }
                _ if strictly_below(&pt, &eu) => {
                    outcome = Some(Some(false));
                    break;
                }
                _ => bits *= 2,
            }
        }
        match outcome {
            // `Some(None)`: a triangle may violate the triangle inequality (no Euclidean flip).
            Some(None | Some(true)) => {}
            Some(Some(false)) => witnesses.push(disagreement(e, sign)),
            None => undecided.push(Witness {
                element: e.to_string(),
                detail: "enclosures of the two new lengths overlap at every precision".into(),
                value: 0.0,
            }),
        }
    }
    count.finish();
    Verdict::certified(witnesses, undecided, settings.ladder.max_bits)
}

/// Outward `f64` enclosures of the lengths (B21): the point itself for `f64` values, the
/// directed roundings of the exact value otherwise; `None` for a non-finite length.
pub(crate) fn f64_enclosures<T: Real>(lengths: &[T]) -> Vec<Option<Interval<f64>>> {
    let exact_f64 = T::is_point()
        && lengths
            .first()
            .is_some_and(|x| T::precision_bits(x.ctx()) == 53);
    lengths
        .iter()
        .map(|x| {
            if exact_f64 {
                let v = x.approx_f64();
                v.is_finite().then(|| Interval::point(v))
            } else {
                x.to_rational()
                    .map(|q| Interval::<f64>::from_rational(&q, ()))
            }
        })
        .collect()
}

/// The first rung of T29's comparison, on `f64` enclosures (B21): `Some(true)` when the
/// enclosures of the Euclidean and Ptolemy lengths agree with a nonzero sign of `D`
/// (Ptolemy strictly above), `Some(false)` when they certifiably contradict the sign
/// (disjoint at `D = 0`, Ptolemy strictly below otherwise), `None` when this rung cannot
/// tell (the MPFR rungs follow; at `D = 0` they judge the intersection at their width).
fn compare_f64(fast: &[Option<Interval<f64>>], q: QuadEdges, sign: Sign) -> Option<bool> {
    let [a, b, c, d, e] = q.edges.to_array().map(|e| fast[e.idx()].as_ref());
    let quad = Quad {
        ij: a?,
        jk: b?,
        ki: c?,
        il: d?,
        lj: e?,
    };
    let eu = euclidean_length_enclosure(quad)?;
    let pt = ptolemy_length_enclosure(quad)?;
    match sign {
        // Intersecting f64 enclosures are weaker evidence than the MPFR rung's: only a
        // refutation is final here.
        Sign::Zero => (!overlaps(&eu, &pt)).then_some(false),
        _ if strictly_below(&eu, &pt) => Some(true),
        _ if strictly_below(&pt, &eu) => Some(false),
        _ => None,
    }
}

/// The witness of an edge whose new lengths contradict the sign of `D`.
fn disagreement(e: crate::mesh::Edge, sign: Sign) -> Witness {
    Witness {
        element: e.to_string(),
        detail: format!("D is {sign}, but the Euclidean and Ptolemy lengths disagree with that"),
        value: 1.0,
    }
}
