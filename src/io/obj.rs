//! Wavefront OBJ: vertices `v x y z` with exact decimal coordinates and triangular faces
//! `f a b c` (corners `i`, `i/t`, `i/t/n`, `i//n`; 1-based, negative = relative).
//!
//! Faces with more than three corners are refused ([`ReadError::NotTriangle`]) rather than
//! triangulated: a fan would invent edges the file does not have. `v` lines take 3
//! coordinates, 4 with `w = 1`, or 6 (xyz + an RGB colour, ignored). `vt`, `vn`, `vp`,
//! `g`, `o`, `s`, `usemtl`, `mtllib`, `l` and `p` lines are ignored; any other statement
//! is an error.

use super::decimal::Coordinate;
use super::decimal_surface::DecimalSurface;
use super::surface::Surface;
use super::text::{content_lines, coordinate, surface_from_soup};
use super::{text_of, ReadError};

/// Read an OBJ surface from bytes (refusing non-UTF-8 data).
pub fn read_bytes(bytes: &[u8]) -> Result<Surface, ReadError> {
    read(text_of(bytes)?)
}

/// Read a surface from text into its compact form (exact coordinates, metric computed per
/// edge): the fast path for large meshes. [`read`] is this followed by
/// [`DecimalSurface::into_surface`].
pub fn read_decimal(text: &str) -> Result<DecimalSurface, ReadError> {
    read_soup(text)
}

/// Read an OBJ surface from text.
///
/// ```
/// let s = penner::io::obj::read("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
///     f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n").unwrap();
/// assert_eq!(s.mesh.euler_characteristic(), 2);
/// ```
pub fn read(text: &str) -> Result<Surface, ReadError> {
    read_soup(text).map(DecimalSurface::into_surface)
}

fn read_soup(text: &str) -> Result<DecimalSurface, ReadError> {
    let mut positions: Vec<[Coordinate; 3]> = Vec::new();
    let mut vertex_lines = Vec::new();
    // Corners as written (resolved after all vertices are known), with their line.
    let mut raw_faces: Vec<([i64; 3], usize, usize)> = Vec::new();
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
                if args.len() != 3 {
                    return Err(ReadError::NotTriangle {
                        element: format!("line {line}"),
                        count: args.len(),
                    });
                }
                let mut c = [0i64; 3];
                for (k, a) in args.iter().enumerate() {
                    let idx = a.split('/').next().unwrap_or("");
                    c[k] = idx.parse::<i64>().map_err(|_| ReadError::Syntax {
                        line,
                        message: format!("`{}` is not a vertex index", short(a)),
                    })?;
                }
                raw_faces.push((c, line, positions.len()));
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
    let mut faces = Vec::with_capacity(raw_faces.len());
    let mut face_lines = Vec::with_capacity(raw_faces.len());
    for (c, line, seen) in raw_faces {
        let mut tri = [0u32; 3];
        for k in 0..3 {
            // 1-based; negative counts back from the vertices defined so far.
            let i = c[k];
            let zero_based = if i > 0 { i - 1 } else { seen as i64 + i };
            if i == 0 || zero_based < 0 || zero_based >= n as i64 {
                return Err(ReadError::IndexOutOfRange {
                    element: format!("line {line}"),
                    index: i,
                    n_vertices: n,
                });
            }
            tri[k] = zero_based as u32;
        }
        faces.push(tri);
        face_lines.push(line);
    }
    surface_from_soup(positions, &faces, &vertex_lines, &face_lines)
}

fn short(s: &str) -> String {
    s.chars().take(40).collect()
}
