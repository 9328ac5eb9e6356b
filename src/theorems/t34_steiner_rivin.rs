//! T34 (notes §1.6.3, Fig. 17; Steiner; Hodgson–Rivin–Smith): the stellated tetrahedron and
//! octahedron admit no Rivin weights, so they cannot be inscribed in a sphere (proofs/T34).
//!
//! The check looks for a Farkas certificate ([`steiner_certificate`]) and verifies it in two
//! independent exact arithmetics; `Holds` (certified) means "Rivin's system is infeasible on
//! this triangulation". Without a certificate the verdict is `Undecided` (the search is
//! Steiner's independent-set argument only, not a complete LP solver).

use super::{Verdict, Witness};
use crate::circles::rivin::{
    certificate_strings, steiner_certificate, verify_certificate_num, verify_certificate_rug,
};
use crate::mesh::Mesh;

/// T34 on a triangulated sphere: see the module docs.
pub fn check_no_rivin_weights(mesh: &Mesh) -> Verdict {
    if !mesh.is_closed() || mesh.euler_characteristic() != 2 {
        return Verdict::NotApplicable {
            reason: "Rivin weights are defined on triangulated spheres".into(),
        };
    }
    let undecided = |detail: &str| Verdict::Undecided {
        bits_tried: 0,
        witnesses: vec![Witness {
            element: "surface".into(),
            detail: detail.into(),
            value: f64::NAN,
        }],
    };
    let Some(y) = steiner_certificate(mesh) else {
        return undecided("no Steiner certificate: infeasibility not proved");
    };
    let rug_ok = verify_certificate_rug(mesh, &y);
    let num_ok = verify_certificate_num(mesh, &certificate_strings(&y));
    match (rug_ok, num_ok) {
        (true, true) => Verdict::Holds {
            certified: true,
            max_error: 0.0,
        },
        _ => undecided("the two exact verifications of the certificate disagree"),
    }
}
