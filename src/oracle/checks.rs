//! The registry's entries: each catalogue check that applies to a single surface with a
//! metric, adapted to a [`Surface`] and a [`Prec`].
//!
//! Where a theorem compares two metrics, the second one is derived from the case by a fixed
//! rule stated in the entry (a conformal scaling by [`scale_factors`], a uniform scale by
//! 3/2, a permutation of lengths), so every run is reproducible.

use super::precision::Prec;
use super::registry::Check;
use crate::algorithms::flip_to_delaunay::FlipKind;
use crate::io::{Metric, Surface};
use crate::theorems::{
    t21_delaunay_flipping, t22_delaunay_uniqueness, t23_euclidean_flip_cone_metric,
    t27_shear_log_cross_ratio, t28_ptolemy_flip, t29_euclidean_ptolemy_cocircular, Settings,
    Verdict,
};
use rug::Rational;

/// Scale factors s_v = e^{u_v/2} = 1 + ((7v + 3) mod 5 − 2)/20 ∈ {9/10, …, 11/10}: a fixed,
/// irregular, exactly rational pattern. The ratio max/min < 1.23 keeps the triangles of
/// well-shaped surfaces triangles after scaling.
pub fn scale_factors(n: usize) -> Vec<Rational> {
    (0..n)
        .map(|v| {
            let k = ((7 * v + 3) % 5) as i64 - 2;
            Rational::from((20 + k, 20))
        })
        .collect()
}

fn exact_lengths(case: &Surface) -> Option<&Vec<Rational>> {
    match &case.metric {
        Metric::Lengths(v) => Some(v),
        Metric::SquaredLengths(_) => None,
    }
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

fn t22(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    at_precision!(prec, case, |l: T| Some(
        t22_delaunay_uniqueness::check_delaunay_uniqueness(
            &case.mesh,
            &l,
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
    ]
}
