//! The integration test crate: one module per area.

mod cli;
mod dual;
mod exact;
mod interval;
mod io;
mod mesh;
mod mesh_core;
mod oracle;
mod predicates_planar;
mod scalar_dd;
#[allow(dead_code)] // helpers used by some areas only
mod support;
mod tidy;
