//! Negative controls of the conformal-equivalence checks: T15 (Lemma 1), T16 (scaling keeps
//! cross ratios), T17 (cross ratios ⇒ equivalent), T18 (two-triangle sphere), T19
//! (one-vertex torus), T20 (inversions), T35 (Definition 2).

// The `at_precision!` bodies are generic code that is also instantiated at `f64`.
#![allow(
    clippy::clone_on_copy,
    clippy::op_ref,
    clippy::let_unit_value,
    clippy::unit_arg
)]

use super::{bump, first_interior_edge, first_quad_side, not_applicable, TRIVIAL_CROSS_RATIOS};
use crate::geometry::scaling::reconstruct_scale_factors;
use crate::io::{Metric, Surface};
use crate::mesh::builders;
use crate::mesh::Mesh;
use crate::oracle::checks::{lengths_of, scale_factors, scaled, t17_against};
use crate::oracle::precision::Prec;
use crate::oracle::registry::Check;
use crate::scalar::Real;
use crate::theorems::t18_two_triangle_sphere::is_two_triangle_sphere;
use crate::theorems::{
    t15_lemma1, t16_scaling_cross_ratios, t18_two_triangle_sphere, t19_one_vertex_torus,
    t20_mobius_cross_ratios, t35_definition_two, Settings, Verdict,
};
use rug::Rational;

/// The registry's second metric ([`scaled`]) with the value (length or squared length) of
/// `e` scaled by 101/100.
fn scaled_with_bump(case: &Surface, e: crate::mesh::Edge) -> Option<Metric> {
    let mut m = scaled(case);
    let (Metric::Lengths(v) | Metric::SquaredLengths(v)) = &mut m;
    *v.get_mut(e.idx())? *= bump();
    Some(m)
}

/// T15-NC: Lemma 1 with the registry's pair (the metric and its scaling by
/// [`scale_factors`]) and the reconstructed factor `e^u` of the first face corner scaled by
/// 101/100 — the tests' control; the two edges at that corner then miss their scaled length
/// by 1/100 relative, far above the B45 tolerance.
fn t15_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let lt = scaled(case);
    let mesh = &case.mesh;
    let corner = mesh.halfedges().find(|&h| !mesh.is_boundary_halfedge(h))?;
    if prec == Prec::Exact {
        let (Metric::Lengths(a), Metric::Lengths(b)) = (&case.metric, &lt) else {
            return None;
        };
        let mut r = reconstruct_scale_factors(mesh, a, b);
        *r.corner_exp_u.get_mut(corner.idx())?.as_mut()? *= bump();
        return Some(t15_lemma1::verify_lemma1_exact(mesh, a, b, &r.corner_exp_u));
    }
    at_precision!(prec, case, |l: T| {
        let ctx = l.first()?.ctx();
        let ltt: Vec<T> = lengths_of(case, &lt, ctx);
        let mut r = reconstruct_scale_factors(mesh, &l, &ltt);
        *r.corner_exp_u.get_mut(corner.idx())?.as_mut()? *= &T::from_rational(&bump(), ctx);
        Some(t15_lemma1::verify_lemma1(
            mesh,
            &l,
            &ltt,
            &r.corner_exp_u,
            s,
        ))
    })
}

/// T16-NC (exact): the cross ratios of the metric against those of its conformal scaling
/// by [`scale_factors`] with the first interior edge's value then scaled by 101/100 (the
/// cross ratios of the edges whose quadrilaterals have that side move; compared in ℚ).
fn t16_nc(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    if is_two_triangle_sphere(&case.mesh) {
        return Some(not_applicable(TRIVIAL_CROSS_RATIOS));
    }
    let e = first_interior_edge(case)?;
    let scaled = scaled_with_bump(case, e)?;
    Some(match (&case.metric, &scaled) {
        (Metric::Lengths(a), Metric::Lengths(b))
        | (Metric::SquaredLengths(a), Metric::SquaredLengths(b)) => {
            t16_scaling_cross_ratios::verify_equal_cross_ratios_exact(&case.mesh, a, b)
        }
        _ => return None,
    })
}

/// T17-NC: T17's equivalence test between the metric and its scaling by [`scale_factors`]
/// with the side `jk` of the first interior edge's quadrilateral ([`first_quad_side`])
/// scaled by 101/100 — the tests' "perturbed metric": that edge's cross ratio moves by 1/100,
/// far above the B45 tolerance. Not applicable on the two-triangle sphere, where every
/// metric is equivalent (T18).
fn t17_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if is_two_triangle_sphere(&case.mesh) {
        return Some(not_applicable(
            "on the two-triangle sphere every metric is equivalent (T18): nothing to refuse",
        ));
    }
    let Some(e) = first_quad_side(case) else {
        return Some(not_applicable("T17's control needs an interior edge"));
    };
    t17_against(case, &scaled_with_bump(case, e)?, prec, s)
}

/// The case's three values moved onto `other` (another surface with three edges and two
/// faces, each face having all three edges), and the same with the value of edge 0 scaled
/// by 101/100.
fn on_other_three_edge_surface(case: &Surface, other: Mesh) -> Option<(Surface, Surface)> {
    if other.n_edges() != case.mesh.n_edges() {
        return None;
    }
    let moved = Surface {
        name: case.name.clone(),
        mesh: other,
        metric: case.metric.clone(),
        positions: None,
    };
    let mut bumped = moved.clone();
    let (Metric::Lengths(v) | Metric::SquaredLengths(v)) = &mut bumped.metric;
    *v.first_mut()? *= bump();
    Some((moved, bumped))
}

/// T18-NC (applies where T18 does, on the two-triangle sphere): T18's check with the case's
/// three lengths against the same with edge 0 scaled by 101/100, run on the one-vertex
/// torus instead — the other surface with three edges and two faces, where (T19) only
/// uniform scalings are equivalent: the tests' "T18 on another surface" control. The
/// Lemma 1 factors of the torus's single vertex then disagree by about 1/100, far above the
/// B45 tolerance.
fn t18_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if !is_two_triangle_sphere(&case.mesh) {
        return Some(not_applicable(
            "T18 concerns the two-triangle sphere (V, E, F = 3, 3, 2)",
        ));
    }
    let (a, b) = on_other_three_edge_surface(case, builders::one_vertex_torus())?;
    if prec == Prec::Exact {
        let (Metric::Lengths(x), Metric::Lengths(y)) = (&a.metric, &b.metric) else {
            return None;
        };
        return Some(t18_two_triangle_sphere::check_all_metrics_equivalent_exact(
            &a.mesh, x, y,
        ));
    }
    at_precision!(prec, a, |l: T| {
        let lt: Vec<T> = b.lengths(l.first()?.ctx());
        Some(t18_two_triangle_sphere::check_all_metrics_equivalent(
            &a.mesh, &l, &lt, s,
        ))
    })
}

/// Whether the case is the one-vertex torus (V, E, F = 1, 3, 2, closed).
fn is_one_vertex_torus(mesh: &Mesh) -> bool {
    (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()) == (1, 3, 2) && mesh.is_closed()
}

/// T19-NC (applies where T19 does, on the one-vertex torus): T19's check with the case's
/// three lengths against the same with edge 0 scaled by 101/100, run on the two-triangle
/// sphere instead — the tests' control: there the pair is equivalent (T18) but not a
/// uniform scaling (the ratios differ by 1/100, far above the B45 tolerance).
fn t19_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if !is_one_vertex_torus(&case.mesh) {
        return Some(not_applicable(
            "T19 concerns the one-vertex torus (V, E, F = 1, 3, 2)",
        ));
    }
    let (a, b) = on_other_three_edge_surface(case, builders::two_triangle_sphere())?;
    if prec == Prec::Exact {
        let (Metric::Lengths(x), Metric::Lengths(y)) = (&a.metric, &b.metric) else {
            return None;
        };
        return Some(t19_one_vertex_torus::check_equivalent_iff_uniform_scale_exact(&a.mesh, x, y));
    }
    at_precision!(prec, a, |l: T| {
        let lt: Vec<T> = b.lengths(l.first()?.ctx());
        Some(t19_one_vertex_torus::check_equivalent_iff_uniform_scale(
            &a.mesh, &l, &lt, s,
        ))
    })
}

/// T20-NC (exact): the cross ratios before and after the inversion of T20, with the image
/// of vertex 0 then moved by (1/10, 0, 0).
fn t20_nc(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    let Some(points) = &case.positions else {
        return Some(not_applicable("T20's control needs vertex positions"));
    };
    let (c, r2) = crate::oracle::checks_extra::t20_sphere(points);
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
/// 101/100 (compared in ℚ). Not applicable on the two-triangle sphere, where every metric
/// is equivalent.
fn t35_nc(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    let Metric::Lengths(l) = &case.metric else {
        return Some(not_applicable("T35's control needs rational lengths"));
    };
    if is_two_triangle_sphere(&case.mesh) {
        return Some(not_applicable(TRIVIAL_CROSS_RATIOS));
    }
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

/// The controls of this module.
pub fn controls() -> Vec<Check> {
    vec![
        Check {
            id: "T15-NC",
            title: "control: one Lemma 1 factor × 1.01",
            run: t15_nc,
        },
        Check {
            id: "T16-NC",
            title: "control: scaled metric, one length × 1.01",
            run: t16_nc,
        },
        Check {
            id: "T17-NC",
            title: "control: scaled metric, one quad side × 1.01",
            run: t17_nc,
        },
        Check {
            id: "T18-NC",
            title: "control: same pair on the one-vertex torus",
            run: t18_nc,
        },
        Check {
            id: "T19-NC",
            title: "control: same pair on the two-triangle sphere",
            run: t19_nc,
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
