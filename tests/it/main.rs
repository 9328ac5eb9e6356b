//! The integration test crate: one module per area.

mod cli;
mod exact;
mod interval;
mod io;
mod mesh;
mod mesh_core;
mod oracle;
mod scalar_dd;
mod predicates_planar;
#[allow(dead_code)] // helpers used by some areas only
mod support;
mod tidy;
