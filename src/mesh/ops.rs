//! Local operations besides the flip: inserting a vertex in a face.

use super::{Face, HalfEdge, Mesh, Vertex};

/// Why a face cannot be split.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SplitError {
    /// No such face.
    #[error("face {0} does not exist")]
    OutOfRange(Face),
    /// The result would exceed the 32-bit index range.
    #[error("the mesh is too large to split further")]
    TooLarge,
}

impl Mesh {
    /// Insert a new vertex `v` inside face `f = abc` (a 1→3 stellar subdivision): `f`
    /// becomes `abv`, two new faces `bcv` and `cav` are appended, and three new edges
    /// `av`, `bv`, `cv` are appended (half-edges `2E, 2E+1` = `a→v, v→a`, then `b→v, v→b`,
    /// then `c→v, v→c`). V, E, F grow by 1, 3, 2, so χ is unchanged. Works on
    /// Δ-complexes (a, b, c need not be distinct).
    ///
    /// ```
    /// use penner::mesh::{builders, Face};
    /// let mut m = builders::one_vertex_torus();
    /// let v = m.split_face(Face(0)).unwrap();
    /// assert_eq!((m.n_vertices(), m.degree(v), m.euler_characteristic()), (2, 3, 0));
    /// ```
    pub fn split_face(&mut self, f: Face) -> Result<Vertex, SplitError> {
        if f.idx() >= self.n_faces() {
            return Err(SplitError::OutOfRange(f));
        }
        if self.n_halfedges() + 6 >= (u32::MAX / 2) as usize {
            return Err(SplitError::TooLarge);
        }
        let [h0, h1, h2] = self.face_halfedges(f);
        let [a, b, c] = [h0, h1, h2].map(|h| self.tail(h));
        let v = Vertex(self.n_vertices);
        self.n_vertices += 1;
        let base = self.n_halfedges() as u32;
        let (x, y, z) = (HalfEdge(base), HalfEdge(base + 2), HalfEdge(base + 4));
        let f1 = self.n_faces() as u32;
        let f2 = f1 + 1;
        // x = a→v, x^1 = v→a, y = b→v, y^1 = v→b, z = c→v, z^1 = v→c
        let links: [(HalfEdge, HalfEdge, Vertex, u32); 6] = [
            (x, z.twin(), a, f2),
            (x.twin(), h0, v, f.0),
            (y, x.twin(), b, f.0),
            (y.twin(), h1, v, f1),
            (z, y.twin(), c, f1),
            (z.twin(), h2, v, f2),
        ];
        for (h, n, t, fa) in links {
            debug_assert_eq!(h.idx(), self.next.len());
            self.next.push(n);
            self.tail.push(t);
            self.face.push(fa);
        }
        self.next[h0.idx()] = y;
        self.next[h1.idx()] = z;
        self.next[h2.idx()] = x;
        self.face[h1.idx()] = f1;
        self.face[h2.idx()] = f2;
        self.face_halfedge[f.idx()] = h0;
        self.face_halfedge.push(h1);
        self.face_halfedge.push(h2);
        self.out.push(x.twin());
        Ok(v)
    }
}
