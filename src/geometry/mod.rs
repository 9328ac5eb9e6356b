//! Numbers on a mesh: lengths, angles, cotan weights, cross ratios. Never branches on values.

pub mod cone_angles;
pub mod triangle;
