//! The only place a number becomes a decision: certified signs and the escalation ladder.
pub mod delaunay;
pub mod directed;
mod filter;
pub mod ladder;
pub mod planar;
pub mod triangle;
pub mod within;
pub mod cotan;
pub mod tolerance;
