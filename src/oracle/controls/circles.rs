//! Negative controls of the circle-pattern checks: T08 (triangle inequality of Eq. 9
//! lengths) and T09 (rigidity).

use super::not_applicable;
use crate::circles::CirclePattern;
use crate::io::Surface;
use crate::oracle::checks_circles::{degree_targets, t09_problem};
use crate::oracle::precision::Prec;
use crate::oracle::registry::Check;
use crate::scalar::{Dd, Mpfr};
use crate::theorems::t08_circle_pattern_lengths::{
    face_triangle_signs, fixed_pattern, verify_faces,
};
use crate::theorems::t09_circle_pattern_rigidity::{fixed_starts, runs, verify_rigidity};
use crate::theorems::{Settings, Verdict};
use rug::Rational;

/// T08-NC: the registry's pattern with the first face made obtuse — radii 1, 1, 1/2 at its
/// corners, `Φ = 0` on its first side and `2π/3` on the other two — where
/// `ℓ_jk + ℓ_ki = √3 < 2 = ℓ_ij` (proofs/T08): the face comparison must refuse it.
fn t08_nc(case: &Surface, prec: Prec, s: &Settings) -> Option<Verdict> {
    let bits = match prec {
        Prec::Exact => return None,
        p => p.bits(),
    };
    let mesh = &case.mesh;
    let (mut r, mut phi) = fixed_pattern(mesh);
    let Some(f) = mesh.faces().find(|&f| {
        let [a, b, c] = mesh.face_vertices(f);
        a != b && b != c && c != a
    }) else {
        return Some(not_applicable("no face with three distinct vertices"));
    };
    let [hij, hjk, hki] = mesh.face_halfedges(f);
    r[mesh.tail(hij).idx()] = Rational::from(1);
    r[mesh.tail(hjk).idx()] = Rational::from(1);
    r[mesh.tail(hki).idx()] = Rational::from((1, 2));
    phi[hij.edge().idx()] = Rational::new();
    phi[hjk.edge().idx()] = Rational::from((2, 3));
    phi[hki.edge().idx()] = Rational::from((2, 3));
    Some(verify_faces(
        mesh,
        &face_triangle_signs(mesh, &r, &phi, bits, s),
        bits,
    ))
}

/// T09-NC: the runs of the registry's problem mixed with runs of the problem whose targets
/// at vertices 1 and 2 are moved by `±π/20` (Gauss–Bonnet kept): two different solutions,
/// which the comparison must find in disjoint certified boxes.
fn t09_nc(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    let p = match t09_problem(&case.mesh) {
        Ok(p) => p,
        Err(reason) => return Some(not_applicable(&reason)),
    };
    let mut t = degree_targets(&case.mesh);
    t[1] += Rational::from((1, 20));
    t[2] -= Rational::from((1, 20));
    let q = match CirclePattern::uniform(case.mesh.clone(), &Rational::new(), t) {
        Ok(q) => q,
        Err(e) => return Some(not_applicable(&e.to_string())),
    };
    let starts = fixed_starts(case.mesh.n_vertices());
    let start = &starts[..1];
    let (mut a, b) = match prec {
        Prec::F64 => (runs::<f64>(&p, start, ()), runs::<f64>(&q, start, ())),
        Prec::Dd => (runs::<Dd>(&p, start, ()), runs::<Dd>(&q, start, ())),
        Prec::Mpfr(bits) => (runs::<Mpfr>(&p, start, bits), runs::<Mpfr>(&q, start, bits)),
        Prec::Exact => return None,
    };
    a.extend(b);
    Some(verify_rigidity(&p, &a))
}

/// The controls of this module.
pub fn controls() -> Vec<Check> {
    vec![
        Check {
            id: "T08-NC",
            title: "control: one face with obtuse angles 2π/3",
            run: t08_nc,
        },
        Check {
            id: "T09-NC",
            title: "control: runs of two problems (targets moved by π/20)",
            run: t09_nc,
        },
    ]
}
