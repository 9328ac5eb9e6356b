//! Pure combinatorics: the half-edge Δ-complex. No numbers live here.
//!
//! A [`Mesh`] is an oriented triangulated surface, possibly with boundary, of any genus,
//! where faces may share several edges, edges may be loops, and a face may be glued to
//! itself (the one-vertex torus: V = 1, E = 3, F = 2).
//!
//! Conventions (docs/catalogue.md): a face `ijk` is counter-clockwise; half-edge `h = (i→j)` lies in
//! face `ijk`, `next(h) = (j→k)`, and the corner *opposite* `h` is at `k = tail(prev(h))`.
//! Boundary half-edges have no face; their `next` runs along the boundary loop.

mod build;
pub mod builders;
mod circulate;
pub mod cut;
pub mod double;
mod flip;
mod ids;
mod invariants;
mod ops;
pub mod relabel;

pub use build::{FaceSide, MeshError};
pub use builders::{BuildError, Embedded, Intrinsic};
pub use circulate::Outgoing;
pub use flip::FlipError;
pub use ids::{Edge, Face, HalfEdge, Vertex};
pub use invariants::{InvariantError, RawMesh};
pub use ops::SplitError;

/// Sentinel for "no face" in the packed face array.
const NO_FACE: u32 = u32::MAX;

/// A half-edge Δ-complex (see the module documentation for conventions).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mesh {
    next: Vec<HalfEdge>,
    tail: Vec<Vertex>,
    face: Vec<u32>,
    face_halfedge: Vec<HalfEdge>,
    /// One outgoing half-edge per vertex: the boundary one for a boundary vertex.
    out: Vec<HalfEdge>,
    n_vertices: u32,
}

impl Mesh {
    /// Number of vertices V.
    pub fn n_vertices(&self) -> usize {
        self.n_vertices as usize
    }
    /// Number of edges E.
    pub fn n_edges(&self) -> usize {
        self.next.len() / 2
    }
    /// Number of faces F.
    pub fn n_faces(&self) -> usize {
        self.face_halfedge.len()
    }
    /// Number of half-edges 2E.
    pub fn n_halfedges(&self) -> usize {
        self.next.len()
    }
    /// Euler characteristic χ = V − E + F, counting every cell of the Δ-complex.
    pub fn euler_characteristic(&self) -> i64 {
        self.n_vertices() as i64 - self.n_edges() as i64 + self.n_faces() as i64
    }

    /// All vertices.
    pub fn vertices(&self) -> impl ExactSizeIterator<Item = Vertex> + Clone + use<> {
        (0..self.n_vertices).map(Vertex)
    }
    /// All edges.
    pub fn edges(&self) -> impl ExactSizeIterator<Item = Edge> + Clone + use<> {
        (0..self.n_edges() as u32).map(Edge)
    }
    /// All faces.
    pub fn faces(&self) -> impl ExactSizeIterator<Item = Face> + Clone + use<> {
        (0..self.n_faces() as u32).map(Face)
    }
    /// All half-edges.
    pub fn halfedges(&self) -> impl ExactSizeIterator<Item = HalfEdge> + Clone + use<> {
        (0..self.n_halfedges() as u32).map(HalfEdge)
    }

    /// Next half-edge around the face (or along the boundary loop).
    #[inline]
    pub fn next(&self, h: HalfEdge) -> HalfEdge {
        self.next[h.idx()]
    }
    /// Previous half-edge around a face: `next(next(h))`. Only meaningful for half-edges
    /// in a face; boundary loops are longer than three.
    #[inline]
    pub fn prev(&self, h: HalfEdge) -> HalfEdge {
        self.next(self.next(h))
    }
    /// Tail (start) vertex of `h`.
    #[inline]
    pub fn tail(&self, h: HalfEdge) -> Vertex {
        self.tail[h.idx()]
    }
    /// Tip (end) vertex of `h` = tail of its twin.
    #[inline]
    pub fn tip(&self, h: HalfEdge) -> Vertex {
        self.tail[h.twin().idx()]
    }
    /// Face containing `h`, or `None` for a boundary half-edge.
    #[inline]
    pub fn face(&self, h: HalfEdge) -> Option<Face> {
        let f = self.face[h.idx()];
        (f != NO_FACE).then_some(Face(f))
    }
    /// Whether `h` is a boundary half-edge (has no face).
    #[inline]
    pub fn is_boundary_halfedge(&self, h: HalfEdge) -> bool {
        self.face[h.idx()] == NO_FACE
    }
    /// Whether `e` has a boundary half-edge on one side.
    #[inline]
    pub fn is_boundary_edge(&self, e: Edge) -> bool {
        self.is_boundary_halfedge(e.side(0)) || self.is_boundary_halfedge(e.side(1))
    }
    /// Vertex opposite `h` in its face: `tail(prev(h))` (the `k` of `α_k^{ij}`).
    #[inline]
    pub fn opposite_vertex(&self, h: HalfEdge) -> Vertex {
        self.tail(self.prev(h))
    }
    /// The corners `[i, j, k, l]` of the quadrilateral around edge `e` (docs/catalogue.md §5): `i→j`
    /// is half-edge `2e` in face `ijk`, `j→i` is `2e+1` in face `jil`. On a boundary side
    /// the opposite corner is read through the boundary loop; callers test interior first.
    #[inline]
    pub fn quad_vertices(&self, e: Edge) -> [Vertex; 4] {
        let h = e.side(0);
        [
            self.tail(h),
            self.tip(h),
            self.opposite_vertex(h),
            self.opposite_vertex(e.side(1)),
        ]
    }
    /// One half-edge of face `f`.
    #[inline]
    pub fn face_halfedge(&self, f: Face) -> HalfEdge {
        self.face_halfedge[f.idx()]
    }
    /// The three half-edges of `f` in counter-clockwise order, starting at `face_halfedge(f)`.
    #[inline]
    pub fn face_halfedges(&self, f: Face) -> [HalfEdge; 3] {
        let a = self.face_halfedge(f);
        let b = self.next(a);
        [a, b, self.next(b)]
    }
    /// The three vertices of `f` (tails of [`Mesh::face_halfedges`]); repeats are possible.
    pub fn face_vertices(&self, f: Face) -> [Vertex; 3] {
        self.face_halfedges(f).map(|h| self.tail(h))
    }
    /// Per vertex: does it lie on the boundary?
    pub fn boundary_vertices(&self) -> Vec<bool> {
        let mut b = vec![false; self.n_vertices()];
        for h in self.halfedges() {
            if self.is_boundary_halfedge(h) {
                b[self.tail(h).idx()] = true;
            }
        }
        b
    }
    /// Whether the surface has no boundary.
    pub fn is_closed(&self) -> bool {
        self.face.iter().all(|&f| f != NO_FACE)
    }
    /// Number of boundary edges.
    pub fn n_boundary_edges(&self) -> usize {
        self.edges().filter(|&e| self.is_boundary_edge(e)).count()
    }
}
