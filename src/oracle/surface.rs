//! The surface JSON format: a Δ-complex (faces, optional explicit gluing) with one exact
//! length or squared length per edge.
//!
//! ```json
//! { "vertices": 4, "faces": [[0,1,2], [0,2,3], [0,3,1], [1,3,2]],
//!   "gluing": [[[0,0],[2,2]], …],
//!   "lengths": ["1", "3/2", "1.25", 2, …] }
//! ```
//! `gluing` is optional: without it, side `a→b` is glued to the unique side `b→a`; with
//! it, exactly the listed pairs of face sides are glued (side `s` of a face runs from
//! corner `s` to corner `s+1`), which expresses loops, multi-edges and self-glued faces.
//! Sides not glued are boundary. Exactly one of `lengths` and `squared_lengths` is given,
//! one positive exact number per edge — a JSON number (the binary64 value it denotes), or a
//! string holding an integer, a fraction or a decimal — with edges in order of first
//! appearance when reading face 0 sides 0, 1, 2, then face 1, … ([`edge_order`]).

use super::case::{Case, Lengths};
use crate::mesh::Mesh;
use crate::scalar::parse::parse_rational;
use rug::Rational;
use serde_json::{json, Value};

/// Why a surface (or a number in it) was refused: the JSON path and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct SurfaceError(pub String);

fn bad(msg: impl Into<String>) -> SurfaceError {
    SurfaceError(msg.into())
}

/// Parse an exact number: a JSON number (the binary64 value it denotes, exactly) or a
/// string holding an integer, a fraction `p/q` or a decimal with optional exponent
/// (`"-1.25e-3"`), read exactly.
pub fn exact_number(v: &Value, path: &str) -> Result<Rational, SurfaceError> {
    match v {
        Value::Number(n) => n
            .as_f64()
            .and_then(Rational::from_f64)
            .ok_or_else(|| bad(format!("{path}: {n} is not a finite number"))),
        Value::String(s) => parse_rational(s.trim()).map_err(|e| {
            bad(format!(
                "{path}: {s:?} is not an exact number such as \"3/2\", \"1.25\" or \"7e-3\" ({e})"
            ))
        }),
        other => Err(bad(format!(
            "{path}: expected a number or an exact number string, found {other}"
        ))),
    }
}

/// The edge order of the format: edges in order of first appearance when reading the
/// faces in order and each face's sides 0, 1, 2. Entry `k` is the `Edge.idx()` of the
/// k-th edge.
pub fn edge_order(mesh: &Mesh) -> Vec<usize> {
    let mut seen = vec![false; mesh.n_edges()];
    let mut order = Vec::with_capacity(mesh.n_edges());
    for f in mesh.faces() {
        for h in mesh.face_halfedges(f) {
            let e = h.edge().idx();
            if !seen[e] {
                seen[e] = true;
                order.push(e);
            }
        }
    }
    order
}

/// A case as surface JSON (exact rational strings), with edges in the order the reader
/// rebuilds them.
pub fn surface_json(case: &Case) -> Value {
    let faces = case.mesh.face_list();
    let gluing = case.mesh.gluing_list();
    let order = edge_order(&case.mesh);
    let strings =
        |v: &Vec<Rational>| -> Vec<String> { order.iter().map(|&i| v[i].to_string()).collect() };
    let gl: Vec<Value> = gluing
        .iter()
        .map(|&((fa, sa), (fb, sb))| json!([[fa, sa], [fb, sb]]))
        .collect();
    let mut s = json!({
        "vertices": case.mesh.n_vertices(),
        "faces": faces,
        "gluing": gl,
    });
    match &case.lengths {
        Lengths::Exact(v) => s["lengths"] = json!(strings(v)),
        Lengths::Squared(v) => s["squared_lengths"] = json!(strings(v)),
    }
    s
}

fn u32_at(v: &Value, what: &str) -> Result<u32, SurfaceError> {
    v.as_u64()
        .and_then(|x| u32::try_from(x).ok())
        .ok_or_else(|| {
            bad(format!(
                "{what}: expected a non-negative 32-bit integer, found {v}"
            ))
        })
}

/// Read surface JSON written by [`surface_json`].
pub fn parse_surface(s: &Value, name: &str) -> Result<Case, SurfaceError> {
    let n = u32_at(&s["vertices"], "surface.vertices")?;
    let faces_v = s["faces"]
        .as_array()
        .ok_or_else(|| bad("surface.faces: expected an array of vertex triples"))?;
    let mut faces = Vec::with_capacity(faces_v.len());
    for (i, f) in faces_v.iter().enumerate() {
        let t = f
            .as_array()
            .filter(|t| t.len() == 3)
            .ok_or_else(|| bad(format!("surface.faces[{i}]: expected three vertex ids")))?;
        let mut tri = [0u32; 3];
        for (k, x) in t.iter().enumerate() {
            tri[k] = u32_at(x, &format!("surface.faces[{i}][{k}]"))?;
        }
        faces.push(tri);
    }
    if u64::from(n) > 3 * faces.len() as u64 {
        return Err(bad(format!(
            "surface.vertices: {n} vertices but {} face(s); every vertex must belong to a face",
            faces.len()
        )));
    }
    let mut gluing = Vec::new();
    let explicit = s.get("gluing").is_some();
    if let Some(g) = s.get("gluing") {
        let g = g
            .as_array()
            .ok_or_else(|| bad("surface.gluing: expected an array of side pairs"))?;
        for (i, pair) in g.iter().enumerate() {
            let side = |k: usize| -> Result<(u32, u8), SurfaceError> {
                let what = format!("surface.gluing[{i}][{k}]");
                let sv = pair
                    .get(k)
                    .and_then(Value::as_array)
                    .filter(|a| a.len() == 2)
                    .ok_or_else(|| bad(format!("{what}: expected [face, side]")))?;
                let f = u32_at(&sv[0], &what)?;
                let side = u8::try_from(u32_at(&sv[1], &what)?)
                    .map_err(|_| bad(format!("{what}: side must be 0, 1 or 2")))?;
                Ok((f, side))
            };
            gluing.push((side(0)?, side(1)?));
        }
    }
    let mesh = if explicit {
        Mesh::from_gluing(n, &faces, &gluing)
    } else {
        Mesh::from_faces(n, &faces)
    }
    .map_err(|e| bad(format!("surface: {e}")))?;
    let (key, squared) = match (s.get("lengths"), s.get("squared_lengths")) {
        (Some(_), None) => ("lengths", false),
        (None, Some(_)) => ("squared_lengths", true),
        _ => {
            return Err(bad(
                "surface: give exactly one of `lengths` and `squared_lengths`",
            ))
        }
    };
    let arr = s[key]
        .as_array()
        .ok_or_else(|| bad(format!("surface.{key}: expected an array of exact strings")))?;
    if arr.len() != mesh.n_edges() {
        return Err(bad(format!(
            "surface.{key}: {} entries for {} edges",
            arr.len(),
            mesh.n_edges()
        )));
    }
    let order = edge_order(&mesh);
    let mut vals = vec![Rational::new(); arr.len()];
    for (i, x) in arr.iter().enumerate() {
        let q = exact_number(x, &format!("surface.{key}[{i}]"))?;
        if q.cmp0() != std::cmp::Ordering::Greater {
            return Err(bad(format!(
                "surface.{key}[{i}] must be positive, found {q}"
            )));
        }
        vals[order[i]] = q;
    }
    Ok(Case {
        name: name.to_string(),
        mesh,
        lengths: if squared {
            Lengths::Squared(vals)
        } else {
            Lengths::Exact(vals)
        },
    })
}
