//! T21 (notes §1.5.2, Eq. 13; MATH.md §5): flipping non-Delaunay edges terminates and every
//! edge ends Delaunay.
//!
//! The check runs [`flip_to_delaunay`] on a copy and then re-decides *every* edge of the
//! result from scratch with [`edge_delaunay_sign`] — the re-check does not trust the
//! driver's bookkeeping.

use super::{Settings, Verdict, Witness};
use crate::algorithms::flip_to_delaunay::{flip_to_delaunay, FlipKind, FlipOptions};
use crate::mesh::Mesh;
use crate::predicates::delaunay::{edge_delaunay_sign, EdgeDelaunay};
use crate::scalar::{Certified, Real, Sign};

/// Flip a copy of `(mesh, lengths)` to Delaunay with `kind` flips and certify every edge.
/// `Holds` (certified) when the run ends before its cap and every edge is certified
/// Delaunay; `Fails` lists each edge certified non-Delaunay (and the cap, if hit);
/// `Undecided` lists the edges no rung could decide.
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
    check_all_edges_delaunay(&m, &l, settings, report.hit_cap, report.flips)
}

/// Certify that every edge of `(mesh, lengths)` is Delaunay (the "afterwards" half of T21).
pub fn check_all_edges_delaunay<T: Real>(
    mesh: &Mesh,
    lengths: &[T],
    settings: &Settings,
    hit_cap: bool,
    flips: usize,
) -> Verdict {
    let mut failing = Vec::new();
    let mut undecided = Vec::new();
    let mut bits = 0;
    if hit_cap {
        failing.push(Witness {
            element: "surface".into(),
            detail: format!("flip cap reached after {flips} flips"),
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
            })) => failing.push(Witness {
                element: e.to_string(),
                detail: "certified non-Delaunay (P < 0)".into(),
                value: -1.0,
            }),
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
    if !failing.is_empty() {
        Verdict::Fails {
            certified: !hit_cap || failing.len() > 1,
            witnesses: failing,
        }
    } else if !undecided.is_empty() {
        Verdict::Undecided {
            bits_tried: bits,
            witnesses: undecided,
        }
    } else {
        Verdict::Holds {
            certified: true,
            max_error: 0.0,
        }
    }
}
