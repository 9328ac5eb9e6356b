//! The registry's entries: each catalogue check that applies to a single surface with a
//! metric, adapted to a [`Surface`] and a [`Prec`].
//!
//! T04, T07, T20 and T35 need data beyond a metric; their entries live in
//! [`super::checks_extra`].
//!
//! Where a theorem compares two metrics, the second one is derived from the case by a fixed
//! rule stated in the entry (a conformal scaling by [`scale_factors`], a uniform scale by
//! 3/2, a permutation of lengths), so every run is reproducible.

// The `at_precision!` bodies are generic code that is also instantiated at `f64`.
#![allow(clippy::clone_on_copy, clippy::op_ref, clippy::let_unit_value)]

use super::case::MetricOps;
pub use super::check_entry::scale_factors;
use super::check_entry::Check;
use super::checks_extra as extra;
use super::precision::Prec;
use crate::algorithms::flip_to_delaunay::FlipKind;
use crate::io::{Metric, Surface};
use crate::scalar::Real;
use crate::theorems::{
    t01_gauss_bonnet, t03_angle_rigidity, t05_cotan_laplacian, t15_lemma1,
    t16_scaling_cross_ratios, t17_cross_ratio_equivalence, t18_two_triangle_sphere,
    t19_one_vertex_torus, t21_delaunay_flipping, t22_delaunay_uniqueness,
    t23_euclidean_flip_cone_metric, t27_shear_log_cross_ratio, t28_ptolemy_flip,
    t29_euclidean_ptolemy_cocircular, Settings, Verdict,
};
use rug::Rational;

fn exact_lengths(case: &Surface) -> Option<&Vec<Rational>> {
    match &case.metric {
        Metric::Lengths(v) => Some(v),
        Metric::SquaredLengths(_) => None,
    }
}

/// The case's metric scaled conformally by [`scale_factors`] (docs/catalogue.md §4, Eq. 10).
pub(crate) fn scaled(case: &Surface) -> Metric {
    case.metric
        .scaled(&case.mesh, &scale_factors(case.mesh.n_vertices()))
}

/// The lengths of another metric on the case's mesh, in backend `T` ([`Surface::lengths`]).
pub(crate) fn lengths_of<T: Real>(case: &Surface, m: &Metric, ctx: T::Ctx) -> Vec<T> {
    Surface {
        name: String::new(),
        mesh: case.mesh.clone(),
        metric: m.clone(),
        positions: None,
    }
    .lengths(ctx)
}

/// Context of the first length (every surface has at least one edge).
fn ctx_of<T: Real>(l: &[T]) -> Option<T::Ctx> {
    l.first().map(Real::ctx)
}

fn not_applicable(reason: &str) -> Verdict {
    Verdict::NotApplicable {
        reason: reason.to_string(),
    }
}

fn t01(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| Some(
        t01_gauss_bonnet::check_gauss_bonnet(&case.mesh, &l, s)
    ))
}

fn t03(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| {
        let lt: Vec<T> = l.iter().map(|x| x.clone() * &x.lit(1.5)).collect();
        Some(t03_angle_rigidity::check_equal_angles_imply_scale(
            &case.mesh, &l, &lt, s,
        ))
    })
}

fn t05(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| Some(
        t05_cotan_laplacian::check_cotan_laplacian(&case.mesh, &l, s)
    ))
}

fn t15(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let lt = scaled(case);
    if prec == Prec::Exact {
        let (Metric::Lengths(a), Metric::Lengths(b)) = (&case.metric, &lt) else {
            return None;
        };
        return Some(t15_lemma1::check_lemma1_exact(&case.mesh, a, b));
    }
    at_precision!(prec, case, |l: T| {
        let ltt: Vec<T> = lengths_of(case, &lt, ctx_of(&l)?);
        Some(t15_lemma1::check_lemma1(&case.mesh, &l, &ltt, s))
    })
}

fn t16(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let sf = scale_factors(case.mesh.n_vertices());
    if prec == Prec::Exact {
        return Some(match &case.metric {
            Metric::Lengths(l) => {
                t16_scaling_cross_ratios::check_scaling_preserves_cross_ratios_exact(
                    &case.mesh, l, &sf,
                )
            }
            // On squared lengths the exact comparison is of squared cross ratios.
            Metric::SquaredLengths(sq) => {
                let Metric::SquaredLengths(lt) = scaled(case) else {
                    return None;
                };
                t16_scaling_cross_ratios::verify_equal_cross_ratios_exact(&case.mesh, sq, &lt)
            }
        });
    }
    at_precision!(prec, case, |l: T| {
        let ctx = ctx_of(&l)?;
        // u_v = 2 log s_v, so that e^{(u_i+u_j)/2} = s_i s_j.
        let u: Vec<T> = sf
            .iter()
            .map(|q| {
                let x = T::from_rational(q, ctx).ln();
                x.clone() + &x
            })
            .collect();
        Some(t16_scaling_cross_ratios::check_scaling_preserves_cross_ratios(&case.mesh, &l, &u, s))
    })
}

fn t17(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    t17_against(case, &scaled(case), prec, s)
}

/// T17 between the case's metric and a second metric `lt` of the same kind: exact in ℚ
/// for rational lengths, else at `prec` (`None` for exact squared lengths).
pub(crate) fn t17_against(
    case: &Surface,
    lt: &Metric,
    prec: Prec,
    s: &Settings,
) -> Option<Verdict> {
    if prec == Prec::Exact {
        let (Metric::Lengths(a), Metric::Lengths(b)) = (&case.metric, lt) else {
            return None;
        };
        return Some(
            t17_cross_ratio_equivalence::check_conformal_equivalence_exact(&case.mesh, a, b),
        );
    }
    at_precision!(prec, case, |l: T| {
        let ltt: Vec<T> = lengths_of(case, lt, ctx_of(&l)?);
        Some(t17_cross_ratio_equivalence::check_conformal_equivalence(
            &case.mesh, &l, &ltt, s,
        ))
    })
}

/// Whether the case is the two-triangle sphere (V, E, F = 3, 3, 2, closed).
fn is_two_triangle_sphere(case: &Surface) -> bool {
    let m = &case.mesh;
    (m.n_vertices(), m.n_edges(), m.n_faces()) == (3, 3, 2) && m.is_closed()
}

/// Whether the case is the one-vertex torus (V, E, F = 1, 3, 2, closed).
fn is_one_vertex_torus(case: &Surface) -> bool {
    let m = &case.mesh;
    (m.n_vertices(), m.n_edges(), m.n_faces()) == (1, 3, 2) && m.is_closed()
}

fn t18(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if !is_two_triangle_sphere(case) {
        return Some(not_applicable(
            "T18 concerns the two-triangle sphere (V, E, F = 3, 3, 2)",
        ));
    }
    // The second metric: the three lengths permuted cyclically (still a triangle).
    let perm = case.metric.reindex(&[1, 2, 0]);
    if prec == Prec::Exact {
        let (Metric::Lengths(a), Metric::Lengths(b)) = (&case.metric, &perm) else {
            return None;
        };
        return Some(t18_two_triangle_sphere::check_all_metrics_equivalent_exact(
            &case.mesh, a, b,
        ));
    }
    at_precision!(prec, case, |l: T| {
        let lt: Vec<T> = lengths_of(case, &perm, ctx_of(&l)?);
        Some(t18_two_triangle_sphere::check_all_metrics_equivalent(
            &case.mesh, &l, &lt, s,
        ))
    })
}

fn t19(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    if !is_one_vertex_torus(case) {
        return Some(not_applicable(
            "T19 concerns the one-vertex torus (V, E, F = 1, 3, 2)",
        ));
    }
    // The second metric: a uniform scale by 3/2 (equivalent, and uniform: the check holds).
    if prec == Prec::Exact {
        let a = exact_lengths(case)?;
        let b: Vec<Rational> = a
            .iter()
            .map(|x| Rational::from(x * &Rational::from((3, 2))))
            .collect();
        return Some(
            t19_one_vertex_torus::check_equivalent_iff_uniform_scale_exact(&case.mesh, a, &b),
        );
    }
    at_precision!(prec, case, |l: T| {
        let lt: Vec<T> = l.iter().map(|x| x.clone() * &x.lit(1.5)).collect();
        Some(t19_one_vertex_torus::check_equivalent_iff_uniform_scale(
            &case.mesh, &l, &lt, s,
        ))
    })
}

fn t21_euclidean(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| Some(
        t21_delaunay_flipping::check_delaunay_flipping(&case.mesh, &l, FlipKind::Euclidean, s)
    ))
}

fn t21_ptolemy(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| Some(
        t21_delaunay_flipping::check_delaunay_flipping(&case.mesh, &l, FlipKind::Ptolemy, s)
    ))
}

/// T22 flips at `prec` and compares the runs on the case's exact metric (each run's flip
/// sequence replayed there, B80): ties are decided on the input, never on rounded lengths.
fn t22(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| Some(
        t22_delaunay_uniqueness::check_delaunay_uniqueness_of(
            &case.mesh,
            &l,
            &case.metric,
            FlipKind::Euclidean,
            &[1, 2, 3],
            s
        )
    ))
}

fn t23(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    // The replay runs on enclosures at twice the working precision (at least 128 bits).
    let bits = (2 * prec.bits()).max(128);
    at_precision!(prec, case, |l: T| Some(
        t23_euclidean_flip_cone_metric::check_euclidean_flips_preserve_cone_metric(
            &case.mesh,
            &l,
            FlipKind::Euclidean,
            bits,
            s
        )
    ))
}

fn t27(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let Prec::Mpfr(p) = prec else {
        return None;
    };
    let l = case.lengths::<crate::scalar::Mpfr>(p);
    Some(t27_shear_log_cross_ratio::check_shear_log_cross_ratio(
        &case.mesh, &l, s,
    ))
}

fn t28(case: &Surface, prec: Prec, _s: &Settings) -> Option<Verdict> {
    if prec != Prec::Exact {
        return None;
    }
    let l = exact_lengths(case)?;
    Some(t28_ptolemy_flip::check_ptolemy_flip(
        &case.mesh,
        l,
        &scale_factors(case.mesh.n_vertices()),
    ))
}

fn t29(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| Some(
        t29_euclidean_ptolemy_cocircular::check_euclidean_equals_ptolemy_iff_cocircular(
            &case.mesh, &l, s
        )
    ))
}

/// Every entry, in catalogue order.
pub fn entries() -> Vec<Check> {
    vec![
        Check {
            id: "T01",
            title: "Gauss–Bonnet",
            run: t01,
        },
        Check {
            id: "T03",
            title: "equal angles ⇒ one scale",
            run: t03,
        },
        Check {
            id: "T04",
            title: "angle integrability (planar)",
            run: extra::t04,
        },
        Check {
            id: "T05",
            title: "cotan Laplacian",
            run: t05,
        },
        Check {
            id: "T07",
            title: "E_C = E_D − A",
            run: extra::t07,
        },
        Check {
            id: "T15",
            title: "Lemma 1 (one triangle)",
            run: t15,
        },
        Check {
            id: "T16",
            title: "scaling keeps cross ratios",
            run: t16,
        },
        Check {
            id: "T17",
            title: "cross ratios ⇒ equivalent",
            run: t17,
        },
        Check {
            id: "T18",
            title: "two-triangle sphere",
            run: t18,
        },
        Check {
            id: "T19",
            title: "one-vertex torus",
            run: t19,
        },
        Check {
            id: "T20",
            title: "inversion keeps cross ratios",
            run: extra::t20,
        },
        Check {
            id: "T21",
            title: "Delaunay flips (Euclidean)",
            run: t21_euclidean,
        },
        Check {
            id: "T21P",
            title: "Delaunay flips (Ptolemy)",
            run: t21_ptolemy,
        },
        Check {
            id: "T22",
            title: "Delaunay uniqueness",
            run: t22,
        },
        Check {
            id: "T23",
            title: "flips keep cone metric",
            run: t23,
        },
        Check {
            id: "T27",
            title: "shear = log cross ratio",
            run: t27,
        },
        Check {
            id: "T28",
            title: "Ptolemy flip identities",
            run: t28,
        },
        Check {
            id: "T29",
            title: "Euclid = Ptolemy ⇔ cocircular",
            run: t29,
        },
        Check {
            id: "T35",
            title: "Definition 2 (scale + flips)",
            run: extra::t35,
        },
    ]
}
