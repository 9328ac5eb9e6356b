//! The penner JSON surface format (`docs/surface-format.md`): any Δ-complex, with an
//! exact metric per edge or per face side, and optional exact positions.

use super::strict_json::{self, JsonError};
use super::surface::{squared_lengths_from_positions, Metric, Surface};
use super::{text_of, ReadError};
use crate::mesh::{Face, FaceSide, Mesh, MeshError};
use crate::scalar::parse_rational;
use rug::Rational;
use serde_json::{Map, Value};

/// The value of the `format` field.
pub const FORMAT: &str = "penner-surface";
/// The format version written, and the only one read.
pub const VERSION: u64 = 1;

const KEYS: [&str; 10] = [
    "format",
    "version",
    "name",
    "vertices",
    "faces",
    "gluing",
    "gluing_exceptions",
    "lengths",
    "squared_lengths",
    "positions",
];

fn schema(element: impl Into<String>, message: impl Into<String>) -> ReadError {
    ReadError::Schema {
        element: element.into(),
        message: message.into(),
    }
}

/// Read a surface from JSON bytes (refusing non-UTF-8 data).
pub fn read_bytes(bytes: &[u8]) -> Result<Surface, ReadError> {
    read(text_of(bytes)?)
}

/// Read a surface from JSON text; a repeated key in any object is refused
/// ([`strict_json`]), as is an unknown field.
pub fn read(text: &str) -> Result<Surface, ReadError> {
    let v = strict_json::parse(text).map_err(|e| match e {
        JsonError::DuplicateKey(d) => ReadError::DuplicateKey(d),
        JsonError::Syntax(e) if e.classify() == serde_json::error::Category::Eof => {
            ReadError::Truncated {
                line: e.line(),
                expected: "the rest of the JSON document".into(),
            }
        }
        JsonError::Syntax(e) => ReadError::Syntax {
            line: e.line(),
            message: e.to_string(),
        },
    })?;
    from_value(&v)
}

/// An exact number from a JSON value: a string literal read by
/// [`crate::scalar::parse_rational`], a JSON integer exactly, or any other JSON number as
/// the binary64 value it denotes (correctly rounded by the JSON reader), exactly.
pub fn exact_number(v: &Value, element: &str) -> Result<Rational, ReadError> {
    match v {
        Value::String(s) => parse_rational(s).map_err(|source| ReadError::Number {
            element: element.to_string(),
            source,
        }),
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                Ok(Rational::from(i))
            } else if let Some(u) = n.as_u64() {
                Ok(Rational::from(u))
            } else {
                n.as_f64()
                    .and_then(Rational::from_f64)
                    .ok_or_else(|| schema(element, format!("{n} is not a finite number")))
            }
        }
        other => Err(schema(
            element,
            format!(
                "expected a number or a number string, found {}",
                kind(other)
            ),
        )),
    }
}

fn kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

fn array<'a>(v: &'a Value, element: &str) -> Result<&'a Vec<Value>, ReadError> {
    v.as_array()
        .ok_or_else(|| schema(element, format!("expected an array, found {}", kind(v))))
}

fn u32_of(v: &Value, element: &str) -> Result<u32, ReadError> {
    v.as_u64()
        .and_then(|x| u32::try_from(x).ok())
        .ok_or_else(|| schema(element, "expected an integer in 0..2³²"))
}

fn triple<'a>(v: &'a Value, element: &str) -> Result<&'a [Value], ReadError> {
    let a = array(v, element)?;
    if a.len() == 3 {
        Ok(a)
    } else {
        Err(schema(
            element,
            format!("expected 3 entries, found {}", a.len()),
        ))
    }
}

/// Read a surface from a parsed JSON value (e.g. a surface embedded in a claim).
pub fn from_value(v: &Value) -> Result<Surface, ReadError> {
    let obj = v
        .as_object()
        .ok_or_else(|| schema("surface", format!("expected an object, found {}", kind(v))))?;
    if let Some(k) = obj.keys().find(|k| !KEYS.contains(&k.as_str())) {
        return Err(schema(
            k.clone(),
            format!("unknown field (a surface has {})", KEYS.join(", ")),
        ));
    }
    check_header(obj)?;
    let name = match obj.get("name") {
        None => String::new(),
        Some(Value::String(s)) => s.clone(),
        Some(other) => {
            return Err(schema(
                "name",
                format!("expected a string, found {}", kind(other)),
            ))
        }
    };
    let n = u32_of(
        obj.get("vertices")
            .ok_or_else(|| schema("vertices", "missing"))?,
        "vertices",
    )?;
    let faces = read_faces(
        obj.get("faces").ok_or_else(|| schema("faces", "missing"))?,
        n,
    )?;
    let field = if obj.contains_key("gluing_exceptions") {
        "gluing_exceptions"
    } else {
        "gluing"
    };
    let mesh = match (obj.get("gluing"), obj.get("gluing_exceptions")) {
        (Some(_), Some(_)) => {
            return Err(schema(
                "gluing_exceptions",
                "give `gluing` or `gluing_exceptions`, not both",
            ))
        }
        (None, None) => Mesh::from_faces(n, &faces),
        (Some(g), None) => Mesh::from_gluing(n, &faces, &read_gluing(g, "gluing", faces.len())?),
        (None, Some(g)) => Mesh::from_faces_with_exceptions(
            n,
            &faces,
            &read_gluing(g, "gluing_exceptions", faces.len())?,
        ),
    }
    .map_err(|e| mesh_error(e, field))?;
    let positions = match obj.get("positions") {
        None => None,
        Some(p) => Some(read_positions(p, mesh.n_vertices())?),
    };
    let metric = match (obj.get("lengths"), obj.get("squared_lengths"), &positions) {
        (Some(_), Some(_), _) => {
            return Err(schema(
                "lengths",
                "give `lengths` or `squared_lengths`, not both",
            ))
        }
        (Some(l), None, _) => Metric::Lengths(read_metric(l, "lengths", &mesh)?),
        (None, Some(l), _) => Metric::SquaredLengths(read_metric(l, "squared_lengths", &mesh)?),
        (None, None, Some(p)) => Metric::SquaredLengths(squared_lengths_from_positions(&mesh, p)),
        (None, None, None) => {
            return Err(schema(
                "surface",
                "no metric: give `lengths`, `squared_lengths` or `positions`",
            ))
        }
    };
    Surface::new(name, mesh, metric, positions).map_err(|source| ReadError::Metric {
        element: "surface".into(),
        source,
    })
}

fn check_header(obj: &Map<String, Value>) -> Result<(), ReadError> {
    if let Some(f) = obj.get("format") {
        if f.as_str() != Some(FORMAT) {
            return Err(schema("format", format!("expected \"{FORMAT}\"")));
        }
    }
    if let Some(ver) = obj.get("version") {
        if ver.as_u64() != Some(VERSION) {
            return Err(schema(
                "version",
                format!("unsupported version {ver} (this reader knows {VERSION})"),
            ));
        }
    }
    Ok(())
}

fn read_faces(v: &Value, n: u32) -> Result<Vec<[u32; 3]>, ReadError> {
    let arr = array(v, "faces")?;
    let mut faces = Vec::new();
    for (i, f) in arr.iter().enumerate() {
        let el = format!("faces[{i}]");
        let t = array(f, &el)?;
        if t.len() != 3 {
            return Err(ReadError::NotTriangle {
                element: el,
                count: t.len(),
            });
        }
        let mut tri = [0u32; 3];
        for (k, x) in t.iter().enumerate() {
            let el = format!("faces[{i}][{k}]");
            let Some(id) = x.as_i64() else {
                return Err(schema(el, "expected an integer vertex id"));
            };
            if id < 0 || id >= i64::from(n) {
                return Err(ReadError::IndexOutOfRange {
                    element: el,
                    index: id,
                    n_vertices: n as usize,
                });
            }
            tri[k] = id as u32;
        }
        faces.push(tri);
    }
    Ok(faces)
}

fn read_gluing(
    v: &Value,
    field: &str,
    n_faces: usize,
) -> Result<Vec<(FaceSide, FaceSide)>, ReadError> {
    let arr = array(v, field)?;
    let mut out = Vec::new();
    for (i, pair) in arr.iter().enumerate() {
        let el = format!("{field}[{i}]");
        let p = array(pair, &el)?;
        if p.len() != 2 {
            return Err(schema(
                el,
                "expected two face sides [[face, side], [face, side]]",
            ));
        }
        let mut sides = [(0u32, 0u8); 2];
        for (k, s) in p.iter().enumerate() {
            let el = format!("{field}[{i}][{k}]");
            let fs = array(s, &el)?;
            if fs.len() != 2 {
                return Err(schema(el, "expected [face, side]"));
            }
            let f = u32_of(&fs[0], &el)?;
            let side = u32_of(&fs[1], &el)?;
            if f as usize >= n_faces || side > 2 {
                return Err(schema(
                    el,
                    format!(
                        "face side ({f}, {side}) does not exist ({n_faces} faces, sides 0..=2)"
                    ),
                ));
            }
            sides[k] = (f, side as u8);
        }
        out.push((sides[0], sides[1]));
    }
    Ok(out)
}

fn read_positions(v: &Value, nv: usize) -> Result<Vec<[Rational; 3]>, ReadError> {
    let arr = array(v, "positions")?;
    if arr.len() != nv {
        return Err(schema(
            "positions",
            format!("{} positions for {nv} vertices", arr.len()),
        ));
    }
    let mut out = Vec::new();
    for (i, p) in arr.iter().enumerate() {
        let t = triple(p, &format!("positions[{i}]"))?;
        let mut q: [Rational; 3] = Default::default();
        for k in 0..3 {
            q[k] = exact_number(&t[k], &format!("positions[{i}][{k}]"))?;
        }
        out.push(q);
    }
    Ok(out)
}

/// The edge order of the per-edge form: edges in order of first appearance when reading
/// face 0 sides 0, 1, 2, then face 1, …. Entry `k` is the `Edge.idx()` of the k-th edge.
pub fn edge_order(mesh: &Mesh) -> Vec<usize> {
    let mut seen = vec![false; mesh.n_edges()];
    let mut order = Vec::with_capacity(mesh.n_edges());
    for f in mesh.faces() {
        for h in mesh.face_halfedges(f) {
            let e = h.edge().idx();
            if !std::mem::replace(&mut seen[e], true) {
                order.push(e);
            }
        }
    }
    order
}

/// Per-edge values (indexed by `Edge.idx()`) from the flat per-edge form or the
/// per-face-side form (an array of triples, one per face; glued sides must be equal).
fn read_metric(v: &Value, key: &str, mesh: &Mesh) -> Result<Vec<Rational>, ReadError> {
    let arr = array(v, key)?;
    let per_side = arr.first().is_some_and(Value::is_array);
    let mut vals: Vec<Option<(Rational, FaceSide)>> = vec![None; mesh.n_edges()];
    if per_side {
        if arr.len() != mesh.n_faces() {
            return Err(schema(
                key,
                format!("{} side triples for {} faces", arr.len(), mesh.n_faces()),
            ));
        }
        for (f, t) in arr.iter().enumerate() {
            let t = triple(t, &format!("{key}[{f}]"))?;
            let hs = mesh.face_halfedges(Face(f as u32));
            for (s, (x, h)) in t.iter().zip(hs).enumerate() {
                let el = format!("{key}[{f}][{s}]");
                let q = exact_number(x, &el)?;
                let here = (f as u32, s as u8);
                match &vals[h.edge().idx()] {
                    Some((prev, side)) if *prev != q => {
                        return Err(ReadError::GluedUnequal {
                            element: el,
                            face_a: side.0,
                            side_a: side.1,
                            face_b: here.0,
                            side_b: here.1,
                            a: prev.to_string(),
                            b: q.to_string(),
                        })
                    }
                    Some(_) => {}
                    None => vals[h.edge().idx()] = Some((q, here)),
                }
            }
        }
    } else {
        let order = edge_order(mesh);
        if arr.len() != order.len() {
            return Err(schema(
                key,
                format!("{} values for {} edges", arr.len(), order.len()),
            ));
        }
        for (k, x) in arr.iter().enumerate() {
            vals[order[k]] = Some((exact_number(x, &format!("{key}[{k}]"))?, (0, 0)));
        }
    }
    Ok(vals
        .into_iter()
        .map(|x| x.map(|(q, _)| q).unwrap_or_default())
        .collect())
}

/// The reader's error for a mesh error, naming the face or the entry of the gluing list
/// `field` (`gluing` or `gluing_exceptions`).
fn mesh_error(e: MeshError, field: &str) -> ReadError {
    let element = match &e {
        MeshError::VertexOutOfRange { face, .. } | MeshError::AmbiguousLoop { face, .. } => {
            format!("faces[{face}]")
        }
        MeshError::GluingOutOfRange { index, .. } | MeshError::InconsistentGluing { index, .. } => {
            format!("{field}[{index}]")
        }
        MeshError::SideGluedTwice { face, side } => format!("faces[{face}] side {side}"),
        _ => "surface".into(),
    };
    ReadError::Mesh { element, source: e }
}

/// The surface as a JSON value: `format`, `version`, `name`, `vertices`, `faces`, the
/// explicit `gluing`, the metric per edge (in [`edge_order`]) as exact strings, and the
/// positions as exact strings when present. [`from_value`] reads it back to an equal
/// surface.
pub fn to_value(s: &Surface) -> Value {
    // The view's keys are strings, so serde_json's conversion cannot fail.
    serde_json::to_value(SurfaceJson(s)).unwrap_or(Value::Null)
}

/// The surface in the JSON format of [`to_value`] as a view that serde serializes straight
/// from the surface (no value tree, no copy of the exact strings): written with
/// `serde_json::to_writer_pretty`, a 10⁵-face surface or claim goes to its file without
/// first being built in memory. Keys are emitted in sorted order, the order of
/// serde_json's own maps, so the text is that of [`to_value`]'s value.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceJson<'a>(pub &'a Surface);

/// A rational serialized as its exact string (`n` or `n/d`), without an owned `String`.
#[derive(Clone, Copy, Debug)]
pub struct ExactString<'a>(pub &'a Rational);

impl serde::Serialize for ExactString<'_> {
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        ser.collect_str(self.0)
    }
}

/// A sequence serialized from an iterator made on demand (serde serializes it once).
pub struct SeqOf<F>(pub F);

impl<F, I> serde::Serialize for SeqOf<F>
where
    F: Fn() -> I,
    I: IntoIterator,
    I::Item: serde::Serialize,
{
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        ser.collect_seq((self.0)())
    }
}

impl serde::Serialize for SurfaceJson<'_> {
    fn serialize<S: serde::Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let s = self.0;
        let order = edge_order(&s.mesh);
        let values = s.metric.values();
        let metric = SeqOf(|| order.iter().map(|&e| ExactString(&values[e])));
        let gluing = s.mesh.gluing_list();
        let mut m = ser.serialize_map(None)?;
        // Sorted keys: faces, format, gluing, lengths, name, positions, squared_lengths,
        // version, vertices.
        m.serialize_entry("faces", &s.mesh.face_list())?;
        m.serialize_entry("format", FORMAT)?;
        m.serialize_entry(
            "gluing",
            &SeqOf(|| {
                gluing
                    .iter()
                    .map(|&((fa, sa), (fb, sb))| [[fa, u32::from(sa)], [fb, u32::from(sb)]])
            }),
        )?;
        if let Metric::Lengths(_) = s.metric {
            m.serialize_entry("lengths", &metric)?;
        }
        m.serialize_entry("name", &s.name)?;
        if let Some(p) = &s.positions {
            m.serialize_entry(
                "positions",
                &SeqOf(|| {
                    p.iter()
                        .map(|q| [ExactString(&q[0]), ExactString(&q[1]), ExactString(&q[2])])
                }),
            )?;
        }
        if let Metric::SquaredLengths(_) = s.metric {
            m.serialize_entry("squared_lengths", &metric)?;
        }
        m.serialize_entry("version", &VERSION)?;
        m.serialize_entry("vertices", &s.mesh.n_vertices())?;
        m.end()
    }
}

/// The surface as pretty-printed JSON text ([`to_value`]).
pub fn write(s: &Surface) -> String {
    serde_json::to_string_pretty(&to_value(s)).unwrap_or_default()
}
