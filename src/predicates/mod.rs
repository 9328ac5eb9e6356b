//! The only place a number becomes a decision: certified signs and the escalation ladder.
mod filter;
pub mod ladder;
pub mod planar;
pub mod triangle;
pub mod within;
