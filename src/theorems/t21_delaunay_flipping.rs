//! T21 (notes §1.5.2, Eq. 13; docs/catalogue.md §5): flipping non-Delaunay edges terminates and every
//! edge ends Delaunay.
//!
//! The check runs [`flip_to_delaunay`] on a copy and then re-decides *every* edge of the
//! result from scratch with [`edge_delaunay_sign`] — the re-check does not trust the
//! driver's bookkeeping.
//!
//! What refutes the theorem, and what does not: an edge certified non-Delaunay that the
//! driver claims to have finished is a certified failure. An edge whose flip the driver
//! *refused* (the rounded new diagonal, or its two new triangles, could not be certified at
//! this precision; B65, B66) or left undecided was not flipped, so its sign says nothing
//! about the theorem: it is `undecided`. A run stopped by the flip cap is `undecided` too —
//! the cap bounds the work, it proves nothing about termination.

use super::{Settings, Verdict, Witness};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::mesh::{Edge, Mesh};
use crate::predicates::delaunay::{edge_delaunay_sign, EdgeDelaunay};
use crate::scalar::{Certified, Real, Sign};

/// Flip a copy of `(mesh, lengths)` to Delaunay with `kind` flips and certify every edge.
/// `Holds` (certified) when the run ends before its cap and every edge is certified
/// Delaunay; `Fails` lists each edge certified non-Delaunay that the driver reported
/// finished; `Undecided` lists the edges no rung could decide, the edges whose flip was
/// refused (their flip could not be certified at this precision), and the cap if it was
/// hit.
pub fn check_delaunay_flipping<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    kind: FlipKind,
    settings: &Settings,
) -> Verdict {
    let mut m = mesh.clone();
    let mut l = lengths.to_vec();
    let opts = FlipOptions {
        ladder: settings.ladder,
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
    let mut unfinished = report.refused.clone();
    unfinished.extend(report.undecided.iter().copied());
    unfinished.sort_unstable();
    certify_edges(
        &m,
        &l,
        settings,
        report.hit_cap.then_some(report.flips),
        &unfinished,
    )
}

/// Certify that every edge of `(mesh, lengths)` is Delaunay (the "afterwards" half of T21).
/// `hit_cap`: the run that produced the triangulation stopped at its flip cap after `flips`
/// flips; then nothing is refuted (an edge may be non-Delaunay because it was never reached)
/// and the verdict is at best `Undecided`.
pub fn check_all_edges_delaunay<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
    hit_cap: bool,
    flips: usize,
) -> Verdict {
    certify_edges(mesh, lengths, settings, hit_cap.then_some(flips), &[])
}

/// The re-check of every edge: `cap` is the flip count when the cap was hit, `unfinished`
/// the edges the driver listed as refused or undecided, sorted (never a refutation).
fn certify_edges<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
    cap: Option<usize>,
    unfinished: &[Edge],
) -> Verdict {
    let mut failing = Vec::new();
    let mut undecided = Vec::new();
    let mut bits = 0;
    if let Some(flips) = cap {
        undecided.push(Witness {
            element: "surface".into(),
            detail: format!(
                "flip cap reached after {flips} flips: the run was stopped, which proves nothing about termination"
            ),
            value: flips as f64,
        });
    }
    for e in mesh.edges() {
        match edge_delaunay_sign(mesh, lengths, e, &settings.ladder) {
            Err(err) => {
                return Verdict::NotApplicable {
                    reason: err.to_string(),
                }
            }
            Ok(EdgeDelaunay::Interior(Certified::Known {
                value: Sign::Negative,
                ..
            })) => {
                if unfinished.binary_search(&e).is_ok() {
                    undecided.push(Witness {
                        element: e.to_string(),
                        detail: "certified non-Delaunay, but its flip was refused: the new diagonal (or its two triangles) could not be certified at this precision".into(),
                        value: -1.0,
                    });
                } else if cap.is_some() {
                    undecided.push(Witness {
                        element: e.to_string(),
                        detail: "certified non-Delaunay when the flip cap stopped the run".into(),
                        value: -1.0,
                    });
                } else {
                    failing.push(Witness {
                        element: e.to_string(),
                        detail:
                            "certified non-Delaunay (P < 0) after a run that reported it finished"
                                .into(),
                        value: -1.0,
                    });
                }
            }
            Ok(EdgeDelaunay::Interior(Certified::Undecided { bits_tried })) => {
                bits = bits.max(bits_tried);
                undecided.push(Witness {
                    element: e.to_string(),
                    detail: "sign of P undecided".into(),
                    value: 0.0,
                });
            }
            Ok(_) => {}
        }
    }
    let bits = if bits == 0 {
        settings.ladder.max_bits
    } else {
        bits
    };
    Verdict::certified(failing, undecided, bits)
}
