//! The first rung of T23's comparison: the whole replay on `f64` enclosures with directed
//! rounding by error terms (B21), escalating to MPFR only the elements it leaves open
//! (proof: B84).
//!
//! [`super::t23_euclidean_flip_cone_metric::verify_flip_sequence`] with the Euclidean
//! update answers `Holds { certified: true }` exactly when, on its MPFR enclosures at `p`
//! bits, every input face is a certified strict triangle, every recorded flip can be
//! replayed with its lemma hypotheses certified and its new length enclosed, and every
//! corner angle at a touched vertex can be enclosed before and after (the cone angles are
//! then equal, so their enclosures intersect). [`proved`] checks the same conditions with
//! the same expressions on `f64` enclosures; for `p ≥ 53` each `f64` interval contains the
//! MPFR one (B84), so a condition certified on `f64` is certified on MPFR. A condition
//! left open is checked on MPFR enclosures built lazily, only for the lengths it reads
//! (a new length from the five lengths of its flip's quadrilateral, recursively), which are
//! the very enclosures of the full replay. When one stays open there too, [`proved`] says
//! `false` and the full MPFR comparison decides as before.

use super::progress::Progress;
use super::t23_hypotheses::{face_certified, flip_hypotheses_certified, half_angle_tangent};
use crate::algorithms::flips::euclidean_length_enclosure;
use crate::mesh::{Edge, HalfEdge, Mesh};
use crate::predicates::delaunay::{Quad, QuadEdges};
use crate::scalar::{Interval, IntervalBound, Mpfr, Precision, Real};

/// Where one length comes from: an input edge (`< n_edges`) or the flip number
/// `s − n_edges` of the sequence.
type Source = usize;

/// MPFR enclosures at `p` bits of the lengths of the replay, built on demand: an input
/// length from its exact value, a flipped length by the Euclidean update of the
/// enclosures of its quadrilateral at the time of the flip (the replay's own arithmetic).
struct LazyMpfr<'a, T> {
    lengths: &'a [T],
    prec: Precision,
    /// The five sources (`ij, jk, ki, il, lj`) of each flip's quadrilateral.
    flips: Vec<[Source; 5]>,
    memo: std::collections::HashMap<Source, Option<Interval<Mpfr>>>,
}

impl<T: Real> LazyMpfr<'_, T> {
    /// The enclosure of `s`, or `None` when it cannot be built (a non-finite length, a
    /// new length the Euclidean update cannot enclose).
    fn get(&mut self, s: Source) -> Option<Interval<Mpfr>> {
        let n = self.lengths.len();
        // Sources of a flip precede it: an explicit stack, no recursion depth.
        let mut stack = vec![s];
        while let Some(&top) = stack.last() {
            if self.memo.contains_key(&top) {
                stack.pop();
                continue;
            }
            if top < n {
                let v = self.lengths[top]
                    .to_rational()
                    .map(|q| Interval::from_rational(&q, self.prec));
                self.memo.insert(top, v);
                stack.pop();
                continue;
            }
            let srcs = self.flips[top - n];
            let missing: Vec<Source> = srcs
                .iter()
                .copied()
                .filter(|x| !self.memo.contains_key(x))
                .collect();
            if !missing.is_empty() {
                stack.extend(missing);
                continue;
            }
            let got: Option<Vec<Interval<Mpfr>>> =
                srcs.iter().map(|x| self.memo[x].clone()).collect();
            let v = got.and_then(|q| euclidean_length_enclosure(quad(&q)));
            self.memo.insert(top, v);
            stack.pop();
        }
        self.memo.get(&s).cloned().flatten()
    }

    /// The enclosures of several sources, or `None` if one cannot be built.
    fn get_all<const K: usize>(&mut self, s: [Source; K]) -> Option<[Interval<Mpfr>; K]> {
        let v: Option<Vec<Interval<Mpfr>>> = s.iter().map(|&x| self.get(x)).collect();
        v?.try_into().ok()
    }
}

/// The quadrilateral of five enclosures in the order `ij, jk, ki, il, lj`.
fn quad<B: IntervalBound>(q: &[Interval<B>]) -> Quad<&Interval<B>> {
    Quad {
        ij: &q[0],
        jk: &q[1],
        ki: &q[2],
        il: &q[3],
        lj: &q[4],
    }
}

/// Whether every condition under which T23's MPFR comparison at `prec` (at least 53
/// bits) answers `Holds { certified: true }` for the Euclidean replay of `sequence` on
/// `(mesh, lengths)` is certified here, on `f64` enclosures first and on lazily built MPFR
/// enclosures for what they leave open (proof: B84). `false` decides nothing.
pub fn proved<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    sequence: &[Edge],
    prec: Precision,
    progress: &Progress,
) -> bool {
    // proof: B84 — the inclusion of the MPFR enclosures in the f64 ones needs p ≥ 53.
    if prec.bits() < 53 || lengths.len() != mesh.n_edges() {
        return false;
    }
    let fast: Option<Vec<Interval<f64>>> =
        super::t29_euclidean_ptolemy_cocircular::f64_enclosures(lengths)
            .into_iter()
            .collect();
    let Some(mut fast) = fast else {
        return false;
    };
    let n = mesh.n_edges();
    let mut lazy = LazyMpfr {
        lengths,
        prec,
        flips: Vec::new(),
        memo: std::collections::HashMap::new(),
    };
    // Input faces: certified strict triangles.
    for f in mesh.faces() {
        let es = mesh.face_halfedges(f).map(|h| h.edge().idx());
        if !face_certified(&fast[es[0]], &fast[es[1]], &fast[es[2]]) {
            match lazy.get_all(es) {
                Some([a, b, c]) if face_certified(&a, &b, &c) => {}
                _ => return false,
            }
        }
    }
    // The replay: each flip's hypotheses and new length.
    let fast0 = fast.clone();
    let mut source: Vec<Source> = (0..n).collect();
    let mut touched = vec![false; mesh.n_vertices()];
    let mut replayed = mesh.clone();
    let mut count = progress.counter("flips replayed on f64 enclosures", sequence.len());
    for (t, &e) in sequence.iter().enumerate() {
        count.add(1);
        let Some(q) = (e.idx() < n).then(|| QuadEdges::of(&replayed, e)).flatten() else {
            return false;
        };
        for h in [q.edge.halfedge(), q.edge.halfedge().twin()] {
            touched[replayed.tail(h).idx()] = true;
            touched[replayed.tail(replayed.prev(h)).idx()] = true;
        }
        let es = q.edges.to_array().map(Edge::idx);
        let srcs = es.map(|x| source[x]);
        lazy.flips.push(srcs);
        let lq = q.lengths(&fast);
        let new = match euclidean_length_enclosure(lq) {
            Some(new) if flip_hypotheses_certified(lq) => new,
            _ => {
                let Some(mq) = lazy.get_all(srcs) else {
                    return false;
                };
                if !flip_hypotheses_certified(quad(&mq)) {
                    return false;
                }
                let Some(new) = euclidean_length_enclosure(quad(&mq)) else {
                    return false;
                };
                match hull_f64(&new) {
                    Some(h) => h,
                    None => return false,
                }
            }
        };
        fast[e.idx()] = new;
        source[e.idx()] = n + t;
        if replayed.flip(e).is_err() {
            return false;
        }
    }
    count.finish();
    let input: Vec<Source> = (0..n).collect();
    corners_certified(mesh, &input, &mut lazy, &touched, &fast0)
        && corners_certified(&replayed, &source, &mut lazy, &touched, &fast)
}

/// Whether [`half_angle_tangent`] encloses every corner at a vertex with `touched[v]` of
/// `mesh`, whose edge `e` has the length of source `source[e]`: on the `f64` enclosures
/// `fast` first, on MPFR ones where those leave it open.
fn corners_certified<T: Real>(
    mesh: &Mesh,
    source: &[Source],
    lazy: &mut LazyMpfr<'_, T>,
    touched: &[bool],
    fast: &[Interval<f64>],
) -> bool {
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        for i in 0..3 {
            if !touched[mesh.tail(hs[(i + 2) % 3]).idx()] {
                continue;
            }
            let es: [usize; 3] = [0, 1, 2].map(|k| edge_of(hs[(i + k) % 3]));
            if half_angle_tangent(&fast[es[0]], &fast[es[1]], &fast[es[2]]).is_some() {
                continue;
            }
            match lazy.get_all(es.map(|x| source[x])) {
                Some([a, b, c]) if half_angle_tangent(&a, &b, &c).is_some() => {}
                _ => return false,
            }
        }
    }
    true
}

fn edge_of(h: HalfEdge) -> usize {
    h.edge().idx()
}

/// The smallest `f64` interval containing an MPFR enclosure (outward conversion of its
/// ends), `None` when an end is not finite.
fn hull_f64(x: &Interval<Mpfr>) -> Option<Interval<f64>> {
    let lo = x.lo().to_rational()?;
    let hi = x.hi().to_rational()?;
    let lo = *Interval::<f64>::from_rational(&lo, ()).lo();
    let hi = *Interval::<f64>::from_rational(&hi, ()).hi();
    Some(Interval::new(lo, hi))
}
