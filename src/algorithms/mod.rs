//! Algorithms on metric Δ-complexes. Every decision goes through [`crate::predicates`].
//!
//! - [`flips`]: Euclidean and Ptolemy flips of one edge (docs/catalogue.md §5).
//! - [`flip_to_delaunay`]: flip to an intrinsic Delaunay triangulation with certified
//!   signs (T21).
//! - [`flip_scaled`]: the same for conformally scaled metrics `e^{(u_i+u_j)/2}·ℓ_ij`, with
//!   the exponent kept apart (no overflow for `|u|` up to 2²⁰).
//! - [`replay`]: replay a recorded flip sequence on the exact input metric with certified
//!   arithmetic (B80), to certify a rounded run's triangulation for the input;
//!   [`replay_dag`] holds its lazily built flip lengths (B85), [`replay_len`] the length
//!   types and their certified arithmetic, [`replay_input`] the input metrics it reads,
//!   [`replay_chord`] the exact new lengths of flips on planar hinges of positions (B106),
//!   [`replay_algebraic`] the exact signs of ties on algebraic lengths (B107).
//! - [`flip_replay`]: a `delaunay_flip` claim's flip sequence replayed on the lengths of
//!   [`replay`] and its result compared under vertex-fixing relabelings (B80, B81);
//!   [`tie_search`] searches the claim's tie flips (B82).
//! - [`verdict`]: witnesses and the three-valued claim verdict, shared with the layers
//!   above.
//! - [`naive`]: an uncertified `f64` baseline, for benchmarks and for showing where raw
//!   floating-point decisions go wrong.

pub mod delaunay_pipeline;
pub mod flip_replay;
pub mod flip_scaled;
pub mod flip_to_delaunay;
pub mod flips;
pub mod naive;
pub mod replay;
pub mod replay_algebraic;
pub mod replay_chord;
pub mod replay_dag;
pub mod replay_input;
pub mod replay_len;
pub mod tie_search;
pub mod verdict;
