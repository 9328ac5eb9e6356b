//! The integration test crate: one module per area.

mod cli;
mod interval;
mod mesh;
mod mesh_core;
#[allow(dead_code)] // helpers used by some areas only
mod support;
mod tidy;
