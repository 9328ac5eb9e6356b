//! Vertex circulators: the outgoing half-edges around a vertex.

use super::{HalfEdge, Mesh, Vertex};

/// Iterator over the outgoing half-edges of a vertex (see [`Mesh::outgoing`]).
#[derive(Clone, Debug)]
pub struct Outgoing<'a> {
    mesh: &'a Mesh,
    start: HalfEdge,
    current: Option<HalfEdge>,
}

impl Iterator for Outgoing<'_> {
    type Item = HalfEdge;
    fn next(&mut self) -> Option<HalfEdge> {
        let g = self.current?;
        let t = g.twin();
        self.current = if self.mesh.is_boundary_halfedge(t) {
            None
        } else {
            Some(self.mesh.next(t)).filter(|&n| n != self.start)
        };
        Some(g)
    }
}

impl Mesh {
    /// One outgoing half-edge of `v`; for a boundary vertex, the boundary half-edge
    /// leaving it.
    #[inline]
    pub fn vertex_halfedge(&self, v: Vertex) -> HalfEdge {
        self.out[v.idx()]
    }

    /// The outgoing half-edges of `v`, each exactly once, by the rotation
    /// `g ↦ next(twin(g))` (clockwise with respect to the counter-clockwise faces). For a
    /// boundary vertex the first is the boundary half-edge leaving `v` and the last is
    /// the interior half-edge whose twin is the boundary half-edge arriving at `v`. A loop
    /// at `v` contributes both of its half-edges.
    ///
    /// ```
    /// use penner::mesh::{builders, Vertex};
    /// let oct = builders::octahedron().mesh;
    /// assert!(oct.vertices().all(|v| oct.degree(v) == 4));
    /// let v = Vertex(0);
    /// assert!(oct.outgoing(v).all(|h| oct.tail(h) == v));
    /// ```
    pub fn outgoing(&self, v: Vertex) -> Outgoing<'_> {
        let start = self.vertex_halfedge(v);
        Outgoing {
            mesh: self,
            start,
            current: Some(start),
        }
    }

    /// Number of outgoing half-edges at `v` (edge ends; a loop counts twice).
    pub fn degree(&self, v: Vertex) -> usize {
        self.outgoing(v).count()
    }

    /// Whether `v` lies on the boundary.
    #[inline]
    pub fn is_boundary_vertex(&self, v: Vertex) -> bool {
        self.is_boundary_halfedge(self.vertex_halfedge(v))
    }

    /// Number of boundary loops (cycles of `next` through boundary half-edges).
    pub fn n_boundary_loops(&self) -> usize {
        let mut seen = vec![false; self.n_halfedges()];
        let mut loops = 0;
        for h in self.halfedges() {
            if self.is_boundary_halfedge(h) && !seen[h.idx()] {
                loops += 1;
                let mut g = h;
                while !seen[g.idx()] {
                    seen[g.idx()] = true;
                    g = self.next(g);
                }
            }
        }
        loops
    }
}
