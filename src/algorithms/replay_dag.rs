//! The lengths of a lazy replay ([`super::replay::replay_lazy`]) as a flip DAG
//! (proof: B85): each flip of the sequence is a node whose five parents are the lengths of
//! its quadrilateral at the time of the flip (input edges or earlier nodes). A node first
//! gets an `f64` enclosure by the flip's own interval formula on the `f64` enclosures of its
//! parents (B21 bounds); its exact or MPFR length ([`super::replay::new_length`]) is built
//! only when a sign stays open on the `f64` enclosures, or when the `f64` formula cannot
//! enclose the flip. Forcing a node forces its ancestors, iteratively.
//!
//! By B84 the `f64` enclosure of a node contains the MPFR enclosure its forced length has
//! at `p ≥ 53` bits, so every sign and every new length the `f64` enclosures certify, the
//! eager replay certifies too, with the same answer: the verdicts are those of the eager
//! replay (B85).

use super::flips::{euclidean_length_enclosure, ptolemy_length_enclosure};
use super::replay_algebraic::{delaunay_sign, Item};
use super::replay_chord::planar_chord;
use super::replay_input::InputMetric;
use super::replay_len::{f64_enclosure, new_length, sign_of_lens, tie_length, Len};
use crate::mesh::{Edge, Vertex};
use crate::predicates::delaunay::Quad;
use crate::predicates::delaunay_widened::{in_range, sign_p, Bounds};
use crate::scalar::{Interval, Mpfr, Precision, Real, Sign};
use std::borrow::Cow;
use std::collections::HashMap;

/// Where a length of a replay comes from: an edge of the input triangulation, or the new
/// diagonal of a node of the DAG.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Source {
    /// The input length of this edge.
    Input(Edge),
    /// The new length of node `n` (the `n`-th flip recorded in the DAG).
    Flip(u32),
}

/// One flip: its quadrilateral's lengths, whether it was a certified tie, and its new
/// length, lazy or built.
#[derive(Clone, Debug)]
struct Node {
    quad: Quad<Source>,
    /// The corners `[i, j, k, l]` of the quadrilateral (for the chordal rule, B106).
    corners: Option<[Vertex; 4]>,
    tie: bool,
    /// Whether the built length is the chord of its ends' input positions (B106).
    chordal: bool,
    /// Whether the new length was recorded lazily (its first-rung enclosure is then the
    /// flip formula's, not the hull of the built length).
    deferred: bool,
    value: Value,
}

/// The new length of a node.
#[derive(Clone, Debug)]
enum Value {
    /// Not built yet: its `f64` enclosure by the flip formula on the parents' (B85), and
    /// the replay's precision.
    Lazy(Bounds, Precision),
    /// The exact or MPFR length, the eager replay's.
    Built(Len),
}

/// The flip DAG of a lazy replay: its nodes and the current source of every edge.
#[derive(Clone, Debug)]
pub struct FlipDag {
    nodes: Vec<Node>,
    /// The node of each edge's current length, [`NOT_FLIPPED`] for the input's.
    current: Vec<u32>,
    ptolemy: bool,
    bits: u32,
}

/// The entry of [`FlipDag::current`] for an edge that still has its input length.
const NOT_FLIPPED: u32 = u32::MAX;

impl FlipDag {
    /// An empty DAG over `n_edges` input edges, for flips of the given kind replayed at
    /// `bits` bits.
    pub fn new(n_edges: usize, ptolemy: bool, bits: u32) -> FlipDag {
        FlipDag {
            nodes: Vec::new(),
            current: vec![NOT_FLIPPED; n_edges],
            ptolemy,
            bits,
        }
    }

    /// The number of flips recorded.
    pub fn n_flips(&self) -> usize {
        self.nodes.len()
    }

    /// The number of flips whose exact or MPFR length has been built.
    pub fn n_built(&self) -> usize {
        self.nodes
            .iter()
            .filter(|n| matches!(n.value, Value::Built(_)))
            .count()
    }

    /// The current source of the length of `e`.
    pub fn source(&self, e: Edge) -> Source {
        match self.current.get(e.idx()) {
            Some(&n) if n != NOT_FLIPPED => Source::Flip(n),
            _ => Source::Input(e),
        }
    }

    /// Whether node `n` is still lazy.
    fn is_lazy(&self, n: u32) -> bool {
        matches!(self.nodes[n as usize].value, Value::Lazy(..))
    }

    /// Build the length of node `n` and of its lazy ancestors (iteratively: a chain of
    /// flips may be long). A length the eager formulas cannot enclose as positive —
    /// excluded by B84 for a node whose `f64` formula did — keeps its `f64` bounds as an
    /// MPFR enclosure, which contains it.
    fn force<S: InputMetric + ?Sized>(&mut self, input: &S, n: u32) {
        let mut stack = vec![n];
        while let Some(&top) = stack.last() {
            let node = &self.nodes[top as usize];
            let Value::Lazy(bounds, p) = node.value else {
                stack.pop();
                continue;
            };
            let before = stack.len();
            for s in node.quad.to_array() {
                if let Source::Flip(q) = s {
                    if self.is_lazy(q) {
                        stack.push(q);
                    }
                }
            }
            if stack.len() > before {
                continue;
            }
            let new = self.build(input, node.quad, node.corners, node.tie);
            stack.pop();
            let node = &mut self.nodes[top as usize];
            node.chordal = new.as_ref().is_some_and(|(_, c)| *c);
            node.value = Value::Built(new.map_or_else(|| enclosure_of(bounds, p), |(l, _)| l));
        }
    }

    /// The new length of a flip of the quadrilateral `quad` (corners `corners`) as the
    /// eager replay builds it, from built parents, and whether it is chordal: the chord of
    /// a planar hinge of chordal lengths (B106), else [`tie_length`] or [`new_length`].
    fn build<S: InputMetric + ?Sized>(
        &self,
        input: &S,
        quad: Quad<Source>,
        corners: Option<[Vertex; 4]>,
        tie: bool,
    ) -> Option<(Len, bool)> {
        if let Some(chord) = self.chord(input, quad, corners, tie) {
            return Some((chord, true));
        }
        let lens = quad.map(|s| self.get(input, s));
        let lens = lens.as_refs().map(|l| &**l);
        let new = if tie {
            tie_length(lens, self.ptolemy, self.bits)
        } else {
            new_length(lens, self.ptolemy, self.bits)
        };
        new.map(|l| (l, false))
    }

    /// The chordal rule (proof: B106): a Euclidean flip (or a tie flip, whose Ptolemy
    /// length is the Euclidean one, T29) of a quadrilateral whose five lengths are chordal
    /// — input lengths of an input with positions, or earlier chordal flips — and whose
    /// corners are coplanar with `k`, `l` on opposite sides of `ij` has the new length
    /// `√|p_k − p_l|²`, exactly.
    fn chord<S: InputMetric + ?Sized>(
        &self,
        input: &S,
        quad: Quad<Source>,
        corners: Option<[Vertex; 4]>,
        tie: bool,
    ) -> Option<Len> {
        if self.ptolemy && !tie {
            return None;
        }
        let chordal = quad.to_array().iter().all(|s| match s {
            Source::Input(_) => true,
            Source::Flip(n) => self.nodes[*n as usize].chordal,
        });
        if !chordal {
            return None;
        }
        let [i, j, k, l] = corners?.map(|v| input.position(v));
        planar_chord([&i?, &j?, &k?, &l?]).map(Len::Root)
    }

    /// The length from `s`: the input's, a built node's, or a lazy node's `f64` bounds as
    /// an MPFR enclosure ([`FlipDag::force`] first for the eager replay's length).
    fn get<'a, S: InputMetric + ?Sized>(&'a self, input: &S, s: Source) -> Cow<'a, Len> {
        match s {
            Source::Input(e) => Cow::Owned(input.exact(e)),
            Source::Flip(n) => match &self.nodes[n as usize].value {
                Value::Built(l) => Cow::Borrowed(l),
                Value::Lazy(b, p) => Cow::Owned(enclosure_of(*b, *p)),
            },
        }
    }

    /// The length of `e` in the eager replay's form (exact or MPFR), building it.
    pub fn len<S: InputMetric + ?Sized>(&mut self, input: &S, e: Edge) -> Len {
        let s = self.source(e);
        if let Source::Flip(n) = s {
            self.force(input, n);
        }
        self.get(input, s).into_owned()
    }

    /// Every edge's length (one per input edge), building every node.
    pub fn materialize<S: InputMetric + ?Sized>(mut self, input: &S) -> Vec<Len> {
        (0..self.current.len() as u32)
            .map(|e| self.len(input, Edge(e)))
            .collect()
    }

    /// Record the flip of `e` with quadrilateral `q` (before the flip), `tie` when its sign
    /// was certified zero, given the `f64` enclosures `first` of the current lengths;
    /// returns the `f64` enclosure of the new length for the first rung, or `None` when
    /// the flip's length cannot be enclosed as positive (the eager replay's `NoLength`).
    ///
    /// The new length stays lazy when the flip is not a tie, MPFR accepts `bits` and the
    /// flip's interval formula on the five `f64` enclosures gives a positive enclosure in
    /// the rung's range (proof: B85); otherwise it is built now, exactly as the eager
    /// replay builds it, and its first-rung enclosure is its `f64` hull.
    pub fn flip<S: InputMetric + ?Sized>(
        &mut self,
        input: &S,
        e: Edge,
        q: Quad<Edge>,
        corners: Option<[Vertex; 4]>,
        tie: bool,
        first: &[Option<Bounds>],
    ) -> Option<Option<Bounds>> {
        let n = u32::try_from(self.nodes.len())
            .ok()
            .filter(|&n| n != NOT_FLIPPED)?;
        let quad = q.map(|e| self.source(e));
        let lazy = match Precision::new(u64::from(self.bits)) {
            Ok(p) if !tie => self.f64_length(q, first).map(|b| (b, p)),
            _ => None,
        };
        let deferred = lazy.is_some();
        let (value, bounds, chordal) = if let Some((b, p)) = lazy {
            (Value::Lazy(b, p), Some(b), false)
        } else {
            for s in quad.to_array() {
                if let Source::Flip(p) = s {
                    self.force(input, p);
                }
            }
            let (new, chordal) = self.build(input, quad, corners, tie)?;
            let h = hull(&new);
            (Value::Built(new), h, chordal)
        };
        self.nodes.push(Node {
            quad,
            corners,
            tie,
            chordal,
            deferred,
            value,
        });
        if let Some(c) = self.current.get_mut(e.idx()) {
            *c = n;
        }
        Some(bounds)
    }

    /// The new length of the flip of `q` by its interval formula on the `f64` enclosures
    /// (B21 bounds; proof: B85), when positive and in the first rung's range.
    fn f64_length(&self, q: Quad<Edge>, first: &[Option<Bounds>]) -> Option<Bounds> {
        let [a, b, c, d, e] = q
            .map(|e| first.get(e.idx()).copied().flatten())
            .to_array()
            .map(|b| b.map(|[lo, hi]| Interval::<f64>::new(lo, hi)));
        let (a, b, c, d, e) = (a?, b?, c?, d?, e?);
        let quad = Quad {
            ij: &a,
            jk: &b,
            ki: &c,
            il: &d,
            lj: &e,
        };
        let x = if self.ptolemy {
            ptolemy_length_enclosure(quad)
        } else {
            euclidean_length_enclosure(quad)
        }?;
        in_range([*x.lo(), *x.hi()])
    }

    /// The certified sign of `D` on the quadrilateral `q` once the first rung on `first`
    /// left it open: the eager replay's rungs — `sign_p` on the `f64` hulls of the built
    /// lengths (when one was recorded lazily; otherwise `first` holds those hulls and has
    /// been tried), then the MPFR and exact rungs.
    pub fn sign_open<S: InputMetric + ?Sized>(
        &mut self,
        input: &S,
        q: Quad<Edge>,
        first: &[Option<Bounds>],
    ) -> Option<Sign> {
        let quad = q.map(|e| self.source(e));
        let mut lazy = false;
        for s in quad.to_array() {
            if let Source::Flip(n) = s {
                lazy |= self.nodes[n as usize].deferred;
                self.force(input, n);
            }
        }
        let l = quad.map(|s| self.get(input, s));
        if lazy {
            let hulls = Quad {
                ij: (q.ij, &l.ij),
                jk: (q.jk, &l.jk),
                ki: (q.ki, &l.ki),
                il: (q.il, &l.il),
                lj: (q.lj, &l.lj),
            }
            .map(|(e, len)| match self.source(e) {
                Source::Flip(_) => hull(len),
                Source::Input(e) => first.get(e.idx()).copied().flatten(),
            });
            if let [Some(a), Some(b), Some(c), Some(d), Some(e)] = hulls.to_array() {
                if let Some(s) = sign_p([a, b, c, d, e]) {
                    return Some(s);
                }
            }
        }
        let s = sign_of_lens([&*l.ij, &*l.jk, &*l.ki, &*l.il, &*l.lj], self.bits);
        if s.is_some() {
            return s;
        }
        self.algebraic_sign(input, quad)
    }

    /// The exact sign of `D` on the quadrilateral of lengths `quad` when no enclosure
    /// decides it (proof: B107, [`delaunay_sign`]): every squared length as an algebraic
    /// number over the input's exact squares — an exact length's square, or its flip's
    /// formula, one square root per flip. `None` when a length is not expressible (an
    /// input that is itself an enclosure), more than [`MAX_RADICALS`] flips are involved,
    /// or a sign stays open.
    fn algebraic_sign<S: InputMetric + ?Sized>(
        &self,
        input: &S,
        quad: Quad<Source>,
    ) -> Option<Sign> {
        let mut items = Vec::new();
        let mut index = HashMap::new();
        let mut budget = MAX_RADICALS;
        let roots = quad
            .to_array()
            .map(|s| self.collect(input, s, &mut items, &mut index, &mut budget));
        let [a, b, c, d, e] = roots;
        delaunay_sign(&items, [a?, b?, c?, d?, e?], self.ptolemy)
    }

    /// The item of the squared length from `s`, its parents collected first (an exact
    /// length's square is a leaf; a flip without one costs one unit of `budget`).
    fn collect<S: InputMetric + ?Sized>(
        &self,
        input: &S,
        s: Source,
        items: &mut Vec<Item>,
        index: &mut HashMap<Source, usize>,
        budget: &mut usize,
    ) -> Option<usize> {
        if let Some(&i) = index.get(&s) {
            return Some(i);
        }
        let item = match s {
            Source::Input(e) => Item::Leaf(input.exact(e).exact_square()?),
            Source::Flip(n) => match &self.nodes[n as usize].value {
                Value::Built(l) if l.exact_square().is_some() => Item::Leaf(l.exact_square()?),
                _ => {
                    *budget = budget.checked_sub(1)?;
                    let q = self.nodes[n as usize].quad.to_array();
                    let [a, b, c, d, e] = q.map(|p| self.collect(input, p, items, index, budget));
                    Item::Flip([a?, b?, c?, d?, e?])
                }
            },
        };
        items.push(item);
        index.insert(s, items.len() - 1);
        Some(items.len() - 1)
    }
}

/// Flips a sign decision may reach back through (one radical each, proof: B107).
pub const MAX_RADICALS: usize = 10;
/// The `f64` hull of a length in the rung's range (the eager replay's first rung).
fn hull(len: &Len) -> Option<Bounds> {
    f64_enclosure(len).and_then(|x| in_range([*x.lo(), *x.hi()]))
}

/// The `f64` bounds `[lo, hi]` as an MPFR enclosure at precision `p` (exact: binary64
/// numbers are `p`-bit numbers for `p ≥ 53`).
fn enclosure_of(b: Bounds, p: Precision) -> Len {
    Len::Enclosed(Interval::new(
        Mpfr::from_f64(b[0], p),
        Mpfr::from_f64(b[1], p),
    ))
}
