//! T18 — notes Example 1: on the two-triangle sphere (V = 3, E = 3, F = 2) all discrete
//! metrics are conformally equivalent (every cross ratio is identically 1).
//!
//! API:
//! - `pub fn check_all_metrics_equivalent<T: Real>(mesh: &Mesh, l: &[T], lt: &[T], settings: &Settings) -> Verdict`
//! - `pub fn check_all_metrics_equivalent_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict`
//!
//! The check is T17's equivalence test applied to an arbitrary pair of metrics: on the
//! two-triangle sphere it holds for every pair; on other surfaces (the negative control, e.g.
//! a tetrahedron) an arbitrary pair is refused.

use super::t17_cross_ratio_equivalence::{
    check_conformal_equivalence, check_conformal_equivalence_exact,
};
use super::verdict::{Settings, Verdict};
use crate::mesh::Mesh;
use crate::scalar::Real;
use rug::Rational;

/// Whether `mesh` is the two-triangle sphere: closed, V = 3, E = 3, F = 2.
pub fn is_two_triangle_sphere(mesh: &Mesh) -> bool {
    mesh.is_closed() && (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()) == (3, 3, 2)
}

/// T18, numerical: `l` and `lt` are conformally equivalent
/// ([`check_conformal_equivalence`]).
///
/// ```
/// use penner::mesh::Mesh;
/// use penner::theorems::{t18_two_triangle_sphere::check_all_metrics_equivalent, Settings};
/// let s = Mesh::from_faces(3, &[[0, 1, 2], [0, 2, 1]]).unwrap();
/// let v = check_all_metrics_equivalent(&s, &[3.0_f64, 4.0, 5.0], &[1.0, 1.0, 1.5], &Settings::default());
/// assert!(v.holds());
/// ```
pub fn check_all_metrics_equivalent<T: Real>(
    mesh: &Mesh,
    l: &[T],
    lt: &[T],
    settings: &Settings,
) -> Verdict {
    check_conformal_equivalence(mesh, l, lt, settings)
}

/// T18, exact in ℚ (certified).
pub fn check_all_metrics_equivalent_exact(mesh: &Mesh, l: &[Rational], lt: &[Rational]) -> Verdict {
    check_conformal_equivalence_exact(mesh, l, lt)
}
