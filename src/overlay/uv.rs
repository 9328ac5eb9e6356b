//! Texture coordinates on the refinement and the files that carry them (proof: B109).
//!
//! `T_F` is laid out with its final lengths over the faces that hold a triangle of the
//! refinement (all of them, or those a part such as copy 1 of a double meets), cut open
//! along a cut graph through the cones ([`cut_through_cones`], B113): breadth first across
//! every edge that is not cut. The cut surface is a disk with no cone inside, so the flat
//! metric develops consistently across every edge not cut, and the corners around a vertex
//! between two cut edges (a *wedge*) share one position, bit for bit; a crossing on an edge
//! not cut is placed from its own half-edge and parameter, so both faces give it the same
//! coordinates. A refinement vertex in a face of `T_F` gets the point of that face's
//! layout at its place, linearly: a corner `p_r`, or `(1 − τ) p_r + τ p_{r+1}` on side
//! `c_r`. The map is affine on each face of `T_F` (exact for the final flat metric there)
//! and, since every cell is convex with the same corners in the input face and in the
//! face of `T_F` (B108), a homeomorphism on each cell. Texture coordinates therefore differ
//! across an edge only on the cut: the seams (B110).
//!
//! The 3-D position of a crossing at `s` along input edge `pq` is `(1 − s) p + s q`, and
//! its barycentric coordinates in an input face with that side `c_r` are
//! `(1 − σ) e_r + σ e_{r+1}`, `σ = s` when `c_r = 2g`, `1 − s` otherwise. The complement
//! `1 − σ` is written as the exact decimal complement of the written `σ`, so each
//! written triple sums to 1 in ℚ.

use super::refinement::{FacePlace, RefinedVertex, Refinement};
use crate::geometry::unfold::unfold_across;
use crate::mesh::cut::cut_through_cones;
use crate::mesh::{Face, HalfEdge, Mesh};
use crate::scalar::parse::parse_rational;
use rug::ops::Pow;
use rug::{Integer, Rational};
use serde::ser::{SerializeMap, SerializeSeq};
use serde::{Serialize, Serializer};
use serde_json::Value;
use std::collections::HashMap;
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

/// Lay `final_mesh` (= `T_F`) out with `final_lengths`, cut through the vertices with
/// `cones[v]` (per vertex of `T_F`), and attach texture coordinates, positions
/// (`input_positions`, per input vertex) and barycentric coordinates in `input` (= `T_in`)
/// to `refinement` (module documentation).
pub fn uv_mesh(
    input: &Mesh,
    input_positions: &[[f64; 3]],
    final_mesh: &Mesh,
    final_lengths: &[f64],
    refinement: Refinement,
    cones: &[bool],
) -> Result<UvMesh, UvError> {
    if input_positions.len() != input.n_vertices() {
        return Err(UvError::NoPositions);
    }
    let layout = CutLayout::new(final_mesh, final_lengths, &refinement, cones);
    let mut uv = Vec::with_capacity(refinement.triangles.len());
    for (tri, ids) in refinement
        .triangles
        .iter()
        .zip(refinement.triangles.iter().map(|t| t.vertices))
    {
        let c = final_mesh.face_halfedges(tri.final_face);
        let mut corners = [[0.0; 2]; 3];
        for (k, pl) in tri.places.iter().enumerate() {
            corners[k] = match *pl {
                FacePlace::Corner(r) => layout.at(c[r]),
                FacePlace::Side(r, tau) => {
                    let crossing = match refinement.vertices[ids[k] as usize] {
                        RefinedVertex::Crossing { on, t, .. } if on.edge() == c[r].edge() => {
                            Some((on, t))
                        }
                        _ => None,
                    };
                    layout.on_side(final_mesh, c[r], tau, crossing)
                }
            }
            .ok_or(UvError::Layout(tri.final_face.0))?;
        }
        uv.push(corners);
    }
    let mut barycentric = Vec::with_capacity(refinement.triangles.len());
    for tri in &refinement.triangles {
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

/// `T_F` unfolded across every edge but a cut graph through the cones (B113), with one
/// position per *wedge*: the corners around a vertex between two cut edges (or the
/// region's boundary) share the position of one of them, so the texture coordinates of a
/// vertex are bitwise the same on both sides of every edge that is not cut.
struct CutLayout {
    /// Per half-edge: the position of its tail in its face's wedge.
    wedge: Vec<Option<[f64; 2]>>,
}

impl CutLayout {
    fn new(mesh: &Mesh, lengths: &[f64], refinement: &Refinement, cones: &[bool]) -> Self {
        // The faces holding a triangle (all of them for a whole refinement; for a part,
        // e.g. copy 1 of a double, those it meets), unfolded from `f0` when it is one of
        // them, else from the first triangle's face.
        let mut held = vec![false; mesh.n_faces()];
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
        let cut = cut_through_cones(mesh, &held, root, cones);
        let lay = unfold_across(mesh, lengths, root, |f| held[f.idx()], |e| !cut[e.idx()]);
        // Union the corners around each vertex across the edges not cut:
        // corner `h` (tail(h) in face(h)) and corner `twin(prev(h))` are separated by
        // `edge(prev(h))`.
        let mut parent: Vec<usize> = (0..mesh.n_halfedges()).collect();
        for h in mesh.halfedges() {
            if mesh.face(h).is_none() {
                continue;
            }
            let p = mesh.prev(h);
            let g = p.twin();
            if cut[p.edge().idx()] || lay.corner[h.idx()].is_none() || lay.corner[g.idx()].is_none()
            {
                continue;
            }
            let (a, b) = (find(&mut parent, h.idx()), find(&mut parent, g.idx()));
            if a != b {
                parent[a.max(b)] = a.min(b);
            }
        }
        let wedge = (0..mesh.n_halfedges())
            .map(|h| {
                let r = find(&mut parent, h);
                lay.corner[h].and(lay.corner[r])
            })
            .collect();
        Self { wedge }
    }

    /// The position of corner `tail(h)` in the face of `h`.
    fn at(&self, h: HalfEdge) -> Option<[f64; 2]> {
        self.wedge[h.idx()]
    }

    /// The point at `tau` along side `h` of a face; a crossing `(on, t)` of that edge is
    /// placed from `on`'s tail by its own `t`, so that both faces of an edge not cut give
    /// it the same coordinates bit for bit.
    fn on_side(
        &self,
        mesh: &Mesh,
        h: HalfEdge,
        tau: f64,
        crossing: Option<(HalfEdge, f64)>,
    ) -> Option<[f64; 2]> {
        let n = mesh.next(h);
        let (a, b, t) = match crossing {
            Some((on, t)) if on == h => (self.at(h)?, self.at(n)?, t),
            Some((_, t)) => (self.at(n)?, self.at(h)?, t),
            None => (self.at(h)?, self.at(n)?, tau),
        };
        Some([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])])
    }
}

/// The root of `x` in a union–find forest, halving the path.
fn find(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
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
    /// The OBJ text: `v` per refinement vertex, one `vt` per distinct texture coordinate
    /// (corners sharing a wedge, B113, share it), `f v/vt` per triangle (counterclockwise).
    pub fn obj(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "# common refinement of the input and the final triangulation; vt: the flattened metric");
        for p in &self.positions {
            let _ = writeln!(s, "v {} {} {}", p[0], p[1], p[2]);
        }
        let mut index: HashMap<(u64, u64), usize> = HashMap::new();
        let mut f_lines = String::new();
        for (t, corners) in self.refinement.triangles.iter().zip(&self.uv) {
            let _ = write!(f_lines, "f");
            for (v, q) in t.vertices.iter().zip(corners) {
                let next = index.len() + 1;
                let w = *index
                    .entry((q[0].to_bits(), q[1].to_bits()))
                    .or_insert_with(|| {
                        let _ = writeln!(s, "vt {} {}", q[0], q[1]);
                        next
                    });
                let _ = write!(f_lines, " {}/{w}", v + 1);
            }
            f_lines.push('\n');
        }
        s.push_str(&f_lines);
        s
    }

    /// The sidecar JSON: per vertex its input vertex or crossing (input edge, `s`, edge of
    /// `T_F`, `t`); per face its input face, face of `T_F` and the barycentric coordinates
    /// of its corners in the input face (decimal strings, each triple summing to 1).
    pub fn sidecar(&self) -> Value {
        // The one definition of the format is `SidecarOut`; it serializes plain data (maps
        // with string keys, strings and integers), which cannot fail.
        serde_json::to_value(SidecarOut(self)).unwrap_or(Value::Null)
    }

    /// The sidecar's JSON text, the same bytes as `sidecar().to_string()`, written face by
    /// face without building the JSON value (a fraction of its memory on large meshes).
    pub fn sidecar_text(&self) -> Result<String, serde_json::Error> {
        serde_json::to_string(&SidecarOut(self))
    }
}

/// The barycentric rows of a triangle's corners `(r, σ)` as decimal strings: `1 − σ` (the
/// exact decimal complement) at `r`, `σ` at `r + 1`, `0` elsewhere.
fn barycentric_rows(b: &[(usize, f64); 3]) -> [[String; 3]; 3] {
    b.map(|(r, sigma)| {
        let d = sigma.to_string();
        let mut row = ["0".to_string(), "0".to_string(), "0".to_string()];
        row[r] = decimal_complement(&d);
        if d != "0" {
            row[(r + 1) % 3] = d;
        }
        row
    })
}

/// [`UvMesh::sidecar`] serialized lazily, its keys in the order a JSON object value
/// prints them (sorted), so that the text is the same.
struct SidecarOut<'a>(&'a UvMesh);

impl Serialize for SidecarOut<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let uv = self.0;
        let mut m = s.serialize_map(Some(4))?;
        m.serialize_entry("faces", &FacesOut(uv))?;
        m.serialize_entry("format", "penner-uv-1")?;
        m.serialize_entry("input_faces", &uv.input_faces)?;
        m.serialize_entry("vertices", &VerticesOut(uv))?;
        m.end()
    }
}

/// The sidecar's faces, one map each (keys sorted).
struct FacesOut<'a>(&'a UvMesh);

impl Serialize for FacesOut<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let uv = self.0;
        let mut seq = s.serialize_seq(Some(uv.refinement.triangles.len()))?;
        for (t, b) in uv.refinement.triangles.iter().zip(&uv.barycentric) {
            seq.serialize_element(&FaceOut {
                barycentric: barycentric_rows(b),
                final_face: t.final_face.0,
                input_face: t.input_face.0,
            })?;
        }
        seq.end()
    }
}

/// One face of the sidecar (fields in sorted order).
#[derive(Serialize)]
struct FaceOut {
    barycentric: [[String; 3]; 3],
    final_face: u32,
    input_face: u32,
}

/// The sidecar's vertices (keys sorted).
struct VerticesOut<'a>(&'a UvMesh);

/// A crossing of the sidecar (fields in sorted order).
#[derive(Serialize)]
struct CrossingOut {
    final_edge: u32,
    input_edge: u32,
    s: String,
    t: String,
}

/// A vertex of the sidecar: an input vertex or a crossing.
#[derive(Serialize)]
enum VertexOut {
    #[serde(rename = "input_vertex")]
    Input(u32),
    #[serde(rename = "crossing")]
    Crossing(CrossingOut),
}

impl Serialize for VerticesOut<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let uv = self.0;
        let mut seq = s.serialize_seq(Some(uv.refinement.vertices.len()))?;
        for v in &uv.refinement.vertices {
            let out = match *v {
                RefinedVertex::Input(w) => VertexOut::Input(w.0),
                RefinedVertex::Crossing { edge, s, on, t } => VertexOut::Crossing(CrossingOut {
                    final_edge: on.edge().0,
                    input_edge: edge.0,
                    s: s.to_string(),
                    t: t.to_string(),
                }),
            };
            seq.serialize_element(&out)?;
        }
        seq.end()
    }
}
