//! The double of a surface with boundary: two copies of the mesh, the second with reversed
//! orientation, glued along the boundary (boundary vertices and boundary edges shared).
//! The double is a closed oriented Δ-complex with `χ(D) = 2χ(M) − χ(∂M) = 2χ(M)` (the
//! boundary is a union of circles, `χ(∂M) = 0`), and the mirror involution `ι` swaps the
//! two copies and fixes the boundary (the seam) pointwise. proof: B78
//!
//! Numbering (so that copy 1 keeps the ids of `M`):
//! - vertices: the `V` vertices of `M` (copy 1, boundary vertices shared), then one mirror
//!   vertex per interior vertex of `M`, in the order of `M`;
//! - edges: the `E` edges of `M` (boundary edges shared), then one mirror edge per interior
//!   edge of `M`, in order; half-edges `2e`, `2e + 1` as in every [`Mesh`];
//! - faces: the `F` faces of `M`, then face `F + f` = the mirror of `f`.
//!
//! Half-edge `h = 2e + s` of `M` has the mirror `σ(h)` = the half-edge of the mirror edge
//! with the mirrored tail and tip (`σ(h) = h` on a boundary edge). In the mirror face
//! `F + f` the half-edges of `f` run backwards: `g ↦ σ(twin(g))`, with
//! `next(σ(twin(g))) = σ(twin(prev(g)))`. A boundary half-edge of `M` (no face) becomes
//! the side of its edge in the mirror face. Loops, multi-edges, boundary edges whose two
//! ends are one vertex and several boundary components need no special case.

use super::{Edge, Face, HalfEdge, InvariantError, Mesh, RawMesh, Vertex};

/// Which copy an element of the double lies on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum Sheet {
    /// Copy 1: the surface `M` itself, same orientation, same ids.
    Original,
    /// Copy 2: the mirror image, orientation reversed.
    Mirror,
    /// On the boundary of `M`: shared by both copies, fixed by the mirror.
    Seam,
}

/// Why a double cannot be built.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DoubleError {
    /// The double would exceed the 32-bit index range.
    #[error("the double of a surface with {halfedges} half-edges exceeds the 32-bit index range")]
    TooLarge {
        /// Half-edges of the surface.
        halfedges: usize,
    },
    /// The glued arrays violate a mesh invariant (a bug, reported rather than panicking).
    #[error("the double violates a mesh invariant: {0}")]
    Invariant(#[from] InvariantError),
}

/// The double `D` of a surface `M` with its maps to `M` and the mirror involution `ι`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Double {
    /// The closed surface `D`.
    pub mesh: Mesh,
    /// Per vertex of `D`: the vertex of `M` it copies.
    pub vertex_origin: Vec<Vertex>,
    /// Per vertex of `D`: its copy.
    pub vertex_sheet: Vec<Sheet>,
    /// Per edge of `D`: the edge of `M` it copies.
    pub edge_origin: Vec<Edge>,
    /// Per edge of `D`: its copy.
    pub edge_sheet: Vec<Sheet>,
    /// Per face of `D`: the face of `M` it copies (faces are never on the seam).
    pub face_origin: Vec<Face>,
    /// Per face of `D`: [`Sheet::Original`] or [`Sheet::Mirror`].
    pub face_sheet: Vec<Sheet>,
    /// `ι` on vertices.
    pub vertex_mirror: Vec<Vertex>,
    /// `ι` on edges.
    pub edge_mirror: Vec<Edge>,
    /// `ι` on faces.
    pub face_mirror: Vec<Face>,
}

impl Double {
    /// The double of `mesh` (see the module documentation for the numbering). A closed
    /// `mesh` gives two disjoint copies. proof: B78
    ///
    /// ```
    /// use penner::mesh::{builders, double::Double};
    /// let disk = builders::grid_disk(2, 2).unwrap().mesh;
    /// let d = Double::of(&disk).unwrap();
    /// assert!(d.mesh.is_closed());
    /// assert_eq!(d.mesh.euler_characteristic(), 2 * disk.euler_characteristic());
    /// ```
    #[allow(clippy::too_many_lines)] // the glued arrays, then the maps, in order
    pub fn of(mesh: &Mesh) -> Result<Double, DoubleError> {
        let (nv, ne, nf) = (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
        let on_boundary = mesh.boundary_vertices();
        // Mirror ids.
        let mut vertex_mirror: Vec<u32> = Vec::with_capacity(2 * nv);
        let mut extra_vertices = Vec::new();
        for (v, &on) in on_boundary.iter().enumerate() {
            if on {
                vertex_mirror.push(v as u32);
            } else {
                vertex_mirror.push((nv + extra_vertices.len()) as u32);
                extra_vertices.push(v as u32);
            }
        }
        let mut edge_mirror: Vec<u32> = Vec::with_capacity(2 * ne);
        let mut extra_edges = Vec::new();
        for e in mesh.edges() {
            if mesh.is_boundary_edge(e) {
                edge_mirror.push(e.0);
            } else {
                edge_mirror.push((ne + extra_edges.len()) as u32);
                extra_edges.push(e.0);
            }
        }
        let (dv, de, df) = (nv + extra_vertices.len(), ne + extra_edges.len(), 2 * nf);
        if 2 * de >= (u32::MAX / 2) as usize || dv >= u32::MAX as usize {
            return Err(DoubleError::TooLarge {
                halfedges: mesh.n_halfedges(),
            });
        }
        // σ(h): the half-edge of the mirror edge with the mirrored tail and tip.
        let sigma = |h: HalfEdge| 2 * edge_mirror[h.edge().idx()] + (h.0 & 1);
        let iota = |v: Vertex| vertex_mirror[v.idx()];
        let mut next = vec![u32::MAX; 2 * de];
        let mut tail = vec![u32::MAX; 2 * de];
        let mut face: Vec<Option<u32>> = vec![None; 2 * de];
        for h in mesh.halfedges() {
            let Some(f) = mesh.face(h) else { continue };
            // Copy 1: as in M.
            next[h.idx()] = mesh.next(h).0;
            tail[h.idx()] = mesh.tail(h).0;
            face[h.idx()] = Some(f.0);
            // Copy 2: σ(twin(h)) in the mirror face, running backwards.
            let m = sigma(h.twin()) as usize;
            next[m] = sigma(mesh.prev(h).twin());
            tail[m] = iota(mesh.tip(h));
            face[m] = Some(nf as u32 + f.0);
        }
        let mut face_halfedge: Vec<u32> = mesh.faces().map(|f| mesh.face_halfedge(f).0).collect();
        face_halfedge.extend(mesh.faces().map(|f| sigma(mesh.face_halfedge(f).twin())));
        let mut out: Vec<u32> = mesh.vertices().map(|v| mesh.out[v.idx()].0).collect();
        out.extend(extra_vertices.iter().map(|&v| sigma(mesh.out[v as usize])));
        let raw = RawMesh {
            next,
            tail,
            face,
            face_halfedge,
            out,
            n_vertices: dv as u32,
        };
        let double = Mesh::from_raw(raw)?;
        // Maps.
        let mut vertex_origin: Vec<Vertex> = mesh.vertices().collect();
        vertex_origin.extend(extra_vertices.iter().map(|&v| Vertex(v)));
        let vertex_sheet = (0..dv)
            .map(|v| match v {
                _ if v >= nv => Sheet::Mirror,
                _ if on_boundary[v] => Sheet::Seam,
                _ => Sheet::Original,
            })
            .collect();
        let mut full_vertex_mirror: Vec<Vertex> =
            vertex_mirror.iter().map(|&v| Vertex(v)).collect();
        full_vertex_mirror.extend(extra_vertices.iter().map(|&v| Vertex(v)));
        let mut edge_origin: Vec<Edge> = mesh.edges().collect();
        edge_origin.extend(extra_edges.iter().map(|&e| Edge(e)));
        let edge_sheet = (0..de)
            .map(|e| match e {
                _ if e >= ne => Sheet::Mirror,
                _ if mesh.is_boundary_edge(Edge(e as u32)) => Sheet::Seam,
                _ => Sheet::Original,
            })
            .collect();
        let mut full_edge_mirror: Vec<Edge> = edge_mirror.iter().map(|&e| Edge(e)).collect();
        full_edge_mirror.extend(extra_edges.iter().map(|&e| Edge(e)));
        let face_origin = (0..df).map(|f| Face((f % nf.max(1)) as u32)).collect();
        let face_sheet = (0..df)
            .map(|f| {
                if f < nf {
                    Sheet::Original
                } else {
                    Sheet::Mirror
                }
            })
            .collect();
        let face_mirror = (0..df)
            .map(|f| Face(((f + nf) % df.max(1)) as u32))
            .collect();
        Ok(Double {
            mesh: double,
            vertex_origin,
            vertex_sheet,
            edge_origin,
            edge_sheet,
            face_origin,
            face_sheet,
            vertex_mirror: full_vertex_mirror,
            edge_mirror: full_edge_mirror,
            face_mirror,
        })
    }

    /// A per-edge quantity of `M` (a metric: each edge's length) carried to both copies:
    /// `x_D(e) = x_M(origin(e))`. `None` when `per_edge` does not have one entry per edge
    /// of `M`.
    pub fn pull_back_edges<T: Clone>(&self, per_edge: &[T]) -> Option<Vec<T>> {
        let n_m = self
            .edge_origin
            .iter()
            .map(|e| e.idx() + 1)
            .max()
            .unwrap_or(0);
        if per_edge.len() != n_m {
            return None;
        }
        Some(
            self.edge_origin
                .iter()
                .map(|e| per_edge[e.idx()].clone())
                .collect(),
        )
    }

    /// Check that `ι` is a mirror of the double: an involution on vertices, edges and
    /// faces; it fixes exactly the seam and swaps the sheets; it maps each edge's ends to
    /// the mirrored ends, and each face `abc` (counter-clockwise) to a face reading
    /// `ι(a) ι(c) ι(b)` (orientation reversed); and the origin maps agree with `ι`.
    /// `Err` names the first element where it fails.
    pub fn check_mirror(&self) -> Result<(), String> {
        let m = &self.mesh;
        let (nv, ne, nf) = (m.n_vertices(), m.n_edges(), m.n_faces());
        if self.vertex_mirror.len() != nv
            || self.edge_mirror.len() != ne
            || self.face_mirror.len() != nf
        {
            return Err("mirror arrays have the wrong lengths".into());
        }
        let in_range = |i: usize, n: usize| i < n;
        for v in m.vertices() {
            let w = self.vertex_mirror[v.idx()];
            if !in_range(w.idx(), nv) || self.vertex_mirror[w.idx()] != v {
                return Err(format!("ι is not an involution at {v}"));
            }
            let fixed = w == v;
            if fixed != (self.vertex_sheet[v.idx()] == Sheet::Seam)
                || self.vertex_origin[w.idx()] != self.vertex_origin[v.idx()]
            {
                return Err(format!("ι at {v} does not fix exactly the seam"));
            }
        }
        for e in m.edges() {
            let g = self.edge_mirror[e.idx()];
            if !in_range(g.idx(), ne) || self.edge_mirror[g.idx()] != e {
                return Err(format!("ι is not an involution at {e}"));
            }
            if (g == e) != (self.edge_sheet[e.idx()] == Sheet::Seam)
                || self.edge_origin[g.idx()] != self.edge_origin[e.idx()]
            {
                return Err(format!("ι at {e} does not fix exactly the seam"));
            }
            let (h, k) = (e.halfedge(), g.halfedge());
            let ends = [m.tail(h), m.tip(h)].map(|v| self.vertex_mirror[v.idx()]);
            let mirrored = [m.tail(k), m.tip(k)];
            if ends != mirrored {
                return Err(format!(
                    "ι maps the ends of {e} to other ends than those of {g}"
                ));
            }
        }
        for f in m.faces() {
            let g = self.face_mirror[f.idx()];
            if !in_range(g.idx(), nf) || self.face_mirror[g.idx()] != f || g == f {
                return Err(format!("ι is not a fixed-point-free involution at {f}"));
            }
            let [a, b, c] = m.face_vertices(f).map(|v| self.vertex_mirror[v.idx()]);
            let reversed = [a, c, b];
            let target = m.face_vertices(g);
            let rotations = [
                reversed,
                [reversed[1], reversed[2], reversed[0]],
                [reversed[2], reversed[0], reversed[1]],
            ];
            if !rotations.contains(&target) {
                return Err(format!(
                    "ι maps {f} to {g} without reversing its orientation"
                ));
            }
            let fe = m
                .face_halfedges(f)
                .map(|h| self.edge_mirror[h.edge().idx()]);
            let ge = m.face_halfedges(g).map(HalfEdge::edge);
            if !fe.iter().all(|e| ge.contains(e)) {
                return Err(format!("ι maps the edges of {f} outside {g}"));
            }
            if self.face_origin[g.idx()] != self.face_origin[f.idx()]
                || self.face_sheet[f.idx()] == self.face_sheet[g.idx()]
            {
                return Err(format!("ι at {f} does not swap the sheets"));
            }
        }
        Ok(())
    }
}
