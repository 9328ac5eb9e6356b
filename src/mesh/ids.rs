//! Newtype indices for the half-edge Δ-complex. Half-edges `2e` and `2e+1` are the two
//! sides of edge `e`, so `twin(h) = h ^ 1`.

use std::fmt;

macro_rules! id {
    ($(#[$m:meta])* $name:ident, $tag:literal) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
        pub struct $name(pub u32);
        impl $name {
            /// The index as `usize`, for slicing per-element arrays.
            #[inline]
            pub fn idx(self) -> usize {
                self.0 as usize
            }
        }
        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, concat!($tag, "{}"), self.0)
            }
        }
    };
}
id!(
    /// A half-edge: one side of an edge, oriented from its tail to its tip.
    HalfEdge, "h"
);
id!(
    /// An edge: the pair of half-edges `2e`, `2e+1`.
    Edge, "e"
);
id!(
    /// A vertex.
    Vertex, "v"
);
id!(
    /// A triangular face.
    Face, "f"
);

impl HalfEdge {
    /// The other side of the same edge: `h ^ 1`.
    #[inline]
    pub fn twin(self) -> HalfEdge {
        HalfEdge(self.0 ^ 1)
    }
    /// The edge this half-edge is a side of: `h / 2`.
    #[inline]
    pub fn edge(self) -> Edge {
        Edge(self.0 >> 1)
    }
}

impl Edge {
    /// The half-edge `2e` (side 0) or `2e+1` (side 1).
    #[inline]
    pub fn side(self, s: u32) -> HalfEdge {
        HalfEdge(2 * self.0 + (s & 1))
    }
    /// Half-edge `2e`.
    #[inline]
    pub fn halfedge(self) -> HalfEdge {
        HalfEdge(2 * self.0)
    }
}
