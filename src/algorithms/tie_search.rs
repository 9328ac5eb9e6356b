//! The search over tie flips of a `delaunay_flip` claim (proof: B82).
//!
//! When our certified Delaunay triangulation has cocircular *ties* (interior edges with
//! `D = 0` certified, docs/catalogue.md §5 Eq. 13), the metric has several Delaunay triangulations:
//! the triangulations of the cells of its Delaunay tessellation (notes §1.5.2, T22). Any
//! two of them are joined by a sequence of tie flips, so a breadth-first search over tie
//! flips, starting from ours, reaches every one of them. Each reached triangulation is
//! certified again with the rules of B80 (every interior edge `D ≥ 0`, the ties the same
//! edge ids as at the start) and compared with the claimed `result` under every
//! vertex-fixing relabeling (B81).
//!
//! **Lengths.** A tie quadrilateral is cyclic, so by Ptolemy's theorem the Euclidean
//! flip of a tie gives the Ptolemy length `ℓ_kl = (ℓ_ki ℓ_lj + ℓ_il ℓ_jk)/ℓ_ij` (docs/catalogue.md
//! §5): rational on rational lengths, for both flip kinds. On lengths given by rational
//! squares, `ℓ_kl² = (s_ki s_lj + s_il s_jk + 2√(s_ki s_lj s_il s_jk))/s_ij` is rational when
//! the product under the root is a rational square; otherwise the new length is an
//! enclosure, the ties of its quadrilaterals cannot be certified, and the search is
//! incomplete.
//!
//! **Bounds.** At most [`MAX_TIES`] tie edges are searched and at most [`MAX_STATES`]
//! triangulations are visited. A match is `holds`; `refuted` needs the search to be
//! complete (every reachable triangulation visited and certified, every relabeling
//! compared); otherwise the answer is `undecided` with the reason.

use super::flip_replay::{compare, edge_name, finish, Compared, Ours, MAX_RELABELINGS};
use super::replay::{tie_length, Len};
use super::verdict::{ClaimVerdict, Witness};
use crate::io::json::edge_order;
use crate::io::Surface;
use crate::mesh::relabel::isomorphisms;
use crate::mesh::{Edge, HalfEdge, Mesh};
use crate::predicates::delaunay::QuadEdges;
use rug::Rational;
use std::collections::{HashMap, HashSet, VecDeque};

/// Most tie edges whose flips are searched; with more, the claim is `undecided`
/// (proof: B82). A cell with `m` corners has `m − 3` ties and Catalan(`m − 2`)
/// triangulations; `k` ties in separate quadrilaterals give `2^k` triangulations.
pub const MAX_TIES: usize = 16;

/// Most triangulations the search visits (`2^16`); past it the claim is `undecided`
/// (proof: B82).
pub const MAX_STATES: usize = 1 << 16;

/// The outcome of the search at one precision.
pub(crate) enum Search {
    /// A reached Delaunay triangulation matches the claim.
    Holds { max_discrepancy: Option<f64> },
    /// The search was complete and nothing matched.
    Refuted {
        max_discrepancy: Option<f64>,
        witnesses: Vec<Witness>,
    },
    /// Not decided; `retry` when more precision may settle a length comparison.
    Undecided {
        max_discrepancy: Option<f64>,
        witnesses: Vec<Witness>,
        retry: bool,
    },
}

/// The polygon corner of the Delaunay cell at the tail of `h`: the first half-edge of a
/// non-tie edge met by turning from `h` across tie edges (`h ← next(twin h)`, proof: B82).
fn corner(mesh: &Mesh, mut h: HalfEdge, tie: &[bool]) -> Option<u32> {
    for _ in 0..mesh.n_halfedges() {
        if !tie.get(h.edge().idx()).copied().unwrap_or(false) {
            return Some(h.0);
        }
        h = mesh.next(h.twin());
        if mesh.is_boundary_halfedge(h) {
            return None;
        }
    }
    None
}

/// A key that identifies the triangulation among those reached by tie flips: each face
/// as the sorted triple of its cell corners (proof: B82).
fn key(mesh: &Mesh, tie: &[bool]) -> Option<Vec<[u32; 3]>> {
    let mut faces = Vec::with_capacity(mesh.n_faces());
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_halfedges(f);
        let mut t = [
            corner(mesh, a, tie)?,
            corner(mesh, b, tie)?,
            corner(mesh, c, tie)?,
        ];
        t.sort_unstable();
        faces.push(t);
    }
    faces.sort_unstable();
    Some(faces)
}

/// Unordered vertex pairs of the edges of `mesh`, with multiplicity.
fn pair_counts(mesh: &Mesh) -> HashMap<(u32, u32), usize> {
    let mut m = HashMap::new();
    for e in mesh.edges() {
        let h = e.halfedge();
        let (i, j) = (mesh.tail(h).0, mesh.tip(h).0);
        *m.entry((i.min(j), i.max(j))).or_default() += 1;
    }
    m
}

/// A refutation witness when no reached triangulation is isomorphic to the result: a
/// result edge whose vertex pair occurs more often than in any Delaunay triangulation.
fn no_triangulation_witness(
    result: &Surface,
    most: &HashMap<(u32, u32), usize>,
    states: usize,
) -> Witness {
    let counts = pair_counts(&result.mesh);
    let order = edge_order(&result.mesh);
    for (k, &e) in order.iter().enumerate() {
        let e = Edge(e as u32);
        let h = e.halfedge();
        let (i, j) = (result.mesh.tail(h).0, result.mesh.tip(h).0);
        let pair = (i.min(j), i.max(j));
        let (na, nb) = (
            counts.get(&pair).copied().unwrap_or(0),
            most.get(&pair).copied().unwrap_or(0),
        );
        if na > nb {
            return Witness {
                element: format!("result edge {k} ({})", edge_name(&result.mesh, e)),
                detail: format!(
                    "not an edge of any of the {states} intrinsic Delaunay triangulations (tie flips searched completely): the result has {na} edge(s) between these vertices, the Delaunay triangulations at most {nb}"
                ),
                value: f64::NAN,
            };
        }
    }
    Witness {
        element: "result".to_string(),
        detail: format!(
            "the result is none of the {states} intrinsic Delaunay triangulations (tie flips searched completely)"
        ),
        value: f64::NAN,
    }
}

fn note(reason: String) -> Witness {
    Witness {
        element: "search".to_string(),
        detail: reason,
        value: f64::NAN,
    }
}

/// The state of one search: what was seen, what matched, why it may be incomplete.
struct Walk<'a> {
    result: &'a Surface,
    ptolemy: bool,
    eps: &'a Rational,
    bits: u32,
    /// The tie set `Z` of the start, per edge id.
    tie: Vec<bool>,
    ties: &'a [Edge],
    seen: HashSet<Vec<[u32; 3]>>,
    queue: VecDeque<(Mesh, Vec<Len>)>,
    visited: usize,
    /// Per vertex pair, the most edges any visited triangulation has there.
    most: HashMap<(u32, u32), usize>,
    refuted: Option<Compared>,
    open: Option<Compared>,
    capped: bool,
    incomplete: Vec<String>,
}

impl Walk<'_> {
    /// Certify one state (B80) and compare it with the claim; `Some` on a match.
    fn visit(&mut self, mesh: Mesh, lens: Vec<Len>) -> Option<Search> {
        let state = match finish(mesh, lens, self.bits) {
            Ok(s) if s.ties == self.ties => s,
            Ok(_) => {
                self.incomplete
                    .push("a tie flip changed the set of tie edges".to_string());
                return None;
            }
            Err(o) => {
                self.incomplete.push(format!(
                    "a triangulation reached by tie flips is not certified: {}",
                    o.reason
                ));
                return None;
            }
        };
        self.visited += 1;
        for (pair, n) in pair_counts(&state.mesh) {
            let m = self.most.entry(pair).or_default();
            *m = (*m).max(n);
        }
        let rels = isomorphisms(&self.result.mesh, &state.mesh, MAX_RELABELINGS);
        if rels.len() >= MAX_RELABELINGS {
            self.incomplete.push(format!(
                "more than {MAX_RELABELINGS} relabelings of a reached triangulation"
            ));
        }
        for r in &rels {
            let c = compare(self.result, &state, r, self.eps, self.bits);
            match c.verdict {
                ClaimVerdict::Holds => {
                    return Some(Search::Holds {
                        max_discrepancy: c.max_discrepancy,
                    })
                }
                ClaimVerdict::Undecided => {
                    self.open.get_or_insert(c);
                }
                ClaimVerdict::Refuted => {
                    self.refuted.get_or_insert(c);
                }
            }
        }
        self.expand(&state);
        None
    }

    /// Queue the unseen triangulations one tie flip away from `state`.
    fn expand(&mut self, state: &Ours) {
        for &t in &state.ties {
            let name = edge_name(&state.mesh, t);
            let Some(q) = QuadEdges::of(&state.mesh, t) else {
                self.incomplete
                    .push(format!("tie edge {name} is not flippable"));
                continue;
            };
            let Some(new) = tie_length(q.lengths(&state.lens), self.ptolemy, self.bits) else {
                self.incomplete.push(format!(
                    "the flipped length of tie edge {name} is not enclosed at {} bits",
                    self.bits
                ));
                continue;
            };
            let mut mesh = state.mesh.clone();
            if mesh.flip(t).is_err() {
                self.incomplete
                    .push(format!("the mesh refuses to flip tie edge {name}"));
                continue;
            }
            let Some(k) = key(&mesh, &self.tie) else {
                self.incomplete
                    .push("the ties do not bound polygonal cells".to_string());
                continue;
            };
            if self.seen.contains(&k) {
                continue;
            }
            if self.seen.len() >= MAX_STATES {
                self.capped = true;
                continue;
            }
            self.seen.insert(k);
            let mut lens = state.lens.clone();
            lens[t.idx()] = new;
            self.queue.push_back((mesh, lens));
        }
    }

    /// The verdict once the queue is empty and nothing matched.
    fn conclude(mut self) -> Search {
        if self.capped {
            self.incomplete.push(format!(
                "more than {MAX_STATES} triangulations are reachable by flipping the {} tie edges; the search stopped",
                self.ties.len()
            ));
        }
        let visited = self.visited;
        if self.incomplete.is_empty() && self.open.is_none() {
            return match self.refuted {
                Some(c) => Search::Refuted {
                    max_discrepancy: c.max_discrepancy,
                    witnesses: c
                        .witnesses
                        .into_iter()
                        .map(|mut w| {
                            w.detail = format!(
                                "{} (under every relabeling of all {visited} Delaunay triangulations reached by tie flips, searched completely)",
                                w.detail
                            );
                            w
                        })
                        .collect(),
                },
                None => Search::Refuted {
                    max_discrepancy: None,
                    witnesses: vec![no_triangulation_witness(self.result, &self.most, visited)],
                },
            };
        }
        let mut witnesses: Vec<Witness> = self.incomplete.into_iter().take(8).map(note).collect();
        let retry = self.open.is_some();
        let max_discrepancy = self.open.as_ref().and_then(|c| c.max_discrepancy);
        if let Some(c) = self.open {
            witnesses.extend(c.witnesses);
        }
        Search::Undecided {
            max_discrepancy,
            witnesses,
            retry,
        }
    }
}

/// Search the Delaunay triangulations reached from `ours` by tie flips for one equal to
/// `result` with lengths within `eps` (module docs; proof: B82).
pub(crate) fn search(
    result: &Surface,
    ours: &Ours,
    ptolemy: bool,
    eps: &Rational,
    bits: u32,
) -> Search {
    let k = ours.ties.len();
    if k > MAX_TIES {
        return Search::Undecided {
            max_discrepancy: None,
            witnesses: vec![note(format!(
                "the computed Delaunay triangulation has {k} cocircular tie edges (D = 0), more than the {MAX_TIES} whose flips are searched; the claim may be another Delaunay triangulation"
            ))],
            retry: false,
        };
    }
    let mut tie = vec![false; ours.mesh.n_edges()];
    for e in &ours.ties {
        tie[e.idx()] = true;
    }
    let mut walk = Walk {
        result,
        ptolemy,
        eps,
        bits,
        tie,
        ties: &ours.ties,
        seen: HashSet::new(),
        queue: VecDeque::new(),
        visited: 0,
        most: HashMap::new(),
        refuted: None,
        open: None,
        capped: false,
        incomplete: Vec::new(),
    };
    match key(&ours.mesh, &walk.tie) {
        Some(k0) => {
            walk.seen.insert(k0);
        }
        None => walk
            .incomplete
            .push("the ties do not bound polygonal cells".to_string()),
    }
    walk.queue.push_back((ours.mesh.clone(), ours.lens.clone()));
    while let Some((mesh, lens)) = walk.queue.pop_front() {
        if let Some(found) = walk.visit(mesh, lens) {
            return found;
        }
    }
    walk.conclude()
}
