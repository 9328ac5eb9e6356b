//! The integration test crate: one module per area.

mod cli;
mod interval;
mod io;
mod mesh;
mod mesh_core;
mod oracle;
#[allow(dead_code)] // helpers used by some areas only
mod support;
mod tidy;
