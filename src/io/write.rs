//! Writers streaming a surface to any `io::Write`: compact surface JSON (one face or one
//! length per line), OBJ and OFF (positions and faces), and a lengths file (a JSON array,
//! one length per line). Every file written here is read back by [`super::json`],
//! [`super::obj`], [`super::off`] and [`read_lengths`] to the same mesh and the same
//! exact values (`docs/surface-format.md`, "Files penner writes").

use super::json::{edge_order, exact_number, FORMAT, VERSION};
use super::ReadError;
use crate::mesh::{FaceSide, HalfEdge, Mesh};
use rug::Rational;
use std::fmt::Display;
use std::io::{self, Write};

/// The first bytes of every surface JSON file penner writes: a reader may recognise its own
/// output by them.
pub const JSON_MARKER: &str = "{\"format\":\"penner-surface\"";

/// Per-edge values to write, indexed by `Edge.idx()`.
#[derive(Clone, Copy, Debug)]
pub enum Values<'a> {
    /// Exact rationals, written as exact strings (`"p/q"`).
    Exact(&'a [Rational]),
    /// Binary64 values, written as JSON numbers in the shortest form that reads back to
    /// the same `f64` (a JSON number denotes its binary64 value exactly,
    /// [`exact_number`]).
    Binary64(&'a [f64]),
}

impl Values<'_> {
    fn len(&self) -> usize {
        match self {
            Values::Exact(v) => v.len(),
            Values::Binary64(v) => v.len(),
        }
    }
    fn write_one(&self, w: &mut (impl Write + ?Sized), e: usize) -> io::Result<()> {
        match self {
            Values::Exact(v) => write!(w, "\"{}\"", v[e]),
            Values::Binary64(v) => {
                let x = v[e];
                if x.is_finite() {
                    write!(w, "{x:e}")
                } else {
                    Err(io::Error::new(
                        io::ErrorKind::InvalidData,
                        format!("edge {e}: length {x} is not finite"),
                    ))
                }
            }
        }
    }
}

/// A JSON string literal (quotes, backslashes and control characters escaped).
fn json_string(s: &str) -> String {
    serde_json::Value::String(s.to_string()).to_string()
}

/// Whether the vertex triples of `mesh`'s faces determine its gluing (no loops or
/// repeated directed sides that would make [`Mesh::from_faces`] build another surface):
/// then the `gluing` field can be left out.
pub fn faces_determine_gluing(mesh: &Mesh) -> bool {
    let faces = mesh.face_list();
    Mesh::from_faces(mesh.n_vertices() as u32, &faces)
        .is_ok_and(|m| side_twins(&m) == side_twins(mesh))
}

/// The glued pairs of face sides that `mesh`'s vertex triples cannot describe — the
/// sides of interior edges with a loop side or with a directed side `a→b` or `b→a` that
/// occurs more than once among the face sides (parallel edges) — when the triples with
/// these pairs determine the gluing ([`Mesh::from_faces_with_exceptions`] rebuilds it);
/// `None` when they do not (a boundary loop, or a boundary side `a→b` beside an unlisted
/// side `b→a`): then the full gluing is needed. An empty list when the triples alone
/// determine it ([`faces_determine_gluing`]).
///
/// Why the rebuild is the mesh: a listed pair is an edge's two sides; an unlisted interior
/// side `a→b` is the only unlisted `a→b` and its twin the only `b→a`, so they are matched;
/// an unlisted boundary side has no unlisted `b→a` to be matched with (checked here).
/// Linear time, memory one flag per edge: per vertex, the tips of its outgoing face sides.
pub fn gluing_exceptions(mesh: &Mesh) -> Option<Vec<(FaceSide, FaceSide)>> {
    // Directed sides a→b that occur more than once, as (a, b), sorted.
    let mut repeated: Vec<(u32, u32)> = Vec::new();
    let mut tips: Vec<u32> = Vec::new();
    for a in mesh.vertices() {
        tips.clear();
        tips.extend(
            mesh.outgoing(a)
                .filter(|&h| !mesh.is_boundary_halfedge(h))
                .map(|h| mesh.tip(h).0),
        );
        tips.sort_unstable();
        for w in tips.windows(2) {
            if w[0] == w[1] && repeated.last() != Some(&(a.0, w[0])) {
                repeated.push((a.0, w[0]));
            }
        }
    }
    let is_repeated = |a: u32, b: u32| repeated.binary_search(&(a, b)).is_ok();
    let special = |h: HalfEdge| {
        let (a, b) = (mesh.tail(h).0, mesh.tip(h).0);
        a == b || is_repeated(a, b) || is_repeated(b, a)
    };
    let side_of = |h: HalfEdge| -> Option<FaceSide> {
        let f = mesh.face(h)?;
        let s = mesh.face_halfedges(f).iter().position(|&g| g == h)?;
        Some((f.0, s as u8))
    };
    let mut listed = vec![false; mesh.n_edges()];
    let mut exceptions = Vec::new();
    for e in mesh.edges() {
        let (p, q) = (e.side(0), e.side(1));
        if mesh.is_boundary_edge(e) || !(special(p) || special(q)) {
            continue;
        }
        listed[e.idx()] = true;
        exceptions.push((side_of(p)?, side_of(q)?));
    }
    // An unlisted boundary side a→b must have no unlisted face side b→a (nor be a loop).
    for e in mesh.edges().filter(|&e| mesh.is_boundary_edge(e)) {
        let h = [e.side(0), e.side(1)]
            .into_iter()
            .find(|&h| !mesh.is_boundary_halfedge(h))?;
        let (a, b) = (mesh.tail(h), mesh.tip(h));
        let partner = mesh
            .outgoing(b)
            .any(|g| !mesh.is_boundary_halfedge(g) && mesh.tip(g) == a && !listed[g.edge().idx()]);
        if a == b || partner {
            return None;
        }
    }
    Some(exceptions)
}

/// For side `s` of face `f` (entry `3f + s`), the face side glued to it (`None` on the
/// boundary): the gluing, independent of how edges are numbered.
fn side_twins(mesh: &Mesh) -> Vec<Option<(u32, u8)>> {
    let mut side_of = vec![None; mesh.n_halfedges()];
    for f in mesh.faces() {
        for (s, h) in mesh.face_halfedges(f).into_iter().enumerate() {
            side_of[h.idx()] = Some((f.0, s as u8));
        }
    }
    let mut twins = Vec::with_capacity(3 * mesh.n_faces());
    for f in mesh.faces() {
        for h in mesh.face_halfedges(f) {
            twins.push(side_of[h.twin().idx()]);
        }
    }
    twins
}

/// What a metric's values are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MetricKind {
    /// Lengths ℓ_e (`"lengths"`).
    Lengths,
    /// Squared lengths ℓ_e² (`"squared_lengths"`).
    SquaredLengths,
}

/// Write a surface as compact JSON: the header fields on the first line (starting with
/// [`JSON_MARKER`]), then one face per line, the glued side pairs the faces cannot
/// describe as `gluing_exceptions` ([`gluing_exceptions`]; the full `gluing` when those
/// do not determine it, nothing when the faces do), one metric value per line in
/// [`edge_order`], and the positions (one vertex per line) when given.
///
/// ```
/// use penner::io::{json, write, Surface};
/// use penner::mesh::builders;
/// let s = Surface::from_embedded("tet", builders::tetrahedron()).unwrap();
/// let mut out = Vec::new();
/// write::surface_json(&mut out, &s).unwrap();
/// let text = String::from_utf8(out).unwrap();
/// assert!(text.starts_with(write::JSON_MARKER));
/// assert_eq!(json::read(&text).unwrap(), s);
/// ```
pub fn json<P: Display>(
    w: &mut (impl Write + ?Sized),
    name: &str,
    mesh: &Mesh,
    kind: MetricKind,
    values: Values<'_>,
    positions: Option<&[[P; 3]]>,
) -> io::Result<()> {
    if values.len() != mesh.n_edges() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} values for {} edges", values.len(), mesh.n_edges()),
        ));
    }
    write!(
        w,
        "{JSON_MARKER},\"version\":{VERSION},\"name\":{},\"vertices\":{},\n\"faces\":[",
        json_string(name),
        mesh.n_vertices()
    )?;
    debug_assert_eq!(format!("{{\"format\":\"{FORMAT}\""), JSON_MARKER);
    for (i, f) in mesh.face_list().iter().enumerate() {
        let sep = if i == 0 { "\n" } else { ",\n" };
        write!(w, "{sep}[{},{},{}]", f[0], f[1], f[2])?;
    }
    w.write_all(b"]")?;
    let (field, pairs) = match gluing_exceptions(mesh) {
        Some(e) if e.is_empty() => ("", e),
        Some(e) => ("gluing_exceptions", e),
        None => ("gluing", mesh.gluing_list()),
    };
    if !field.is_empty() {
        write!(w, ",\n\"{field}\":[")?;
        for (i, ((fa, sa), (fb, sb))) in pairs.iter().enumerate() {
            let sep = if i == 0 { "\n" } else { ",\n" };
            write!(w, "{sep}[[{fa},{sa}],[{fb},{sb}]]")?;
        }
        w.write_all(b"]")?;
    }
    let key = match kind {
        MetricKind::Lengths => "lengths",
        MetricKind::SquaredLengths => "squared_lengths",
    };
    write!(w, ",\n\"{key}\":[")?;
    for (i, e) in edge_order(mesh).into_iter().enumerate() {
        w.write_all(if i == 0 { b"\n" } else { b",\n" })?;
        values.write_one(w, e)?;
    }
    w.write_all(b"]")?;
    if let Some(ps) = positions {
        w.write_all(b",\n\"positions\":[")?;
        for (i, p) in ps.iter().enumerate() {
            let sep = if i == 0 { "\n" } else { ",\n" };
            write!(w, "{sep}[\"{}\",\"{}\",\"{}\"]", p[0], p[1], p[2])?;
        }
        w.write_all(b"]")?;
    }
    w.write_all(b"}\n")
}

/// [`json`] of a [`super::Surface`], exact values as strings.
pub fn surface_json(w: &mut (impl Write + ?Sized), s: &super::Surface) -> io::Result<()> {
    let kind = match s.metric {
        super::Metric::Lengths(_) => MetricKind::Lengths,
        super::Metric::SquaredLengths(_) => MetricKind::SquaredLengths,
    };
    json(
        w,
        &s.name,
        &s.mesh,
        kind,
        Values::Exact(s.metric.values()),
        s.positions.as_deref(),
    )
}

fn not_by_faces() -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidInput,
        "the triangulation has loops or repeated edges that vertex triples cannot describe; write surface JSON (.json) instead",
    )
}

fn check_positions<P>(mesh: &Mesh, positions: &[[P; 3]]) -> io::Result<()> {
    if positions.len() != mesh.n_vertices() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!(
                "{} positions for {} vertices",
                positions.len(),
                mesh.n_vertices()
            ),
        ));
    }
    if !faces_determine_gluing(mesh) {
        return Err(not_by_faces());
    }
    Ok(())
}

/// Write OFF: `OFF`, `V F 0`, one vertex per line with exact coordinates (`parse_rational`
/// literals), one face `3 a b c` per line. Refused (`InvalidInput`) when the faces do not
/// determine the gluing ([`faces_determine_gluing`]).
pub fn off<P: Display>(
    w: &mut (impl Write + ?Sized),
    mesh: &Mesh,
    positions: &[[P; 3]],
) -> io::Result<()> {
    check_positions(mesh, positions)?;
    writeln!(w, "OFF\n{} {} 0", mesh.n_vertices(), mesh.n_faces())?;
    for p in positions {
        writeln!(w, "{} {} {}", p[0], p[1], p[2])?;
    }
    for f in mesh.face_list() {
        writeln!(w, "3 {} {} {}", f[0], f[1], f[2])?;
    }
    Ok(())
}

/// Write OBJ: `v x y z` per vertex, `f a b c` (1-based) per face; refused like [`off`].
pub fn obj<P: Display>(
    w: &mut (impl Write + ?Sized),
    mesh: &Mesh,
    positions: &[[P; 3]],
) -> io::Result<()> {
    check_positions(mesh, positions)?;
    for p in positions {
        writeln!(w, "v {} {} {}", p[0], p[1], p[2])?;
    }
    for f in mesh.face_list() {
        writeln!(w, "f {} {} {}", f[0] + 1, f[1] + 1, f[2] + 1)?;
    }
    Ok(())
}

/// Write a lengths file: a JSON array with one value per line, in [`edge_order`] (the
/// order of the `lengths` field of surface JSON), for a mesh written as OBJ or OFF.
pub fn lengths(w: &mut (impl Write + ?Sized), mesh: &Mesh, values: Values<'_>) -> io::Result<()> {
    if values.len() != mesh.n_edges() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} values for {} edges", values.len(), mesh.n_edges()),
        ));
    }
    w.write_all(b"[")?;
    for (i, e) in edge_order(mesh).into_iter().enumerate() {
        w.write_all(if i == 0 { b"\n" } else { b",\n" })?;
        values.write_one(w, e)?;
    }
    w.write_all(b"]\n")
}

/// Read a lengths file ([`lengths`]) for `mesh`: a JSON array of exact numbers (JSON
/// numbers as their binary64 values, strings by `parse_rational`) in [`edge_order`];
/// returns the values indexed by `Edge.idx()`. Errors name the entry (`lengths[k]`).
pub fn read_lengths(text: &str, mesh: &Mesh) -> Result<Vec<Rational>, ReadError> {
    let v: serde_json::Value = serde_json::from_str(text).map_err(|e| ReadError::Syntax {
        line: e.line(),
        message: e.to_string(),
    })?;
    let Some(items) = v.as_array() else {
        return Err(ReadError::Schema {
            element: "lengths".into(),
            message: "expected a JSON array with one length per edge".into(),
        });
    };
    let order = edge_order(mesh);
    if items.len() != order.len() {
        return Err(ReadError::Schema {
            element: "lengths".into(),
            message: format!("{} values for {} edges", items.len(), order.len()),
        });
    }
    let mut out = vec![Rational::new(); order.len()];
    for (k, (x, &e)) in items.iter().zip(&order).enumerate() {
        out[e] = exact_number(x, &format!("lengths[{k}]"))?;
    }
    Ok(out)
}
