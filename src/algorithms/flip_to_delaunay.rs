//! Flip to an intrinsic Delaunay triangulation (notes §1.5.2; docs/catalogue.md §5), deciding every
//! edge with the certified predicate of [`crate::predicates::delaunay`] — never with a raw
//! floating-point comparison.
//!
//! The algorithm keeps a work list of edges. An edge is flipped only when its sign is
//! certified `Negative`; the new diagonal is accepted only when *its* sign, computed on
//! the stored new length, is certified `Positive` or `Zero`. Near a tie the rounded new
//! length can land on the wrong side; since `P` of the new edge decreases with its length
//! and the exact new diagonal is strictly Delaunay, the stored length is then shrunk by
//! `4u` relative, at most [`MAX_NUDGES`] times (proof: B65; counted in
//! [`FlipReport::nudged`]). If that does not certify it, the flip is undone
//! and the edge reported in [`FlipReport::refused`]. A Euclidean flip is also undone when its
//! two new faces are not certified non-degenerate triangles for the stored lengths (proof:
//! B66). After a flip the four sides of the quadrilateral are re-queued. When the list is empty every edge not listed in
//! [`FlipReport::undecided`] or [`FlipReport::refused`] is certified Delaunay for the
//! stored lengths (T21). A cap on the number of flips (default `64·E + 1024`) bounds the
//! run even if rounding of new lengths were to create a cycle; hitting it is reported.
//!
//! While every stored length is a binary64 number in the filter's range (B61), the edge
//! test and, when the edge is flipped, the new length, the test of the new edge and the
//! triangle test run in one pass on values held in registers (`RealMetric::fast_step`);
//! whatever that pass does not certify goes through the general path above.
//!
//! # What is certified
//!
//! Exactly this (proof: B65): for the lengths *returned* in the slice, every edge not
//! listed in [`FlipReport::undecided`] or [`FlipReport::refused`] is Delaunay (`P ≥ 0`),
//! unless [`FlipReport::hit_cap`] is set, and after Euclidean flips every face created by a
//! flip is a non-degenerate triangle (proof: B66). The returned lengths are the input lengths on
//! edges never flipped; on a flipped edge they are the flip formula evaluated in the
//! backend's arithmetic (so rounded in `f64`/`Dd`/`Mpfr`), and on the
//! [`FlipReport::nudged`] flips that value shrunk by at most [`MAX_NUDGES`] steps
//! `ℓ ← fl(ℓ − fl(4u·ℓ))` (at most `40u` relative in all). The certificate is about the
//! returned metric, not about the exact flips of the input metric. Exact Ptolemy flipping
//! over ℚ ([`flip_to_delaunay_exact`]) has no rounding and no nudge until the bit-growth
//! guard is passed, after which it continues on outward-rounded MPFR enclosures.
//!
//!
//! ```
//! use penner::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
//! use penner::mesh::Mesh;
//! // A thin rhombus split along its long diagonal: not Delaunay, one flip fixes it.
//! let mut m = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
//! let mut l: Vec<f64> = m.edges().map(|e| {
//!     let h = e.halfedge();
//!     let (a, b) = (m.tail(h).0, m.tip(h).0);
//!     if a.min(b) == 0 && a.max(b) == 2 { 1.9 } else { 1.0 }
//! }).collect();
//! let r = flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &FlipOptions::default()).unwrap();
//! assert_eq!(r.flips, 1);
//! assert!(r.all_certified_delaunay());
//! ```

pub use super::flips::FlipKind;
use super::flips::{
    euclidean_length, moderate_f64, ptolemy_length, ptolemy_length_enclosure, ptolemy_length_exact,
};
use crate::mesh::{Edge, Face, Mesh};
use crate::predicates::delaunay::{
    check_length, f64_exact, filter_f64_in_range, in_filter_range, DelaunayError, EnclosureQuad,
    Quad, QuadEdges, RationalQuad, RealQuad,
};
use crate::predicates::ladder::{decide, Ladder, SignPredicate};
use crate::predicates::triangle::{strict_triangle_f64, strict_triangle_real};
use crate::scalar::{Certified, Interval, Mpfr, Precision, Real, Sign, Stage};
use rug::Rational;
use std::sync::atomic::{AtomicUsize, Ordering as AtomicOrdering};
use std::sync::Arc;

/// At most this many times a rounded new diagonal is replaced by `fl(ℓ − fl(4u·ℓ))`
/// (a relative decrease in `[3u, 5u]`) before a flip is refused (proof: B65).
pub const MAX_NUDGES: usize = 8;

/// Options of [`flip_to_delaunay`] (default: [`Ladder::default`], cap `64·E + 1024`,
/// edge order, no recording).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FlipOptions {
    /// The ladder for every decision.
    pub ladder: Ladder,
    /// Stop after this many flips (default `64·E + 1024`).
    pub max_flips: Option<usize>,
    /// Visit the edges in a random order drawn from this seed (default: edge order).
    pub order_seed: Option<u64>,
    /// Record the flipped edges in order in [`FlipReport::sequence`].
    pub record: bool,
    /// A counter of the flips done, which another thread may read for a progress display.
    pub progress: Option<FlipCounter>,
}

/// A shared count of flips done (relaxed atomic increments; read for display only).
#[derive(Clone, Debug, Default)]
pub struct FlipCounter(pub Arc<AtomicUsize>);

impl FlipCounter {
    /// The flips counted so far.
    pub fn get(&self) -> usize {
        self.0.load(AtomicOrdering::Relaxed)
    }
}

impl PartialEq for FlipCounter {
    /// The same counter.
    fn eq(&self, other: &FlipCounter) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

/// How many decisions each rung of the ladder made.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct StageCounts {
    /// Decided by the f64 filter.
    pub filter: usize,
    /// Decided by an MPFR enclosure.
    pub interval: usize,
    /// Decided in exact arithmetic.
    pub exact: usize,
    /// Not decided.
    pub undecided: usize,
}

impl StageCounts {
    fn record(&mut self, c: &Certified<Sign>) {
        match c {
            Certified::Known {
                stage: Stage::Filter,
                ..
            } => self.filter += 1,
            Certified::Known {
                stage: Stage::Interval { .. },
                ..
            } => self.interval += 1,
            Certified::Known {
                stage: Stage::Exact,
                ..
            } => self.exact += 1,
            Certified::Undecided { .. } => self.undecided += 1,
        }
    }
}

/// What [`flip_to_delaunay`] did.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct FlipReport {
    /// Flips performed.
    pub flips: usize,
    /// Edges whose sign no rung could decide at the end (sorted).
    pub undecided: Vec<Edge>,
    /// Edges certified non-Delaunay whose flip was undone because the new diagonal could
    /// not be certified Delaunay on its stored length, or (Euclidean flips) its two new
    /// faces could not be certified non-degenerate triangles (sorted).
    pub refused: Vec<Edge>,
    /// Whether the flip cap stopped the run (then edges may remain unchecked).
    pub hit_cap: bool,
    /// Decisions per rung.
    pub stages: StageCounts,
    /// Exact path only: the largest bit size (numerator + denominator) of a length seen.
    pub max_bits: u64,
    /// Exact path only: the flip count at which the bit guard switched to enclosures.
    pub fell_back_after: Option<usize>,
    /// Flips whose rounded new length was shrunk by at most [`MAX_NUDGES`] steps of
    /// `ℓ ← fl(ℓ − fl(4u·ℓ))` so that the new diagonal is certified Delaunay: the returned
    /// metric differs there from the rounded flip by at most `40u` relative (proof: B65).
    pub nudged: usize,
    /// The flipped edges in order, when [`FlipOptions::record`] is set.
    pub sequence: Vec<Edge>,
}

impl FlipReport {
    /// Whether every edge ended certified Delaunay.
    pub fn all_certified_delaunay(&self) -> bool {
        self.undecided.is_empty() && self.refused.is_empty() && !self.hit_cap
    }
}

/// Why flipping could not start.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FlipToDelaunayError {
    /// A length is invalid or the length array has the wrong size.
    #[error(transparent)]
    Lengths(#[from] DelaunayError),
}

/// Per-edge lengths together with how to decide and how to flip them.
pub(super) trait Metric {
    /// The old length of a flipped edge, kept to undo the flip.
    type Saved;
    /// The first rung alone (a proven `f64` filter), `None` when it does not decide.
    fn filter(&self, _q: Quad<Edge>) -> Option<Sign> {
        None
    }
    /// The whole ladder.
    fn sign(&self, q: Quad<Edge>, ladder: &Ladder) -> Certified<Sign>;
    /// Compute the new diagonal length, store it, and return the old one (`None` if the
    /// new length is invalid; nothing is stored then).
    fn flip_length(&mut self, q: &QuadEdges) -> Option<Self::Saved>;
    fn restore(&mut self, e: Edge, old: Self::Saved);
    /// Shrink the stored length of `e` by a few units of rounding (see [`MAX_NUDGES`]);
    /// `false` where lengths are exact.
    fn nudge(&mut self, _e: Edge) -> bool {
        false
    }
    /// Called after an accepted flip.
    fn accepted(&mut self, _flips: usize) {}
    /// Whether the two triangles of the flipped quadrilateral `q.flipped()` are certified
    /// non-degenerate triangles for the stored lengths (Euclidean flips only: Ptolemy
    /// lengths need not satisfy the triangle inequality; proof: B66).
    fn new_triangles_valid(&self, _q: &QuadEdges, _ladder: &Ladder) -> bool {
        true
    }
    /// The whole test-and-flip step in one pass where a fast path applies: `Some(Kept)`
    /// when the filter certifies `e` Delaunay, `Some(Flipped(old))` when it certifies `e`
    /// non-Delaunay and the new length is stored, certified Delaunay and (Euclidean)
    /// certified to form two non-degenerate triangles; `None` (nothing stored) sends the
    /// edge to the general path.
    fn fast_step(&mut self, _q: &QuadEdges) -> Option<FastStep<Self::Saved>> {
        None
    }
}

/// The outcome of [`Metric::fast_step`].
pub(super) enum FastStep<S> {
    /// The edge is certified Delaunay by the filter.
    Kept,
    /// The edge was certified non-Delaunay and its new length stored (the old one kept).
    Flipped(S),
}

/// Per-edge state of the driver, one byte per edge so that an edge test touches one
/// cache line of it.
const QUEUED: u8 = 1;
const UNDECIDED: u8 = 2;
const REFUSED: u8 = 4;

/// The certified sign of `P` on `q`: the filter inline, the rest of the ladder out of
/// line; every decision is counted in `stages`.
#[allow(clippy::inline_always)] // hot path of the flip loop (measured)
#[inline(always)]
fn certified_sign<M: Metric>(
    m: &M,
    q: Quad<Edge>,
    ladder: &Ladder,
    stages: &mut StageCounts,
) -> Option<Sign> {
    if let Some(s) = m.filter(q) {
        stages.filter += 1;
        return Some(s);
    }
    let c = m.sign(q, ladder);
    stages.record(&c);
    c.value()
}

/// The driver shared by every length type.
pub(super) fn run<M: Metric>(mesh: &mut Mesh, m: &mut M, opts: &FlipOptions) -> FlipReport {
    let ne = mesh.n_edges();
    let cap = opts.max_flips.unwrap_or(64 * ne + 1024);
    let mut report = FlipReport::default();
    // Edges the fast path certified Delaunay (a local, so that it stays in a register).
    let mut fast_kept = 0usize;
    let mut state = vec![QUEUED; ne];
    // Whether any edge was ever marked undecided or refused (else the final scan is moot).
    let mut flags_set = false;
    let mut stack: Vec<Edge> = (0..ne as u32).rev().map(Edge).collect();
    if let Some(seed) = opts.order_seed {
        use rand::seq::SliceRandom;
        use rand::SeedableRng;
        stack.shuffle(&mut rand_chacha::ChaCha8Rng::seed_from_u64(seed));
    }
    while let Some(e) = stack.pop() {
        let Some(q) = QuadEdges::of(mesh, e) else {
            state[e.idx()] = 0;
            continue;
        };
        state[e.idx()] = 0;
        match m.fast_step(&q) {
            Some(FastStep::Kept) => {
                fast_kept += 1;
                continue;
            }
            Some(FastStep::Flipped(saved)) => {
                if report.flips >= cap {
                    m.restore(e, saved);
                    report.hit_cap = true;
                    break;
                }
                {
                    // The old edge and the new one, both by the filter.
                    report.stages.filter += 2;
                    if mesh.flip(e).is_ok() {
                        accept(m, &q, &mut state, &mut stack, &mut report, opts);
                    } else {
                        // Cannot happen: `QuadEdges::of` succeeded, so `e` is flippable.
                        m.restore(e, saved);
                        state[e.idx()] = REFUSED;
                        flags_set = true;
                    }
                    continue;
                }
            }
            None => {}
        }
        match certified_sign(m, q.edges, &opts.ladder, &mut report.stages) {
            None => {
                state[e.idx()] = UNDECIDED;
                flags_set = true;
                continue;
            }
            Some(Sign::Positive | Sign::Zero) => continue,
            Some(Sign::Negative) => {}
        }
        if report.flips >= cap {
            report.hit_cap = true;
            break;
        }
        let Some(saved) = m.flip_length(&q) else {
            state[e.idx()] = REFUSED;
            flags_set = true;
            continue;
        };
        let mut nudges = 0;
        let accepted = loop {
            match certified_sign(m, q.flipped(), &opts.ladder, &mut report.stages) {
                Some(Sign::Positive | Sign::Zero) => break true,
                // Rounded new length on the wrong side of a near-tie: the exact new
                // diagonal is strictly Delaunay and `P` decreases with its length.
                Some(Sign::Negative) if nudges < MAX_NUDGES && m.nudge(e) => nudges += 1,
                _ => break false,
            }
        };
        report.nudged += usize::from(nudges > 0);
        if !accepted || !m.new_triangles_valid(&q, &opts.ladder) || mesh.flip(e).is_err() {
            // `mesh.flip` cannot fail here: `QuadEdges::of` succeeded, so the edge is
            // flippable; undo the length either way.
            m.restore(e, saved);
            state[e.idx()] = REFUSED;
            flags_set = true;
            continue;
        }
        accept(m, &q, &mut state, &mut stack, &mut report, opts);
    }
    report.stages.filter += fast_kept;
    if flags_set {
        report.undecided = flagged(&state, UNDECIDED);
        report.refused = flagged(&state, REFUSED);
    }
    report
}

/// Book-keeping after the flip of `q.edge` was accepted: count and record it, tell the
/// metric, and queue the four sides of the quadrilateral.
#[allow(clippy::inline_always)] // hot path of the flip loop (measured)
#[inline(always)]
fn accept<M: Metric>(
    m: &mut M,
    q: &QuadEdges,
    state: &mut [u8],
    stack: &mut Vec<Edge>,
    report: &mut FlipReport,
    opts: &FlipOptions,
) {
    report.flips += 1;
    if opts.record {
        report.sequence.push(q.edge);
    }
    if let Some(c) = &opts.progress {
        c.0.fetch_add(1, AtomicOrdering::Relaxed);
    }
    m.accepted(report.flips);
    for side in [q.edges.jk, q.edges.ki, q.edges.il, q.edges.lj] {
        let st = &mut state[side.idx()];
        if *st & QUEUED == 0 {
            *st |= QUEUED;
            stack.push(side);
        }
    }
}

fn flagged(state: &[u8], flag: u8) -> Vec<Edge> {
    state
        .iter()
        .enumerate()
        .filter(|&(_, &f)| f & flag != 0)
        .map(|(i, _)| Edge(i as u32))
        .collect()
}

/// Validate the lengths; `Ok(true)` when the backend has 53 bits and every length is in
/// the f64 filter's unscaled range (then the filter may skip its range test).
fn check_all<T: Real>(mesh: &Mesh, lengths: &[T]) -> Result<bool, DelaunayError> {
    if lengths.len() != mesh.n_edges() {
        return Err(DelaunayError::LengthCount {
            expected: mesh.n_edges(),
            got: lengths.len(),
        });
    }
    // Fast path for 53-bit backends: every image finite and positive (the test of
    // `check_length`); otherwise find the offending edge.
    let f53 = lengths.first().is_some_and(|l| f64_exact::<T>(l.ctx()));
    if f53 && lengths.iter().all(|l| in_filter_range(l.approx_f64())) {
        return Ok(true);
    }
    if f53
        && lengths.iter().all(|l| {
            let x = l.approx_f64();
            x > 0.0 && x < f64::INFINITY
        })
    {
        return Ok(false);
    }
    for e in mesh.edges() {
        check_length(e, &lengths[e.idx()])?;
    }
    Ok(false)
}

/// The side lengths of the two faces `lki` and `klj` of the flipped quadrilateral `q`
/// (roles of [`QuadEdges::flipped`]: the new edge first).
pub(super) fn new_faces<'a, L>(q: &QuadEdges, lengths: &'a [L]) -> [[&'a L; 3]; 2] {
    let f = q.flipped().map(|e| &lengths[e.idx()]);
    [[f.ij, f.jk, f.ki], [f.ij, f.il, f.lj]]
}

/// Refuse a metric on which Euclidean flips are meaningless: the first face that `strict`
/// does not certify to be a non-degenerate triangle.
pub(super) fn check_faces(
    mesh: &Mesh,
    strict: impl Fn(Face) -> Certified<bool>,
) -> Result<(), DelaunayError> {
    match mesh.faces().find(|&f| strict(f).value() != Some(true)) {
        Some(face) => Err(DelaunayError::NotATriangle { face }),
        None => Ok(()),
    }
}

struct RealMetric<'a, T> {
    lengths: &'a mut [T],
    kind: FlipKind,
    /// Invariant while `true`: the backend has 53 bits and every stored length is an f64
    /// in [`in_filter_range`], so the filter needs no range test (proof: B61). Cleared
    /// when a new or nudged length leaves the range.
    in_range: bool,
}

impl<T: Real> RealMetric<'_, T> {
    /// Keep the `in_range` invariant after storing `x`.
    #[inline]
    fn stored(&mut self, x: f64) {
        self.in_range &= in_filter_range(x);
    }

    /// The flip of the fast path, for an edge the filter certified non-Delaunay with the
    /// binary64 lengths `[a, b, c, d, e]` of its quadrilateral: the new length, the test of
    /// the new edge and (Euclidean) of its two faces, then the store; `None` (nothing
    /// stored) sends the edge to the general path.
    fn fast_flip(&mut self, edge: Edge, l: [f64; 5]) -> Option<FastStep<T>> {
        let [a, b, c, d, e] = l;
        let quad = Quad {
            ij: &a,
            jk: &b,
            ki: &c,
            il: &d,
            lj: &e,
        };
        // The same formulas as `flip_length`, in binary64: correctly rounded 53-bit
        // arithmetic without overflow or underflow (lengths in 2^±100 for the Euclidean
        // formula, 2^±200 for Ptolemy's) gives the same bits in every 53-bit backend.
        let new = match self.kind {
            FlipKind::Euclidean => {
                if !l.into_iter().all(moderate_f64) {
                    return None;
                }
                euclidean_length(quad)
            }
            FlipKind::Ptolemy => ptolemy_length(quad),
        };
        if !in_filter_range(new) {
            return None;
        }
        // The new edge `kl` in the roles `[kl, ki, il, lj, jk]` of `QuadEdges::flipped`.
        if filter_f64_in_range([new, c, d, e, b]) != Some(Sign::Positive) {
            return None;
        }
        // proof: B66 — faces `lki` and `klj` are non-degenerate for the stored lengths.
        if self.kind == FlipKind::Euclidean
            && !(strict_triangle_f64(new, c, d) && strict_triangle_f64(new, e, b))
        {
            return None;
        }
        let ctx = self.lengths[edge.idx()].ctx();
        let old = std::mem::replace(&mut self.lengths[edge.idx()], T::from_f64(new, ctx));
        Some(FastStep::Flipped(old))
    }
}

impl<T: Real> Metric for RealMetric<'_, T> {
    type Saved = T;
    #[allow(clippy::inline_always)] // hot path of the flip loop (measured)
    #[inline(always)]
    fn filter(&self, q: Quad<Edge>) -> Option<Sign> {
        let l = q.map(|e| &self.lengths[e.idx()]);
        if self.in_range {
            // 53-bit values in the f64 range are f64 numbers exactly.
            filter_f64_in_range(l.to_array().map(Real::approx_f64))
        } else {
            RealQuad(l).filter()
        }
    }
    fn sign(&self, q: Quad<Edge>, ladder: &Ladder) -> Certified<Sign> {
        decide(&RealQuad(q.map(|e| &self.lengths[e.idx()])), ladder)
    }
    fn flip_length(&mut self, q: &QuadEdges) -> Option<T> {
        let quad = q.lengths(self.lengths);
        let new = match self.kind {
            FlipKind::Euclidean => euclidean_length(quad),
            FlipKind::Ptolemy => ptolemy_length(quad),
        };
        check_length(q.edge, &new).ok()?;
        self.stored(new.approx_f64());
        Some(std::mem::replace(&mut self.lengths[q.edge.idx()], new))
    }
    fn restore(&mut self, e: Edge, old: T) {
        self.lengths[e.idx()] = old;
    }
    fn new_triangles_valid(&self, q: &QuadEdges, ladder: &Ladder) -> bool {
        if self.kind == FlipKind::Ptolemy {
            return true;
        }
        // proof: B66
        new_faces(q, self.lengths)
            .iter()
            .all(|&t| strict_triangle_real(t, ladder).value() == Some(true))
    }
    #[allow(clippy::inline_always)] // hot path of the flip loop (measured)
    #[inline(always)]
    fn fast_step(&mut self, q: &QuadEdges) -> Option<FastStep<T>> {
        if !self.in_range {
            return None;
        }
        // 53-bit values in the f64 range are f64 numbers exactly (proof: B61).
        let l = q
            .edges
            .map(|e| self.lengths[e.idx()].approx_f64())
            .to_array();
        match filter_f64_in_range(l)? {
            Sign::Positive | Sign::Zero => Some(FastStep::Kept),
            // Out of line, with the lengths by value: the common (kept) case then holds
            // nothing in memory for the flip.
            Sign::Negative => self.fast_flip(q.edge, l),
        }
    }
    fn nudge(&mut self, e: Edge) -> bool {
        let l = &mut self.lengths[e.idx()];
        // proof: B65 — one step decreases the stored value by 3u to 5u relative. Past 1000
        // bits 4u = 2^(2−p) is below the f64 range: the step is then an exact shift
        // (MPFR's ldexp has no range limit).
        let bits = T::precision_bits(l.ctx());
        let step = if bits <= 1000 {
            l.clone() * &l.lit(4.0 * T::unit_roundoff(l.ctx()))
        } else {
            let mut s = l.clone();
            s.ldexp_assign(2 - bits as i32);
            s
        };
        *l -= &step;
        let x = l.approx_f64();
        self.stored(x);
        true
    }
}

/// Flip `mesh` to an intrinsic Delaunay triangulation of the metric `lengths` (one per
/// edge) with Euclidean or Ptolemy flips (T21). Works on closed surfaces and surfaces with
/// boundary; boundary edges and self-folded edges are never flipped. Euclidean flips need
/// a Euclidean metric: a face not certified to be a non-degenerate triangle is refused
/// ([`DelaunayError::NotATriangle`]); Ptolemy flips accept any positive lengths.
pub fn flip_to_delaunay<T: Real>(
    mesh: &mut Mesh,
    lengths: &mut [T],
    kind: FlipKind,
    opts: &FlipOptions,
) -> Result<FlipReport, FlipToDelaunayError> {
    let in_range = check_all(mesh, lengths)?;
    if kind == FlipKind::Euclidean {
        // proof: B66 — while every stored length is a binary64 number in range, one
        // rounded sum and difference per face certify it; the general test finds the face.
        let fast = in_range
            && mesh.faces().all(|f| {
                let [a, b, c] = mesh
                    .face_halfedges(f)
                    .map(|h| lengths[h.edge().idx()].approx_f64());
                strict_triangle_f64(a, b, c)
            });
        if !fast {
            check_faces(mesh, |f| {
                let [a, b, c] = mesh.face_halfedges(f).map(|h| &lengths[h.edge().idx()]);
                strict_triangle_real([a, b, c], &opts.ladder)
            })?;
        }
    }
    let mut m = RealMetric {
        lengths,
        kind,
        in_range,
    };
    Ok(run(mesh, &mut m, opts))
}

/// Rational lengths, or enclosures once the bit-growth guard is passed.
#[derive(Clone, Debug)]
pub enum ExactLengths {
    /// Exact lengths.
    Exact(Vec<Rational>),
    /// Outward-rounded enclosures of the exact lengths.
    Enclosed(Vec<Interval<Mpfr>>),
}

/// Bit size of a rational: significant bits of numerator plus denominator.
pub fn rational_bits(q: &Rational) -> u64 {
    u64::from(q.numer().significant_bits()) + u64::from(q.denom().significant_bits())
}

struct ExactMetric {
    lengths: ExactLengths,
    guard_bits: u64,
    max_bits: u64,
    fell_back_after: Option<usize>,
}

impl ExactMetric {
    fn enclosure_precision(&self) -> Precision {
        // Enough to hold the guard-sized rationals tightly, at least 128 bits.
        Precision::new(self.guard_bits.saturating_mul(2).clamp(128, 1 << 14))
            .expect("128 to 16384 bits is within MPFR's precision range")
    }
}

/// An old length on the exact path.
enum ExactSaved {
    Exact(Rational),
    Enclosed(Interval<Mpfr>),
}

impl Metric for ExactMetric {
    type Saved = ExactSaved;
    fn sign(&self, q: Quad<Edge>, ladder: &Ladder) -> Certified<Sign> {
        match &self.lengths {
            ExactLengths::Exact(l) => decide(&RationalQuad(q.map(|e| &l[e.idx()])), ladder),
            ExactLengths::Enclosed(l) => EnclosureQuad(q.map(|e| &l[e.idx()])).decide_once(),
        }
    }
    fn flip_length(&mut self, q: &QuadEdges) -> Option<ExactSaved> {
        match &mut self.lengths {
            ExactLengths::Exact(l) => {
                let new = ptolemy_length_exact(q.lengths(l));
                self.max_bits = self.max_bits.max(rational_bits(&new));
                Some(ExactSaved::Exact(std::mem::replace(
                    &mut l[q.edge.idx()],
                    new,
                )))
            }
            ExactLengths::Enclosed(l) => {
                let new = ptolemy_length_enclosure(q.lengths(l))?;
                if new.sign() != Some(Sign::Positive) {
                    return None;
                }
                Some(ExactSaved::Enclosed(std::mem::replace(
                    &mut l[q.edge.idx()],
                    new,
                )))
            }
        }
    }
    fn restore(&mut self, e: Edge, old: ExactSaved) {
        match (&mut self.lengths, old) {
            (ExactLengths::Exact(l), ExactSaved::Exact(o)) => l[e.idx()] = o,
            (ExactLengths::Enclosed(l), ExactSaved::Enclosed(o)) => l[e.idx()] = o,
            // A fall-back happens only after an accepted flip, never between a flip and
            // its undo; keep the current value otherwise.
            _ => {}
        }
    }
    fn accepted(&mut self, flips: usize) {
        if self.fell_back_after.is_none() && self.max_bits > self.guard_bits {
            let prec = self.enclosure_precision();
            if let ExactLengths::Exact(l) = &self.lengths {
                let enc = l.iter().map(|q| Interval::from_rational(q, prec)).collect();
                self.lengths = ExactLengths::Enclosed(enc);
                self.fell_back_after = Some(flips);
            }
        }
    }
}

/// Exact Ptolemy flipping over ℚ (rational lengths stay rational, T28). When a length
/// exceeds `guard_bits` (numerator + denominator bits) the run continues on MPFR
/// enclosures at `2·guard_bits` bits (at least 128), rounded outward, and says so in
/// [`FlipReport::fell_back_after`]; [`FlipReport::max_bits`] reports the growth. An edge
/// decided exactly (possibly a tie, `P = 0`) before the fall-back and not touched after it
/// stays certified, though re-deciding it on the returned enclosures may give `Undecided`:
/// the enclosures cannot express an exact zero.
pub fn flip_to_delaunay_exact(
    mesh: &mut Mesh,
    lengths: Vec<Rational>,
    guard_bits: u64,
    opts: &FlipOptions,
) -> Result<(FlipReport, ExactLengths), FlipToDelaunayError> {
    if lengths.len() != mesh.n_edges() {
        return Err(DelaunayError::LengthCount {
            expected: mesh.n_edges(),
            got: lengths.len(),
        }
        .into());
    }
    for e in mesh.edges() {
        if lengths[e.idx()] <= 0 {
            return Err(DelaunayError::BadLength {
                edge: e,
                value: lengths[e.idx()].to_f64(),
            }
            .into());
        }
    }
    let max_bits = lengths.iter().map(rational_bits).max().unwrap_or(0);
    let mut m = ExactMetric {
        lengths: ExactLengths::Exact(lengths),
        guard_bits,
        max_bits,
        fell_back_after: None,
    };
    m.accepted(0);
    let mut report = run(mesh, &mut m, opts);
    report.max_bits = m.max_bits;
    report.fell_back_after = m.fell_back_after;
    Ok((report, m.lengths))
}
