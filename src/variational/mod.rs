//! Variational principles of discrete conformal geometry (notes §1.6.3–1.6.4, Eqs. 16–17;
//! docs/catalogue.md §7): the per-triangle function `f` whose gradient is half the angles, the
//! discrete-uniformization energy `E(u)` with gradient `Θ − θ(u)` and the cotan Laplacian
//! as Hessian, on a fixed triangulation and on the intrinsic Delaunay triangulation of the
//! scaled metric, and the hyperbolic analogue (BPS15 §6).
//!
//! Layer: above `algorithms` (the variable triangulation is reached by Ptolemy flips), below
//! `theorems`. Everything is generic over [`Real`](crate::scalar::Real), so
//! [`Dual`](crate::scalar::Dual) numbers give exact-rule derivatives and
//! `Interval<Mpfr>` gives enclosures. Lobachevsky's `Л` comes from
//! [`crate::special::lobachevsky`], called generically: on `Interval<Mpfr>` it returns
//! its rigorous enclosure (proofs/B52).

pub mod energy;
pub mod fast_f64;
pub mod fast_mpfr;
pub mod hyperbolic;
pub mod pattern;
pub mod triangle;
pub mod weights;
