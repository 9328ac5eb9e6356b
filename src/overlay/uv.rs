//! Texture coordinates on the refinement and the files that carry them (proof: B109).
//!
//! `T_F` is laid out with its final lengths by unfolding along a dual spanning tree of the
//! faces that hold a triangle of the refinement (all of them, or those a part such as copy
//! 1 of a double meets): the surface is cut along the edges outside the tree, a cut graph
//! through every vertex and so through every cone, and each face gets its own three
//! corners. A refinement vertex
//! in a face of `T_F` gets the point of that face's layout at its place, linearly:
//! a corner `p_r`, or `(1 − τ) p_r + τ p_{r+1}` on side `c_r`. The map is affine on each
//! face of `T_F` (exact for the final flat metric there) and, since every cell is convex
//! with the same corners in the input face and in the face of `T_F` (B108), a
//! homeomorphism on each cell.
//!
//! The 3-D position of a crossing at `s` along input edge `pq` is `(1 − s) p + s q`, and
//! its barycentric coordinates in an input face with that side `c_r` are
//! `(1 − σ) e_r + σ e_{r+1}`, `σ = s` when `c_r = 2g`, `1 − s` otherwise. The complement
//! `1 − σ` is written as the exact decimal complement of the written `σ`, so each
//! written triple sums to 1 in ℚ.

use super::refinement::{FacePlace, RefinedVertex, Refinement};
use crate::geometry::unfold::unfold_faces;
use crate::mesh::{Face, Mesh};
use crate::scalar::parse::parse_rational;
use rug::ops::Pow;
use rug::{Integer, Rational};
use serde_json::{json, Value};
use std::fmt::Write as _;

/// Why the texture coordinates could not be written.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum UvError {
    /// Not one positive length per edge of `T_F`, or a face not reached by the layout.
    #[error("the final triangulation could not be laid out (face f{0} not reached or a length not finite)")]
    Layout(u32),
    /// The input surface has no vertex positions in ℝ³.
    #[error("the input has no vertex positions: the UV mesh needs 3-D positions")]
    NoPositions,
    /// An input face does not have three distinct corners (barycentric coordinates are
    /// not defined by vertex).
    #[error("input face f{0} does not have three distinct corners")]
    RepeatedCorner(u32),
    /// A refinement vertex is not on the boundary of its input face.
    #[error("refinement vertex {0} is not on its input face f{1}")]
    NotOnFace(u32, u32),
}

/// The refinement with texture coordinates, 3-D positions and barycentric coordinates,
/// ready to write.
#[derive(Clone, Debug)]
pub struct UvMesh {
    /// 3-D position of each refinement vertex on the input surface.
    pub positions: Vec<[f64; 3]>,
    /// Per triangle, the texture coordinates of its three corners.
    pub uv: Vec<[[f64; 2]; 3]>,
    /// Per triangle, per corner: `(r, σ)`, the point `(1 − σ) e_r + σ e_{r+1}` of its
    /// input face in barycentric coordinates (corner `r` = `tail(c_r)`).
    pub barycentric: Vec<[(usize, f64); 3]>,
    /// The refinement.
    pub refinement: Refinement,
    /// The number of input faces.
    pub input_faces: usize,
}

/// Lay `final_mesh` (= `T_F`) out with `final_lengths` and attach texture coordinates,
/// positions (`input_positions`, per input vertex) and barycentric coordinates in
/// `input` (= `T_in`) to `refinement` (module documentation).
pub fn uv_mesh(
    input: &Mesh,
    input_positions: &[[f64; 3]],
    final_mesh: &Mesh,
    final_lengths: &[f64],
    refinement: Refinement,
) -> Result<UvMesh, UvError> {
    if input_positions.len() != input.n_vertices() {
        return Err(UvError::NoPositions);
    }
    // The faces of `T_F` holding a triangle (all of them for a whole refinement; for a
    // restricted one, e.g. copy 1 of a double, those it meets), unfolded from `f0` when it
    // is one of them, else from the first triangle's face.
    let mut held = vec![false; final_mesh.n_faces()];
    for t in &refinement.triangles {
        if let Some(h) = held.get_mut(t.final_face.idx()) {
            *h = true;
        }
    }
    let root = match refinement.triangles.first() {
        Some(_) if held.first() == Some(&true) => Face(0),
        Some(t) => t.final_face,
        None => Face(0),
    };
    let lay = unfold_faces(final_mesh, final_lengths, root, |f| held[f.idx()]);
    let mut uv = Vec::with_capacity(refinement.triangles.len());
    let mut barycentric = Vec::with_capacity(refinement.triangles.len());
    for tri in &refinement.triangles {
        let c = final_mesh.face_halfedges(tri.final_face);
        let p = c.map(|h| lay.corner[h.idx()]);
        let [Some(p0), Some(p1), Some(p2)] = p else {
            return Err(UvError::Layout(tri.final_face.0));
        };
        let p = [p0, p1, p2];
        uv.push(tri.places.map(|pl| match pl {
            FacePlace::Corner(r) => p[r],
            FacePlace::Side(r, t) => {
                let (a, b) = (p[r], p[(r + 1) % 3]);
                [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
            }
        }));
        let ci = input.face_halfedges(tri.input_face);
        let corners = ci.map(|h| input.tail(h));
        if corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2] {
            return Err(UvError::RepeatedCorner(tri.input_face.0));
        }
        let mut b = [(0, 0.0); 3];
        for (k, &v) in tri.vertices.iter().enumerate() {
            let not_on = UvError::NotOnFace(v, tri.input_face.0);
            b[k] = match refinement.vertices[v as usize] {
                RefinedVertex::Input(w) => {
                    (corners.iter().position(|&x| x == w).ok_or(not_on)?, 0.0)
                }
                RefinedVertex::Crossing { edge, s, .. } => {
                    let r = ci.iter().position(|h| h.edge() == edge).ok_or(not_on)?;
                    (r, if ci[r] == edge.side(0) { s } else { 1.0 - s })
                }
            };
        }
        barycentric.push(b);
    }
    let positions = refinement
        .vertices
        .iter()
        .map(|v| match *v {
            RefinedVertex::Input(w) => input_positions[w.idx()],
            RefinedVertex::Crossing { edge, s, .. } => {
                let h = edge.side(0);
                let (a, b) = (
                    input_positions[input.tail(h).idx()],
                    input_positions[input.tip(h).idx()],
                );
                [0, 1, 2].map(|i| a[i] + s * (b[i] - a[i]))
            }
        })
        .collect();
    Ok(UvMesh {
        positions,
        uv,
        barycentric,
        refinement,
        input_faces: input.n_faces(),
    })
}

/// `1 − d` for a decimal string `d` (as Rust prints an `f64`), as an exact decimal string
/// with no more digits after the point than `d`.
pub fn decimal_complement(d: &str) -> String {
    let digits = d.split_once('.').map_or(0, |(_, f)| f.len());
    let q = parse_rational(d).unwrap_or_default();
    let scaled = (Rational::from(1) - q) * Rational::from(Integer::from(10).pow(digits as u32));
    let n = scaled.numer().clone();
    let neg = n < 0;
    let s = n.abs().to_string();
    let s = format!("{s:0>width$}", width = digits + 1);
    let (int, frac) = s.split_at(s.len() - digits);
    let sign = if neg { "-" } else { "" };
    if digits == 0 {
        format!("{sign}{int}")
    } else {
        format!("{sign}{int}.{frac}")
    }
}

impl UvMesh {
    /// The OBJ text: `v` per refinement vertex, `vt` per triangle corner, `f v/vt` per
    /// triangle (counterclockwise).
    pub fn obj(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "# common refinement of the input and the final triangulation; vt: the flattened metric");
        for p in &self.positions {
            let _ = writeln!(s, "v {} {} {}", p[0], p[1], p[2]);
        }
        for t in &self.uv {
            for q in t {
                let _ = writeln!(s, "vt {} {}", q[0], q[1]);
            }
        }
        for (k, t) in self.refinement.triangles.iter().enumerate() {
            let [a, b, c] = t.vertices.map(|v| v + 1);
            let w = 3 * k + 1;
            let _ = writeln!(s, "f {a}/{w} {b}/{} {c}/{}", w + 1, w + 2);
        }
        s
    }

    /// The sidecar JSON: per vertex its input vertex or crossing (input edge, `s`, edge of
    /// `T_F`, `t`); per face its input face, face of `T_F` and the barycentric coordinates
    /// of its corners in the input face (decimal strings, each triple summing to 1).
    pub fn sidecar(&self) -> Value {
        let vertices: Vec<Value> = self
            .refinement
            .vertices
            .iter()
            .map(|v| match *v {
                RefinedVertex::Input(w) => json!({ "input_vertex": w.0 }),
                RefinedVertex::Crossing { edge, s, on, t } => json!({
                    "crossing": { "input_edge": edge.0, "s": s.to_string(), "final_edge": on.edge().0, "t": t.to_string() }
                }),
            })
            .collect();
        let faces: Vec<Value> = self
            .refinement
            .triangles
            .iter()
            .zip(&self.barycentric)
            .map(|(t, b)| {
                let bary: Vec<Vec<String>> = b
                    .iter()
                    .map(|&(r, sigma)| {
                        let d = sigma.to_string();
                        let mut row = vec!["0".to_string(); 3];
                        row[r] = decimal_complement(&d);
                        if d != "0" {
                            row[(r + 1) % 3] = d;
                        }
                        row
                    })
                    .collect();
                json!({ "input_face": t.input_face.0, "final_face": t.final_face.0, "barycentric": bary })
            })
            .collect();
        json!({ "format": "penner-uv-1", "input_faces": self.input_faces, "vertices": vertices, "faces": faces })
    }
}
