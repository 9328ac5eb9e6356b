//! T28 (notes Eq. 18; MATH.md §5–6): the Ptolemy flip, exactly over ℚ —
//! (a) is an involution, (b) commutes with scaling `ℓ_ij ↦ s_i s_j ℓ_ij` for rational
//! `s_i = e^{u_i/2}`, (c) changes the five affected cross ratios by the cluster rule
//! `c_kl = 1/c`, `c'_jk = c_jk(1+c)`, `c'_il = c_il(1+c)`, `c'_ki = c_ki c/(1+c)`,
//! `c'_lj = c_lj c/(1+c)` and no other, (d) keeps every vertex product `Π c = 1`.

use super::{Verdict, Witness};
use crate::algorithms::flips::flip_ptolemy_exact;
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::QuadEdges;
use rug::Rational;

/// The length cross ratio `c_ij = ℓ_il ℓ_jk / (ℓ_ki ℓ_lj)` of every edge (`None` on boundary
/// and self-folded edges).
pub fn cross_ratios(mesh: &Mesh, l: &[Rational]) -> Vec<Option<Rational>> {
    mesh.edges()
        .map(|e| {
            let q = QuadEdges::of(mesh, e)?;
            let x = q.lengths(l);
            Some(Rational::from(x.il * x.jk) / Rational::from(x.ki * x.lj))
        })
        .collect()
}

/// Vertices whose product of cross ratios over outgoing half-edges is not 1 (interior
/// vertices whose edges all have cross ratios).
pub fn vertex_product_violations(mesh: &Mesh, l: &[Rational]) -> Vec<Witness> {
    let c = cross_ratios(mesh, l);
    let mut prod = vec![Some(Rational::from(1)); mesh.n_vertices()];
    for v in mesh.boundary_vertices().iter().enumerate().filter(|x| *x.1) {
        prod[v.0] = None;
    }
    for h in mesh.halfedges() {
        let v = mesh.tail(h).idx();
        prod[v] = match (prod[v].take(), &c[h.edge().idx()]) {
            (Some(p), Some(x)) => Some(p * x),
            _ => None,
        };
    }
    prod.iter()
        .enumerate()
        .filter_map(|(v, p)| match p {
            Some(p) if *p != 1 => Some(Witness {
                element: format!("v{v}"),
                detail: format!("product of cross ratios is {p}, not 1"),
                value: p.to_f64(),
            }),
            _ => None,
        })
        .collect()
}

/// Cluster-rule violations of the flip of `e` from `(before, lb)` to `(after, la)`.
pub fn cluster_rule_violations(
    before: &Mesh,
    lb: &[Rational],
    after: &Mesh,
    la: &[Rational],
    e: Edge,
) -> Vec<Witness> {
    let mut w = Vec::new();
    let Some(q) = QuadEdges::of(before, e) else {
        return w;
    };
    let (cb, ca) = (cross_ratios(before, lb), cross_ratios(after, la));
    let Some(c) = cb[e.idx()].clone() else {
        return w;
    };
    let one_plus = Rational::from(&c + 1u32);
    let sides = q.edges;
    let distinct = {
        let mut v = [sides.ij, sides.jk, sides.ki, sides.il, sides.lj].map(|x| x.0);
        v.sort_unstable();
        v.windows(2).all(|p| p[0] != p[1])
    };
    let mut expected: Vec<Option<Rational>> = cb.clone();
    expected[e.idx()] = Some(Rational::from(c.recip_ref()));
    if distinct {
        for s in [sides.jk, sides.il] {
            expected[s.idx()] = expected[s.idx()].take().map(|x| x * &one_plus);
        }
        let ratio = Rational::from(&c / &one_plus);
        for s in [sides.ki, sides.lj] {
            expected[s.idx()] = expected[s.idx()].take().map(|x| x * &ratio);
        }
    }
    for f in after.edges() {
        if !distinct && f != e {
            continue;
        }
        if expected[f.idx()] != ca[f.idx()] {
            w.push(Witness {
                element: f.to_string(),
                detail: format!("cross ratio after flipping {e} breaks the cluster rule"),
                value: ca[f.idx()].as_ref().map_or(f64::NAN, Rational::to_f64),
            });
        }
    }
    w
}

/// Check (a)–(d) for a Ptolemy flip of every flippable edge of `(mesh, lengths)` with
/// per-vertex rational scale factors `s` (positive).
pub fn check_ptolemy_flip(mesh: &Mesh, lengths: &[Rational], s: &[Rational]) -> Verdict {
    if lengths.len() != mesh.n_edges() || s.len() != mesh.n_vertices() {
        return Verdict::NotApplicable {
            reason: "one length per edge and one scale factor per vertex are required".into(),
        };
    }
    if lengths.iter().chain(s).any(|x| *x <= 0) {
        return Verdict::NotApplicable {
            reason: "lengths and scale factors must be positive".into(),
        };
    }
    let scale = |m: &Mesh, l: &[Rational]| -> Vec<Rational> {
        m.edges()
            .map(|e| {
                let h = e.halfedge();
                Rational::from(&s[m.tail(h).idx()] * &s[m.tip(h).idx()]) * &l[e.idx()]
            })
            .collect()
    };
    let mut witnesses = vertex_product_violations(mesh, lengths);
    for e in mesh.edges() {
        if QuadEdges::of(mesh, e).is_none() {
            continue;
        }
        let (mut m1, mut l1) = (mesh.clone(), lengths.to_vec());
        if flip_ptolemy_exact(&mut m1, &mut l1, e).is_err() {
            continue;
        }
        witnesses.extend(cluster_rule_violations(mesh, lengths, &m1, &l1, e));
        witnesses.extend(vertex_product_violations(&m1, &l1));
        // (b) scale then flip = flip then scale.
        let (mut m2, mut l2) = (mesh.clone(), scale(mesh, lengths));
        let _ = flip_ptolemy_exact(&mut m2, &mut l2, e);
        if l2 != scale(&m1, &l1) {
            witnesses.push(Witness {
                element: e.to_string(),
                detail: "Ptolemy flip does not commute with scaling".into(),
                value: 1.0,
            });
        }
        // (a) involution.
        let _ = flip_ptolemy_exact(&mut m1, &mut l1, e);
        let ends = |m: &Mesh| {
            let h = e.halfedge();
            let (a, b) = (m.tail(h).0, m.tip(h).0);
            (a.min(b), a.max(b))
        };
        if l1 != lengths || ends(&m1) != ends(mesh) {
            witnesses.push(Witness {
                element: e.to_string(),
                detail: "flipping twice does not restore the edge and its length".into(),
                value: 1.0,
            });
        }
    }
    Verdict::certified(witnesses, Vec::new(), 0)
}
