//! The common refinement of the input triangulation `T_in` and a triangulation `T`
//! reached from it by flips (issue 29), first slice: the combinatorics.
//!
//! - [`normal_coordinates`]: the integer normal coordinates of the edges of `T_in`
//!   relative to the current triangulation `T`, kept through flips by a purely
//!   combinatorial update (proof: B105). The update holds for Euclidean and Ptolemy flips
//!   alike, since the flipped edge is the same isotopy class of arc either way.
//!
//! Not computed yet: the crossing positions along the edges and the faces of the
//! refinement with their barycentric coordinates; after Ptolemy flips the positions need
//! the projective maps of the flips and are not computed either (the combinatorics are).

pub mod normal_coordinates;

pub use normal_coordinates::{replay_normal_coordinates, NormalCoordinates, NormalError};
