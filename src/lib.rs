//! # penner
//!
//! Certified checks of the theorems of discrete conformal geometry on triangulated
//! surfaces (Δ-complexes with edge-length metrics), following K. Crane, *Conformal
//! Geometry of Simplicial Surfaces*. One numeric-generic core runs in `f64`, double-double
//! ([`scalar::Dd`]) and MPFR ([`scalar::Mpfr`]); predicates are decided exactly or with
//! rigorous enclosures, and answer `Undecided` rather than guess.
//!
//! Layers (each imports only layers above it): [`scalar`] → [`special`] → [`mesh`] → [`geometry`] →
//! [`predicates`] → `algorithms` → [`overlay`] → `theorems` → `oracle` → the `penner` binary.

pub mod algorithms;
pub mod circles;
pub mod geometry;
pub mod io;
pub mod mesh;
pub mod oracle;
pub mod overlay;
pub mod predicates;
pub mod scalar;
pub mod special;
#[cfg(feature = "strategies")]
pub mod strategies;
pub mod theorems;
pub mod uniformization;
pub mod variational;
