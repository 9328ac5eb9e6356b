//! Negative controls of the uniformization checks: T24 (the certified box of the solution
//! against targets with `π/100` moved between two vertices, which the box is proved to
//! exclude, B73), T25 (the second certified solution moved by `1/1000` at one free
//! vertex), T26 (scaling after the flips by a factor changed by 1% at vertex 0).

use crate::io::Surface;
use crate::oracle::checks_uniformization::{
    input_metric, prepare, t24_existence, t25_pair, t26_path, t26_replay,
};
use crate::oracle::precision::Prec;
use crate::oracle::registry::Check;
use crate::theorems::t25_uniformization_unique::compare_normalized;
use crate::theorems::{Settings, Verdict, Witness};
use crate::uniformization::components::Components;
use crate::uniformization::exclusion::excluded_vertices;
use crate::uniformization::Targets;
use rug::Rational;

const ONE_VERTEX: &str = "one vertex: its angle sum is fixed by Gauss–Bonnet, nothing can be moved";

fn undecided(detail: String) -> Verdict {
    Verdict::Undecided {
        bits_tried: 0,
        witnesses: vec![Witness {
            element: "surface".into(),
            detail,
            value: f64::NAN,
        }],
    }
}

/// The control of a check that did not certify on this surface (e.g. Delaunay ties at
/// the solution, B71 Limits) has no certified box to perturb: not applicable, naming the
/// check's own reason.
fn not_certified(id: &str, v: &Verdict) -> Verdict {
    let why = match v {
        Verdict::Undecided { witnesses, .. } => witnesses
            .iter()
            .map(|w| w.detail.clone())
            .collect::<Vec<_>>()
            .join("; "),
        other => format!("{other:?}"),
    };
    super::not_applicable(&format!(
        "{id} is not certified on this surface ({why}): no certified solution to perturb"
    ))
}

/// The targets with `π/100` moved from vertex `a` to vertex `b` (Gauss–Bonnet still holds).
pub fn moved_targets(t: &Targets, a: usize, b: usize) -> Targets {
    let mut q = t.over_pi().to_vec();
    let step = Rational::from((1, 100));
    q[a] -= &step;
    q[b] += &step;
    Targets::from_multiples_of_pi(q)
}

/// T24-NC: the box the T24 certificate proved around its solution, claimed to hold a
/// solution for the targets with `π/100` moved from the first vertex to the second:
/// refuted when some target is certified outside the angle sums over the box (B73).
fn t24_nc(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    if case.mesh.n_vertices() < 2 {
        return Some(super::not_applicable(ONE_VERTEX));
    }
    let ex = match t24_existence(case, prec)? {
        Ok(ex) => ex,
        Err(v) => return Some(v),
    };
    let Some(proof) = ex.proof.filter(|_| ex.verdict.holds()) else {
        return Some(not_certified("T24", &ex.verdict));
    };
    let p = match prepare(case, prec)? {
        Ok(p) => p,
        Err(v) => return Some(v),
    };
    let mut data = proof.data;
    data.targets = moved_targets(&data.targets, 0, 1);
    // The same T₀ metric as the certificate (the solve is deterministic).
    let sol = match crate::uniformization::uniformize(
        &case.mesh,
        &p.lengths,
        &p.targets,
        &crate::uniformization::UniformizeOptions::default(),
    ) {
        Ok(s) => s,
        Err(e) => return Some(undecided(e.to_string())),
    };
    let metric = match input_metric(case, &p.lengths, p.prec, &sol) {
        Ok(m) => m,
        Err(reason) => return Some(undecided(reason)),
    };
    Some(
        match excluded_vertices(&data, Some(&metric.enclosures), p.prec.bits()) {
            Err(e) => undecided(e.to_string()),
            Ok(Err(reason)) => undecided(reason),
            Ok(Ok(ex)) if ex.is_empty() => {
                undecided("no target certified outside the angle sums over the box".into())
            }
            Ok(Ok(ex)) => Verdict::certified(
                ex.iter()
                    .map(|x| Witness {
                        element: format!("v{}", x.vertex),
                        detail: format!(
                            "target {:.17} outside the angle sums [{:.17}, {:.17}] over the box",
                            x.target, x.angle_sum.0, x.angle_sum.1
                        ),
                        value: x.target,
                    })
                    .collect(),
                Vec::new(),
                p.prec.bits(),
            ),
        },
    )
}

/// T25-NC: the two certified solutions of T25 with the second moved by `1/1000` at the
/// first vertex that is not grounded.
fn t25_nc(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    let comps = Components::of(&case.mesh);
    let Some(v) = (0..case.mesh.n_vertices()).find(|&v| !comps.is_root(v)) else {
        return Some(super::not_applicable(ONE_VERTEX));
    };
    let (verdict, pair) = match t25_pair(case, prec)? {
        Ok(x) => x,
        Err(v) => return Some(v),
    };
    let Some(((p1, d1), (p2, d2))) = pair else {
        return Some(not_certified("T25", &verdict));
    };
    let mut u2 = p2.data.u.clone();
    u2[v] += Rational::from((1, 1000));
    Some(compare_normalized(&case.mesh, &p1.data.u, d1, &u2, d2))
}

/// T26-NC: the exact replay of T26 with the scale factor of vertex 0 after the flips
/// multiplied by 101/100.
fn t26_nc(case: &Surface, prec: Prec, _: &Settings) -> Option<Verdict> {
    let path = match t26_path(case, prec)? {
        Ok(p) => p,
        Err(v) => return Some(v),
    };
    let mut t = path.s.clone();
    t[0] *= Rational::from((101, 100));
    Some(t26_replay(&path, &t))
}

/// The controls of this module.
pub fn controls() -> Vec<Check> {
    vec![
        Check {
            id: "T24-NC",
            title: "certified box vs targets moved by π/100",
            run: t24_nc,
        },
        Check {
            id: "T25-NC",
            title: "second solution moved by 1/1000",
            run: t25_nc,
        },
        Check {
            id: "T26-NC",
            title: "scale after flips × 1.01 at v0",
            run: t26_nc,
        },
    ]
}
