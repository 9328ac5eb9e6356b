//! Does given data realize a triangulation as a circle packing or a circle pattern? The
//! quantities behind the claim kinds `circle_packing` and `circle_pattern` of
//! `penner certify` (docs/oracle.md), as rigorous `Interval<Mpfr>` enclosures (inclusion
//! property, proofs/B20) and exact rational signs (proofs/B98).
//!
//! - Plane packings (circles with rational centres `c_v` and radii `ρ_v > 0`): the tangency
//!   defect `‖c_i − c_j‖ − (ρ_i + ρ_j)` of every edge ([`plane_tangency_defects`]); every
//!   face's centres positively oriented and every interior vertex's neighbours winding once
//!   around it, exactly ([`plane_orientation_violations`], proofs/B95).
//! - Sphere packings (caps `{P: N·P > H}` with rational `N`, `H`, `|N|² > H²`): the
//!   inversive-distance defect `I_ij − 1` of every edge ([`cap_tangency_defects`]); every
//!   face's cap centres positively oriented (`det(N_a, N_b, N_c) > 0`) and every vertex's
//!   neighbours winding once, exactly ([`cap_orientation_violations`], proofs/B96).
//! - Patterns (radii `r_v > 0`, intersection angles `Φ_e = q_e π ∈ [0, π/2]`): the cone
//!   angle `θ_v` of the Euclidean metric `ℓ_ij² = r_i² + r_j² + 2 r_i r_j cos Φ_ij` (notes
//!   Eq. 9) at every vertex ([`pattern_cone_angles`]).

use super::maximal::sphere::ExactCap;
use super::maximal::tangency::{orientation_violations, ExactCircle};
pub use super::maximal::violation::Violation;
use super::metric::{cone_angles, cos_pi, lengths_from_radii};
use crate::mesh::Mesh;
use crate::scalar::{Interval, Mpfr, Precision};
use rug::Rational;

type I = Interval<Mpfr>;

/// Enclosures of `‖c_i − c_j‖ − (ρ_i + ρ_j)` per edge of `mesh` (mesh edge order) at
/// precision `p`; `circles` has one entry per vertex.
pub fn plane_tangency_defects(mesh: &Mesh, circles: &[ExactCircle], p: Precision) -> Vec<I> {
    super::maximal::tangency::tangency_defects(mesh, circles, p)
}

/// Faces whose centres are not positively oriented and, when there is none, interior
/// vertices around which the neighbours do not wind exactly once (exact, proofs/B95).
pub fn plane_orientation_violations(mesh: &Mesh, circles: &[ExactCircle]) -> Vec<Violation> {
    orientation_violations(mesh, circles)
}

/// Enclosures of the inversive distance minus one, `I_ij − 1` with
/// `I_ij = (H_i H_j − N_i·N_j)/√((|N_i|² − H_i²)(|N_j|² − H_j²))`, per edge of `mesh` (mesh
/// edge order) at precision `p`: zero exactly for externally tangent caps (proofs/B96).
/// Every cap must be proper (`|N|² > H²`), else the entry is invalid.
pub fn cap_tangency_defects(mesh: &Mesh, caps: &[ExactCap], p: Precision) -> Vec<I> {
    super::maximal::sphere::inversive_defects(mesh, caps, p)
}

/// Faces whose cap centres are not positively oriented and, when there is none, vertices
/// around which the neighbours' centres do not wind exactly once (exact, proofs/B96).
pub fn cap_orientation_violations(mesh: &Mesh, caps: &[ExactCap]) -> Vec<Violation> {
    super::maximal::sphere::orientation_violations(mesh, caps)
}

/// Enclosures of the cone angle `θ_v` per vertex of the circle pattern with radii `radii`
/// (one per vertex, positive) and intersection angles `Φ_e = phi_over_pi[e]·π` (mesh edge
/// order, in `[0, π/2]`) at precision `p`: Eq. 9 lengths, corner angles by the half-angle
/// formula, summed (`cos Φ` exact for `Φ/π ∈ {0, 1/3, 1/2}`). A face whose enclosed lengths
/// are not proved a triangle gives invalid enclosures at its vertices.
pub fn pattern_cone_angles(
    mesh: &Mesh,
    radii: &[Rational],
    phi_over_pi: &[Rational],
    p: Precision,
) -> Vec<I> {
    let r: Vec<I> = radii.iter().map(|q| I::from_rational(q, p)).collect();
    let c: Vec<I> = phi_over_pi.iter().map(|q| cos_pi::<I>(q, p)).collect();
    cone_angles(mesh, &lengths_from_radii(mesh, &r, &c))
}
