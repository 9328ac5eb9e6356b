//! Shared pieces of the line-based readers (OBJ, OFF): comment stripping, exact
//! coordinates, and turning a face soup with exact positions into a located
//! [`DecimalSurface`].

use super::decimal::{parse_coordinate, Coordinate};
use super::decimal_surface::DecimalSurface;
use super::surface::MetricError;
use super::ReadError;
use crate::mesh::{Mesh, MeshError};

/// Non-empty lines with comments (`#` to end of line) removed, with 1-based line numbers.
pub fn content_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines().enumerate().filter_map(|(i, l)| {
        let l = l.split('#').next().unwrap_or("").trim();
        (!l.is_empty()).then_some((i + 1, l))
    })
}

/// An exact coordinate at `line`.
pub fn coordinate(tok: &str, line: usize) -> Result<Coordinate, ReadError> {
    parse_coordinate(tok).map_err(|source| ReadError::Number {
        element: format!("line {line}"),
        source,
    })
}

/// Build the surface from faces (0-based vertex ids) and exact positions, naming the line
/// of the face or vertex an error concerns.
pub fn surface_from_soup(
    positions: Vec<[Coordinate; 3]>,
    faces: &[[u32; 3]],
    vertex_lines: &[usize],
    face_lines: &[usize],
) -> Result<DecimalSurface, ReadError> {
    let vline = |v: u32| vertex_lines.get(v as usize).copied().unwrap_or(0);
    let fline = |f: u32| face_lines.get(f as usize).copied().unwrap_or(0);
    let nv = u32::try_from(positions.len()).map_err(|_| ReadError::HugeCount {
        what: "vertices",
        count: positions.len() as u64,
    })?;
    let mesh = Mesh::from_faces(nv, faces).map_err(|e| {
        let element = match &e {
            MeshError::VertexOutOfRange { face, .. } | MeshError::AmbiguousLoop { face, .. } => {
                format!("line {}", fline(*face))
            }
            MeshError::IsolatedVertex { vertex } | MeshError::NonManifoldVertex { vertex } => {
                format!("line {} (vertex {vertex}, 0-based)", vline(*vertex))
            }
            MeshError::NonManifoldEdge { a, b } => format!(
                "edge between the vertices of lines {} and {}",
                vline(*a),
                vline(*b)
            ),
            _ => "surface".into(),
        };
        ReadError::Mesh { element, source: e }
    })?;
    let ends: Vec<(u32, u32)> = mesh
        .edges()
        .map(|e| (mesh.tail(e.halfedge()).0, mesh.tip(e.halfedge()).0))
        .collect();
    DecimalSurface::new("", mesh, positions).map_err(|source| {
        let element = match &source {
            MetricError::TriangleInequality { face, .. } => format!("line {}", fline(*face)),
            MetricError::NonPositive { edge, .. } => {
                let (a, b) = ends.get(*edge as usize).copied().unwrap_or((0, 0));
                format!("coincident vertices of lines {} and {}", vline(a), vline(b))
            }
            _ => "surface".into(),
        };
        ReadError::Metric { element, source }
    })
}
