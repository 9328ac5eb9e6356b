//! T22 (notes §1.5.2): without cocircular pairs the Delaunay triangulation is unique;
//! at ties `D = 0` and both diagonals pass.
//!
//! Two comparisons:
//! - [`check_delaunay_uniqueness`]: flip one start with several visit orders and compare
//!   the results. Vertex labels are preserved by flips, so without ties the results must
//!   be the same triangulation up to renumbering of edges and faces
//!   ([`same_triangulation`], a vertex-fixing isomorphism of the gluing, which also
//!   separates Δ-complexes whose multi-edges make face lists ambiguous). With ties
//!   (certified `P = 0`) the strictly Delaunay edges are compared as multisets of vertex
//!   pairs, and each tie edge must stay a tie after flipping it.
//! - [`check_planar_delaunay_matches_spade`]: a planar triangulation with convex boundary,
//!   flipped intrinsically, has the edge set of `spade`'s constrained Delaunay
//!   triangulation of the same points (an independent implementation).

use super::{Settings, Verdict, Witness};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::algorithms::flips::flip_metric;
use crate::mesh::relabel::isomorphisms;
use crate::mesh::Mesh;
use crate::predicates::delaunay::{edge_delaunay_sign, EdgeDelaunay};
use crate::scalar::{Certified, Real, Sign};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
use std::collections::BTreeMap;

type PairCounts = BTreeMap<(u32, u32), usize>;

fn pair(mesh: &Mesh, e: crate::mesh::Edge) -> (u32, u32) {
    let h = e.halfedge();
    let (a, b) = (mesh.tail(h).0, mesh.tip(h).0);
    (a.min(b), a.max(b))
}

/// Strict (P > 0 or boundary) edges, tie edges, and undecided edges of a triangulation.
fn classify<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
) -> Result<(PairCounts, Vec<crate::mesh::Edge>, Vec<Witness>), String> {
    let mut strict = PairCounts::new();
    let mut ties = Vec::new();
    let mut bad = Vec::new();
    for e in mesh.edges() {
        match edge_delaunay_sign(mesh, lengths, e, &settings.ladder).map_err(|x| x.to_string())? {
            EdgeDelaunay::Interior(Certified::Known {
                value: Sign::Zero, ..
            }) => ties.push(e),
            EdgeDelaunay::Interior(Certified::Known {
                value: Sign::Negative,
                ..
            }) => bad.push(Witness {
                element: e.to_string(),
                detail: "non-Delaunay edge after flipping".into(),
                value: -1.0,
            }),
            EdgeDelaunay::Interior(Certified::Undecided { .. }) => bad.push(Witness {
                element: e.to_string(),
                detail: "undecided edge after flipping".into(),
                value: 0.0,
            }),
            _ => *strict.entry(pair(mesh, e)).or_default() += 1,
        }
    }
    Ok((strict, ties, bad))
}

/// Whether `a` and `b` are the same triangulation of one vertex set: some bijection of
/// half-edges keeps every tail and tip and commutes with `twin` and `next`
/// ([`isomorphisms`], proofs/B81).
///
/// ```
/// use penner::mesh::{Edge, Mesh};
/// use penner::theorems::t22_delaunay_uniqueness::same_triangulation;
/// let a = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3]]).unwrap();
/// let b = Mesh::from_faces(4, &[[2, 3, 0], [1, 2, 0]]).unwrap();
/// assert!(same_triangulation(&a, &b));
/// let mut c = a.clone();
/// let diagonal = c.edges().find(|&e| !c.is_boundary_edge(e)).unwrap();
/// c.flip(diagonal).unwrap();
/// assert!(!same_triangulation(&a, &c));
/// ```
pub fn same_triangulation(a: &Mesh, b: &Mesh) -> bool {
    !isomorphisms(a, b, 1).is_empty()
}

/// Flip `(mesh, lengths)` to Delaunay once per seed in `seeds` (random visit orders) and
/// compare the results (see the module documentation).
pub fn check_delaunay_uniqueness<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    kind: FlipKind,
    seeds: &[u64],
    settings: &Settings,
) -> Verdict {
    let mut reference: Option<(Mesh, PairCounts, bool)> = None;
    let mut witnesses = Vec::new();
    let mut undecided = Vec::new();
    for &seed in seeds {
        let (mut m, mut l) = (mesh.clone(), lengths.to_vec());
        let opts = FlipOptions {
            ladder: settings.ladder,
            order_seed: Some(seed),
            ..FlipOptions::default()
        };
        if let Err(err) = flip_to_delaunay(&mut m, &mut l, kind, &opts) {
            return Verdict::NotApplicable {
                reason: err.to_string(),
            };
        }
        let (strict, ties, bad) = match classify(&m, &l, settings) {
            Ok(x) => x,
            Err(reason) => return Verdict::NotApplicable { reason },
        };
        witnesses.extend(bad);
        // At a tie both diagonals pass: flip it and the new diagonal is a tie again. The
        // flipped length is rounded to the working precision (unless the backend is exact
        // and the flip rational), so a nonzero sign of the rounded quadrilateral refutes
        // nothing: it leaves the tie claim undecided, never failed.
        let tied = !ties.is_empty();
        for e in ties {
            let (mut m2, mut l2) = (m.clone(), l.clone());
            if flip_metric(&mut m2, &mut l2, e, kind).is_ok() {
                let s = edge_delaunay_sign(&m2, &l2, e, &settings.ladder);
                if !matches!(s, Ok(EdgeDelaunay::Interior(c)) if c.value() == Some(Sign::Zero)) {
                    undecided.push(Witness {
                        element: e.to_string(),
                        detail: format!(
                            "seed {seed}: tie edge whose flip, with the new length rounded, is not a certified tie"
                        ),
                        value: 0.0,
                    });
                }
            }
        }
        match &reference {
            None => reference = Some((m, strict, tied)),
            Some((rm, _, false)) if !tied && !same_triangulation(rm, &m) => {
                witnesses.push(Witness {
                    element: "surface".into(),
                    detail: format!(
                        "seed {seed}: not the same triangulation as the first run (no ties)"
                    ),
                    value: seed as f64,
                });
            }
            Some((_, r, _)) if *r != strict => witnesses.push(Witness {
                element: "surface".into(),
                detail: format!("seed {seed}: strictly Delaunay edges differ from the first run"),
                value: seed as f64,
            }),
            Some(_) => {}
        }
    }
    Verdict::certified(witnesses, undecided, settings.ladder.max_bits)
}

/// Flip the planar triangulation `faces` of `points` (convex boundary) with Euclidean flips
/// on its `f64` edge lengths and compare its edges with `spade`'s constrained Delaunay
/// triangulation (boundary edges as constraints). Every edge present in one and not in the
/// other is listed. Edges at certified ties are exempt.
pub fn check_planar_delaunay_matches_spade(
    points: &[[f64; 2]],
    faces: &[[u32; 3]],
    settings: &Settings,
) -> Verdict {
    let Ok(mut m) = Mesh::from_faces(points.len() as u32, faces) else {
        return Verdict::NotApplicable {
            reason: "faces do not form a surface".into(),
        };
    };
    let mut l: Vec<f64> = m
        .edges()
        .map(|e| {
            let (a, b) = pair(&m, e);
            let (p, q) = (points[a as usize], points[b as usize]);
            (p[0] - q[0]).hypot(p[1] - q[1])
        })
        .collect();
    let opts = FlipOptions {
        ladder: settings.ladder,
        ..FlipOptions::default()
    };
    if let Err(err) = flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &opts) {
        return Verdict::NotApplicable {
            reason: err.to_string(),
        };
    }
    let witnesses = match planar_edge_mismatches(points, &m, &l, settings) {
        Ok(w) => w,
        Err(reason) => return Verdict::NotApplicable { reason },
    };
    Verdict::certified(witnesses, Vec::new(), 0)
}

/// Every edge of the triangulation `(m, l)` of `points` that is not in `spade`'s constrained
/// Delaunay triangulation (boundary edges as constraints), and every edge of spade's that
/// is missing here; edges at certified ties are exempt.
pub fn planar_edge_mismatches(
    points: &[[f64; 2]],
    m: &Mesh,
    l: &[f64],
    settings: &Settings,
) -> Result<Vec<Witness>, String> {
    let mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>> =
        ConstrainedDelaunayTriangulation::new();
    let mut handles = Vec::with_capacity(points.len());
    for p in points {
        match cdt.insert(Point2::new(p[0], p[1])) {
            Ok(h) => handles.push(h),
            Err(err) => return Err(format!("spade rejected a point: {err:?}")),
        }
    }
    if cdt.num_vertices() != points.len() {
        return Err("duplicate points".into());
    }
    for e in m.edges().filter(|&e| m.is_boundary_edge(e)) {
        let (a, b) = pair(m, e);
        cdt.add_constraint(handles[a as usize], handles[b as usize]);
    }
    let index_of: BTreeMap<usize, u32> = handles
        .iter()
        .enumerate()
        .map(|(i, h)| (h.index(), i as u32))
        .collect();
    let mut theirs = std::collections::BTreeSet::new();
    for e in cdt.undirected_edges() {
        let [a, b] = e.vertices().map(|v| index_of[&v.fix().index()]);
        theirs.insert((a.min(b), a.max(b)));
    }
    let (strict, ties, mut witnesses) = classify(m, l, settings)?;
    let tie_pairs: std::collections::BTreeSet<_> = ties.iter().map(|&e| pair(m, e)).collect();
    for p in strict.keys() {
        if !theirs.contains(p) {
            witnesses.push(Witness {
                element: format!("v{}-v{}", p.0, p.1),
                detail: "edge not in spade's Delaunay triangulation".into(),
                value: 1.0,
            });
        }
    }
    for p in &theirs {
        if !strict.contains_key(p) && !tie_pairs.contains(p) {
            witnesses.push(Witness {
                element: format!("v{}-v{}", p.0, p.1),
                detail: "spade's Delaunay edge missing after flipping".into(),
                value: 1.0,
            });
        }
    }
    Ok(witnesses)
}
