//! An *uncertified* baseline: flip to Delaunay deciding with the raw `f64` value of `P`
//! (`P < 0` ⇒ flip). It is what floating-point libraries do, kept for benchmarks (the cost
//! of certification) and for tests that show its decisions contradict exact arithmetic.
//! Its results are numerical (`certified: false`); nothing in the library relies on it.

use super::flips::{euclidean_length, ptolemy_length, FlipKind};
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::QuadEdges;

/// What the naive run did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NaiveReport {
    /// Flips performed.
    pub flips: usize,
    /// Whether the flip cap stopped the run (a floating-point flip loop).
    pub hit_cap: bool,
}

/// The raw `f64` value of `P = d·e·(b²+c²−a²) + b·c·(d²+e²−a²)` (no error bound).
#[inline]
pub fn naive_p(q: [f64; 5]) -> f64 {
    let [a, b, c, d, e] = q;
    let a2 = a * a;
    d * e * (b * b + c * c - a2) + b * c * (d * d + e * e - a2)
}

/// Flip while the raw `f64` value of `P` is negative, at most `max_flips` times.
pub fn flip_to_delaunay_naive(
    mesh: &mut Mesh,
    lengths: &mut [f64],
    kind: FlipKind,
    max_flips: usize,
) -> NaiveReport {
    let ne = mesh.n_edges();
    let mut report = NaiveReport::default();
    let mut queued = vec![true; ne];
    let mut stack: Vec<Edge> = (0..ne as u32).rev().map(Edge).collect();
    while let Some(e) = stack.pop() {
        queued[e.idx()] = false;
        let Some(q) = QuadEdges::of(mesh, e) else {
            continue;
        };
        let quad = q.lengths(lengths);
        if naive_p(quad.map(|x| *x).to_array()) >= 0.0 {
            continue;
        }
        if report.flips >= max_flips {
            report.hit_cap = true;
            break;
        }
        let new = match kind {
            FlipKind::Euclidean => euclidean_length(quad),
            FlipKind::Ptolemy => ptolemy_length(quad),
        };
        if mesh.flip(e).is_err() {
            continue;
        }
        lengths[e.idx()] = new;
        report.flips += 1;
        for side in [q.edges.jk, q.edges.ki, q.edges.il, q.edges.lj] {
            if !queued[side.idx()] {
                queued[side.idx()] = true;
                stack.push(side);
            }
        }
    }
    report
}
