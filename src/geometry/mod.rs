//! Numbers on a mesh: lengths, angles, cotan weights, cross ratios. Never branches on values.

pub mod cone_angles;
pub mod corners;
pub mod cotan;
pub mod cross_ratio;
pub mod curvature;
pub mod enclosure;
pub mod energy;
pub mod exact3d;
pub mod laplacian;
pub mod scaling;
pub mod triangle;
pub mod unfold;
