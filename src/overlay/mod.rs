//! The common refinement of the input triangulation `T_in` and a triangulation `T`
//! reached from it by flips (issue 29).
//!
//! - [`normal_coordinates`]: the integer normal coordinates of the edges of `T_in`
//!   relative to the current triangulation `T`, kept through flips by a purely
//!   combinatorial update (proof: B105). The update holds for Euclidean and Ptolemy flips
//!   alike, since the flipped edge is the same isotopy class of arc either way.
//! - [`tracking`]: the crossing positions, tracked through the Euclidean flips in the
//!   input metric (every edge of `T` then a geodesic of the input metric; B108) and through
//!   the Ptolemy flips in the Klein picture of the base metric (B111).
//! - [`refinement`]: the refinement as a triangle mesh, each triangle knowing its face of
//!   `T` and of `T_in` (B108).
//! - [`uv`]: texture coordinates from a layout of `T` with its final lengths, 3-D
//!   positions and barycentric coordinates, and the OBJ and sidecar texts (B109).
//! - [`check`]: the exact checks of written files: no fold, each input face tiled (B109).
//! - [`seams`]: the exact seam check: rotations by multiples of π/2 within `ε` (B110).
//! - [`claim`]: the claim kind `parametrization`, answered by those checks.
//!
//! A surface with boundary is refined on its double and restricted to copy 1
//! ([`Refinement::restricted_to_input_faces`]). Along an input edge, positions made by
//! Ptolemy flips are a parametrization choice (B111), not the flat arc length.

pub mod check;
pub mod claim;
pub mod normal_coordinates;
pub mod refinement;
pub mod seams;
pub mod svg;
pub mod tracking;
pub mod uv;

pub use check::{check_parametrization, check_parametrization_text, ParametrizationReport};
pub use normal_coordinates::{replay_normal_coordinates, NormalCoordinates, NormalError};
pub use refinement::{common_refinement, Refinement, RefinementError};
pub use seams::{check_seams, SeamReport};
pub use svg::render_uv_svg;
pub use tracking::{track_euclidean_then_ptolemy, track_flips, TrackError, TrackedOverlay};
pub use uv::{uv_mesh, UvError, UvMesh};
