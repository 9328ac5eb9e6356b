//! Surfaces from Python data: vertex positions and faces (the `(V, F)` convention), faces
//! with per-face lengths in the opposite-corner layout (libigl's `l`), or a file.
//!
//! Everything here runs without the GIL on plain Rust data copied out of the arrays; each
//! refusal is an [`InputError`] naming the array element (`V[2, 1]`, `F[3, 0]`,
//! `l[5, 2]`) or the face.

use penner::io::{surface::squared_lengths_from_positions, Metric, MetricError, Surface};
use penner::mesh::{Face, Mesh, MeshError};
use penner::scalar::parse::parse_rational;
use rug::Rational;

/// Bad input, with a message naming the element.
#[derive(Debug)]
pub struct InputError(pub String);

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// The numbers of an `(rows, 3)` array as Python gave them: binary64 values (taken
/// exactly) or exact decimal strings (`"1.25"`, `"3/2"`, `"1e-30"`).
pub enum Numbers {
    /// Row-major binary64 values.
    F64(Vec<f64>),
    /// Row-major exact literals.
    Exact(Vec<String>),
}

impl Numbers {
    /// The number of values.
    fn len(&self) -> usize {
        match self {
            Numbers::F64(v) => v.len(),
            Numbers::Exact(v) => v.len(),
        }
    }

    /// Value `k` (row `k / 3`, column `k % 3` of array `name`) as an exact rational.
    fn rational(&self, k: usize, name: &str) -> Result<Rational, InputError> {
        let at = || format!("{name}[{}, {}]", k / 3, k % 3);
        match self {
            Numbers::F64(v) => Rational::from_f64(v[k])
                .ok_or_else(|| InputError(format!("{} = {}: not a finite number", at(), v[k]))),
            Numbers::Exact(v) => {
                parse_rational(&v[k]).map_err(|e| InputError(format!("{}: {e}", at())))
            }
        }
    }
}

/// What a surface is made from.
pub enum Source {
    /// Positions `V` (n, 3) and faces `F` (m, 3).
    Positions {
        /// `V`, row-major.
        v: Numbers,
        /// `F`, row-major.
        f: Vec<i64>,
    },
    /// Faces `F` (m, 3) and per-face lengths `l` (m, 3), `l[f, i]` opposite corner `i`.
    FaceLengths {
        /// `F`, row-major.
        f: Vec<i64>,
        /// `l`, row-major.
        l: Numbers,
    },
}

/// Check that a row-major array of `len` values has 3 columns (the caller checked the
/// number of dimensions) and is not empty.
pub fn rows(len: usize, name: &str) -> Result<usize, InputError> {
    if len == 0 {
        return Err(InputError(format!("{name} is empty")));
    }
    if len % 3 != 0 {
        return Err(InputError(format!(
            "{name} has {len} values: expected shape (rows, 3)"
        )));
    }
    Ok(len / 3)
}

/// The faces, every index in `0..n_vertices` (`None`: the largest index plus one).
fn faces(f: &[i64], n_vertices: Option<usize>) -> Result<(u32, Vec<[u32; 3]>), InputError> {
    rows(f.len(), "F")?;
    let n = n_vertices.unwrap_or_else(|| {
        let top = f.iter().copied().max().unwrap_or(0);
        usize::try_from(top).map_or(0, |t| t + 1)
    });
    let n32 = u32::try_from(n)
        .map_err(|_| InputError(format!("{n} vertices exceed the 32-bit index range")))?;
    let mut out = Vec::with_capacity(f.len() / 3);
    for (r, row) in f.chunks_exact(3).enumerate() {
        let mut t = [0u32; 3];
        for (c, &x) in row.iter().enumerate() {
            t[c] = u32::try_from(x).ok().filter(|&i| i < n32).ok_or_else(|| {
                InputError(format!("F[{r}, {c}] = {x} is out of range ({n} vertices)"))
            })?;
        }
        out.push(t);
    }
    Ok((n32, out))
}

/// The mesh of the faces, its refusals prefixed by `F`.
fn mesh(n: u32, faces: &[[u32; 3]]) -> Result<Mesh, InputError> {
    Mesh::from_faces(n, faces).map_err(|e| match e {
        MeshError::AmbiguousLoop { face, .. } => InputError(format!(
            "F: {e} (a face with a repeated vertex: F[{face}] = {:?})",
            faces[face as usize]
        )),
        e => InputError(format!("F: {e}")),
    })
}

/// A metric refusal named by face or by the vertices of the edge.
fn metric_error(mesh: &Mesh, faces: &[[u32; 3]], e: MetricError) -> InputError {
    match e {
        MetricError::NonPositive { edge, .. } => {
            let h = penner::mesh::Edge(edge).halfedge();
            let (a, b) = (mesh.tail(h).0, mesh.tip(h).0);
            InputError(format!(
                "the edge between vertices {a} and {b} has length 0 (coincident positions)"
            ))
        }
        MetricError::TriangleInequality { face, .. } => InputError(format!(
            "face {face} (F[{face}] = {:?}): {}",
            faces.get(face as usize).copied().unwrap_or_default(),
            e.to_string()
                .split_once(": ")
                .map_or(e.to_string(), |(_, m)| m.to_string())
        )),
        e => InputError(e.to_string()),
    }
}

/// Build the surface named `name` from `source` (validated exactly: positive lengths,
/// strict triangle inequalities).
pub fn surface(source: Source, name: &str) -> Result<Surface, InputError> {
    match source {
        Source::Positions { v, f } => {
            let n = rows(v.len(), "V")?;
            let positions = (0..n)
                .map(|i| {
                    Ok([
                        v.rational(3 * i, "V")?,
                        v.rational(3 * i + 1, "V")?,
                        v.rational(3 * i + 2, "V")?,
                    ])
                })
                .collect::<Result<Vec<[Rational; 3]>, InputError>>()?;
            let (n32, tris) = faces(&f, Some(n))?;
            let m = mesh(n32, &tris)?;
            let metric = Metric::SquaredLengths(squared_lengths_from_positions(&m, &positions));
            Surface::new(name, m.clone(), metric, Some(positions))
                .map_err(|e| metric_error(&m, &tris, e))
        }
        Source::FaceLengths { f, l } => {
            let (n32, tris) = faces(&f, None)?;
            if l.len() != f.len() {
                return Err(InputError(format!(
                    "l has {} rows for {} faces: expected shape ({}, 3)",
                    l.len() / 3,
                    tris.len(),
                    tris.len()
                )));
            }
            let m = mesh(n32, &tris)?;
            let lengths = edge_lengths(&m, &l)?;
            Surface::new(name, m.clone(), Metric::Lengths(lengths), None)
                .map_err(|e| metric_error(&m, &tris, e))
        }
    }
}

/// One length per edge from the per-face lengths (`l[f, i]` is side `(i + 1) mod 3` of
/// face `f`, the side opposite corner `i`): positive, and equal on the two faces of an
/// interior edge.
fn edge_lengths(m: &Mesh, l: &Numbers) -> Result<Vec<Rational>, InputError> {
    let mut out: Vec<Option<(Rational, usize)>> = vec![None; m.n_edges()];
    for f in m.faces() {
        let sides = m.face_halfedges(f);
        for i in 0..3 {
            let k = 3 * f.idx() + i;
            let q = l.rational(k, "l")?;
            if q <= 0 {
                return Err(InputError(format!(
                    "l[{}, {i}] = {q}: a length must be positive",
                    f.idx()
                )));
            }
            let e = sides[(i + 1) % 3].edge();
            match &out[e.idx()] {
                None => out[e.idx()] = Some((q, k)),
                Some((p, j)) if *p != q => {
                    return Err(InputError(format!(
                        "l[{}, {}] = {p} and l[{}, {i}] = {q} are the two sides of one edge (vertices {} and {}) and differ",
                        j / 3,
                        j % 3,
                        f.idx(),
                        m.tail(e.halfedge()).0,
                        m.tip(e.halfedge()).0
                    )))
                }
                Some(_) => {}
            }
        }
    }
    Ok(out
        .into_iter()
        .map(|x| x.map(|(q, _)| q).unwrap_or_default())
        .collect())
}

/// The per-face lengths `l` (m, 3) of `values` given per edge of `mesh`: `l[f, i]` is the
/// length of the side opposite corner `i` of face `f`.
pub fn per_face(mesh: &Mesh, values: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(3 * mesh.n_faces());
    for f in mesh.faces() {
        let h = mesh.face_halfedges(f);
        for i in 0..3 {
            out.push(values[h[(i + 1) % 3].edge().idx()]);
        }
    }
    out
}

/// The face with index `f` (for layouts).
pub fn face(f: usize) -> Face {
    Face(f as u32)
}

/// The mesh of faces alone (`F` (m, 3) row-major; the vertices are `0..=max F`), for the
/// calls that need only the combinatorics (circle packings).
pub fn mesh_of_faces(f: &[i64]) -> Result<Mesh, InputError> {
    let (n, tris) = faces(f, None)?;
    mesh(n, &tris)
}
