//! Special functions generic over [`Real`](crate::scalar::Real): Lobachevsky's function `Л`
//! and Clausen's `Cl₂` (MATH.md §7, notes §1.6.3), the base of the hyperbolic volumes and
//! of the discrete-uniformization energy.

pub mod lobachevsky;

pub use lobachevsky::{clausen2, ideal_tetrahedron_volume, lobachevsky};
