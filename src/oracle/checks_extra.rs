//! Registry entries for the checks that need more than a metric: T04 (a planar layout),
//! T07 (a map to ℂ), T20 (vertex positions in ℝ³) and T35 (a second metric). Each states
//! the fixed rule that supplies the extra data, or answers `NotApplicable` with a reason.

// The `at_precision!` bodies are generic code that is also instantiated at `f64`.
#![allow(clippy::clone_on_copy, clippy::op_ref, clippy::let_unit_value)]

use super::case::MetricOps;
use super::check_entry::scale_factors;
use super::precision::Prec;
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay_exact, ExactLengths, FlipOptions};
use crate::io::{Metric, Surface};
use crate::mesh::Edge;
use crate::predicates::delaunay::QuadEdges;
use crate::scalar::Real;
use crate::theorems::{
    t04_angle_integrability, t07_conformal_energy, t20_mobius_cross_ratios, t35_definition_two,
    Settings, Verdict,
};
use rug::Rational;

/// Bit size past which T35's exact Ptolemy flipping gives up (the check is exact-only).
const T35_GUARD_BITS: u64 = 4096;

fn not_applicable(reason: &str) -> Verdict {
    Verdict::NotApplicable {
        reason: reason.to_string(),
    }
}

fn sub(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    std::array::from_fn(|k| Rational::from(&a[k] - &b[k]))
}

fn cross(a: &[Rational; 3], b: &[Rational; 3]) -> [Rational; 3] {
    let m = |i: usize, j: usize| Rational::from(&a[i] * &b[j]) - Rational::from(&a[j] * &b[i]);
    [m(1, 2), m(2, 0), m(0, 1)]
}

fn dot(a: &[Rational; 3], b: &[Rational; 3]) -> Rational {
    a.iter()
        .zip(b)
        .fold(Rational::new(), |acc, (x, y)| acc + Rational::from(x * y))
}

/// Whether every position lies in one plane (exact: the normal of the first
/// non-collinear triple is orthogonal to every difference).
pub fn coplanar(points: &[[Rational; 3]]) -> bool {
    let Some(p0) = points.first() else {
        return true;
    };
    let diffs: Vec<[Rational; 3]> = points.iter().map(|p| sub(p, p0)).collect();
    let normal = diffs.iter().enumerate().find_map(|(i, a)| {
        diffs[i + 1..]
            .iter()
            .map(|b| cross(a, b))
            .find(|n| n.iter().any(|x| x.cmp0().is_ne()))
    });
    match normal {
        None => true,
        Some(n) => diffs.iter().all(|d| dot(&n, d).cmp0().is_eq()),
    }
}

/// T04 applies to planar triangulations: the case must carry vertex positions, all in one
/// plane (checked exactly). Then the angles of its metric satisfy the triangle sums, the
/// interior vertex sums and the sine closure (notes §1.3.1).
pub fn t04(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    match &case.positions {
        Some(p) if coplanar(p) => {}
        _ => {
            return Some(not_applicable(
                "T04 concerns planar triangulations: give vertex positions in one plane",
            ))
        }
    }
    at_precision!(prec, case, |l: T| Some(
        t04_angle_integrability::check_angle_integrability_from_lengths(&case.mesh, &l, s)
    ))
}

/// [`t07_map`] rounded to the backend of `ctx`.
pub fn t07_map_at<T: Real>(n: usize, ctx: T::Ctx) -> Vec<[T; 2]> {
    t07_map(n)
        .iter()
        .map(|z| [T::from_rational(&z[0], ctx), T::from_rational(&z[1], ctx)])
        .collect()
}

/// The fixed map of T07: `f(v) = ((3v + 1) mod 7)/7 + i·((5v + 2) mod 11)/11`, irregular and
/// exactly rational.
pub fn t07_map(n: usize) -> Vec<[Rational; 2]> {
    (0..n)
        .map(|v| {
            [
                Rational::from((((3 * v + 1) % 7) as i64, 7)),
                Rational::from((((5 * v + 2) % 11) as i64, 11)),
            ]
        })
        .collect()
}

/// T07 (`E_C = E_D − A`) for the map [`t07_map`] on the case's metric; applies to every
/// surface (the identity holds triangle by triangle).
pub fn t07(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| {
        let ctx = l.first()?.ctx();
        let ft: Vec<[T; 2]> = t07_map_at(case.mesh.n_vertices(), ctx);
        Some(t07_conformal_energy::check_conformal_energy(
            &case.mesh, &l, &ft, s,
        ))
    })
}

/// The inversion sphere of T20: center `(x_max + 1, 1/3, 1/7)` (outside the bounding box in
/// x, so never a vertex), squared radius 2.
pub fn t20_sphere(points: &[[Rational; 3]]) -> ([Rational; 3], Rational) {
    let x_max = points
        .iter()
        .map(|p| p[0].clone())
        .max()
        .unwrap_or_default();
    (
        [
            x_max + Rational::from(1),
            Rational::from((1, 3)),
            Rational::from((1, 7)),
        ],
        Rational::from(2),
    )
}

/// T20 (an inversion in a sphere preserves length cross ratios) on the case's vertex
/// positions; `NotApplicable` without positions. The sphere is [`t20_sphere`].
pub fn t20(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let Some(points) = &case.positions else {
        return Some(not_applicable(
            "T20 needs vertex positions in ℝ³ (an OBJ/OFF file or `positions` in JSON)",
        ));
    };
    let (c, r2) = t20_sphere(points);
    if prec == Prec::Exact {
        return Some(
            t20_mobius_cross_ratios::check_mobius_preserves_cross_ratios_exact(
                &case.mesh, points, &c, &r2,
            ),
        );
    }
    at_precision!(prec, case, |l: T| {
        let ctx = l.first()?.ctx();
        let conv =
            |p: &[Rational; 3]| -> [T; 3] { std::array::from_fn(|k| T::from_rational(&p[k], ctx)) };
        let pts: Vec<[T; 3]> = points.iter().map(conv).collect();
        Some(
            t20_mobius_cross_ratios::check_mobius_preserves_cross_ratios(
                &case.mesh,
                &pts,
                &conv(&c),
                &T::from_rational(&r2, ctx),
                s,
            ),
        )
    })
}

/// T35 (Definition 2), exact only, with a built-in second metric: the case's lengths scaled
/// by [`scale_factors`] and then Ptolemy-flipped to intrinsic Delaunay by
/// `flip_to_delaunay_exact` (or, when that needs no flip, scaled and flipped across the
/// first flippable edge). `NotApplicable` on squared lengths (Ptolemy
/// flips leave ℚ) or when exact lengths outgrow the bit guard.
pub fn t35(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    let (Metric::Lengths(l), Metric::Lengths(scaled)) = (
        &case.metric,
        case.metric
            .scaled(&case.mesh, &scale_factors(case.mesh.n_vertices())),
    ) else {
        return Some(not_applicable(
            "T35 is checked exactly and needs rational lengths, not squared lengths",
        ));
    };
    let opts = FlipOptions {
        record: true,
        ..FlipOptions::default()
    };
    let mut m = case.mesh.clone();
    let Ok((report, ExactLengths::Exact(flipped))) =
        flip_to_delaunay_exact(&mut m, scaled.clone(), T35_GUARD_BITS, &opts)
    else {
        return Some(not_applicable(
            "T35: exact Ptolemy lengths outgrew 4096 bits while flipping the second metric",
        ));
    };
    let (flips, lb) = if report.sequence.is_empty() {
        let first = case
            .mesh
            .edges()
            .find(|&e: &Edge| QuadEdges::of(&case.mesh, e).is_some());
        let flips: Vec<Edge> = first.into_iter().collect();
        let sf = scale_factors(case.mesh.n_vertices());
        let Ok((_, lb)) = t35_definition_two::scaled_then_flipped_exact(&case.mesh, l, &sf, &flips)
        else {
            return Some(not_applicable("T35: the flip sequence is not flippable"));
        };
        (flips, lb)
    } else {
        // The Delaunay flipping of `algorithms` supplies the second metric, independently
        // of the theorem module's own flip code.
        (report.sequence, flipped)
    };
    Some(t35_definition_two::check_definition_two_exact(
        &case.mesh, l, &flips, &lb,
    ))
}
