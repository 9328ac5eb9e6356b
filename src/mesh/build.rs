//! Building a [`Mesh`] from faces (vertex triples) and, where vertex ids alone are
//! ambiguous (loops, multi-edges, self-glued faces), from an explicit gluing of face sides.

use super::{HalfEdge, Mesh, Vertex, NO_FACE};

/// A side of a face: side `s` of face `f` runs from corner `s` to corner `(s+1) mod 3`.
pub type FaceSide = (u32, u8);

/// Why a list of faces (and gluing) does not describe an oriented surface.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MeshError {
    /// No faces at all.
    #[error("the surface has no faces")]
    Empty,
    /// A face names a vertex id ≥ the vertex count.
    #[error("face {face} names vertex {vertex}, but there are only {n_vertices} vertices")]
    VertexOutOfRange {
        /// Face index.
        face: u32,
        /// Offending vertex id.
        vertex: u32,
        /// Number of vertices.
        n_vertices: u32,
    },
    /// A vertex belongs to no face.
    #[error("vertex {vertex} belongs to no face")]
    IsolatedVertex {
        /// The unused vertex.
        vertex: u32,
    },
    /// Three or more face sides share one edge, or two sides run the same way.
    #[error("edge {a}→{b} is used by more than one face in the same direction (non-manifold edge or inconsistent orientation)")]
    NonManifoldEdge {
        /// Tail vertex.
        a: u32,
        /// Tip vertex.
        b: u32,
    },
    /// A side whose two ends are one vertex needs an explicit gluing.
    #[error("face {face} has a loop side at vertex {vertex}; give an explicit gluing")]
    AmbiguousLoop {
        /// Face index.
        face: u32,
        /// The loop's vertex.
        vertex: u32,
    },
    /// The faces around a vertex form more than one fan.
    #[error("vertex {vertex} is non-manifold (its faces form more than one fan)")]
    NonManifoldVertex {
        /// Offending vertex.
        vertex: u32,
    },
    /// A gluing names a face or side that does not exist.
    #[error("gluing {index} names face side ({face}, {side}) that does not exist")]
    GluingOutOfRange {
        /// Position in the gluing list.
        index: usize,
        /// Face index.
        face: u32,
        /// Side index.
        side: u8,
    },
    /// A face side appears in two gluings (or is glued to itself).
    #[error("face side ({face}, {side}) is glued more than once")]
    SideGluedTwice {
        /// Face index.
        face: u32,
        /// Side index.
        side: u8,
    },
    /// The glued sides' vertex ids do not match as an orientable gluing requires.
    #[error("gluing {index} joins side {a0}→{a1} to side {b0}→{b1}; an orientable gluing needs {a0}→{a1} against {a1}→{a0}")]
    InconsistentGluing {
        /// Position in the gluing list.
        index: usize,
        /// First side tail.
        a0: u32,
        /// First side tip.
        a1: u32,
        /// Second side tail.
        b0: u32,
        /// Second side tip.
        b1: u32,
    },
    /// Too many elements for 32-bit indices.
    #[error("too many elements: {count} exceeds the 32-bit index range")]
    TooLarge {
        /// The count.
        count: usize,
    },
}

impl Mesh {
    /// Build from counter-clockwise vertex triples, gluing side `a→b` to the unique side
    /// `b→a`. Unmatched sides become boundary. Loops and multi-edges need
    /// [`Mesh::from_gluing`].
    ///
    /// ```
    /// use penner::mesh::Mesh;
    /// let tet = Mesh::from_faces(4, &[[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]).unwrap();
    /// assert_eq!(tet.euler_characteristic(), 2);
    /// ```
    pub fn from_faces(n_vertices: u32, faces: &[[u32; 3]]) -> Result<Mesh, MeshError> {
        check_faces(n_vertices, faces)?;
        let gluing = gluing_by_vertices(n_vertices, faces, None)?;
        Mesh::from_gluing(n_vertices, faces, &gluing)
    }

    /// Build from vertex triples and the glued pairs of face sides that the triples cannot
    /// describe (`exceptions`, e.g. the sides of loops and of parallel edges): the listed
    /// pairs are glued as in [`Mesh::from_gluing`], and every other side `a→b` to the
    /// unique other unlisted side `b→a` as in [`Mesh::from_faces`]. With no exceptions this
    /// is [`Mesh::from_faces`].
    ///
    /// ```
    /// use penner::mesh::Mesh;
    /// // A tetrahedron with edge 01 flipped: two edges join vertices 2 and 3 (the new
    /// // diagonal, sides 0 of faces 0 and 2, and the old edge, sides 1 of faces 1 and 3).
    /// let faces = [[3, 2, 0], [0, 2, 3], [2, 3, 1], [1, 3, 2]];
    /// let m = Mesh::from_faces_with_exceptions(4, &faces, &[((0, 0), (2, 0)), ((1, 1), (3, 1))])
    ///     .unwrap();
    /// assert_eq!((m.n_edges(), m.euler_characteristic()), (6, 2));
    /// assert!(Mesh::from_faces(4, &faces).is_err());
    /// ```
    pub fn from_faces_with_exceptions(
        n_vertices: u32,
        faces: &[[u32; 3]],
        exceptions: &[(FaceSide, FaceSide)],
    ) -> Result<Mesh, MeshError> {
        check_faces(n_vertices, faces)?;
        let mut listed = vec![false; 3 * faces.len()];
        for (index, &(p, q)) in exceptions.iter().enumerate() {
            for (f, s) in [p, q] {
                if f as usize >= faces.len() || s > 2 {
                    return Err(MeshError::GluingOutOfRange {
                        index,
                        face: f,
                        side: s,
                    });
                }
                listed[3 * f as usize + s as usize] = true;
            }
        }
        let mut gluing = exceptions.to_vec();
        gluing.extend(gluing_by_vertices(n_vertices, faces, Some(&listed))?);
        Mesh::from_gluing(n_vertices, faces, &gluing)
    }

    /// Build a Δ-complex from faces and an explicit list of glued side pairs. Side `s` of
    /// face `f` runs from `faces[f][s]` to `faces[f][(s+1)%3]`; a glued pair must run in
    /// opposite directions (orientable). Unglued sides become boundary.
    ///
    /// ```
    /// use penner::mesh::Mesh;
    /// // One-vertex torus: two triangles, three edges, one vertex.
    /// let t = Mesh::from_gluing(1, &[[0, 0, 0], [0, 0, 0]],
    ///     &[((0, 0), (1, 0)), ((0, 1), (1, 1)), ((0, 2), (1, 2))]).unwrap();
    /// assert_eq!((t.n_vertices(), t.n_edges(), t.n_faces()), (1, 3, 2));
    /// assert_eq!(t.euler_characteristic(), 0);
    /// ```
    pub fn from_gluing(
        n_vertices: u32,
        faces: &[[u32; 3]],
        gluing: &[(FaceSide, FaceSide)],
    ) -> Result<Mesh, MeshError> {
        check_faces(n_vertices, faces)?;
        let nf = faces.len();
        let side_vertex = |(f, s): FaceSide| -> (u32, u32) {
            let t = faces[f as usize];
            (t[s as usize], t[(s as usize + 1) % 3])
        };
        // Half-edge of each side, assigned edge by edge.
        let mut side_he = vec![u32::MAX; 3 * nf];
        let mut n_edges: u32 = 0;
        for (index, &(p, q)) in gluing.iter().enumerate() {
            for (f, s) in [p, q] {
                if f as usize >= nf || s > 2 {
                    return Err(MeshError::GluingOutOfRange {
                        index,
                        face: f,
                        side: s,
                    });
                }
            }
            let (a0, a1) = side_vertex(p);
            let (b0, b1) = side_vertex(q);
            if a0 != b1 || a1 != b0 {
                return Err(MeshError::InconsistentGluing {
                    index,
                    a0,
                    a1,
                    b0,
                    b1,
                });
            }
            for (k, (f, s)) in [p, q].into_iter().enumerate() {
                let slot = &mut side_he[3 * f as usize + s as usize];
                if *slot != u32::MAX || (k == 1 && p == q) {
                    return Err(MeshError::SideGluedTwice { face: f, side: s });
                }
                *slot = 2 * n_edges + k as u32;
            }
            n_edges += 1;
        }
        for slot in &mut side_he {
            if *slot == u32::MAX {
                *slot = 2 * n_edges;
                n_edges += 1;
            }
        }
        let nh = 2 * n_edges as usize;
        let mut next = vec![HalfEdge(u32::MAX); nh];
        let mut tail = vec![Vertex(u32::MAX); nh];
        let mut face = vec![NO_FACE; nh];
        let mut face_halfedge = Vec::with_capacity(nf);
        for (f, tri) in faces.iter().enumerate() {
            for s in 0..3 {
                let h = side_he[3 * f + s] as usize;
                next[h] = HalfEdge(side_he[3 * f + (s + 1) % 3]);
                tail[h] = Vertex(tri[s]);
                face[h] = f as u32;
            }
            face_halfedge.push(HalfEdge(side_he[3 * f]));
        }
        // Boundary half-edges: tail is the tip of their interior twin.
        for h in 0..nh {
            if face[h] == NO_FACE {
                let t = HalfEdge(h as u32).twin();
                tail[h] = tail[next[t.idx()].idx()];
            }
        }
        let mut mesh = Mesh {
            next,
            tail,
            face,
            face_halfedge,
            out: Vec::new(),
            n_vertices,
        };
        mesh.link_boundary_and_check_vertices()?;
        Ok(mesh)
    }

    /// Link each boundary half-edge to the boundary half-edge leaving its tip, and check
    /// that the corners around every vertex form a single fan.
    fn link_boundary_and_check_vertices(&mut self) -> Result<(), MeshError> {
        let nv = self.n_vertices();
        let mut degree = vec![0usize; nv];
        let mut boundary_out: Vec<Option<HalfEdge>> = vec![None; nv];
        let mut any_out: Vec<Option<HalfEdge>> = vec![None; nv];
        for h in self.halfedges() {
            let v = self.tail(h).idx();
            degree[v] += 1;
            any_out[v] = Some(h);
            if self.is_boundary_halfedge(h) {
                if boundary_out[v].is_some() {
                    return Err(MeshError::NonManifoldVertex { vertex: v as u32 });
                }
                boundary_out[v] = Some(h);
            }
        }
        for h in self.halfedges() {
            if self.is_boundary_halfedge(h) {
                let v = self.tip(h).idx();
                let out =
                    boundary_out[v].ok_or(MeshError::NonManifoldVertex { vertex: v as u32 })?;
                self.next[h.idx()] = out;
            }
        }
        for v in 0..nv {
            let Some(start) = boundary_out[v].or(any_out[v]) else {
                return Err(MeshError::IsolatedVertex { vertex: v as u32 });
            };
            // Rotate through outgoing half-edges: g ↦ next(twin(g)) while twin(g) is interior.
            let mut count = 1;
            let mut g = start;
            loop {
                let t = g.twin();
                if self.is_boundary_halfedge(t) {
                    break;
                }
                g = self.next(t);
                if g == start {
                    break;
                }
                count += 1;
                if count > degree[v] {
                    break;
                }
            }
            if count != degree[v] {
                return Err(MeshError::NonManifoldVertex { vertex: v as u32 });
            }
            self.out.push(start);
        }
        Ok(())
    }

    /// The face list as vertex triples (starting at each face's first half-edge).
    pub fn face_list(&self) -> Vec<[u32; 3]> {
        self.faces()
            .map(|f| self.face_vertices(f).map(|v| v.0))
            .collect()
    }

    /// The gluing of face sides: for each interior edge, the two (face, side) pairs, where
    /// side indices refer to [`Mesh::face_halfedges`] order. Together with
    /// [`Mesh::face_list`] this rebuilds the mesh with [`Mesh::from_gluing`].
    pub fn gluing_list(&self) -> Vec<(FaceSide, FaceSide)> {
        let mut side_of = vec![(u32::MAX, 0u8); self.n_halfedges()];
        for f in self.faces() {
            for (s, h) in self.face_halfedges(f).into_iter().enumerate() {
                side_of[h.idx()] = (f.0, s as u8);
            }
        }
        self.edges()
            .filter(|&e| !self.is_boundary_edge(e))
            .map(|e| (side_of[e.side(0).idx()], side_of[e.side(1).idx()]))
            .collect()
    }
}

fn check_faces(n_vertices: u32, faces: &[[u32; 3]]) -> Result<(), MeshError> {
    if faces.is_empty() {
        return Err(MeshError::Empty);
    }
    if faces.len() >= (u32::MAX / 8) as usize {
        return Err(MeshError::TooLarge { count: faces.len() });
    }
    for (f, tri) in faces.iter().enumerate() {
        for &v in tri {
            if v >= n_vertices {
                return Err(MeshError::VertexOutOfRange {
                    face: f as u32,
                    vertex: v,
                    n_vertices,
                });
            }
        }
    }
    // More vertices than face corners: some vertex is unused. Found without allocating
    // per vertex, so a huge declared count costs nothing.
    if n_vertices as usize > 3 * faces.len() {
        let mut used: Vec<u32> = faces.iter().flatten().copied().collect();
        used.sort_unstable();
        used.dedup();
        let vertex = used
            .iter()
            .enumerate()
            .find(|&(i, &v)| v != i as u32)
            .map_or(used.len() as u32, |(i, _)| i as u32);
        return Err(MeshError::IsolatedVertex { vertex });
    }
    Ok(())
}

/// The gluing of [`Mesh::from_faces`] over the sides not marked in `skip`: each side
/// `a→b` glued to the unique unmarked side `b→a`; a loop side or a repeated directed side
/// among them is an error.
fn gluing_by_vertices(
    n_vertices: u32,
    faces: &[[u32; 3]],
    skip: Option<&[bool]>,
) -> Result<Vec<(FaceSide, FaceSide)>, MeshError> {
    let side = |p: usize| -> (u32, u32) {
        let t = faces[p / 3];
        (t[p % 3], t[(p % 3 + 1) % 3])
    };
    let n_sides = 3 * faces.len();
    let used = |p: usize| skip.is_none_or(|s| !s[p]);
    // Sides bucketed by tail vertex (a counting sort), each bucket sorted by (tip,
    // position): equal directed sides are adjacent, and a side's opposite is found by
    // binary search in its tip's bucket. Linear memory, no hashing.
    let mut start = vec![0u32; n_vertices as usize + 1];
    for p in (0..n_sides).filter(|&p| used(p)) {
        start[side(p).0 as usize + 1] += 1;
    }
    for v in 0..n_vertices as usize {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut by_tail = vec![(0u32, 0u32); start[n_vertices as usize] as usize];
    for p in (0..n_sides).filter(|&p| used(p)) {
        let (a, b) = side(p);
        let slot = &mut fill[a as usize];
        by_tail[*slot as usize] = (b, p as u32);
        *slot += 1;
    }
    // The first error in face order, as a scan inserting side after side finds it: a
    // loop, or the second occurrence of a directed side.
    let mut first: Option<(u32, MeshError)> = None;
    let mut keep_first = |pos: u32, e: MeshError| {
        if first.as_ref().is_none_or(|(q, _)| pos < *q) {
            first = Some((pos, e));
        }
    };
    for a in 0..n_vertices {
        let lo = start[a as usize] as usize;
        let hi = start[a as usize + 1] as usize;
        by_tail[lo..hi].sort_unstable();
        for w in by_tail[lo..hi].windows(2) {
            if w[0].0 == w[1].0 {
                keep_first(w[1].1, MeshError::NonManifoldEdge { a, b: w[0].0 });
            }
        }
        for &(b, p) in &by_tail[lo..hi] {
            if a == b {
                keep_first(
                    p,
                    MeshError::AmbiguousLoop {
                        face: p / 3,
                        vertex: a,
                    },
                );
            }
        }
    }
    if let Some((_, e)) = first {
        return Err(e);
    }
    // Glue each side a→b (a < b) to the side b→a, in order of the first side: the
    // list comes out sorted.
    let bucket = |a: u32| &by_tail[start[a as usize] as usize..start[a as usize + 1] as usize];
    let mut gluing = Vec::new();
    for p in (0..n_sides).filter(|&p| used(p)) {
        let (a, b) = side(p);
        if a < b {
            let twins = bucket(b);
            if let Ok(k) = twins.binary_search_by(|&(t, _)| t.cmp(&a)) {
                let q = twins[k].1 as usize;
                gluing.push((
                    ((p / 3) as u32, (p % 3) as u8),
                    ((q / 3) as u32, (q % 3) as u8),
                ));
            }
        }
    }
    Ok(gluing)
}
