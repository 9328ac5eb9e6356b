//! T36 (notes §1.3.3, Fig. 7; Tutte 1963, Floater 2003): a harmonic map of a triangulated
//! disk to a convex polygon with positive edge weights is an embedding; with negative
//! (cotan) weights it can fold (proofs/T36).
//!
//! The check computes the map ([`harmonic_map`], `f64`) onto the regular polygon and decides
//! the orientation of every face of the computed map exactly: all faces of one sign is a
//! certified embedding of the computed map (`Holds`). A computed map with mixed signs under
//! positive weights is `Undecided`, not `Fails`: the computed map is not the exact one.

use super::{Verdict, Witness};
use crate::circles::harmonic::{boundary_loop, face_orientations, harmonic_map, regular_polygon};
use crate::mesh::Mesh;
use crate::predicates::ladder::Ladder;
use crate::scalar::{Certified, Sign};

/// The signs of the faces of the map, counted: (positive, negative, zero or undecided).
pub fn orientation_counts(signs: &[Certified<Sign>]) -> (usize, usize, usize) {
    let pos = signs
        .iter()
        .filter(|s| s.value() == Some(Sign::Positive))
        .count();
    let neg = signs
        .iter()
        .filter(|s| s.value() == Some(Sign::Negative))
        .count();
    (pos, neg, signs.len() - pos - neg)
}

/// T36 on a disk with positive weights `w` (one per edge): see the module docs.
pub fn check_harmonic_embedding(mesh: &Mesh, w: &[f64], ladder: &Ladder) -> Verdict {
    if w.len() != mesh.n_edges() || w.iter().any(|&x| x <= 0.0 || !x.is_finite()) {
        return Verdict::NotApplicable {
            reason: "T36 needs one positive weight per edge".into(),
        };
    }
    let Some(loop_) = boundary_loop(mesh) else {
        return Verdict::NotApplicable {
            reason: "T36 needs a disk (one boundary loop)".into(),
        };
    };
    let Some(pos) = harmonic_map(mesh, w, &regular_polygon(loop_.len())) else {
        return Verdict::Undecided {
            bits_tried: 0,
            witnesses: vec![Witness {
                element: "surface".into(),
                detail: "the harmonic map could not be computed".into(),
                value: f64::NAN,
            }],
        };
    };
    let signs = face_orientations(mesh, &pos, ladder);
    match orientation_counts(&signs) {
        (_, 0, 0) | (0, _, 0) => Verdict::Holds {
            certified: true,
            max_error: 0.0,
        },
        _ => Verdict::Undecided {
            bits_tried: ladder.max_bits,
            witnesses: mesh
                .faces()
                .zip(&signs)
                .filter(|(_, s)| s.value() != signs[0].value() || s.value().is_none())
                .map(|(f, _)| Witness {
                    element: format!("f{}", f.idx()),
                    detail: "face orientation differs in the computed map".into(),
                    value: f64::NAN,
                })
                .collect(),
        },
    }
}
