//! Failure files: what `penner check` writes when a check fails — the check, the
//! precision, every witness, and a shrunk surface that still fails — and what
//! `penner replay` reads back.
//!
//! Format (`"penner_failure": 1`):
//! ```json
//! { "penner_failure": 1, "check": "T01", "precision": "mpfr-256",
//!   "source": "my_surface.json", "source_faces": 20,
//!   "witnesses": [ { "element": "v3", "detail": "…", "value": 1e-3 } ],
//!   "surface": { "vertices": 4, "faces": [[0,1,2], …], "gluing": [[[0,0],[1,2]], …],
//!                "squared_lengths": ["2", "9/4", …] } }
//! ```
//! `gluing` (optional: without it, side `a→b` is glued to the unique side `b→a`) lists the interior edges as pairs of face sides (side `s` of a face runs from
//! corner `s` to corner `s+1`); sides not listed are boundary. Exactly one of `lengths`
//! and `squared_lengths` is present, one exact rational string per edge of the rebuilt
//! mesh, in the order of first appearance: the glued sides in `gluing` order, then the
//! remaining sides face by face.

use super::case::{Case, Lengths};
use super::precision::{parse_list, Prec};
use crate::mesh::{Face, Mesh};
use crate::theorems::Witness;
use rug::Rational;
use serde_json::{json, Value};

/// Version of the failure-file format.
pub const FORMAT_VERSION: u64 = 1;

/// The per-edge order used by the format: for each edge of `mesh` as rebuilt by
/// `Mesh::from_gluing(face_list, gluing_list)`, the edge of `mesh` it came from.
fn rebuilt_edge_order(mesh: &Mesh, rebuilt: &Mesh) -> Vec<usize> {
    let mut map = vec![0; rebuilt.n_edges()];
    for f in mesh.faces() {
        let a = mesh.face_halfedges(f);
        let b = rebuilt.face_halfedges(Face(f.0));
        for s in 0..3 {
            map[b[s].edge().idx()] = a[s].edge().idx();
        }
    }
    map
}

/// A case as surface JSON (exact rational strings), with edges in the order the reader
/// rebuilds them.
pub fn surface_json(case: &Case) -> Value {
    let faces = case.mesh.face_list();
    let gluing = case.mesh.gluing_list();
    let order = Mesh::from_gluing(case.mesh.n_vertices() as u32, &faces, &gluing).map_or_else(
        |_| (0..case.mesh.n_edges()).collect(),
        |r| rebuilt_edge_order(&case.mesh, &r),
    );
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

/// Why a failure file was refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct FailureFileError(pub String);

fn bad(msg: impl Into<String>) -> FailureFileError {
    FailureFileError(msg.into())
}

fn u32_at(v: &Value, what: &str) -> Result<u32, FailureFileError> {
    v.as_u64()
        .and_then(|x| u32::try_from(x).ok())
        .ok_or_else(|| {
            bad(format!(
                "{what}: expected a non-negative 32-bit integer, found {v}"
            ))
        })
}

/// Read surface JSON written by [`surface_json`].
pub fn parse_surface(s: &Value, name: &str) -> Result<Case, FailureFileError> {
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
            let side = |k: usize| -> Result<(u32, u8), FailureFileError> {
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
    let mut vals = Vec::with_capacity(arr.len());
    for (i, x) in arr.iter().enumerate() {
        let q = x
            .as_str()
            .and_then(|t| Rational::parse(t).ok())
            .map(Rational::from)
            .ok_or_else(|| bad(format!("surface.{key}[{i}] (edge e{i}): expected an exact rational string such as \"3/2\", found {x}")))?;
        if q.cmp0() != std::cmp::Ordering::Greater {
            return Err(bad(format!(
                "surface.{key}[{i}] (edge e{i}): must be positive, found {q}"
            )));
        }
        vals.push(q);
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

/// A failure file's contents.
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    /// Catalogue ID of the failing check.
    pub check: String,
    /// The precision it failed at.
    pub precision: Prec,
    /// Where the original surface came from.
    pub source: String,
    /// Number of faces of the original surface.
    pub source_faces: usize,
    /// Every witness of the failure on the original surface.
    pub witnesses: Vec<Witness>,
    /// The shrunk surface that still fails.
    pub surface: Case,
}

impl Failure {
    /// As JSON (see the module documentation).
    pub fn to_json(&self) -> Value {
        json!({
            "penner_failure": FORMAT_VERSION,
            "check": self.check,
            "precision": self.precision.to_string(),
            "source": self.source,
            "source_faces": self.source_faces,
            "witnesses": self.witnesses,
            "surface": surface_json(&self.surface),
        })
    }

    /// Read a failure file's text; `name` names the file in messages.
    pub fn parse(text: &str, name: &str) -> Result<Failure, FailureFileError> {
        let v: Value = serde_json::from_str(text)
            .map_err(|e| bad(format!("{name}:{}:{}: {e}", e.line(), e.column())))?;
        match v.get("penner_failure").and_then(Value::as_u64) {
            Some(FORMAT_VERSION) => {}
            Some(other) => {
                return Err(bad(format!(
                    "{name}: failure-file version {other} is not supported (this build reads version {FORMAT_VERSION})"
                )))
            }
            None => {
                return Err(bad(format!(
                    "{name}: not a penner failure file (no \"penner_failure\": {FORMAT_VERSION})"
                )))
            }
        }
        let check = v["check"]
            .as_str()
            .ok_or_else(|| bad(format!("{name}: `check` must be a catalogue ID string")))?
            .to_string();
        let precision = v["precision"]
            .as_str()
            .ok_or_else(|| bad(format!("{name}: `precision` must be a string")))
            .and_then(|p| parse_list(p).map_err(|e| bad(format!("{name}: precision: {e}"))))?;
        let [precision] = precision[..] else {
            return Err(bad(format!("{name}: `precision` must name one precision")));
        };
        let witnesses: Vec<Witness> = serde_json::from_value(v["witnesses"].clone())
            .map_err(|e| bad(format!("{name}: witnesses: {e}")))?;
        let surface =
            parse_surface(&v["surface"], name).map_err(|e| bad(format!("{name}: {e}")))?;
        Ok(Failure {
            check,
            precision,
            source: v["source"].as_str().unwrap_or("").to_string(),
            source_faces: v["source_faces"].as_u64().unwrap_or(0) as usize,
            witnesses,
            surface,
        })
    }
}
