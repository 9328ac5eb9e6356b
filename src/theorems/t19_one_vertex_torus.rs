//! T19 — notes Example 2: on the one-vertex torus (V = 1, E = 3, F = 2) two metrics are
//! conformally equivalent iff one is a uniform scaling of the other.
//!
//! API:
//! - `pub fn check_equivalent_iff_uniform_scale<T: Real>(mesh: &Mesh, l: &[T], lt: &[T], settings: &Settings) -> Verdict`
//! - `pub fn check_equivalent_iff_uniform_scale_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict`
//!
//! The check decides both sides independently — equivalence by T17 (Lemma 1
//! reconstruction), uniformity by comparing the ratios `ℓ̃_e/ℓ_e` — and fails when they
//! disagree. On a surface with more vertices (the negative control) a non-uniform conformal
//! scaling is equivalent but not uniform, and the check fails.

use super::bounds::SAFETY;
use super::inputs::{two_metrics, two_rational_metrics};
use super::report::Tally;
use super::t17_cross_ratio_equivalence::{
    check_conformal_equivalence, check_conformal_equivalence_exact,
};
use super::verdict::{Settings, Verdict};
use crate::mesh::Mesh;
use crate::scalar::Real;
use rug::Rational;

/// Compare the two sides; `None` if either is undecided.
fn conclude(equivalent: &Verdict, uniform: &Verdict, certified: bool) -> Verdict {
    let side = |v: &Verdict| match v {
        Verdict::Holds { .. } => Some(true),
        Verdict::Fails { .. } => Some(false),
        _ => None,
    };
    match (side(equivalent), side(uniform)) {
        (Some(a), Some(b)) if a == b => Verdict::Holds {
            certified,
            max_error: 0.0,
        },
        (Some(a), Some(_)) => Verdict::Fails {
            certified,
            witnesses: vec![super::verdict::Witness {
                element: "surface".to_string(),
                detail: if a {
                    "conformally equivalent but not a uniform scaling".to_string()
                } else {
                    "a uniform scaling that is not conformally equivalent".to_string()
                },
                value: 0.0,
            }],
        },
        _ => Verdict::Undecided {
            bits_tried: 0,
            witnesses: Vec::new(),
        },
    }
}

/// T19, numerical: equivalence by [`check_conformal_equivalence`]; uniformity by
/// `|r_e − r_0| ≤ 2ε(|r_e| + |r_0| + |r_e − r_0|)` with `r_e = ℓ̃_e/ℓ_e` (proofs/B45).
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t19_one_vertex_torus::check_equivalent_iff_uniform_scale, Settings};
/// let t = Mesh::from_gluing(1, &[[0, 0, 0], [0, 0, 0]],
///     &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))]).unwrap();
/// let s = Settings::default();
/// assert!(check_equivalent_iff_uniform_scale(&t, &[3.0_f64, 4.0, 5.0], &[6.0, 8.0, 10.0], &s).holds());
/// assert!(check_equivalent_iff_uniform_scale(&t, &[3.0_f64, 4.0, 5.0], &[3.0, 4.0, 6.0], &s).holds());
/// ```
pub fn check_equivalent_iff_uniform_scale<T: Real>(
    mesh: &Mesh,
    l: &[T],
    lt: &[T],
    settings: &Settings,
) -> Verdict {
    let p = match two_metrics(mesh, l, lt) {
        Ok(p) => p,
        Err(v) => return v,
    };
    let e = p.eps;
    let r: Vec<T> = l.iter().zip(lt).map(|(a, b)| b.clone() / a).collect();
    let mut tally = p.tally();
    for (k, rk) in r.iter().enumerate() {
        let d = rk.clone() - &r[0];
        let tol = settings.slack
            * SAFETY
            * e
            * (rk.approx_f64().abs() + r[0].approx_f64().abs() + d.approx_f64().abs());
        tally.within(format!("e{k}"), "ℓ̃/ℓ differs from that of e0", &d, tol);
    }
    conclude(
        &check_conformal_equivalence(mesh, l, lt, settings),
        &tally.verdict(),
        false,
    )
}

/// T19, exact in ℚ (certified).
pub fn check_equivalent_iff_uniform_scale_exact(
    mesh: &Mesh,
    l: &[Rational],
    lt: &[Rational],
) -> Verdict {
    if let Some(v) = two_rational_metrics(mesh, l, lt) {
        return v;
    }
    let r: Vec<Rational> = l
        .iter()
        .zip(lt)
        .map(|(a, b)| Rational::from(b / a))
        .collect();
    let mut tally = Tally::new(true, 0);
    for (k, rk) in r.iter().enumerate() {
        if *rk != r[0] {
            tally.fail(format!("e{k}"), "ℓ̃/ℓ differs from that of e0", 0.0);
        }
    }
    conclude(
        &check_conformal_equivalence_exact(mesh, l, lt),
        &tally.verdict(),
        true,
    )
}
