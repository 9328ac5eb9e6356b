//! Circle patterns and circle packings (notes Part II §1.4, Eq. 9; docs/catalogue.md §8): a circle of
//! radius `r_i = e^{u_i}` at every vertex, an intersection angle `Φ_e ∈ [0, π/2]` on every
//! edge (0 tangent, π/2 orthogonal), and the Euclidean metric they induce.
//!
//! - [`metric`]: lengths from radii and angles (Euclidean, inversive distance,
//!   hyperbolic), corner and cone angles, generic over [`Real`](crate::scalar::Real) —
//!   evaluated on [`Interval`](crate::scalar::Interval)s they are certified enclosures.
//! - [`jacobian`]: `∂θ/∂u` from the power centres of the faces (symmetric, zero row sums).
//! - [`pattern`]: a problem (mesh, angles `Φ`, target cone angles `Θ`) with typed errors.
//! - [`solve`]: Newton on the convex energy and the combinatorial Ricci flow (Chow–Luo).
//! - [`certify`]: a ball around a computed solution on which the grounded Hessian is proved
//!   positive definite and which provably contains a solution (T09).
//! - [`thurston`]: Thurston's 3- and 4-cycle conditions (T10).
//! - [`layout`], [`svg`], [`pack`]: planar layouts, pictures, and the packing of a surface
//!   that `penner pack` draws.
//! - [`realize`]: enclosures and exact signs deciding whether given circles, caps or radii
//!   realize a triangulation as a packing or pattern (the `circle_packing` and
//!   `circle_pattern` claims of `penner certify`).
//! - [`harmonic`]: harmonic maps of disks to convex polygons (T36).
//! - [`hexagonal`]: hexagonal lattice complexes of planar domains (Rodin–Sullivan, T12).
//! - [`face_pattern`]: circle patterns with one circle per face from intersection angles
//!   (Rivin angle systems, T14).
//! - [`rivin`]: Rivin weights of ideal polyhedra and Farkas certificates of their
//!   infeasibility (T34).

pub mod certify;
pub mod face_pattern;
pub mod harmonic;
pub mod hexagonal;
pub mod jacobian;
pub mod layout;
pub mod maximal;
pub mod metric;
pub mod pack;
pub mod pattern;
pub mod realize;
pub mod rivin;
pub mod solve;
pub mod svg;

pub mod thurston;
pub use pattern::{CirclePattern, PatternError};
