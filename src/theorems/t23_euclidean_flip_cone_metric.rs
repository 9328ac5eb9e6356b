//! T23 (notes §1.5.2): Euclidean flips preserve the cone metric — every cone angle is
//! unchanged and discrete Gauss–Bonnet still holds.
//!
//! The flip sequence chosen by [`flip_to_delaunay`] is replayed on outward-rounded MPFR
//! enclosures of the *exact* flipped lengths ([`euclidean_length_enclosure`]), and cone
//! angles are enclosed with the half-angle form (docs/catalogue.md §1) before and after
//! ([`verify_flip_sequence`]). Two independent parts decide the verdict (proof: T23):
//!
//! - **Refutation.** Disjoint enclosures of a cone angle before and after (or of the
//!   Gauss–Bonnet sum and `2πχ`) prove that the exact values differ: a certified `Fails`.
//!   With the Ptolemy update instead of the Euclidean one the cone angles change and the
//!   enclosures separate (the negative control of the tests and of `T23-NC`).
//! - **Proof of equality.** Intersecting enclosures cannot prove equality. The equality is
//!   proved instead from the hypotheses of the planar lemma of T23, certified per replayed
//!   flip on the enclosures ([`flip_hypotheses_certified`]): both triangles of the
//!   quadrilateral strictly satisfy the triangle inequality, and the quadrilateral is
//!   strictly convex at `i` and `j` (`α_i^{ijk} + α_i^{jil} < π`, the same at `j`), decided
//!   as the signs of `Q_i = ℓ_il(a² + c² − b²) + ℓ_ki(a² + d² − e²) > 0` and
//!   `Q_j = ℓ_lj(a² + b² − c²) + ℓ_jk(a² + e² − d²) > 0`. Then the exact Euclidean flip
//!   leaves every corner-angle sum at `i, j, k, l` unchanged, so the exact cone angles are
//!   equal. A `Holds` is certified only when every replayed flip is Euclidean with its
//!   hypotheses certified; otherwise it is `Holds { certified: false }` ("not refuted": the
//!   enclosures intersect, which is all that is known).

use super::progress::Progress;
pub use super::t23_hypotheses::flip_hypotheses_certified;
use super::t23_hypotheses::{face_certified, half_angle_tangent};
use super::{Settings, Verdict, Witness};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::algorithms::flips::{euclidean_length_enclosure, ptolemy_length_enclosure};
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::QuadEdges;
use crate::predicates::directed::{enclose_f64, overlaps, valid};
use crate::scalar::{Interval, Mpfr, Precision, Real};

/// Enclosures of the corner angle opposite `a` in a triangle `a, b, c`:
/// `2·atan √((a−b+c)(a+b−c) / ((a+b+c)(−a+b+c)))` (docs/catalogue.md §1); `None` if the triangle may
/// be invalid.
pub fn corner_angle_enclosure(
    a: &Interval<Mpfr>,
    b: &Interval<Mpfr>,
    c: &Interval<Mpfr>,
) -> Option<Interval<Mpfr>> {
    let half = half_angle_tangent(a, b, c)?.atan();
    valid(half * &enclose_f64(2.0, a.ctx()))
}

/// Enclosures of all cone angles `θ_v = Σ` corner angles at `v` ([`corner_angle_enclosure`]),
/// or the first face whose angles cannot be enclosed (also when `l` has no entry for one of
/// its edges).
pub fn cone_angle_enclosures(
    mesh: &Mesh,
    l: &[Interval<Mpfr>],
    prec: Precision,
) -> Result<Vec<Interval<Mpfr>>, u32> {
    let all = vec![true; mesh.n_vertices()];
    cone_angle_enclosures_at(mesh, l, prec, &all)
}

/// [`cone_angle_enclosures`] at the vertices `v` with `only[v]` (the others stay `[0, 0]`):
/// corner angles are enclosed only at those vertices, so the cost is proportional to their
/// degrees plus one pass over the faces.
pub fn cone_angle_enclosures_at(
    mesh: &Mesh,
    l: &[Interval<Mpfr>],
    prec: Precision,
    only: &[bool],
) -> Result<Vec<Interval<Mpfr>>, u32> {
    let mut theta = vec![enclose_f64(0.0, prec); mesh.n_vertices()];
    for f in mesh.faces() {
        let hs = mesh.face_halfedges(f);
        let len = |h: crate::mesh::HalfEdge| l.get(h.edge().idx()).ok_or(f.0);
        for i in 0..3 {
            let v = mesh.tail(hs[(i + 2) % 3]).idx();
            if !only.get(v).copied().unwrap_or(false) {
                continue;
            }
            let a = len(hs[i])?;
            let b = len(hs[(i + 1) % 3])?;
            let c = len(hs[(i + 2) % 3])?;
            theta[v] += &corner_angle_enclosure(a, b, c).ok_or(f.0)?;
        }
    }
    Ok(theta)
}

/// The first face of `mesh` whose side enclosures `l` are not certified to satisfy the
/// triangle inequality (some `b + c − a` not certified positive), if any.
fn first_invalid_face(mesh: &Mesh, l: &[Interval<Mpfr>]) -> Option<u32> {
    mesh.faces().find_map(|f| {
        let [a, b, c] = mesh.face_halfedges(f).map(|h| l.get(h.edge().idx()));
        let (Some(a), Some(b), Some(c)) = (a, b, c) else {
            return Some(f.0);
        };
        (!face_certified(a, b, c)).then_some(f.0)
    })
}

/// Flip a copy of `(mesh, lengths)` to Delaunay with Euclidean flips ([`flip_to_delaunay`],
/// recording the sequence) and compare cone angles and the Gauss–Bonnet sum before and
/// after the flips replayed with the `replay` update (Euclidean for the theorem) on
/// enclosures at `prec` bits ([`verify_flip_sequence`], whose verdict this is).
pub fn check_euclidean_flips_preserve_cone_metric<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    replay: FlipKind,
    prec: u32,
    settings: &Settings,
) -> Verdict {
    if let Err(err) = Precision::new(u64::from(prec)) {
        return Verdict::NotApplicable {
            reason: err.to_string(),
        };
    }
    if lengths.iter().any(|l| l.to_rational().is_none()) {
        return Verdict::NotApplicable {
            reason: "a length is not finite".into(),
        };
    }
    let (mut m, mut l) = (mesh.clone(), lengths.to_vec());
    let opts = FlipOptions {
        ladder: settings.ladder,
        record: true,
        ..FlipOptions::default()
    };
    match flip_to_delaunay(&mut m, &mut l, FlipKind::Euclidean, &opts) {
        Ok(report) => verify_flip_sequence_with(
            mesh,
            lengths,
            &report.sequence,
            replay,
            prec,
            &settings.progress,
        ),
        Err(err) => Verdict::NotApplicable {
            reason: err.to_string(),
        },
    }
}

/// The comparison of T23 for the flips `sequence` of `(mesh, lengths)` (the exact values of
/// `lengths`), replayed with the `replay` update on outward-rounded enclosures at `prec`
/// bits: every cone angle and the Gauss–Bonnet sum `Σ_int (2π − θ) + Σ_∂ (π − θ) = 2πχ`
/// after the flips against the cone angles before.
///
/// - `NotApplicable`: a bad precision, a length count other than one per edge, a
///   non-finite length, or an input face whose angles cannot be enclosed (it may violate
///   the triangle inequality);
/// - `Undecided`: a flip that cannot be replayed (no such edge, boundary, same face on both
///   sides), a new length or the final cone angles that cannot be enclosed;
/// - `Fails { certified: true }`: disjoint enclosures (the exact values differ), every such
///   vertex listed;
/// - `Holds { certified: true }`: the enclosures intersect and every flip is Euclidean with
///   [`flip_hypotheses_certified`], which proves the exact cone angles equal (proof: T23,
///   Lemma; an empty sequence leaves the metric unchanged);
/// - `Holds { certified: false }`: the enclosures intersect but some flip's hypotheses are
///   not certified, or some flip is not Euclidean: not refuted, not proved.
///
/// `max_error` is the widest enclosure of a cone angle (an upper bound on any difference
/// the comparison could have missed); `0` when the first rung proves the certified
/// `Holds` (proof: B84), which establishes exact equality of the cone angles without
/// enclosing them.
pub fn verify_flip_sequence<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    sequence: &[Edge],
    replay: FlipKind,
    prec: u32,
) -> Verdict {
    verify_flip_sequence_with(mesh, lengths, sequence, replay, prec, &Progress::default())
}

/// [`verify_flip_sequence`], reporting the flips replayed to `progress`.
pub fn verify_flip_sequence_with<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    sequence: &[Edge],
    replay: FlipKind,
    prec: u32,
    progress: &Progress,
) -> Verdict {
    let bits = prec;
    let prec = match replay_precision(mesh, lengths.len(), bits) {
        Ok(p) => p,
        Err(not_applicable) => return not_applicable,
    };
    // The first rung (proof: B84): on f64 enclosures, MPFR only for what they leave open.
    // When it proves every condition of a certified `Holds` of the comparison on MPFR
    // enclosures, the exact cone angles are equal and nothing is left to compare.
    if replay == FlipKind::Euclidean
        && super::t23_first_rung::proved(mesh, lengths, sequence, prec, progress)
    {
        return Verdict::Holds {
            certified: true,
            max_error: 0.0,
        };
    }
    verify_flip_sequence_on_mpfr(mesh, lengths, sequence, replay, bits, progress)
}

/// The working precision of a replay at `bits`, or the `NotApplicable` verdict when `bits`
/// is not a precision or `n_lengths` is not the edge count of `mesh`.
fn replay_precision(mesh: &Mesh, n_lengths: usize, bits: u32) -> Result<Precision, Verdict> {
    let prec = Precision::new(u64::from(bits)).map_err(|err| Verdict::NotApplicable {
        reason: err.to_string(),
    })?;
    if n_lengths != mesh.n_edges() {
        return Err(Verdict::NotApplicable {
            reason: format!(
                "{n_lengths} lengths given for a mesh with {} edges",
                mesh.n_edges()
            ),
        });
    }
    Ok(prec)
}

/// [`verify_flip_sequence`] without its first rung: the whole replay and both cone-angle
/// comparisons on MPFR enclosures at `prec` bits (the verdicts of the first rung are
/// those of this comparison, proof: B84; `max_error` is always the widest enclosure).
#[allow(clippy::too_many_lines)]
pub fn verify_flip_sequence_on_mpfr<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    sequence: &[Edge],
    replay: FlipKind,
    prec: u32,
    progress: &Progress,
) -> Verdict {
    let bits = prec;
    let prec = match replay_precision(mesh, lengths.len(), bits) {
        Ok(p) => p,
        Err(not_applicable) => return not_applicable,
    };
    let mut enc = Vec::with_capacity(lengths.len());
    for l in lengths {
        let Some(q) = l.to_rational() else {
            return Verdict::NotApplicable {
                reason: "a length is not finite".into(),
            };
        };
        enc.push(Interval::from_rational(&q, prec));
    }
    if let Some(f) = first_invalid_face(mesh, &enc) {
        return Verdict::NotApplicable {
            reason: format!("face f{f} violates the triangle inequality"),
        };
    }
    // Only the corners of the four vertices of each flipped quadrilateral change: the other
    // vertices keep the same corners with the same lengths, hence the same cone angles.
    let enc0 = enc.clone();
    let mut touched = vec![false; mesh.n_vertices()];
    let mut replayed = mesh.clone();
    let mut undecided = Vec::new();
    // Whether T23's lemma proves the exact cone angles equal: every flip Euclidean with its
    // hypotheses certified (no flip: the metric is unchanged).
    let mut proved = true;
    let mut count = progress.counter("flips replayed on MPFR enclosures", sequence.len());
    for &e in sequence {
        count.add(1);
        let quad = (e.idx() < replayed.n_edges())
            .then(|| QuadEdges::of(&replayed, e))
            .flatten();
        let Some(q) = quad else {
            undecided.push(Witness {
                element: e.to_string(),
                detail: "recorded flip not replayable".into(),
                value: 0.0,
            });
            break;
        };
        for h in [q.edge.halfedge(), q.edge.halfedge().twin()] {
            touched[replayed.tail(h).idx()] = true;
            touched[replayed.tail(replayed.prev(h)).idx()] = true;
        }
        let lq = q.lengths(&enc);
        proved = proved && replay == FlipKind::Euclidean && flip_hypotheses_certified(lq);
        let new = match replay {
            FlipKind::Euclidean => euclidean_length_enclosure(lq),
            FlipKind::Ptolemy => ptolemy_length_enclosure(lq),
        };
        let Some(new) = new else {
            undecided.push(Witness {
                element: e.to_string(),
                detail: "new length could not be enclosed".into(),
                value: 0.0,
            });
            break;
        };
        enc[e.idx()] = new;
        let _ = replayed.flip(e);
    }
    count.finish();
    let (before, after) = if undecided.is_empty() {
        (
            cone_angle_enclosures_at(mesh, &enc0, prec, &touched).ok(),
            cone_angle_enclosures_at(&replayed, &enc, prec, &touched).ok(),
        )
    } else {
        (None, None)
    };

    let Some(after) = after else {
        if undecided.is_empty() {
            undecided.push(Witness {
                element: "surface".into(),
                detail: "cone angles after flipping could not be enclosed".into(),
                value: 0.0,
            });
        }
        return Verdict::Undecided {
            bits_tried: bits,
            witnesses: undecided,
        };
    };
    let Some(before) = before else {
        return Verdict::NotApplicable {
            reason: "the input's cone angles could not be enclosed".into(),
        };
    };
    let mut witnesses = Vec::new();
    let mut max_width: f64 = 0.0;
    for v in mesh.vertices().filter(|v| touched[v.idx()]) {
        let (b, a) = (&before[v.idx()], &after[v.idx()]);
        max_width = max_width.max(a.width_f64()).max(b.width_f64());
        if !overlaps(a, b) {
            witnesses.push(Witness {
                element: v.to_string(),
                detail: format!(
                    "cone angle changed: [{:.17e}, …] before, [{:.17e}, …] after",
                    b.lo().approx_f64(),
                    a.lo().approx_f64()
                ),
                value: (a.lo().approx_f64() - b.lo().approx_f64()).abs(),
            });
        }
    }
    // Gauss–Bonnet on the flipped metric: Σ_int (2π − θ) + Σ_∂ (π − θ) = 2πχ. The input
    // satisfies it (T01: every metric does) and χ is unchanged, so after the flips it holds
    // iff the cone angles' total change Σ_v (θ_after − θ_before) is 0 — a sum over the
    // touched vertices only (proof: T23).
    let mut change = enclose_f64(0.0, prec);
    for v in mesh.vertices().filter(|v| touched[v.idx()]) {
        change += &(after[v.idx()].clone() - &before[v.idx()]);
    }
    if !overlaps(&change, &enclose_f64(0.0, prec)) {
        witnesses.push(Witness {
            element: "surface".into(),
            detail: "Gauss–Bonnet fails after flipping (the total cone angle changed)".into(),
            value: change.lo().approx_f64(),
        });
    }
    if witnesses.is_empty() {
        Verdict::Holds {
            certified: proved,
            max_error: max_width,
        }
    } else {
        Verdict::Fails {
            certified: true,
            witnesses,
        }
    }
}
