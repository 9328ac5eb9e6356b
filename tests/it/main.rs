//! The integration test crate: one module per area.

mod claims;
mod cli;
mod cli_controls;
mod cli_io;
mod cone_angles_kernel;
mod controls;
mod definition_two;
mod delaunay;
mod delaunay_adversarial;
mod delaunay_flips;
mod delaunay_genus;
mod delaunay_scaled;
mod delaunay_triangles;
mod delaunay_undecided;
mod delaunay_uniqueness;
mod dual;
mod exact;
mod interval;
mod io;
mod io_decimal;
mod laplacian;
mod mesh;
mod mesh_core;
mod mesh_enumeration;
mod meshgen;
mod oracle;
mod planar_gen;
mod predicates_planar;
mod registry_extra;
mod scalar_dd;
mod scalar_dd_div;
mod scalar_dd_exp;
mod scalar_dd_reduction;
#[cfg(feature = "strategies")]
mod strategies;
#[allow(dead_code)] // helpers used by some areas only
mod support;
mod theorems_certified;
mod theorems_fixed;
mod theorems_flips;
mod theorems_random;
mod tidy;
mod tie_claims;
mod tolerance_range;
