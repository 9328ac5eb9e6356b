//! The structural invariants of a half-edge Δ-complex, checked from scratch, and the raw
//! arrays a [`Mesh`] is made of.

use super::{HalfEdge, Mesh, Vertex, NO_FACE};

/// The arrays of a [`Mesh`], with plain integer indices. [`Mesh::to_raw`] exports them;
/// [`Mesh::from_raw`] accepts them only if [`Mesh::check_invariants`] holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RawMesh {
    /// `next[h]`: next half-edge around the face of `h`, or along its boundary loop.
    pub next: Vec<u32>,
    /// `tail[h]`: the vertex `h` starts at.
    pub tail: Vec<u32>,
    /// `face[h]`: the face of `h`, `None` for a boundary half-edge.
    pub face: Vec<Option<u32>>,
    /// `face_halfedge[f]`: one half-edge of face `f`.
    pub face_halfedge: Vec<u32>,
    /// `out[v]`: one half-edge leaving `v`; for a boundary vertex, the boundary one.
    pub out: Vec<u32>,
    /// Number of vertices.
    pub n_vertices: u32,
}

/// A violated structural invariant (see [`Mesh::check_invariants`]).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum InvariantError {
    /// Per-half-edge, per-face or per-vertex arrays have inconsistent lengths.
    #[error("array `{array}` has length {len}, expected {expected}")]
    Length {
        /// Name of the array.
        array: &'static str,
        /// Its length.
        len: usize,
        /// The expected length.
        expected: usize,
    },
    /// An index points outside its array.
    #[error("`{array}[{index}]` = {value} is out of range")]
    OutOfRange {
        /// Name of the array.
        array: &'static str,
        /// Position in the array.
        index: usize,
        /// The offending value.
        value: u32,
    },
    /// `next` maps two half-edges to the same one: not a permutation.
    #[error("`next` is not a permutation: h{0} is the next of two half-edges")]
    NotPermutation(u32),
    /// A face's half-edges do not form a 3-cycle of `next`.
    #[error(
        "face f{face}: `next` does not cycle through three half-edges of the face (at h{halfedge})"
    )]
    NotTriangle {
        /// The face.
        face: u32,
        /// A half-edge of it where the cycle breaks.
        halfedge: u32,
    },
    /// A face's stored half-edge does not belong to it.
    #[error("face_halfedge[f{face}] = h{halfedge} belongs to another face")]
    FaceHalfedge {
        /// The face.
        face: u32,
        /// Its stored half-edge.
        halfedge: u32,
    },
    /// Both sides of an edge are boundary: a dangling edge.
    #[error("edge e{0} has no face on either side")]
    DanglingEdge(u32),
    /// `next` leaves the boundary from a boundary half-edge.
    #[error("boundary half-edge h{0} is followed by an interior half-edge")]
    BoundaryLoop(u32),
    /// `tail(next(h)) ≠ tip(h)`.
    #[error("h{halfedge} ends at v{tip} but its next half-edge starts at v{next_tail}")]
    TailMismatch {
        /// The half-edge.
        halfedge: u32,
        /// Its tip (tail of its twin).
        tip: u32,
        /// Tail of its next half-edge.
        next_tail: u32,
    },
    /// A vertex is the tail of no half-edge.
    #[error("vertex v{0} has no outgoing half-edge")]
    IsolatedVertex(u32),
    /// `out[v]` does not leave `v`, or is interior while `v` has a boundary half-edge.
    #[error("out[v{vertex}] = h{halfedge} is not a valid (boundary-first) outgoing half-edge")]
    BadOut {
        /// The vertex.
        vertex: u32,
        /// Its stored half-edge.
        halfedge: u32,
    },
    /// The corners around a vertex do not form a single fan (or disk).
    #[error("vertex v{vertex} is non-manifold: rotation reaches {reached} of its {degree} outgoing half-edges")]
    NonManifoldVertex {
        /// The vertex.
        vertex: u32,
        /// Outgoing half-edges reached by rotation.
        reached: usize,
        /// Outgoing half-edges in total.
        degree: usize,
    },
}

impl Mesh {
    /// The raw arrays of this mesh.
    pub fn to_raw(&self) -> RawMesh {
        RawMesh {
            next: self.next.iter().map(|h| h.0).collect(),
            tail: self.tail.iter().map(|v| v.0).collect(),
            face: self
                .face
                .iter()
                .map(|&f| (f != NO_FACE).then_some(f))
                .collect(),
            face_halfedge: self.face_halfedge.iter().map(|h| h.0).collect(),
            out: self.out.iter().map(|h| h.0).collect(),
            n_vertices: self.n_vertices,
        }
    }

    /// A mesh from raw arrays, refused with the first violated invariant
    /// ([`Mesh::check_invariants`]).
    ///
    /// ```
    /// use penner::mesh::{builders, InvariantError, Mesh};
    /// let mut raw = builders::tetrahedron().mesh.to_raw();
    /// assert!(Mesh::from_raw(raw.clone()).is_ok());
    /// raw.next.swap(0, 1);
    /// assert!(Mesh::from_raw(raw).is_err());
    /// ```
    pub fn from_raw(raw: RawMesh) -> Result<Mesh, InvariantError> {
        let nh = raw.next.len();
        let nf = raw.face_halfedge.len();
        let nv = raw.n_vertices as usize;
        len_is("next", nh, nh + nh % 2)?;
        len_is("tail", raw.tail.len(), nh)?;
        len_is("face", raw.face.len(), nh)?;
        len_is("out", raw.out.len(), nv)?;
        in_range("next", &raw.next, nh)?;
        in_range("tail", &raw.tail, nv)?;
        in_range("face_halfedge", &raw.face_halfedge, nh)?;
        in_range("out", &raw.out, nh)?;
        for (index, f) in raw.face.iter().enumerate() {
            if let Some(f) = *f {
                if f as usize >= nf || f == NO_FACE {
                    return Err(InvariantError::OutOfRange {
                        array: "face",
                        index,
                        value: f,
                    });
                }
            }
        }
        let mesh = Mesh {
            next: raw.next.into_iter().map(HalfEdge).collect(),
            tail: raw.tail.into_iter().map(Vertex).collect(),
            face: raw.face.into_iter().map(|f| f.unwrap_or(NO_FACE)).collect(),
            face_halfedge: raw.face_halfedge.into_iter().map(HalfEdge).collect(),
            out: raw.out.into_iter().map(HalfEdge).collect(),
            n_vertices: raw.n_vertices,
        };
        mesh.check_invariants()?;
        Ok(mesh)
    }

    /// Check every structural invariant from scratch, returning the first violation:
    ///
    /// 1. array lengths agree and every index is in range;
    /// 2. `next` is a permutation of the half-edges;
    /// 3. every face is a 3-cycle of `next` whose half-edges all name the face, and
    ///    `face_halfedge[f]` lies in `f`;
    /// 4. no edge has boundary on both sides, and `next` of a boundary half-edge is a
    ///    boundary half-edge (boundary loops are closed cycles of `next`);
    /// 5. `tail(next(h)) = tip(h)` for every half-edge;
    /// 6. every vertex has an outgoing half-edge, `out[v]` leaves `v` and is the boundary
    ///    one when `v` is on the boundary, and rotating `g ↦ next(twin(g))` from `out[v]`
    ///    reaches all outgoing half-edges of `v` (one fan per vertex: a disk or a
    ///    half-disk neighbourhood).
    ///
    /// Every constructor and [`Mesh::flip`] keep these; the check is for tests and for
    /// meshes built with [`Mesh::from_raw`].
    pub fn check_invariants(&self) -> Result<(), InvariantError> {
        self.check_arrays()?;
        self.check_faces_and_boundary()?;
        self.check_vertices()
    }

    /// Invariants 1 and 2.
    fn check_arrays(&self) -> Result<(), InvariantError> {
        let nh = self.next.len();
        let nf = self.face_halfedge.len();
        let nv = self.n_vertices();
        len_is("next", nh, nh + nh % 2)?;
        len_is("tail", self.tail.len(), nh)?;
        len_is("face", self.face.len(), nh)?;
        len_is("out", self.out.len(), nv)?;
        let next_raw: Vec<u32> = self.next.iter().map(|h| h.0).collect();
        in_range("next", &next_raw, nh)?;
        let tail_raw: Vec<u32> = self.tail.iter().map(|v| v.0).collect();
        in_range("tail", &tail_raw, nv)?;
        let fh_raw: Vec<u32> = self.face_halfedge.iter().map(|h| h.0).collect();
        in_range("face_halfedge", &fh_raw, nh)?;
        let out_raw: Vec<u32> = self.out.iter().map(|h| h.0).collect();
        in_range("out", &out_raw, nh)?;
        for (index, &f) in self.face.iter().enumerate() {
            if f != NO_FACE && f as usize >= nf {
                return Err(InvariantError::OutOfRange {
                    array: "face",
                    index,
                    value: f,
                });
            }
        }
        // 2. permutation
        let mut hit = vec![false; nh];
        for &n in &self.next {
            if std::mem::replace(&mut hit[n.idx()], true) {
                return Err(InvariantError::NotPermutation(n.0));
            }
        }
        Ok(())
    }

    /// Invariants 3, 4 and 5.
    fn check_faces_and_boundary(&self) -> Result<(), InvariantError> {
        let nf = self.face_halfedge.len();
        // 3. faces
        let mut per_face = vec![0usize; nf];
        for h in self.halfedges() {
            if let Some(f) = self.face(h) {
                per_face[f.idx()] += 1;
                let (a, b) = (self.next(h), self.next(self.next(h)));
                if self.next(b) != h || a == h || self.face(a) != Some(f) || self.face(b) != Some(f)
                {
                    return Err(InvariantError::NotTriangle {
                        face: f.0,
                        halfedge: h.0,
                    });
                }
            }
        }
        for f in self.faces() {
            if per_face[f.idx()] != 3 {
                return Err(InvariantError::NotTriangle {
                    face: f.0,
                    halfedge: self.face_halfedge(f).0,
                });
            }
            let h = self.face_halfedge(f);
            if self.face(h) != Some(f) {
                return Err(InvariantError::FaceHalfedge {
                    face: f.0,
                    halfedge: h.0,
                });
            }
        }
        // 4. boundary
        for e in self.edges() {
            if self.is_boundary_halfedge(e.side(0)) && self.is_boundary_halfedge(e.side(1)) {
                return Err(InvariantError::DanglingEdge(e.0));
            }
        }
        for h in self.halfedges() {
            if self.is_boundary_halfedge(h) && !self.is_boundary_halfedge(self.next(h)) {
                return Err(InvariantError::BoundaryLoop(h.0));
            }
        }
        // 5. tails
        for h in self.halfedges() {
            let (tip, next_tail) = (self.tip(h), self.tail(self.next(h)));
            if tip != next_tail {
                return Err(InvariantError::TailMismatch {
                    halfedge: h.0,
                    tip: tip.0,
                    next_tail: next_tail.0,
                });
            }
        }
        Ok(())
    }

    /// Invariant 6.
    fn check_vertices(&self) -> Result<(), InvariantError> {
        let nv = self.n_vertices();
        let mut degree = vec![0usize; nv];
        let mut on_boundary = vec![false; nv];
        for h in self.halfedges() {
            let v = self.tail(h).idx();
            degree[v] += 1;
            on_boundary[v] |= self.is_boundary_halfedge(h);
        }
        for v in self.vertices() {
            if degree[v.idx()] == 0 {
                return Err(InvariantError::IsolatedVertex(v.0));
            }
            let o = self.out[v.idx()];
            if self.tail(o) != v || on_boundary[v.idx()] != self.is_boundary_halfedge(o) {
                return Err(InvariantError::BadOut {
                    vertex: v.0,
                    halfedge: o.0,
                });
            }
            let reached = self.outgoing(v).take(degree[v.idx()] + 1).count();
            if reached != degree[v.idx()] {
                return Err(InvariantError::NonManifoldVertex {
                    vertex: v.0,
                    reached,
                    degree: degree[v.idx()],
                });
            }
        }
        Ok(())
    }
}

fn len_is(array: &'static str, len: usize, expected: usize) -> Result<(), InvariantError> {
    if len == expected {
        Ok(())
    } else {
        Err(InvariantError::Length {
            array,
            len,
            expected,
        })
    }
}

fn in_range(array: &'static str, values: &[u32], bound: usize) -> Result<(), InvariantError> {
    match values.iter().position(|&x| x as usize >= bound) {
        None => Ok(()),
        Some(index) => Err(InvariantError::OutOfRange {
            array,
            index,
            value: values[index],
        }),
    }
}
