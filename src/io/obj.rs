//! Wavefront OBJ: vertices `v x y z` with exact decimal coordinates and triangular faces
//! `f a b c` (corners `i`, `i/t`, `i/t/n`, `i//n`; 1-based, negative = relative).
//!
//! Faces with more than three corners are refused ([`ReadError::NotTriangle`]) rather than
//! triangulated silently: a triangulation invents edges the file does not have. The
//! `triangulate` repair ([`super::repair`]) splits them on request, reported. `v` lines take 3
//! coordinates, 4 with `w = 1`, or 6 (xyz + an RGB colour, ignored). `vt`, `vn`, `vp`,
//! `g`, `o`, `s`, `usemtl`, `mtllib`, `l` and `p` lines are ignored; any other statement
//! is an error.

use super::decimal::Coordinate;
use super::decimal_surface::DecimalSurface;
use super::soup::PolygonSoup;
use super::surface::Surface;
use super::text::{content_lines, coordinate};
use super::{text_of, ReadError};

/// Read an OBJ surface from bytes (refusing non-UTF-8 data).
pub fn read_bytes(bytes: &[u8]) -> Result<Surface, ReadError> {
    read(text_of(bytes)?)
}

/// Read a surface from text into its compact form (exact coordinates, metric computed per
/// edge): the fast path for large meshes. [`read`] is this followed by
/// [`DecimalSurface::into_surface`].
pub fn read_decimal(text: &str) -> Result<DecimalSurface, ReadError> {
    read_polygons(text)?.into_surface()
}

/// Read an OBJ surface from text.
///
/// ```
/// let s = penner::io::obj::read("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
///     f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n").unwrap();
/// assert_eq!(s.mesh.euler_characteristic(), 2);
/// ```
pub fn read(text: &str) -> Result<Surface, ReadError> {
    read_decimal(text).map(DecimalSurface::into_surface)
}

/// Read the vertices and faces as written (polygons kept), for [`super::repair`].
pub fn read_polygons(text: &str) -> Result<PolygonSoup, ReadError> {
    let mut positions: Vec<[Coordinate; 3]> = Vec::new();
    let mut vertex_lines = Vec::new();
    // Corners as written (resolved after all vertices are known), with their line.
    let mut raw_corners: Vec<i64> = Vec::new();
    let mut raw_faces: Vec<(usize, usize, usize)> = Vec::new(); // (end in raw_corners, line, vertices seen)
    for (line, l) in content_lines(text) {
        let mut toks = l.split_ascii_whitespace();
        let Some(key) = toks.next() else { continue };
        let args: Vec<&str> = toks.collect();
        match key {
            "v" => {
                if !matches!(args.len(), 3 | 4 | 6) {
                    return Err(ReadError::Syntax {
                        line,
                        message: format!("`v` needs 3 coordinates, found {}", args.len()),
                    });
                }
                let q = [
                    coordinate(args[0], line)?,
                    coordinate(args[1], line)?,
                    coordinate(args[2], line)?,
                ];
                for extra in &args[3..] {
                    coordinate(extra, line)?;
                }
                if args.len() == 4 && coordinate(args[3], line)?.to_rational() != 1 {
                    return Err(ReadError::Syntax {
                        line,
                        message: "homogeneous coordinate w ≠ 1 is not supported".into(),
                    });
                }
                positions.push(q);
                vertex_lines.push(line);
            }
            "f" => {
                if args.len() < 3 {
                    return Err(ReadError::NotTriangle {
                        element: format!("line {line}"),
                        count: args.len(),
                    });
                }
                for a in &args {
                    let idx = a.split('/').next().unwrap_or("");
                    raw_corners.push(idx.parse::<i64>().map_err(|_| ReadError::Syntax {
                        line,
                        message: format!("`{}` is not a vertex index", short(a)),
                    })?);
                }
                raw_faces.push((raw_corners.len(), line, positions.len()));
            }
            "vt" | "vn" | "vp" | "g" | "o" | "s" | "usemtl" | "mtllib" | "l" | "p" => {}
            other => {
                return Err(ReadError::Syntax {
                    line,
                    message: format!("unknown statement `{}`", short(other)),
                })
            }
        }
    }
    let n = positions.len();
    let mut soup = PolygonSoup {
        positions: Vec::new(),
        vertex_lines,
        corners: Vec::with_capacity(raw_corners.len()),
        ends: Vec::with_capacity(raw_faces.len()),
        face_lines: Vec::with_capacity(raw_faces.len()),
    };
    let mut start = 0;
    for (end, line, seen) in raw_faces {
        for &i in &raw_corners[start..end] {
            // 1-based; negative counts back from the vertices defined so far.
            let zero_based = if i > 0 { i - 1 } else { seen as i64 + i };
            if i == 0 || zero_based < 0 || zero_based >= n as i64 {
                return Err(ReadError::IndexOutOfRange {
                    element: format!("line {line}"),
                    index: i,
                    n_vertices: n,
                });
            }
            soup.corners.push(zero_based as u32);
        }
        soup.ends.push(soup.corners.len());
        soup.face_lines.push(line);
        start = end;
    }
    soup.positions = positions;
    Ok(soup)
}
fn short(s: &str) -> String {
    s.chars().take(40).collect()
}
