//! The only place a number becomes a decision: certified signs and the escalation ladder.
pub mod cotan;
pub mod delaunay;
pub mod delaunay_exp;
pub mod delaunay_widened;
pub mod directed;
mod filter;
pub mod ladder;
pub mod planar;
pub mod separation;
pub mod tolerance;
pub mod triangle;
pub mod within;
