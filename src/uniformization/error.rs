//! Typed errors of the uniformization solver and its certificate.

use crate::algorithms::flip_to_delaunay::FlipToDelaunayError;

/// Why a uniformization problem was refused (bad input, named by element).
#[derive(Debug, thiserror::Error)]
pub enum UniformizeError {
    /// The surface has boundary edges; only closed surfaces are handled.
    #[error("the surface has {edges} boundary edge(s); uniformization needs a closed surface")]
    NotClosed {
        /// How many boundary edges.
        edges: usize,
    },
    /// The surface has no faces.
    #[error("the surface has no faces")]
    Empty,
    /// Wrong number of targets.
    #[error("{expected} target angles expected (one per vertex), got {got}")]
    TargetCount {
        /// Vertices.
        expected: usize,
        /// Targets given.
        got: usize,
    },
    /// A target is not finite.
    #[error("target angle of vertex v{vertex} is {value}: not a finite number")]
    NonFiniteTarget {
        /// The vertex.
        vertex: u32,
        /// The value given.
        value: f64,
    },
    /// A target is `≤ 0`.
    #[error("target angle of vertex v{vertex} is {over_pi}·π: cone angles must be > 0")]
    NonPositiveTarget {
        /// The vertex.
        vertex: u32,
        /// `Θ/π` as an exact rational.
        over_pi: String,
    },
    /// Gauss–Bonnet is violated on a component.
    #[error(
        "Gauss–Bonnet: on the component of v{root}, Σ(2π − Θ_i) = {sum_over_pi}·π but 2πχ = {}·π (χ = {chi})",
        2 * chi
    )]
    GaussBonnet {
        /// The smallest vertex of the component.
        root: u32,
        /// `Σ(2 − Θ_i/π)` exactly.
        sum_over_pi: String,
        /// The Euler characteristic of the component.
        chi: i64,
    },
    /// Wrong number of lengths.
    #[error("{expected} edge lengths expected, got {got}")]
    LengthCount {
        /// Edges.
        expected: usize,
        /// Lengths given.
        got: usize,
    },
    /// A length is not positive and finite.
    #[error("length of edge e{edge} is {value}: not a positive finite number")]
    BadLength {
        /// The edge.
        edge: u32,
        /// The value.
        value: f64,
    },
    /// A starting scale factor is not finite or too large.
    #[error("starting scale factor of vertex v{vertex} is {value}: not finite or |u| > 2²⁰")]
    BadStart {
        /// The vertex.
        vertex: u32,
        /// The value.
        value: f64,
    },
    /// The initial Euclidean flips to an intrinsic Delaunay triangulation failed (e.g. a face
    /// is not a certified triangle).
    #[error("making the input intrinsic Delaunay: {0}")]
    InitialDelaunay(#[from] FlipToDelaunayError),
    /// The initial Euclidean flips did not certify every edge Delaunay.
    #[error("making the input intrinsic Delaunay: {undecided} edge(s) undecided or refused, or the flip cap was hit")]
    InitialNotDelaunay {
        /// Edges left undecided or refused.
        undecided: usize,
    },
}
