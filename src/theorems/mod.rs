//! Read-only checks, one per catalogue ID (MATH.md). Checks never mutate and never panic;
//! a failing check lists *all* failing elements.

pub mod verdict;

pub use verdict::{Settings, Verdict, Witness};
