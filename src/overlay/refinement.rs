//! The common refinement of `T_in` and the final triangulation `T_F` as a triangle mesh
//! (proof: B108).
//!
//! **Representation.** The vertices are the input vertices (ids `0..V`) followed by the
//! crossings of input edges with edges of `T_F`, input edge by input edge in order along
//! each. Inside a face of `T_F` the pieces of input edges are chords between points of
//! its boundary (a corner or a crossing on a side) that do not interleave (B105: corner
//! arcs and arcs from a corner), so they cut the face into convex polygons, the *cells*;
//! each cell lies in one input face, read from the orientation of any input piece on its
//! boundary (the cell lies to the left of the input half-edge it runs along). A cell is
//! split into triangles by a fan from its first vertex. Each triangle knows its three
//! vertices, its face of `T_F` with each corner's place there (a corner, or a point of a
//! side at a parameter), and its input face.
//!
//! **Counts** (a face of `T_F` with `1 + Σ n̂` triangles, where `n̂` are its sides' crossing
//! counts): `|F_R| = |F| + 2 Σ_e max(n_e, 0)` triangles and `|V_R| = |V| + Σ_e max(n_e, 0)`
//! vertices.

use super::tracking::TrackedOverlay;
use crate::mesh::{Edge, Face, HalfEdge, Mesh, Vertex};
use std::collections::{HashMap, HashSet};

/// A vertex of the refinement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RefinedVertex {
    /// An input vertex.
    Input(Vertex),
    /// A crossing of input edge `edge` (at `s` from the tail of its half-edge `2·edge`)
    /// with the edge of `T_F` of half-edge `on` (at `t` from `tail(on)`).
    Crossing {
        /// The input edge.
        edge: Edge,
        /// The position along it.
        s: f64,
        /// The crossed half-edge of `T_F`.
        on: HalfEdge,
        /// The position along `on`.
        t: f64,
    },
}

/// Where a corner of a refinement triangle lies in its face of `T_F` (sides and corners
/// numbered from the face's first half-edge `c₀`: corner `r` is `tail(c_r)`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FacePlace {
    /// Corner `r` of the face.
    Corner(usize),
    /// The point of side `c_r` at the parameter (from `tail(c_r)`).
    Side(usize, f64),
}

/// A triangle of the refinement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefinedTriangle {
    /// Its vertices (indices into [`Refinement::vertices`]), counterclockwise.
    pub vertices: [u32; 3],
    /// The face of `T_F` it lies in.
    pub final_face: Face,
    /// Its corners' places in that face.
    pub places: [FacePlace; 3],
    /// The face of `T_in` it lies in.
    pub input_face: Face,
}

/// The common refinement (module documentation).
#[derive(Clone, Debug)]
pub struct Refinement {
    /// The vertices: the input vertices, then the crossings.
    pub vertices: Vec<RefinedVertex>,
    /// The triangles.
    pub triangles: Vec<RefinedTriangle>,
}

/// Why the refinement could not be built.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RefinementError {
    /// The input is not the triangulation the overlay was tracked from.
    #[error("the overlay was not tracked from this input triangulation")]
    Mismatch,
    /// A face of `T_F` whose pieces do not cut it into cells of one input face.
    #[error("face f{face} of the final triangulation: {reason}")]
    Face {
        /// The face of `T_F`.
        face: u32,
        /// What went wrong.
        reason: &'static str,
    },
}

/// A step along a cell's boundary: a side piece of `T_F`, or a piece of input edge `g`
/// run along `2g` (`true`) or against it.
#[derive(Clone, Copy, Debug)]
enum Step {
    Side(usize),
    Input(Edge, bool),
}

/// The common refinement of `input` (= `T_in`) and the triangulation `tracked` reached
/// from it (module documentation).
pub fn common_refinement(
    input: &Mesh,
    tracked: &TrackedOverlay,
) -> Result<Refinement, RefinementError> {
    let t = &tracked.mesh;
    if input.n_edges() != t.n_edges() || input.n_vertices() != t.n_vertices() {
        return Err(RefinementError::Mismatch);
    }
    let mut vertices: Vec<RefinedVertex> = input.vertices().map(RefinedVertex::Input).collect();
    let mut first = Vec::with_capacity(tracked.paths.len());
    // Per half-edge of T_F, the crossings on it: (vertex id, parameter along it).
    let mut on_he: Vec<Vec<(u32, f64)>> = vec![Vec::new(); t.n_halfedges()];
    // Per face of T_F, its input pieces: (g, piece index).
    let mut pieces: Vec<Vec<(usize, usize)>> = vec![Vec::new(); t.n_faces()];
    for (g, p) in tracked.paths.iter().enumerate() {
        first.push(vertices.len() as u32);
        for c in &p.crossings {
            let id = vertices.len() as u32;
            vertices.push(RefinedVertex::Crossing {
                edge: Edge(g as u32),
                s: c.s,
                on: c.h,
                t: c.t,
            });
            on_he[c.h.idx()].push((id, c.t));
            on_he[c.h.twin().idx()].push((id, 1.0 - c.t));
        }
        if p.along.is_none() {
            for m in 0..=p.crossings.len() {
                if let Some(f) = tracked.piece_face(g, m) {
                    pieces[f.idx()].push((g, m));
                }
            }
        }
    }
    for l in &mut on_he {
        l.sort_by(|a, b| a.1.total_cmp(&b.1));
    }
    let mut triangles = Vec::new();
    for f in t.faces() {
        face_cells(
            input,
            tracked,
            f,
            &on_he,
            &pieces[f.idx()],
            &first,
            &mut triangles,
        )?;
    }
    Ok(Refinement {
        vertices,
        triangles,
    })
}

impl Refinement {
    /// The part of the refinement lying in the input faces `0..n_faces`, with its vertices
    /// renumbered: the input vertices `0..n_vertices` keep their ids, then come the
    /// crossings that a kept triangle uses, in their order here. On the double of a
    /// surface with boundary (B78: copy 1 keeps the ids of `M`) this is the refinement of
    /// `M`, since a face of copy 1 has only vertices `< V` and edges `< E` of `M`.
    /// `None` when a kept triangle uses an input vertex `≥ n_vertices`.
    pub fn restricted_to_input_faces(&self, n_faces: usize, n_vertices: usize) -> Option<Self> {
        let kept: Vec<RefinedTriangle> = self
            .triangles
            .iter()
            .filter(|t| t.input_face.idx() < n_faces)
            .copied()
            .collect();
        let mut used = vec![false; self.vertices.len()];
        for t in &kept {
            for v in t.vertices {
                used[v as usize] = true;
            }
        }
        let mut new_id = vec![u32::MAX; self.vertices.len()];
        let mut vertices = Vec::new();
        for (k, v) in self.vertices.iter().enumerate() {
            let keep = match v {
                RefinedVertex::Input(w) if w.idx() < n_vertices => true,
                RefinedVertex::Input(_) if used[k] => return None,
                RefinedVertex::Input(_) => false,
                RefinedVertex::Crossing { .. } => used[k],
            };
            if keep {
                new_id[k] = vertices.len() as u32;
                vertices.push(*v);
            }
        }
        let triangles = kept
            .into_iter()
            .map(|t| RefinedTriangle {
                vertices: t.vertices.map(|v| new_id[v as usize]),
                ..t
            })
            .collect();
        Some(Self {
            vertices,
            triangles,
        })
    }
}

/// The triangles of face `f` of `T_F`, appended to `out`.
fn face_cells(
    input: &Mesh,
    tracked: &TrackedOverlay,
    f: Face,
    on_he: &[Vec<(u32, f64)>],
    pieces: &[(usize, usize)],
    first: &[u32],
    out: &mut Vec<RefinedTriangle>,
) -> Result<(), RefinementError> {
    let t = &tracked.mesh;
    let bad = |reason| RefinementError::Face { face: f.0, reason };
    let c = t.face_halfedges(f);
    // The boundary cycle: (vertex id, place, the side the step after it runs along).
    let mut cycle: Vec<(u32, FacePlace, usize)> = Vec::new();
    let mut at: HashMap<(u32, HalfEdge), usize> = HashMap::new();
    let mut corner_at = [0usize; 3];
    for (r, &h) in c.iter().enumerate() {
        corner_at[r] = cycle.len();
        cycle.push((t.tail(h).0, FacePlace::Corner(r), r));
        for &(id, tau) in &on_he[h.idx()] {
            at.insert((id, h), cycle.len());
            cycle.push((id, FacePlace::Side(r, tau), r));
        }
    }
    let n = cycle.len();
    let mut adj: Vec<Vec<(usize, Step)>> = vec![Vec::new(); n];
    for (p, &(_, _, r)) in cycle.iter().enumerate() {
        adj[p].push(((p + 1) % n, Step::Side(r)));
        adj[(p + 1) % n].push((p, Step::Side(r)));
    }
    let corner_pos = |h: HalfEdge| c.iter().position(|&x| x == h).map(|r| corner_at[r]);
    for &(g, m) in pieces {
        let path = &tracked.paths[g];
        let k = path.crossings.len();
        let a = if m == 0 {
            corner_pos(path.start)
        } else {
            let x = path.crossings[m - 1];
            at.get(&(first[g] + m as u32 - 1, x.h)).copied()
        };
        let b = if m == k {
            corner_pos(path.end)
        } else {
            let x = path.crossings[m];
            at.get(&(first[g] + m as u32, x.h.twin())).copied()
        };
        let (Some(a), Some(b)) = (a, b) else {
            return Err(bad("a piece's end is not on the face's boundary"));
        };
        let d = (b + n - a) % n;
        if d <= 1 || d == n - 1 {
            return Err(bad(
                "a piece joins two neighbouring boundary points (a bigon)",
            ));
        }
        adj[a].push((b, Step::Input(Edge(g as u32), true)));
        adj[b].push((a, Step::Input(Edge(g as u32), false)));
    }
    check_no_interleaving(n, &adj).map_err(bad)?;
    for (cell, steps) in walk_cells(n, &adj).map_err(bad)? {
        let mut face_in: Option<Face> = None;
        for &s in &steps {
            if let Some(fi) = input_face_of(input, tracked, &c, s) {
                if face_in.is_some_and(|g| g != fi) {
                    return Err(bad("a cell touches two input faces"));
                }
                face_in = Some(fi);
            }
        }
        let input_face = face_in.ok_or(bad("a cell with no input piece on its boundary"))?;
        if cell.len() < 3 {
            return Err(bad("a cell with fewer than three corners"));
        }
        for w in 1..cell.len() - 1 {
            let ids = [cell[0], cell[w], cell[w + 1]];
            out.push(RefinedTriangle {
                vertices: ids.map(|p| cycle[p].0),
                final_face: f,
                places: ids.map(|p| cycle[p].1),
                input_face,
            });
        }
    }
    Ok(())
}

/// A cell: its corners (boundary positions) counterclockwise and the steps after each.
type Cell = (Vec<usize>, Vec<Step>);

/// The cells of a face with `n` boundary points (counterclockwise) and adjacency `adj`
/// (boundary steps both ways, chords both ways), each as its corners counterclockwise
/// and the steps between them: every directed edge (boundary forward, chords both ways)
/// is entered once, and at `y` from `x` the walk turns to the neighbour with the largest
/// cyclic offset below `x`'s (the next edge clockwise, for points in convex position).
fn walk_cells(n: usize, adj: &[Vec<(usize, Step)>]) -> Result<Vec<Cell>, &'static str> {
    let mut used: HashSet<(usize, usize)> = HashSet::new();
    let mut cells = Vec::new();
    for x0 in 0..n {
        for &(y0, s0) in &adj[x0] {
            if matches!(s0, Step::Side(_)) && y0 != (x0 + 1) % n || used.contains(&(x0, y0)) {
                continue;
            }
            let (mut x, mut y, mut s) = (x0, y0, s0);
            let (mut cell, mut steps) = (Vec::new(), Vec::new());
            loop {
                used.insert((x, y));
                cell.push(x);
                steps.push(s);
                let back = (x + n - y) % n;
                let Some(&(z, s2)) = adj[y]
                    .iter()
                    .filter(|&&(z, _)| (z + n - y) % n < back && z != y)
                    .max_by_key(|&&(z, _)| (z + n - y) % n)
                else {
                    return Err("a cell does not close");
                };
                (x, y, s) = (y, z, s2);
                if (x, y) == (x0, y0) {
                    break;
                }
                if cell.len() > n {
                    return Err("a cell does not close");
                }
            }
            cells.push((cell, steps));
        }
    }
    Ok(cells)
}

/// Chords `a < b` and `c < d` (boundary positions) interleave when exactly one of `c, d`
/// lies strictly between `a` and `b`: pieces of input edges would cross, which they do
/// not (B105), so crossings out of order along an edge are refused here.
fn check_no_interleaving(n: usize, adj: &[Vec<(usize, Step)>]) -> Result<(), &'static str> {
    let mut chords: Vec<(usize, usize)> = (0..n)
        .flat_map(|p| {
            adj[p]
                .iter()
                .filter(move |&&(q, s)| matches!(s, Step::Input(_, true)) && q != p)
                .map(move |&(q, _)| (p.min(q), p.max(q)))
        })
        .collect();
    chords.sort_unstable();
    // A stack sweep: chords of a non-crossing family nest or are disjoint.
    let mut stack: Vec<usize> = Vec::new();
    let mut events: Vec<(usize, bool, usize)> = Vec::new();
    for &(a, b) in &chords {
        events.push((a, true, b));
        events.push((b, false, a));
    }
    // Close before open at one position (chords sharing an end do not cross); among
    // openings at one position, the longer first; among closings, the shorter first.
    events.sort_by(|x, y| {
        x.0.cmp(&y.0)
            .then(x.1.cmp(&y.1))
            .then_with(|| y.2.cmp(&x.2))
    });
    for (p, open, other) in events {
        if open {
            stack.push(other);
        } else if stack.pop() != Some(p) {
            return Err("pieces of input edges cross inside the face (crossings out of order)");
        }
    }
    Ok(())
}

/// The input face to the left of step `s` when it runs along input: a chord of input
/// edge `g` run along `2g` or against it, or a side of the face that is an input edge.
fn input_face_of(
    input: &Mesh,
    tracked: &TrackedOverlay,
    c: &[HalfEdge; 3],
    s: Step,
) -> Option<Face> {
    match s {
        Step::Input(g, forward) => input.face(g.side(u32::from(!forward))),
        Step::Side(r) => {
            let h = c[r];
            let g = tracked.along_of(h.edge())?;
            let a = tracked.paths[g as usize].along?;
            input.face(Edge(g).side(u32::from(a != h)))
        }
    }
}
