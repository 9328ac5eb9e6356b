//! Negative controls: each runs the comparison of one catalogue check on data made wrong
//! by a fixed, stated perturbation — the kind the property tests use — so the check is
//! *expected to fail*. `penner check SURFACE --negative-controls` runs them, writes a failure
//! file (shrunk surface and witnesses) for each control that fails, and `penner replay`
//! re-runs such a file by the control's ID.
//!
//! A control that holds is reported as such, never hidden: it means the check did not see
//! its perturbation on this surface, which deserves a look (`penner check` then exits 1).
//!
//! Control IDs are the check's ID followed by `-NC` (`T16-NC`); they are not in the
//! catalogue, so reports never list them as theorems.

// The `at_precision!` bodies are generic code that is also instantiated at `f64`.
#![allow(clippy::clone_on_copy, clippy::op_ref, clippy::let_unit_value)]

use super::case::MetricOps;
use super::checks::scale_factors;
use super::checks_extra::{coplanar, t04};
use super::precision::Prec;
use super::registry::Check;
use crate::geometry::curvature::curvature;
use crate::geometry::laplacian::cotan_laplacian;
use crate::io::{Metric, Surface};
use crate::mesh::Edge;
use crate::predicates::delaunay::QuadEdges;
use crate::scalar::Real;
use crate::theorems::{
    t01_gauss_bonnet, t05_cotan_laplacian, t16_scaling_cross_ratios, t20_mobius_cross_ratios,
    t35_definition_two, Settings, Verdict,
};
use rug::Rational;

/// The relative perturbation of a length (or squared length) used by the metric controls:
/// 1/100, far above every tolerance of the catalogue at every precision.
fn bump() -> Rational {
    Rational::from((101, 100))
}

/// The first interior edge (both sides in distinct faces), where a length change is seen
/// by the quantities around it.
fn first_interior_edge(case: &Surface) -> Option<Edge> {
    case.mesh
        .edges()
        .find(|&e| QuadEdges::of(&case.mesh, e).is_some())
}

/// T01-NC: Gauss–Bonnet compared with the curvature of vertex 0 raised by 1/1000.
fn t01_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| {
        let mut k = curvature(&case.mesh, &l);
        let first = k.first_mut()?;
        let d = first.lit(1e-3);
        *first += &d;
        Some(t01_gauss_bonnet::verify_gauss_bonnet(&case.mesh, &l, &k, s))
    })
}

/// T04-NC: T04 on the planar layout with the squared length of its first interior edge
/// scaled by 101/100 (no longer flat at the edge's ends).
fn t04_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if !case.positions.as_deref().is_some_and(coplanar) {
        return Some(Verdict::NotApplicable {
            reason: "T04's control needs a planar layout".to_string(),
        });
    }
    let e = first_interior_edge(case)?;
    let mut bent = case.clone();
    let (Metric::Lengths(v) | Metric::SquaredLengths(v)) = &mut bent.metric;
    *v.get_mut(e.idx())? *= bump();
    bent.validate().ok()?;
    t04(&bent, prec, s)
}

/// T05-NC: the cotan Laplacian with one off-diagonal entry of row 0 raised by 1/1000
/// (symmetry and zero row sums broken).
fn t05_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| {
        let mut lap = cotan_laplacian(&case.mesh, &l);
        let j = lap.row(0).map(|(j, _)| j).find(|&j| j != 0)?;
        let x = lap.get_mut(0, j)?;
        let d = x.lit(1e-3);
        *x += &d;
        Some(t05_cotan_laplacian::verify_laplacian(&case.mesh, &lap, s))
    })
}

/// T16-NC (exact): the cross ratios of the metric against those of its conformal scaling
/// by [`scale_factors`] with the first interior edge's value then scaled by 101/100.
fn t16_nc(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    let e = first_interior_edge(case)?;
    let mut scaled = case
        .metric
        .scaled(&case.mesh, &scale_factors(case.mesh.n_vertices()));
    let (Metric::Lengths(v) | Metric::SquaredLengths(v)) = &mut scaled;
    *v.get_mut(e.idx())? *= bump();
    Some(match (&case.metric, &scaled) {
        (Metric::Lengths(a), Metric::Lengths(b))
        | (Metric::SquaredLengths(a), Metric::SquaredLengths(b)) => {
            t16_scaling_cross_ratios::verify_equal_cross_ratios_exact(&case.mesh, a, b)
        }
        _ => return None,
    })
}

/// T20-NC (exact): the cross ratios before and after the inversion of T20, with the image
/// of vertex 0 then moved by (1/10, 0, 0).
fn t20_nc(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    let Some(points) = &case.positions else {
        return Some(Verdict::NotApplicable {
            reason: "T20's control needs vertex positions".to_string(),
        });
    };
    let (c, r2) = super::checks_extra::t20_sphere(points);
    let mut after = t20_mobius_cross_ratios::invert_in_sphere_exact(points, &c, &r2)?;
    after.first_mut()?[0] += Rational::from((1, 10));
    Some(
        t20_mobius_cross_ratios::verify_map_preserves_cross_ratios_exact(
            &case.mesh, points, &after,
        ),
    )
}

/// T35-NC (exact): Definition 2 against the second metric of T35's entry (scaled, then
/// Ptolemy-flipped across the first interior edge) with that edge's length scaled by
/// 101/100.
fn t35_nc(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    let Metric::Lengths(l) = &case.metric else {
        return Some(Verdict::NotApplicable {
            reason: "T35's control needs rational lengths".to_string(),
        });
    };
    let e = first_interior_edge(case)?;
    let sf = scale_factors(case.mesh.n_vertices());
    let (_, mut lb) =
        t35_definition_two::scaled_then_flipped_exact(&case.mesh, l, &sf, &[e]).ok()?;
    *lb.get_mut(e.idx())? *= bump();
    Some(t35_definition_two::check_definition_two_exact(
        &case.mesh,
        l,
        &[e],
        &lb,
    ))
}

/// Every negative control, in catalogue order of the checks they exercise.
pub fn controls() -> Vec<Check> {
    vec![
        Check {
            id: "T01-NC",
            title: "control: curvature of v0 + 1e-3",
            run: t01_nc,
        },
        Check {
            id: "T04-NC",
            title: "control: one squared length × 1.01",
            run: t04_nc,
        },
        Check {
            id: "T05-NC",
            title: "control: L[0][j] + 1e-3",
            run: t05_nc,
        },
        Check {
            id: "T16-NC",
            title: "control: scaled metric, one length × 1.01",
            run: t16_nc,
        },
        Check {
            id: "T20-NC",
            title: "control: image of v0 moved by 1/10",
            run: t20_nc,
        },
        Check {
            id: "T35-NC",
            title: "control: second metric, one length × 1.01",
            run: t35_nc,
        },
    ]
}

/// The control with exactly this ID (case-insensitive).
pub fn by_id(id: &str) -> Option<Check> {
    controls()
        .into_iter()
        .find(|c| c.id.eq_ignore_ascii_case(id))
}
