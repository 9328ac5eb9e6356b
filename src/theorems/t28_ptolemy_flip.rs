//! T28 (notes Eq. 18; docs/catalogue.md §5–6): the Ptolemy flip of any flippable edge of any
//! Δ-complex, exactly over ℚ —
//! (a) is an involution;
//! (b) commutes with scaling `ℓ_ij ↦ s_i s_j ℓ_ij` for rational `s_i = e^{u_i/2}`;
//! (c) changes the cross ratios by the cluster rule *with multiplicity*: with `c = c_ij`,
//!     the new diagonal gets `c_kl = 1/c`, and every other edge's cross ratio is multiplied
//!     by one factor per role it plays among the four sides of the quadrilateral — `1+c`
//!     per role `jk` or `il`, `c/(1+c)` per role `ki` or `lj` (a side in two roles gets the
//!     product of both; with five distinct edges this is docs/catalogue.md §6's rule
//!     `c'_jk = c_jk(1+c)`, `c'_il = c_il(1+c)`, `c'_ki = c_ki c/(1+c)`, `c'_lj = c_lj c/(1+c)`);
//! (d) keeps every vertex product `Π c = 1`.
//!
//! Cross ratios are the half-edge products `c_e = Π_{g ∈ {h, twin h}} ℓ(next g)/ℓ(prev g)`
//! ([`cross_ratios`]): docs/catalogue.md §4's `ℓ_il ℓ_jk/(ℓ_ki ℓ_lj)` on an edge with two faces, and 1
//! on an edge with the same face on both sides, whose two factors are inverse (proof: T28).
//!
//! Each identity has a `verify_*` comparison that [`check_ptolemy_flip`] runs on the true
//! data and the negative controls run on wrong data (a wrong rule, a wrong length, other
//! scale factors, a wrong cross ratio). Every comparison is an equality of rationals.
//!
//! ```
//! use penner::algorithms::flips::flip_ptolemy_exact;
//! use penner::mesh::{builders, Edge};
//! use penner::theorems::t28_ptolemy_flip::{cluster_rule_prediction, verify_cluster_rule};
//! use rug::Rational;
//! // The one-vertex torus: every side of every quadrilateral plays two roles.
//! let m = builders::one_vertex_torus();
//! let l: Vec<Rational> = [2, 3, 4].iter().map(|&x| Rational::from(x)).collect();
//! let predicted = cluster_rule_prediction(&m, &l, Edge(0)).unwrap();
//! let (mut m1, mut l1) = (m.clone(), l.clone());
//! flip_ptolemy_exact(&mut m1, &mut l1, Edge(0)).unwrap();
//! assert!(verify_cluster_rule(&m1, &l1, Edge(0), &predicted).is_empty());
//! // A wrong length after the flip is caught by the same comparison.
//! l1[0] *= Rational::from((101, 100));
//! assert!(!verify_cluster_rule(&m1, &l1, Edge(0), &predicted).is_empty());
//! ```

use super::{Verdict, Witness};
use crate::algorithms::flips::flip_ptolemy_exact;
use crate::mesh::{Edge, HalfEdge, Mesh};
use crate::predicates::delaunay::QuadEdges;
use crate::scalar::nearest_f64;
use rug::Rational;

/// Whether `l` has one positive length per edge of `mesh`.
fn positive_lengths(mesh: &Mesh, l: &[Rational]) -> bool {
    l.len() == mesh.n_edges() && l.iter().all(|x| *x > 0)
}

/// The witness for lengths that are not one positive rational per edge.
fn bad_lengths(which: &str) -> Witness {
    Witness {
        element: "surface".into(),
        detail: format!("the lengths {which} must be one positive rational per edge"),
        value: f64::NAN,
    }
}

/// The lengths scaled by `ℓ_ij ↦ s_i s_j ℓ_ij` (docs/catalogue.md §4 with `s_i = e^{u_i/2}`); the caller
/// checks the counts.
fn scaled(m: &Mesh, l: &[Rational], s: &[Rational]) -> Vec<Rational> {
    m.edges()
        .map(|e| {
            let h = e.halfedge();
            Rational::from(&s[m.tail(h).idx()] * &s[m.tip(h).idx()]) * &l[e.idx()]
        })
        .collect()
}

/// The cross ratio of every edge as the half-edge product
/// `c_e = Π_{g ∈ {h, twin h}} ℓ(next g)/ℓ(prev g)` (proof: T28, "Cross ratios on
/// Δ-complexes"): `ℓ_il ℓ_jk/(ℓ_ki ℓ_lj)` on an edge `ij` between faces `ijk` and `jil`
/// (docs/catalogue.md §4), exactly 1 on an edge with the same face on both sides, `None` on a boundary
/// edge and where a length is missing or a denominator is 0.
pub fn cross_ratios(mesh: &Mesh, l: &[Rational]) -> Vec<Option<Rational>> {
    let len = |h: HalfEdge| l.get(h.edge().idx());
    mesh.edges()
        .map(|e| {
            let (h, t) = (e.side(0), e.side(1));
            if mesh.is_boundary_halfedge(h) || mesh.is_boundary_halfedge(t) {
                return None;
            }
            let num = Rational::from(len(mesh.next(h))? * len(mesh.next(t))?);
            let den = Rational::from(len(mesh.prev(h))? * len(mesh.prev(t))?);
            (den != 0).then(|| num / den)
        })
        .collect()
}

/// T28 (d): vertices of `(mesh, l)` whose product of cross ratios over the outgoing
/// half-edges is not 1 ([`verify_vertex_products`] on [`cross_ratios`]); one witness if the
/// lengths are not one positive rational per edge.
pub fn vertex_product_violations(mesh: &Mesh, l: &[Rational]) -> Vec<Witness> {
    if !positive_lengths(mesh, l) {
        return vec![bad_lengths("of the vertex products")];
    }
    verify_vertex_products(mesh, &cross_ratios(mesh, l))
}

/// The comparison of T28 (d): at every interior vertex `v`, `Π_{h out of v} c_{edge(h)} = 1`
/// exactly (a loop at `v` counts twice, once per outgoing half-edge), for the given cross
/// ratios `c` (one per edge). Boundary vertices are skipped; an interior vertex with an edge
/// without a cross ratio, or a `c` of the wrong length, is a witness.
pub fn verify_vertex_products(mesh: &Mesh, c: &[Option<Rational>]) -> Vec<Witness> {
    if c.len() != mesh.n_edges() {
        return vec![Witness {
            element: "surface".into(),
            detail: format!(
                "{} cross ratios given for a mesh with {} edges",
                c.len(),
                mesh.n_edges()
            ),
            value: f64::NAN,
        }];
    }
    let boundary = mesh.boundary_vertices();
    let mut prod: Vec<Option<Rational>> = boundary
        .iter()
        .map(|&b| (!b).then(|| Rational::from(1)))
        .collect();
    let mut missing = vec![false; mesh.n_vertices()];
    for h in mesh.halfedges() {
        let v = mesh.tail(h).idx();
        if let Some(p) = prod[v].as_mut() {
            match &c[h.edge().idx()] {
                Some(x) => *p *= x,
                None => missing[v] = true,
            }
        }
    }
    prod.iter()
        .enumerate()
        .filter_map(|(v, p)| match p {
            Some(_) if missing[v] => Some(Witness {
                element: format!("v{v}"),
                detail: "an edge at this interior vertex has no cross ratio".into(),
                value: f64::NAN,
            }),
            Some(p) if *p != 1 => Some(Witness {
                element: format!("v{v}"),
                detail: format!("product of cross ratios is {p}, not 1"),
                value: nearest_f64(p),
            }),
            _ => None,
        })
        .collect()
}

/// The cluster rule with multiplicity applied to the cross ratios `cb` before the flip of the
/// quadrilateral `q`: `1/c` on the diagonal, and per side role a factor `1+c` (`jk`, `il`)
/// or `c/(1+c)` (`ki`, `lj`), composed when an edge plays several roles (proof: T28 (c)).
fn predict(mut cb: Vec<Option<Rational>>, q: &QuadEdges) -> Option<Vec<Option<Rational>>> {
    let c = cb.get(q.edge.idx())?.clone()?;
    if c <= 0 {
        return None;
    }
    let up = Rational::from(&c + 1u32);
    let down = Rational::from(&c / &up);
    let s = q.edges;
    for (side, factor) in [(s.jk, &up), (s.il, &up), (s.ki, &down), (s.lj, &down)] {
        // A boundary side has no cross ratio before or after the flip.
        if let Some(x) = cb.get_mut(side.idx())?.as_mut() {
            *x *= factor;
        }
    }
    // No side is the diagonal itself: the sides are the other half-edges of its two faces.
    cb[q.edge.idx()] = Some(c.recip());
    Some(cb)
}

/// T28 (c): the cross ratio of every edge after the Ptolemy flip of `e`, predicted by the
/// cluster rule with multiplicity from the cross ratios of `(before, lb)` alone: `c_kl = 1/c`
/// and, for every side role of the quadrilateral `ij; jk, ki, il, lj` that an edge `s`
/// plays, `c_s` multiplied by `1+c` (roles `jk`, `il`) or `c/(1+c)` (roles `ki`, `lj`);
/// other edges unchanged (proof: T28). `None` if `e` cannot be flipped (no such edge, a
/// boundary edge, the same face on both sides) or the lengths are not one positive rational
/// per edge.
pub fn cluster_rule_prediction(
    before: &Mesh,
    lb: &[Rational],
    e: Edge,
) -> Option<Vec<Option<Rational>>> {
    if e.idx() >= before.n_edges() || !positive_lengths(before, lb) {
        return None;
    }
    let q = QuadEdges::of(before, e)?;
    predict(cross_ratios(before, lb), &q)
}

/// The comparison of T28 (c): the cross ratios of `(after, la)` recomputed from the lengths
/// by definition ([`cross_ratios`]) against `predicted` (one per edge), exactly; every edge
/// that differs is a witness, and so is input of the wrong size or a non-positive length.
/// `e` names the flipped edge in the messages.
pub fn verify_cluster_rule(
    after: &Mesh,
    la: &[Rational],
    e: Edge,
    predicted: &[Option<Rational>],
) -> Vec<Witness> {
    if !positive_lengths(after, la) {
        return vec![bad_lengths("after the flip")];
    }
    if predicted.len() != after.n_edges() {
        return vec![Witness {
            element: "surface".into(),
            detail: format!(
                "{} predicted cross ratios for a mesh with {} edges",
                predicted.len(),
                after.n_edges()
            ),
            value: f64::NAN,
        }];
    }
    let show = |x: &Option<Rational>| x.as_ref().map_or("none".to_string(), ToString::to_string);
    cross_ratios(after, la)
        .iter()
        .zip(predicted)
        .enumerate()
        .filter(|(_, (a, p))| a != p)
        .map(|(f, (a, p))| Witness {
            element: format!("e{f}"),
            detail: format!(
                "cross ratio after flipping {e} is {}, the cluster rule gives {}",
                show(a),
                show(p)
            ),
            value: a.as_ref().map_or(f64::NAN, nearest_f64),
        })
        .collect()
}

/// T28 (c) for the flip of `e` from `(before, lb)` to `(after, la)`:
/// [`verify_cluster_rule`] against [`cluster_rule_prediction`]. Empty if `e` cannot be
/// flipped in `before` (nothing to check); one witness if the lengths before the flip are not
/// one positive rational per edge.
pub fn cluster_rule_violations(
    before: &Mesh,
    lb: &[Rational],
    after: &Mesh,
    la: &[Rational],
    e: Edge,
) -> Vec<Witness> {
    if e.idx() >= before.n_edges() || QuadEdges::of(before, e).is_none() {
        return Vec::new();
    }
    match cluster_rule_prediction(before, lb, e) {
        Some(p) => verify_cluster_rule(after, la, e, &p),
        None => vec![bad_lengths("before the flip")],
    }
}

/// The endpoints of `e` in `m` as an unordered pair.
fn ends(m: &Mesh, e: Edge) -> (u32, u32) {
    let h = e.halfedge();
    let (a, b) = (m.tail(h).0, m.tip(h).0);
    (a.min(b), a.max(b))
}

/// The comparison of T28 (a): `(twice, l2)`, the result of flipping `e` of `(mesh, l)` twice,
/// restores every length exactly and the endpoints of `e`. Every edge whose length differs
/// is a witness, and so are other endpoints of `e` and input of the wrong size.
pub fn verify_involution(
    mesh: &Mesh,
    l: &[Rational],
    e: Edge,
    twice: &Mesh,
    l2: &[Rational],
) -> Vec<Witness> {
    let n = mesh.n_edges();
    if e.idx() >= n || twice.n_edges() != n || l.len() != n || l2.len() != n {
        return vec![Witness {
            element: "surface".into(),
            detail: format!("flipping {e} twice: meshes or lengths of different sizes"),
            value: f64::NAN,
        }];
    }
    let mut w: Vec<Witness> = l
        .iter()
        .zip(l2)
        .enumerate()
        .filter(|(_, (a, b))| a != b)
        .map(|(f, (a, b))| Witness {
            element: format!("e{f}"),
            detail: format!("flipping {e} twice gives length {b}, not {a}"),
            value: nearest_f64(b),
        })
        .collect();
    if ends(twice, e) != ends(mesh, e) {
        w.push(Witness {
            element: e.to_string(),
            detail: "flipping twice does not restore the endpoints of the edge".into(),
            value: f64::NAN,
        });
    }
    w
}

/// The comparison of T28 (b) for the Ptolemy flip of `e`: the lengths of
/// `flip(scale_s(ℓ))` against `scale_t(flip(ℓ))`, with `scale_s(ℓ)_ij = s_i s_j ℓ_ij`
/// (docs/catalogue.md §4), exactly; the theorem is the case `t = s`. Every edge whose lengths differ
/// is a witness; lengths or factors that are not one positive rational per edge or vertex
/// give one witness; empty if `e` cannot be flipped.
pub fn verify_scaling_commutes(
    mesh: &Mesh,
    l: &[Rational],
    e: Edge,
    s: &[Rational],
    t: &[Rational],
) -> Vec<Witness> {
    let factors_ok = |x: &[Rational]| x.len() == mesh.n_vertices() && x.iter().all(|v| *v > 0);
    if !positive_lengths(mesh, l) || !factors_ok(s) || !factors_ok(t) {
        return vec![Witness {
            element: "surface".into(),
            detail: "one positive length per edge and one positive scale factor per vertex \
                     are required"
                .into(),
            value: f64::NAN,
        }];
    }
    let (mut m1, mut l1) = (mesh.clone(), l.to_vec());
    let (mut m2, mut l2) = (mesh.clone(), scaled(mesh, l, s));
    if flip_ptolemy_exact(&mut m1, &mut l1, e).is_err()
        || flip_ptolemy_exact(&mut m2, &mut l2, e).is_err()
    {
        return Vec::new();
    }
    scaled(&m1, &l1, t)
        .iter()
        .zip(&l2)
        .enumerate()
        .filter(|(_, (a, b))| a != b)
        .map(|(f, (a, b))| Witness {
            element: format!("e{f}"),
            detail: format!("flipping {e}: scale then flip gives {b}, flip then scale gives {a}"),
            value: nearest_f64(b),
        })
        .collect()
}

/// Check (a)–(d) for the Ptolemy flip of every flippable edge of `(mesh, lengths)` with
/// per-vertex rational scale factors `s` (positive): (d) on the input and after each flip,
/// (c) by [`cluster_rule_violations`], (b) by [`verify_scaling_commutes`] with `t = s`, (a)
/// by [`verify_involution`]. Exact in ℚ, so a `Holds` is certified; on any Δ-complex
/// (loops, multi-edges, self-folded triangles).
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
    let cb = cross_ratios(mesh, lengths);
    let mut witnesses = verify_vertex_products(mesh, &cb);
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        let (mut m1, mut l1) = (mesh.clone(), lengths.to_vec());
        if flip_ptolemy_exact(&mut m1, &mut l1, e).is_err() {
            continue;
        }
        // (c), with the before cross ratios computed once for all edges.
        match predict(cb.clone(), &q) {
            Some(p) => witnesses.extend(verify_cluster_rule(&m1, &l1, e, &p)),
            None => witnesses.push(bad_lengths("before the flip")),
        }
        // (d) after the flip.
        witnesses.extend(vertex_product_violations(&m1, &l1));
        // (b) scale then flip = flip then scale.
        witnesses.extend(verify_scaling_commutes(mesh, lengths, e, s, s));
        // (a) involution.
        let _ = flip_ptolemy_exact(&mut m1, &mut l1, e);
        witnesses.extend(verify_involution(mesh, lengths, e, &m1, &l1));
    }
    Verdict::certified(witnesses, Vec::new(), 0)
}
