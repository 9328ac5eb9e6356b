//! OFF (Object File Format): a header line `OFF`, a count line `V F E` (the counts may
//! also follow `OFF` on its line; E is ignored), V vertex lines `x y z` with exact decimal
//! coordinates, and F face lines `3 a b c` (0-based), optionally followed by colour
//! numbers, which are ignored. `#` starts a comment. Faces with other than three corners
//! are refused ([`ReadError::NotTriangle`]) unless the `triangulate` repair
//! ([`super::repair`]) is asked for; `COFF`, `NOFF` and other variants are not
//! read. Counts are checked against the file size before anything is allocated.

use super::decimal::Coordinate;
use super::decimal_surface::DecimalSurface;
use super::soup::PolygonSoup;
use super::surface::Surface;
use super::text::{content_lines, coordinate};
use super::{text_of, ReadError};

/// Read an OFF surface from bytes (refusing non-UTF-8 data).
pub fn read_bytes(bytes: &[u8]) -> Result<Surface, ReadError> {
    read(text_of(bytes)?)
}

/// Read a surface from text into its compact form (exact coordinates, metric computed per
/// edge): the fast path for large meshes. [`read`] is this followed by
/// [`DecimalSurface::into_surface`].
pub fn read_decimal(text: &str) -> Result<DecimalSurface, ReadError> {
    read_polygons(text)?.into_surface()
}

fn count(tok: Option<&str>, line: usize, what: &str) -> Result<u64, ReadError> {
    let tok = tok.ok_or_else(|| ReadError::Syntax {
        line,
        message: format!("expected the {what} count"),
    })?;
    tok.parse::<u64>().map_err(|_| ReadError::Syntax {
        line,
        message: format!(
            "the {what} count `{}` is not a non-negative integer",
            short(tok)
        ),
    })
}

/// Read an OFF surface from text.
///
/// ```
/// let s = penner::io::off::read("OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n\
///     3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n").unwrap();
/// assert_eq!(s.mesh.n_faces(), 4);
/// ```
pub fn read(text: &str) -> Result<Surface, ReadError> {
    read_decimal(text).map(DecimalSurface::into_surface)
}

/// Read the vertices and faces as written (polygons kept), for [`super::repair`].
pub fn read_polygons(text: &str) -> Result<PolygonSoup, ReadError> {
    // Only an error at the end of the file needs the last line's number.
    let last = || text.lines().count().max(1);
    let mut lines = content_lines(text).peekable();
    let Some((hline, header)) = lines.next() else {
        return Err(ReadError::Truncated {
            line: last(),
            expected: "the `OFF` header".into(),
        });
    };
    let mut toks = header.split_ascii_whitespace();
    if toks.next() != Some("OFF") {
        return Err(ReadError::Syntax {
            line: hline,
            message: "expected the header `OFF`".into(),
        });
    }
    let rest: Vec<&str> = toks.collect();
    let (cline, counts): (usize, Vec<&str>) = if rest.is_empty() {
        let (l, c) = lines.next().ok_or_else(|| ReadError::Truncated {
            line: last(),
            expected: "the counts line `V F E`".into(),
        })?;
        (l, c.split_ascii_whitespace().collect())
    } else {
        (hline, rest)
    };
    if counts.len() > 3 {
        return Err(ReadError::Syntax {
            line: cline,
            message: "expected `V F E`".into(),
        });
    }
    let nv = count(counts.first().copied(), cline, "vertex")?;
    let nf = count(counts.get(1).copied(), cline, "face")?;
    // Smallest possible lines: "0 0 0" and "3 0 1 2", plus a newline each.
    let remaining = text.len() as u64;
    if nv.saturating_mul(6) > remaining + 1 {
        return Err(ReadError::HugeCount {
            what: "vertices",
            count: nv,
        });
    }
    if nf.saturating_mul(8) > remaining + 1 {
        return Err(ReadError::HugeCount {
            what: "faces",
            count: nf,
        });
    }
    let mut positions: Vec<[Coordinate; 3]> = Vec::with_capacity(nv as usize);
    let mut vertex_lines = Vec::with_capacity(nv as usize);
    for i in 0..nv {
        let (line, l) = lines.next().ok_or_else(|| ReadError::Truncated {
            line: last(),
            expected: format!("vertex {} of {nv}", i + 1),
        })?;
        positions.push(vertex_line(line, l)?);
        vertex_lines.push(line);
    }
    let mut soup = PolygonSoup {
        corners: Vec::with_capacity(3 * nf as usize),
        ends: Vec::with_capacity(nf as usize),
        face_lines: Vec::with_capacity(nf as usize),
        ..PolygonSoup::default()
    };
    for i in 0..nf {
        let (line, l) = lines.next().ok_or_else(|| ReadError::Truncated {
            line: last(),
            expected: format!("face {} of {nf}", i + 1),
        })?;
        face_line(line, l, nv, &mut soup.corners)?;
        soup.ends.push(soup.corners.len());
        soup.face_lines.push(line);
    }
    if let Some((line, _)) = lines.next() {
        return Err(ReadError::Syntax {
            line,
            message: "unexpected content after the last face".into(),
        });
    }
    soup.positions = positions;
    soup.vertex_lines = vertex_lines;
    Ok(soup)
}

fn short(s: &str) -> String {
    s.chars().take(40).collect()
}

fn vertex_line(line: usize, l: &str) -> Result<[Coordinate; 3], ReadError> {
    let mut t = l.split_ascii_whitespace();
    let (Some(x), Some(y), Some(z), None) = (t.next(), t.next(), t.next(), t.next()) else {
        return Err(ReadError::Syntax {
            line,
            message: format!(
                "a vertex line needs 3 coordinates, found {}",
                l.split_ascii_whitespace().count()
            ),
        });
    };
    Ok([
        coordinate(x, line)?,
        coordinate(y, line)?,
        coordinate(z, line)?,
    ])
}

/// Append the corners of the face line `l` to `corners`.
fn face_line(line: usize, l: &str, nv: u64, corners: &mut Vec<u32>) -> Result<(), ReadError> {
    let t: Vec<&str> = l.split_ascii_whitespace().collect();
    let k = count(t.first().copied(), line, "corner")?;
    if k < 3 {
        return Err(ReadError::NotTriangle {
            element: format!("line {line}"),
            count: usize::try_from(k).unwrap_or(usize::MAX),
        });
    }
    let k = usize::try_from(k).unwrap_or(usize::MAX);
    if t.len() - 1 < k {
        return Err(ReadError::Syntax {
            line,
            message: format!(
                "a face line `{k} a b c …` needs {k} indices, found {}",
                t.len() - 1
            ),
        });
    }
    for tok in &t[1..=k] {
        let idx: i64 = tok.parse().map_err(|_| ReadError::Syntax {
            line,
            message: format!("`{}` is not a vertex index", short(tok)),
        })?;
        if idx < 0 || idx >= nv as i64 {
            return Err(ReadError::IndexOutOfRange {
                element: format!("line {line}"),
                index: idx,
                n_vertices: nv as usize,
            });
        }
        corners.push(idx as u32);
    }
    for colour in &t[k + 1..] {
        coordinate(colour, line)?;
    }
    Ok(())
}
