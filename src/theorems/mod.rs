//! Read-only checks, one per catalogue ID (MATH.md). Checks never mutate and never panic;
//! a failing check lists *all* failing elements.

pub mod verdict;

pub use verdict::{Settings, Verdict, Witness};
pub mod t21_delaunay_flipping;
pub mod t22_delaunay_uniqueness;
pub mod t23_euclidean_flip_cone_metric;
pub mod t27_shear_log_cross_ratio;
pub mod t28_ptolemy_flip;
pub mod t29_euclidean_ptolemy_cocircular;
