//! The only place a number becomes a decision: certified signs and the escalation ladder.
pub mod ladder;
pub mod within;
