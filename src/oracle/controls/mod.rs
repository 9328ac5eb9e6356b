//! Negative controls: each runs the comparison of one catalogue check on data made wrong
//! by a fixed, stated perturbation — the kind the property tests use — so the check is
//! *expected to fail*. `penner check SURFACE --negative-controls` runs them, writes a failure
//! file (shrunk surface and witnesses) for each control that fails, and `penner replay`
//! re-runs such a file by the control's ID.
//!
//! A control that holds is reported as such, never hidden: it means the check did not see
//! its perturbation on this surface, which deserves a look (`penner check` then exits 1).
//! A control answers `NotApplicable` (with the reason) where its check does not apply to
//! the surface, mirroring the registry ([`super::checks`]).
//!
//! Control IDs are the check's ID followed by `-NC` (`T16-NC`); they are not in the
//! catalogue, so reports never list them as theorems. The controls live by subject:
//! [`metric`] (T01–T07), [`conformal`] (T15–T20, T35), [`flips`] (T21–T29).

use super::registry::Check;
use crate::io::Surface;
use crate::mesh::Edge;
use crate::predicates::delaunay::QuadEdges;
use crate::theorems::Verdict;
use rug::Rational;

pub mod circles;
pub mod conformal;
pub mod energy;
pub mod flips;
pub mod lobachevsky;
pub mod metric;
pub mod uniformization;

/// The relative perturbation of a length (or squared length) used by the metric controls:
/// 1/100, far above every tolerance of the catalogue at every precision (the largest, at
/// `f64`, are a few hundred units of 2⁻⁵³ relative: B40, B45, B48, B64).
pub fn bump() -> Rational {
    Rational::from((101, 100))
}

/// The first interior edge (both sides in distinct faces), where a length change is seen
/// by the quantities around it.
pub fn first_interior_edge(case: &Surface) -> Option<Edge> {
    case.mesh
        .edges()
        .find(|&e| QuadEdges::of(&case.mesh, e).is_some())
}

/// The side `jk` of the quadrilateral of [`first_interior_edge`]: a length whose change
/// moves that edge's cross ratio `c_ij = ℓ_il ℓ_jk / (ℓ_ki ℓ_lj)`.
pub fn first_quad_side(case: &Surface) -> Option<Edge> {
    let e = first_interior_edge(case)?;
    QuadEdges::of(&case.mesh, e).map(|q| q.edges.jk)
}

/// Why the cross-ratio controls do not apply to the two-triangle sphere.
pub const TRIVIAL_CROSS_RATIOS: &str =
    "every cross ratio of the two-triangle sphere is 1 whatever the lengths (T18): nothing to perturb";

fn not_applicable(reason: &str) -> Verdict {
    Verdict::NotApplicable {
        reason: reason.to_string(),
    }
}

/// Every negative control, in catalogue order of the checks they exercise.
pub fn controls() -> Vec<Check> {
    let mut all = metric::controls();
    all.extend(conformal::controls());
    all.extend(flips::controls());
    all.extend(energy::controls());
    all.extend(circles::controls());
    all.extend(lobachevsky::controls());
    all.extend(uniformization::controls());
    all.sort_by_key(|c| c.id);
    all
}

/// The control with exactly this ID (case-insensitive).
pub fn by_id(id: &str) -> Option<Check> {
    controls()
        .into_iter()
        .find(|c| c.id.eq_ignore_ascii_case(id))
}
