//! Negative controls of the flip checks: T21 (Delaunay flipping), T22 (uniqueness), T23
//! (Euclidean flips keep the cone metric), T27 (shear = log cross ratio), T28 (Ptolemy flip
//! identities), T29 (Euclid = Ptolemy ⇔ cocircular).

// The `at_precision!` bodies are generic code that is also instantiated at `f64`.
#![allow(clippy::clone_on_copy, clippy::op_ref, clippy::let_unit_value)]

use super::{bump, first_interior_edge, first_quad_side, not_applicable, TRIVIAL_CROSS_RATIOS};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::algorithms::flips::{flip_metric, flip_ptolemy_exact};
use crate::geometry::corners::halfedge_angles;
use crate::io::{Metric, Surface};
use crate::mesh::{Edge, Mesh};
use crate::oracle::precision::Prec;
use crate::oracle::registry::Check;
use crate::predicates::delaunay::QuadEdges;
use crate::scalar::{Real, Sign};
use crate::theorems::t18_two_triangle_sphere::is_two_triangle_sphere;
use crate::theorems::t22_delaunay_uniqueness::same_triangulation;
use crate::theorems::{
    t21_delaunay_flipping, t23_euclidean_flip_cone_metric, t27_shear_log_cross_ratio,
    t28_ptolemy_flip, t29_euclidean_ptolemy_cocircular, Settings, Verdict, Witness,
};

/// Margin, in radians, of the choice made by [`flip_one_delaunay_edge`]: 1/100, far above
/// the error of a corner angle at every precision (B40: a few units of roundoff).
const ANGLE_MARGIN: f64 = 0.01;

/// Flip, in place with a Euclidean flip, the first interior edge `ij` that is Delaunay and
/// convex with a margin: opposite angles `α_k + α_l ≤ π − 1/100` and angles at its ends
/// `α_i, α_j ≤ π − 1/100` (read from the corner angles at the working precision; the choice
/// is a heuristic, the control's verdict comes from the check). The angles at the ends of
/// the new diagonal `kl` are `α_i, α_j` and its opposite angles sum to
/// `2π − α_k − α_l ≥ π + 1/100`: the flip makes that one edge strictly non-Delaunay, far from
/// a tie (docs/catalogue.md §5). Returns the edge.
fn flip_one_delaunay_edge<T: Real>(mesh: &mut Mesh, l: &mut [T]) -> Option<Edge> {
    let a: Vec<f64> = halfedge_angles(mesh, l)
        .iter()
        .map(Real::approx_f64)
        .collect();
    let pi = std::f64::consts::PI;
    let chosen = mesh.edges().find(|&e| {
        if QuadEdges::of(mesh, e).is_none() {
            return false;
        }
        let (h, t) = (e.side(0), e.side(1));
        let opposite = a[h.idx()] + a[t.idx()];
        let at_i = a[mesh.next(h).idx()] + a[mesh.prev(t).idx()];
        let at_j = a[mesh.prev(h).idx()] + a[mesh.next(t).idx()];
        [opposite, at_i, at_j]
            .iter()
            .all(|&x| x.is_finite() && x <= pi - ANGLE_MARGIN)
    })?;
    flip_metric(mesh, l, chosen, FlipKind::Euclidean).ok()?;
    Some(chosen)
}

fn flip_options(s: &Settings, seed: Option<u64>) -> FlipOptions {
    FlipOptions {
        ladder: s.ladder,
        order_seed: seed,
        ..FlipOptions::default()
    }
}

/// A triangulation with an edge non-Delaunay by a margin: the case itself when some
/// interior edge has opposite angles `α_k + α_l ≥ π + 1/100` (read like the choice of
/// [`flip_one_delaunay_edge`]), otherwise the case with one edge flipped by
/// [`flip_one_delaunay_edge`]; `Err` with the reason when neither exists. (Rounded lengths
/// of a surface with cocircular quadrilaterals can make a tie certified non-Delaunay by a
/// hair; the margin keeps such ties out.)
fn non_delaunay_start<T: Real>(case: &Surface, l: &[T]) -> Result<(Mesh, Vec<T>), Verdict> {
    let (mut m, mut l2) = (case.mesh.clone(), l.to_vec());
    let a: Vec<f64> = halfedge_angles(&m, &l2)
        .iter()
        .map(Real::approx_f64)
        .collect();
    let bad = m.edges().any(|e| {
        QuadEdges::of(&m, e).is_some()
            && a[e.side(0).idx()] + a[e.side(1).idx()] >= std::f64::consts::PI + ANGLE_MARGIN
    });
    if bad || flip_one_delaunay_edge(&mut m, &mut l2).is_some() {
        Ok((m, l2))
    } else {
        Err(not_applicable(
            "no edge is non-Delaunay, or Delaunay with a convex quadrilateral, by a margin of \
             1/100 rad: no clearly non-Delaunay start",
        ))
    }
}

/// T21-NC: T21's certification "every edge Delaunay" (`check_all_edges_delaunay`) on a
/// triangulation that is not Delaunay ([`non_delaunay_start`]: the input when it is not
/// Delaunay — the tests' control — otherwise the input with one Delaunay edge flipped). The
/// non-Delaunay edge is a certified sign (decided exactly if need be, no tolerance).
fn t21_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| {
        Some(match non_delaunay_start(case, &l) {
            Ok((m, l2)) => t21_delaunay_flipping::check_all_edges_delaunay(&m, &l2, s, false, 0),
            Err(v) => v,
        })
    })
}

/// T22-NC: T22's comparison of triangulations ([`same_triangulation`], a vertex-fixing
/// isomorphism) between the Delaunay result of the registry's first visit order (seed 1) and
/// that result with one more flip — of the first edge whose flip joins another vertex pair,
/// the tests' control. Such a flip changes the multiset of edge endpoints, which every
/// vertex-fixing isomorphism keeps (an exact, combinatorial comparison).
fn t22_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| {
        let (mut d, mut l2) = (case.mesh.clone(), l.clone());
        if let Err(err) = flip_to_delaunay(
            &mut d,
            &mut l2,
            FlipKind::Euclidean,
            &flip_options(s, Some(1)),
        ) {
            return Some(not_applicable(&err.to_string()));
        }
        let pair = |m: &Mesh, e: Edge| {
            let h = e.halfedge();
            let (a, b) = (m.tail(h).0, m.tip(h).0);
            (a.min(b), a.max(b))
        };
        let more = d.edges().find_map(|e| {
            let mut x = d.clone();
            (x.flip(e).is_ok() && pair(&x, e) != pair(&d, e)).then_some((e, x))
        });
        let Some((e, x)) = more else {
            return Some(not_applicable(
                "no flip of the Delaunay result joins another vertex pair",
            ));
        };
        let witnesses = if same_triangulation(&d, &x) {
            Vec::new()
        } else {
            vec![Witness {
                element: e.to_string(),
                detail: format!(
                    "seed 1: the result with {e} flipped once more is another triangulation"
                ),
                value: 1.0,
            }]
        };
        Some(Verdict::certified(witnesses, Vec::new(), 0))
    })
}

/// T23-NC: T23's cone-angle comparison with the recorded flips replayed by the *Ptolemy*
/// update instead of the Euclidean one (the tests' control), started from a non-Delaunay
/// triangulation ([`non_delaunay_start`]) so that at least one flip of a non-cocircular
/// quadrilateral is replayed. The Ptolemy length is strictly longer there
/// (T29), which moves the cone angles at the quadrilateral's corners by far more than the
/// width of the enclosures (at least 128 bits): the disjointness is certified.
fn t23_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if case.mesh.n_vertices() == 1 {
        return Some(not_applicable(
            "one vertex: its cone angle is π per face whatever the lengths, no update moves it",
        ));
    }
    let bits = (2 * prec.bits()).max(128);
    at_precision!(prec, case, |l: T| {
        let (m, l2) = match non_delaunay_start(case, &l) {
            Ok(x) => x,
            Err(v) => return Some(v),
        };
        Some(
            t23_euclidean_flip_cone_metric::check_euclidean_flips_preserve_cone_metric(
                &m,
                &l2,
                FlipKind::Ptolemy,
                bits,
                s,
            ),
        )
    })
}

/// T27-NC (MPFR): T27's comparison with the shear taken from the metric and the cross ratio
/// from the metric with the side `jk` of the first interior edge's quadrilateral
/// ([`first_quad_side`]) scaled by 101/100: `log c` of that edge moves by `ln 1.01 ≈ 0.00995`,
/// far above the B64 tolerance `8u(Σ|ln ℓ| + |ln c| + 1)`.
fn t27_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let Prec::Mpfr(p) = prec else {
        return None;
    };
    if is_two_triangle_sphere(&case.mesh) {
        return Some(not_applicable(TRIVIAL_CROSS_RATIOS));
    }
    let Some(e) = first_quad_side(case) else {
        return Some(not_applicable("T27's control needs an interior edge"));
    };
    let l = case.lengths::<crate::scalar::Mpfr>(p);
    let mut lr = l.clone();
    let x = lr.get_mut(e.idx())?;
    *x = x.clone() * &crate::scalar::Mpfr::from_rational(&bump(), p);
    Some(t27_shear_log_cross_ratio::verify_shear_log_cross_ratio(
        &case.mesh, &l, &lr, s,
    ))
}

/// T28-NC (exact): T28's cluster rule for the Ptolemy flip of the first interior edge, with
/// the side `jk` of its quadrilateral scaled by 101/100 after the flip — the tests' control
/// ("perturb one side after the flip"): the new diagonal's cross ratio, whose quadrilateral
/// has that side, moves by a factor 101/100 (exact comparison in ℚ).
fn t28_nc(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    let Metric::Lengths(l) = &case.metric else {
        return Some(not_applicable(
            "T28 is exact and needs rational lengths (Ptolemy flips of square roots leave ℚ)",
        ));
    };
    if is_two_triangle_sphere(&case.mesh) {
        return Some(not_applicable(TRIVIAL_CROSS_RATIOS));
    }
    let Some(e) = first_interior_edge(case) else {
        return Some(not_applicable("T28's control needs an interior edge"));
    };
    let side = QuadEdges::of(&case.mesh, e)?.edges.jk;
    let (mut m1, mut l1) = (case.mesh.clone(), l.clone());
    flip_ptolemy_exact(&mut m1, &mut l1, e).ok()?;
    *l1.get_mut(side.idx())? *= bump();
    let w = t28_ptolemy_flip::cluster_rule_violations(&case.mesh, l, &m1, &l1, e);
    Some(Verdict::certified(w, Vec::new(), 0))
}

/// T29-NC: T29's comparison of the Euclidean and Ptolemy new lengths against the claim
/// `D = 0` (cocircular) at every interior edge instead of the certified signs: at every
/// edge whose quadrilateral is not cocircular the enclosures of the two lengths are
/// disjoint (Ptolemy's inequality is strict) and the claim is refused — a comparison of
/// rigorous enclosures, no tolerance.
fn t29_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let signs: Vec<Option<Sign>> = case
        .mesh
        .edges()
        .map(|e| QuadEdges::of(&case.mesh, e).map(|_| Sign::Zero))
        .collect();
    at_precision!(prec, case, |l: T| Some(
        t29_euclidean_ptolemy_cocircular::verify_cocircularity_signs(&case.mesh, &l, &signs, s)
    ))
}

/// The controls of this module.
pub fn controls() -> Vec<Check> {
    vec![
        Check {
            id: "T21-NC",
            title: "control: non-Delaunay input or one edge flipped",
            run: t21_nc,
        },
        Check {
            id: "T22-NC",
            title: "control: Delaunay result vs one more flip",
            run: t22_nc,
        },
        Check {
            id: "T23-NC",
            title: "control: flips replayed with Ptolemy lengths",
            run: t23_nc,
        },
        Check {
            id: "T27-NC",
            title: "control: cross ratio from one side × 1.01",
            run: t27_nc,
        },
        Check {
            id: "T28-NC",
            title: "control: one side × 1.01 after the flip",
            run: t28_nc,
        },
        Check {
            id: "T29-NC",
            title: "control: every quadrilateral claimed cocircular",
            run: t29_nc,
        },
    ]
}
