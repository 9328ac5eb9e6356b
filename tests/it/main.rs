//! The integration test crate: one module per area.

mod mesh_core;
mod support;
