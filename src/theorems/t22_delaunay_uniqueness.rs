//! T22 (notes §1.5.2): without cocircular pairs the Delaunay triangulation is unique;
//! at ties `D = 0` and both diagonals pass.
//!
//! Two comparisons:
//! - [`check_delaunay_uniqueness_of`]: flip one start with several visit orders and
//!   compare the results *on one metric*, the exact input: each run's recorded flip
//!   sequence is replayed on the input metric with certified arithmetic (B80), and only
//!   runs certified Delaunay there are compared (a rounded run whose flips round
//!   differently ran on another metric; it is `undecided`, never a refutation). Vertex
//!   labels are preserved by flips, so without ties the results must be the same
//!   triangulation up to renumbering of edges and faces ([`same_triangulation`], a
//!   vertex-fixing isomorphism of the gluing, which also separates Δ-complexes whose
//!   multi-edges make face lists ambiguous). With ties (`D = 0` certified on the input
//!   metric, exact lengths) the strictly Delaunay edges are compared as multisets of
//!   vertex pairs, and each tie edge must stay a tie after flipping it.
//! - [`check_planar_delaunay_matches_spade`]: a planar triangulation with convex boundary,
//!   flipped intrinsically, has the edge set of `spade`'s constrained Delaunay
//!   triangulation of the same points (an independent implementation).

use super::{Settings, Verdict, Witness};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::algorithms::replay::{replay_escalating_lazy, FlippedLens, Replayed};
use crate::io::Metric;
use crate::mesh::relabel::isomorphisms;
use crate::mesh::Mesh;
use crate::predicates::delaunay::{edge_delaunay_sign, EdgeDelaunay, QuadEdges};
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
/// compare the results on the metric of the given lengths, taken exactly
/// ([`check_delaunay_uniqueness_of`] with `input` their exact values).
pub fn check_delaunay_uniqueness<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    kind: FlipKind,
    seeds: &[u64],
    settings: &Settings,
) -> Verdict {
    let Some(exact) = lengths
        .iter()
        .map(Real::to_rational)
        .collect::<Option<Vec<_>>>()
    else {
        return Verdict::NotApplicable {
            reason: "a length has no exact value (not finite)".into(),
        };
    };
    check_delaunay_uniqueness_of(
        mesh,
        lengths,
        &Metric::Lengths(exact),
        kind,
        seeds,
        settings,
    )
}

/// One run of the uniqueness check, certified on the input metric.
struct CertifiedRun {
    seed: u64,
    mesh: Mesh,
    strict: PairCounts,
    tied: bool,
}

/// Flip `(mesh, lengths)` in the backend of `lengths` once per seed in `seeds` (random
/// visit orders), replay each recorded flip sequence on the exact `input` metric with
/// certified arithmetic ([`replay_escalating_lazy`], proof: B80) and compare the runs certified
/// there (module documentation). Every comparison is about the one metric `input`: two
/// runs in a rounded backend round their new lengths differently and so run on two
/// different metrics, which refutes nothing. A run whose triangulation is not certified
/// Delaunay for `input` (a flip certified strictly Delaunay there, an undecided sign, a
/// refused flip or the flip cap) makes the verdict `Undecided`; `Fails` needs two runs
/// certified Delaunay for `input` whose triangulations differ without ties, or whose
/// strictly Delaunay edges differ, or a certified tie whose flip is certified not a tie.
pub fn check_delaunay_uniqueness_of<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    input: &Metric,
    kind: FlipKind,
    seeds: &[u64],
    settings: &Settings,
) -> Verdict {
    let max_bits = settings.ladder.max_bits.max(REPLAY_START_BITS);
    let mut witnesses = Vec::new();
    let mut undecided = Vec::new();
    let mut runs: Vec<CertifiedRun> = Vec::new();
    // Two steps per seed: flipping, then the replay on the input metric.
    let mut count = settings
        .progress
        .counter("runs flipped and replayed", 2 * seeds.len());
    for &seed in seeds {
        let (mut m, mut l) = (mesh.clone(), lengths.to_vec());
        let opts = FlipOptions {
            ladder: settings.ladder,
            order_seed: Some(seed),
            record: true,
            ..FlipOptions::default()
        };
        let report = match flip_to_delaunay(&mut m, &mut l, kind, &opts) {
            Ok(r) => r,
            Err(err) => {
                return Verdict::NotApplicable {
                    reason: err.to_string(),
                }
            }
        };
        count.add(1);
        if !report.all_certified_delaunay() {
            undecided.push(Witness {
                element: "surface".into(),
                detail: format!(
                    "seed {seed}: the run did not finish ({} undecided, {} refused{})",
                    report.undecided.len(),
                    report.refused.len(),
                    if report.hit_cap { ", flip cap hit" } else { "" }
                ),
                value: seed as f64,
            });
            continue;
        }
        let (r, bits) = replay_escalating_lazy(
            mesh,
            input,
            &report.sequence,
            kind,
            REPLAY_START_BITS,
            max_bits,
        );
        count.add(1);
        if !r.certified_delaunay() {
            undecided.push(Witness {
                element: "surface".into(),
                detail: format!(
                    "seed {seed}: the rounded run is not certified Delaunay for the input metric at {bits} bits ({})",
                    replay_gap(&r)
                ),
                value: seed as f64,
            });
            continue;
        }
        let strict = strict_pairs(&r.mesh, &r.ties);
        // At a tie both diagonals pass: flipping it gives a tie again (exact lengths where
        // Ptolemy's theorem keeps them exact; an open sign is undecided).
        for &e in &r.ties {
            match tie_flip_sign(&r, input, e) {
                Some(Sign::Zero) => {}
                Some(_) => witnesses.push(Witness {
                    element: e.to_string(),
                    detail: format!(
                        "seed {seed}: tie edge (D = 0) whose flip is certified not a tie"
                    ),
                    value: 0.0,
                }),
                None => undecided.push(Witness {
                    element: e.to_string(),
                    detail: format!("seed {seed}: tie edge whose flip is not decided a tie"),
                    value: 0.0,
                }),
            }
        }
        runs.push(CertifiedRun {
            seed,
            tied: !r.ties.is_empty(),
            mesh: r.mesh,
            strict,
        });
    }
    count.finish();
    witnesses.extend(compare_runs(&runs));
    Verdict::certified(witnesses, undecided, max_bits)
}

/// The comparison of runs certified Delaunay for one metric: each against the first.
fn compare_runs(runs: &[CertifiedRun]) -> Vec<Witness> {
    let mut witnesses = Vec::new();
    if let Some((first, rest)) = runs.split_first() {
        for run in rest {
            let seed = run.seed;
            if !first.tied && !run.tied {
                if !same_triangulation(&first.mesh, &run.mesh) {
                    witnesses.push(Witness {
                        element: "surface".into(),
                        detail: format!(
                            "seeds {} and {seed}: two Delaunay triangulations of the input metric without ties differ",
                            first.seed
                        ),
                        value: seed as f64,
                    });
                }
            } else if first.strict != run.strict {
                witnesses.push(Witness {
                    element: "surface".into(),
                    detail: format!(
                        "seeds {} and {seed}: strictly Delaunay edges of the input metric differ",
                        first.seed
                    ),
                    value: seed as f64,
                });
            }
        }
    }
    witnesses
}

/// First MPFR precision of the replays on the input metric (doubling to the ladder's top).
const REPLAY_START_BITS: u32 = 128;

/// Why a replay is not certified, in words.
fn replay_gap(r: &Replayed<FlippedLens>) -> String {
    match &r.broken {
        Some((n, e, why)) => format!("flip {n} of the sequence, edge {e}: {why:?}"),
        None => format!(
            "{} edge(s) certified non-Delaunay, {} undecided",
            r.negative.len(),
            r.undecided.len()
        ),
    }
}

/// Vertex pairs of the edges of `mesh` that are not ties (strictly Delaunay interior
/// edges, boundary and self-folded edges), with multiplicity.
fn strict_pairs(mesh: &Mesh, ties: &[crate::mesh::Edge]) -> PairCounts {
    let mut strict = PairCounts::new();
    for e in mesh.edges() {
        if !ties.contains(&e) {
            *strict.entry(pair(mesh, e)).or_default() += 1;
        }
    }
    strict
}

/// The certified sign of `D` of the tie `e` of the replay `r` after flipping it: the tie
/// flip recorded on a copy of the replay's flip DAG (its new length by Ptolemy's theorem,
/// exact where the lengths are, B82), then the replay's rungs on the flipped
/// quadrilateral, the algebraic one included (B107).
fn tie_flip_sign(r: &Replayed<FlippedLens>, input: &Metric, e: crate::mesh::Edge) -> Option<Sign> {
    let q = QuadEdges::of(&r.mesh, e)?;
    let (mut m, mut dag) = (r.mesh.clone(), r.lens.clone());
    let none = vec![None; m.n_edges()];
    dag.flip(input, e, q.edges, Some(m.quad_vertices(e)), true, &none)?;
    m.flip(e).ok()?;
    let q2 = QuadEdges::of(&m, e)?;
    dag.sign_open(input, q2.edges, &none)
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
