//! Replaying a flip sequence on the *input* metric with certified arithmetic (proof: B80).
//!
//! A flip run in a rounded backend (`f64`, `Dd`, MPFR) certifies its result for the lengths
//! it stores, which are rounded flips of the input (B65). To certify the same triangulation
//! for the input metric itself, the recorded sequence is replayed here on exact lengths:
//! rational lengths stay rational under Ptolemy flips (T28), lengths given by rational
//! squares stay exact until a Euclidean flip, and everything else becomes an
//! outward-rounded MPFR enclosure (B62). Every flip must be certified not strictly Delaunay
//! (`D ≤ 0`) on the input metric at the time of its flip, so it is a legal step; a flip
//! certified `D = 0` (a cocircular tie) takes its new length by Ptolemy's theorem, exact
//! where the lengths are (B82). At the end every interior edge is classified: certified
//! strictly Delaunay, a certified tie, certified non-Delaunay, or undecided.
//!
//! The replay costs one sign and one new length per flip, and one sign per edge at the
//! end: linear in the length of the sequence plus the number of edges.

use super::flips::FlipKind;
use super::replay_dag::FlipDag;
use super::replay_input::InputMetric;
pub use super::replay_len::{
    f64_enclosure, from_q, new_length, positive, sign, sign_after_f64, tie_length, Enclosure, Len,
    EXACT_GUARD_BITS,
};
use crate::io::Metric;
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::{Quad, QuadEdges};
use crate::predicates::delaunay_widened::{sign_p, Bounds};
use crate::scalar::Sign;

/// Why a step of a replay is not a certified legal flip.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BrokenStep {
    /// The edge is not flippable in the replayed mesh.
    NotFlippable,
    /// The edge is certified strictly Delaunay (`D > 0`) on the input metric.
    StrictlyDelaunay,
    /// The sign of `D` is not decided at the replay's precision.
    Undecided,
    /// The new length could not be enclosed as positive.
    NoLength,
}

/// The lengths of a lazy replay ([`replay_lazy`]): the flip DAG, each flip's length built
/// only when a sign needs it (proof: B85); every other edge keeps its input length.
pub type FlippedLens = FlipDag;

/// The outcome of [`replay_on_input`] (lengths `L = Vec<Len>`, one per edge) or of
/// [`replay_lazy`] (`L =` [`FlippedLens`]).
#[derive(Clone, Debug)]
pub struct Replayed<L = Vec<Len>> {
    /// The triangulation after the replayed flips (all of them when `broken` is `None`).
    pub mesh: Mesh,
    /// Its lengths for the input metric: exact or enclosed.
    pub lens: L,
    /// The first step that is not a certified legal flip, with its index and edge; the
    /// replay stops there and the triangulation is then not certified for the input.
    pub broken: Option<(usize, Edge, BrokenStep)>,
    /// Interior edges certified `D = 0` (ties) at the end (empty when `broken`).
    pub ties: Vec<Edge>,
    /// Interior edges certified `D < 0` at the end (empty when `broken`).
    pub negative: Vec<Edge>,
    /// Interior edges whose sign is not decided at the end (empty when `broken`).
    pub undecided: Vec<Edge>,
}

impl<L> Replayed<L> {
    /// Whether the replayed triangulation is certified intrinsic Delaunay for the input
    /// metric: every step legal and every interior edge certified `D ≥ 0`.
    pub fn certified_delaunay(&self) -> bool {
        self.broken.is_none() && self.negative.is_empty() && self.undecided.is_empty()
    }
    /// Whether a sign or a length was left open (an undecided step, a length not
    /// enclosed, an undecided edge at the end): more bits may decide it.
    fn open(&self) -> bool {
        matches!(
            self.broken,
            Some((_, _, BrokenStep::Undecided | BrokenStep::NoLength))
        ) || !self.undecided.is_empty()
    }
}

impl Replayed<FlippedLens> {
    /// Every edge's length in the eager replay's form: the flipped ones' (built now), the
    /// input's for the others.
    pub fn materialized<S: InputMetric + ?Sized>(self, input: &S) -> Replayed {
        let Replayed {
            mesh,
            lens,
            broken,
            ties,
            negative,
            undecided,
        } = self;
        Replayed {
            mesh,
            lens: lens.materialize(input),
            broken,
            ties,
            negative,
            undecided,
        }
    }
}

/// The lengths during a lazy replay: the first-rung enclosures of all edges (B83, B85) and
/// the flip DAG over the input.
struct Lazy<'a, S: ?Sized> {
    input: &'a S,
    first: Vec<Option<Bounds>>,
    dag: FlipDag,
}

impl<S: InputMetric + ?Sized> Lazy<'_, S> {
    /// The certified sign of `D` on the quadrilateral `q`: the first rung on `f64`
    /// enclosures (B83, B85), then the eager replay's rungs on the built lengths.
    fn sign(&mut self, q: Quad<Edge>) -> Option<Sign> {
        if let [Some(a), Some(b), Some(c), Some(d), Some(e)] =
            q.map(|e| self.first[e.idx()]).to_array()
        {
            if let Some(s) = sign_p([a, b, c, d, e]) {
                return Some(s);
            }
        }
        self.dag.sign_open(self.input, q, &self.first)
    }
}

/// Replay `sequence` (flips of `kind`) on `mesh` with the exact `metric` at `bits` bits
/// (module docs; proof: B80).
pub fn replay_on_input(
    mesh: &Mesh,
    metric: &Metric,
    sequence: &[Edge],
    kind: FlipKind,
    bits: u32,
) -> Replayed {
    replay_lazy(mesh, metric, sequence, kind, bits).materialized(metric)
}

/// [`replay_on_input`] on any [`InputMetric`], building exact lengths only for the edges
/// a sign or a flip needs them for (the first rung decides the rest, proof: B83), and the
/// new length of a flip as an `f64` enclosure by its formula first, exact or MPFR only
/// when a sign stays open on the enclosures ([`FlipDag`], proof: B85); the verdicts are
/// those of [`replay_on_input`] on the same metric.
pub fn replay_lazy<S: InputMetric + ?Sized>(
    mesh: &Mesh,
    input: &S,
    sequence: &[Edge],
    kind: FlipKind,
    bits: u32,
) -> Replayed<FlippedLens> {
    let ptolemy = kind == FlipKind::Ptolemy;
    let mut mesh = mesh.clone();
    let out = |mesh: Mesh, lens: FlippedLens, broken| Replayed {
        mesh,
        lens,
        broken,
        ties: Vec::new(),
        negative: Vec::new(),
        undecided: Vec::new(),
    };
    if input.n_edges() != mesh.n_edges() {
        let e = Edge(0);
        let dag = FlipDag::new(mesh.n_edges(), ptolemy, bits);
        return out(mesh, dag, Some((0, e, BrokenStep::NoLength)));
    }
    let mut lens = Lazy {
        input,
        first: mesh.edges().map(|e| input.first_rung(e)).collect(),
        dag: FlipDag::new(mesh.n_edges(), ptolemy, bits),
    };
    for (n, &e) in sequence.iter().enumerate() {
        let Some(q) = (e.idx() < mesh.n_edges())
            .then(|| QuadEdges::of(&mesh, e))
            .flatten()
        else {
            return out(mesh, lens.dag, Some((n, e, BrokenStep::NotFlippable)));
        };
        let tie = match lens.sign(q.edges) {
            Some(Sign::Zero) => true,
            Some(Sign::Negative) => false,
            Some(Sign::Positive) => {
                return out(mesh, lens.dag, Some((n, e, BrokenStep::StrictlyDelaunay)))
            }
            None => return out(mesh, lens.dag, Some((n, e, BrokenStep::Undecided))),
        };
        // The new length, lazy where the f64 flip formula encloses it (proof: B85).
        let corners = Some(mesh.quad_vertices(e));
        let Some(first) = lens.dag.flip(input, e, q.edges, corners, tie, &lens.first) else {
            return out(mesh, lens.dag, Some((n, e, BrokenStep::NoLength)));
        };
        if mesh.flip(e).is_err() {
            return out(mesh, lens.dag, Some((n, e, BrokenStep::NotFlippable)));
        }
        lens.first[e.idx()] = first;
    }
    let (mut ties, mut negative, mut undecided) = (Vec::new(), Vec::new(), Vec::new());
    for e in mesh.edges() {
        let Some(q) = QuadEdges::of(&mesh, e) else {
            continue;
        };
        match lens.sign(q.edges) {
            Some(Sign::Positive) => {}
            Some(Sign::Zero) => ties.push(e),
            Some(Sign::Negative) => negative.push(e),
            None => undecided.push(e),
        }
    }
    Replayed {
        mesh,
        lens: lens.dag,
        broken: None,
        ties,
        negative,
        undecided,
    }
}

/// [`replay_on_input`] from `start_bits`, doubling up to `max_bits` while a sign or a length
/// is open (an undecided step, a length not enclosed, an undecided edge at the end); the
/// last replay and its precision.
pub fn replay_escalating(
    mesh: &Mesh,
    metric: &Metric,
    sequence: &[Edge],
    kind: FlipKind,
    start_bits: u32,
    max_bits: u32,
) -> (Replayed, u32) {
    let (r, bits) = replay_escalating_lazy(mesh, metric, sequence, kind, start_bits, max_bits);
    (r.materialized(metric), bits)
}

/// [`replay_escalating`] with [`replay_lazy`] on any [`InputMetric`].
pub fn replay_escalating_lazy<S: InputMetric + ?Sized>(
    mesh: &Mesh,
    input: &S,
    sequence: &[Edge],
    kind: FlipKind,
    start_bits: u32,
    max_bits: u32,
) -> (Replayed<FlippedLens>, u32) {
    let mut bits = start_bits.max(53);
    loop {
        let r = replay_lazy(mesh, input, sequence, kind, bits);
        let next = bits.saturating_mul(2);
        if !r.open() || next > max_bits {
            return (r, bits);
        }
        bits = next;
    }
}
