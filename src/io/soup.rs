//! A polygon soup as OBJ and OFF files hold it: exact positions and faces with three or
//! more corners, each with the line it was read from. The readers build one, optional
//! repairs ([`super::repair`]) change it and say what they changed, and
//! [`PolygonSoup::into_surface`] turns a soup of triangles into a [`DecimalSurface`].

use super::decimal::Coordinate;
use super::decimal_surface::DecimalSurface;
use super::text::surface_from_soup;
use super::ReadError;

/// Exact vertex positions and polygon faces (0-based vertex ids, in the file's order), with
/// the 1-based line of every vertex and face. Faces are stored flat: face `f` is
/// `corners[ends[f − 1]..ends[f]]` (from 0 for the first).
#[derive(Clone, Debug, Default)]
pub struct PolygonSoup {
    /// Vertex positions, exact.
    pub positions: Vec<[Coordinate; 3]>,
    /// The line of each vertex.
    pub vertex_lines: Vec<usize>,
    /// The corners of all faces, one face after the other.
    pub corners: Vec<u32>,
    /// The end of each face in `corners`.
    pub ends: Vec<usize>,
    /// The line of each face.
    pub face_lines: Vec<usize>,
}

impl PolygonSoup {
    /// The number of faces.
    pub fn n_faces(&self) -> usize {
        self.ends.len()
    }

    /// The corners of face `f`, in order.
    pub fn face(&self, f: usize) -> &[u32] {
        let start = if f == 0 { 0 } else { self.ends[f - 1] };
        &self.corners[start..self.ends[f]]
    }

    /// Append a face read at `line`.
    pub fn push_face(&mut self, corners: &[u32], line: usize) {
        self.corners.extend_from_slice(corners);
        self.ends.push(self.corners.len());
        self.face_lines.push(line);
    }

    /// The surface of a soup of triangles, or [`ReadError::NotTriangle`] naming the line of
    /// the first face with more corners (the `triangulate` repair splits them).
    pub fn into_surface(self) -> Result<DecimalSurface, ReadError> {
        let mut triangles = Vec::with_capacity(self.n_faces());
        for f in 0..self.n_faces() {
            match *self.face(f) {
                [a, b, c] => triangles.push([a, b, c]),
                ref other => {
                    return Err(ReadError::NotTriangle {
                        element: format!("line {}", self.face_lines[f]),
                        count: other.len(),
                    })
                }
            }
        }
        surface_from_soup(
            self.positions,
            &triangles,
            &self.vertex_lines,
            &self.face_lines,
        )
    }
}
